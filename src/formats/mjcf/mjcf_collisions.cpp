#include "formats/mjcf/mjcf_collisions.h"

#include <filesystem>

#include "util/numbers.h"

namespace assetlint::mjcf {
namespace {

using tinyxml2::XMLElement;

std::string joined(const std::string& dir, const std::string& file) {
  if (dir.empty() || std::filesystem::path(file).is_absolute()) return file;
  return dir.back() == '/' ? dir + file : dir + "/" + file;
}

}  // namespace

MeshAssets read_mesh_assets(const MjcfSources& sources, const std::vector<const XMLElement*>& sections,
                            const Defaults& defaults, const Compiler& compiler, Values& values) {
  MeshAssets meshes;
  for (const XMLElement* section : sections) {
    if (std::string_view(section->Name()) != "asset") continue;
    for (const XMLElement* el : sources.children(section)) {
      if (std::string_view(el->Name()) != "mesh") continue;
      const char* cls = el->Attribute("class");
      const auto& defs = defaults.elements(cls && defaults.has_class(cls) ? cls : "main", "mesh");
      MeshAsset mesh;
      if (auto s = values.numbers(Defaults::lookup(el, defs, "scale"), "scale", 3)) mesh.scale = {(*s)[0], (*s)[1], (*s)[2]};
      const char* file = el->Attribute("file");
      std::string name = el->Attribute("name") ? std::string(trim(el->Attribute("name"))) : std::string();
      if (file) {
        mesh.file = joined(compiler.meshdir, std::string(trim(file)));
        if (name.empty()) name = std::filesystem::path(std::string(trim(file))).stem().string();
      } else if (auto v = values.numbers(Attr{el, el->Attribute("vertex")}, "vertex"); v && v->size() % 3 == 0) {
        for (std::size_t i = 0; i < v->size(); i += 3)
          mesh.vertices.push_back(Eigen::Vector3d((*v)[i], (*v)[i + 1], (*v)[i + 2]).cwiseProduct(mesh.scale));
      }
      if (!name.empty()) meshes.emplace(std::move(name), std::move(mesh));
    }
  }
  return meshes;
}

bool geom_collides(const XMLElement* geom, const std::vector<const XMLElement*>& defaults, Values& values) {
  const auto bits = [&](const char* name) {
    auto v = values.numbers(Defaults::lookup(geom, defaults, name), name, 1);
    return v ? (*v)[0] : 1.0;  // MuJoCo's default contype and conaffinity
  };
  return bits("contype") != 0 || bits("conaffinity") != 0;
}

std::optional<CollisionShape> collision_shape(const XMLElement* geom, const GeomShape& shape, const MeshAssets& meshes,
                                              Values& values) {
  CollisionShape out;
  out.pose = shape.pose;
  out.span = values.element_span(geom);
  const Eigen::Vector3d& s = shape.size;
  if (shape.type == "mesh") {
    const auto mesh = meshes.find(shape.mesh);
    if (mesh == meshes.end()) return std::nullopt;
    out.kind = CollisionShape::Kind::Mesh;
    if (mesh->second.file.empty()) {
      out.mesh = shape.mesh;
      out.points = mesh->second.vertices;
    } else {
      out.mesh = mesh->second.file;
      out.mesh_scale = mesh->second.scale;
    }
    return out;
  }
  if (!shape.mesh.empty()) return std::nullopt;  // a primitive MuJoCo fits to a mesh
  if (shape.type == "box" && s.x() > 0 && s.y() > 0 && s.z() > 0) {
    out.kind = CollisionShape::Kind::Box;
    out.size = 2.0 * s;
  } else if (shape.type == "sphere" && s.x() > 0) {
    out.kind = CollisionShape::Kind::Sphere;
    out.size = {s.x(), 0, 0};
  } else if ((shape.type == "capsule" || shape.type == "cylinder") && s.x() > 0 && s.y() > 0) {
    out.kind = shape.type == "capsule" ? CollisionShape::Kind::Capsule : CollisionShape::Kind::Cylinder;
    out.size = {s.x(), 2.0 * s.y(), 0};
  } else {
    return std::nullopt;
  }
  return out;
}

}  // namespace assetlint::mjcf
