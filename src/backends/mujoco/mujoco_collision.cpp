#include "backends/mujoco/mujoco_collision.h"

#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cstring>
#include <map>
#include <regex>
#include <set>

namespace assetlint::backends::mujoco {
namespace {

using collision::Overlap;
using collision::Overlaps;
using collision::PlacedShape;

std::string num(double v) { return fmt::format("{:.9g}", v); }

std::string pose_attributes(const Eigen::Isometry3d& pose) {
  const Eigen::Quaterniond q(pose.linear());
  const Eigen::Vector3d p = pose.translation();
  return fmt::format("pos=\"{} {} {}\" quat=\"{} {} {} {}\"", num(p.x()), num(p.y()), num(p.z()), num(q.w()),
                     num(q.x()), num(q.y()), num(q.z()));
}

// Why MuJoCo cannot collide the shape, or nothing: a size it refuses, a mesh whose vertices
// span no volume (MuJoCo's hull needs four points off one plane).
std::optional<std::string> unusable(const PlacedShape& shape) {
  using Kind = CollisionShape::Kind;
  if (shape.kind != Kind::Mesh) {
    const int needed = shape.kind == Kind::Box ? 3 : shape.kind == Kind::Sphere ? 1 : 2;
    for (int i = 0; i < needed; ++i)
      if (!(shape.size[i] > 0) || !std::isfinite(shape.size[i])) return std::string("a size that is not positive");
    return std::nullopt;
  }
  if (!shape.points || shape.points->size() < 4) return std::string("a mesh with fewer than four vertices");
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : *shape.points) mean += p;
  mean /= static_cast<double>(shape.points->size());
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (const auto& p : *shape.points) spread += (p - mean) * (p - mean).transpose();
  const Eigen::Vector3d sv = Eigen::JacobiSVD<Eigen::Matrix3d>(spread).singularValues();
  if (!(sv[2] > 1e-12 * sv[0])) return std::string("a flat mesh (its vertices lie in one plane)");
  return std::nullopt;
}

// A box as the hull of its eight corners: on two boxes 5 mm into each other MuJoCo 2.2.2's
// box-box function (mjc_BoxBox) reported 2.5 mm, its convex-hull path (mjc_Convex, libccd's MPR)
// the 5 mm there are, so boxes take the hull path.
std::vector<Eigen::Vector3d> box_corners(const Eigen::Vector3d& size) {
  std::vector<Eigen::Vector3d> corners;
  for (int i = 0; i < 8; ++i)
    corners.emplace_back((i & 1 ? 0.5 : -0.5) * size.x(), (i & 2 ? 0.5 : -0.5) * size.y(),
                         (i & 4 ? 0.5 : -0.5) * size.z());
  return corners;
}

std::string vertex_list(const std::vector<Eigen::Vector3d>& points) {
  std::string out;
  for (const auto& p : points) out += fmt::format("{} {} {} ", num(p.x()), num(p.y()), num(p.z()));
  return out;
}

std::string model_text(const std::vector<PlacedShape>& shapes, const std::vector<std::size_t>& used,
                       std::size_t contacts) {
  std::string out = "<mujoco model=\"asset-lint collisions\">\n  <compiler angle=\"radian\"/>\n";
  out += fmt::format("  <size nconmax=\"{}\" njmax=\"{}\"/>\n", contacts, contacts);
  out += "  <asset>\n";
  for (std::size_t g = 0; g < used.size(); ++g) {
    const PlacedShape& s = shapes[used[g]];
    if (s.kind == CollisionShape::Kind::Mesh)
      out += fmt::format("    <mesh name=\"m{}\" vertex=\"{}\"/>\n", g, vertex_list(*s.points));
    else if (s.kind == CollisionShape::Kind::Box)
      out += fmt::format("    <mesh name=\"m{}\" vertex=\"{}\"/>\n", g, vertex_list(box_corners(s.size)));
  }
  out += "  </asset>\n  <worldbody>\n";
  std::map<std::size_t, std::vector<std::size_t>> by_body;
  for (std::size_t g = 0; g < used.size(); ++g) by_body[shapes[used[g]].body].push_back(g);
  for (const auto& [body, geoms] : by_body) {
    out += fmt::format("    <body name=\"b{}\"><freejoint/><inertial pos=\"0 0 0\" mass=\"1\" diaginertia=\"1 1 1\"/>\n",
                       body);
    for (std::size_t g : geoms) {
      const PlacedShape& s = shapes[used[g]];
      std::string type;
      switch (s.kind) {
        case CollisionShape::Kind::Box: type = fmt::format("type=\"mesh\" mesh=\"m{}\"", g); break;
        case CollisionShape::Kind::Sphere: type = fmt::format("type=\"sphere\" size=\"{}\"", num(s.size.x())); break;
        case CollisionShape::Kind::Cylinder:
          type = fmt::format("type=\"cylinder\" size=\"{} {}\"", num(s.size.x()), num(s.size.y() / 2));
          break;
        case CollisionShape::Kind::Capsule:
          type = fmt::format("type=\"capsule\" size=\"{} {}\"", num(s.size.x()), num(s.size.y() / 2));
          break;
        case CollisionShape::Kind::Mesh: type = fmt::format("type=\"mesh\" mesh=\"m{}\"", g); break;
      }
      out += fmt::format("      <geom name=\"g{}\" {} {}/>\n", g, type, pose_attributes(s.pose));
    }
    out += "    </body>\n";
  }
  out += "  </worldbody>\n</mujoco>\n";
  return out;
}

// The geom a compile error names ("Object name = g12" or its mesh "m12"), when it names one.
std::optional<std::size_t> blamed_geom(const std::string& error) {
  static const std::regex named(R"(Object name = [gm](\d+))");
  std::smatch match;
  if (!std::regex_search(error, match, named)) return std::nullopt;
  return static_cast<std::size_t>(std::stoul(match[1].str()));
}

mjModel* compile(const std::string& text, std::string& error) {
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  if (mj_makeEmptyFileVFS(&vfs, "collisions.xml", static_cast<int>(text.size())) != 0) {
    error = "MuJoCo's virtual file system refused the model";
    return nullptr;
  }
  const int file = mj_findFileVFS(&vfs, "collisions.xml");
  std::memcpy(vfs.filedata[file], text.data(), text.size());
  char message[1000] = "";
  mjModel* model = mj_loadXML("collisions.xml", &vfs, message, sizeof message);
  mj_deleteVFS(&vfs);
  if (!model) error = message;
  return model;
}

}  // namespace

std::string MujocoCollision::name() const { return std::string("MuJoCo ") + mj_versionString(); }

std::optional<Overlaps> MujocoCollision::overlaps(const std::vector<PlacedShape>& shapes, std::string& error) const {
  Overlaps result;
  std::vector<std::size_t> used;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    if (auto why = unusable(shapes[i])) result.skipped.emplace_back(i, *why);
    else used.push_back(i);
  }
  std::set<std::size_t> bodies;
  for (std::size_t i : used) bodies.insert(shapes[i].body);
  if (bodies.size() < 2) return result;

  const std::size_t contacts = 16 * used.size() + 256;
  mjModel* model = nullptr;
  // A shape MuJoCo's compiler still refuses is left out with its message, and the rest compiled again.
  for (std::size_t attempt = 0; attempt <= used.size() && !model; ++attempt) {
    std::string message;
    model = compile(model_text(shapes, used, contacts), message);
    if (model) break;
    const auto geom = blamed_geom(message);
    if (!geom || *geom >= used.size()) {
      error = fmt::format("MuJoCo cannot build the collision scene: {}", message);
      return std::nullopt;
    }
    result.skipped.emplace_back(used[*geom], fmt::format("MuJoCo refuses it: {}", message));
    used.erase(used.begin() + static_cast<std::ptrdiff_t>(*geom));
  }
  if (!model) {
    error = "MuJoCo cannot build the collision scene";
    return std::nullopt;
  }
  mjData* data = mj_makeData(model);
  mj_kinematics(model, data);
  mj_collision(model, data);
  if (data->warning[mjWARN_CONTACTFULL].number > 0) {
    error = fmt::format("more than {} contacts: MuJoCo's contact buffer is full", contacts);
    mj_deleteData(data);
    mj_deleteModel(model);
    return std::nullopt;
  }
  // Geoms are numbered body by body; their names carry the position in `used`.
  std::vector<std::size_t> shape_of(static_cast<std::size_t>(model->ngeom));
  for (int g = 0; g < model->ngeom; ++g)
    shape_of[static_cast<std::size_t>(g)] = used[std::stoul(std::string(mj_id2name(model, mjOBJ_GEOM, g) + 1))];
  std::map<std::pair<std::size_t, std::size_t>, Overlap> deepest;
  for (int c = 0; c < data->ncon; ++c) {
    const mjContact& contact = data->contact[c];
    if (!(contact.dist < 0)) continue;
    std::size_t a = shape_of[static_cast<std::size_t>(contact.geom1)], b = shape_of[static_cast<std::size_t>(contact.geom2)];
    if (a > b) std::swap(a, b);
    Overlap& o = deepest[{a, b}];
    if (-contact.dist > o.depth) o = Overlap{a, b, -contact.dist, Eigen::Vector3d(contact.pos[0], contact.pos[1], contact.pos[2])};
  }
  for (auto& [pair, overlap] : deepest) result.overlaps.push_back(overlap);
  mj_deleteData(data);
  mj_deleteModel(model);
  return result;
}

const MujocoCollision& collision_engine() {
  static const MujocoCollision engine;
  return engine;
}

}  // namespace assetlint::backends::mujoco
