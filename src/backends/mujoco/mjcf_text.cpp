#include "backends/mujoco/mjcf_text.h"

#include <fmt/format.h>

namespace assetlint::backends::mujoco {
namespace {

std::string mesh_key(const CollisionShape& shape) { return shape.mesh + "|" + mjcf_vector(shape.mesh_scale); }

}  // namespace

std::string mjcf_number(double v) { return fmt::format("{:.17g}", v); }
std::string mjcf_vector(const Eigen::Vector3d& v) {
  return fmt::format("{} {} {}", mjcf_number(v.x()), mjcf_number(v.y()), mjcf_number(v.z()));
}
std::string mjcf_quat(const Eigen::Matrix3d& r) {
  const Eigen::Quaterniond q(r);
  return fmt::format("{} {} {} {}", mjcf_number(q.w()), mjcf_number(q.x()), mjcf_number(q.y()), mjcf_number(q.z()));
}
std::string mjcf_pose(const Eigen::Isometry3d& pose) {
  return fmt::format("pos=\"{}\" quat=\"{}\"", mjcf_vector(pose.translation()), mjcf_quat(pose.linear()));
}

bool write_mesh_assets(const Asset& asset, const verify::MeshPoints& meshes,
                       const std::function<bool(const Link&)>& include, std::string& out, MeshIds& ids,
                       std::string& error) {
  bool opened = false;
  for (const Link& link : asset.links) {
    if (!include(link)) continue;
    for (const CollisionShape& shape : link.collisions) {
      if (shape.kind != CollisionShape::Kind::Mesh || ids.count(mesh_key(shape))) continue;
      const auto found = meshes.find(shape.mesh);
      if (found == meshes.end() || found->second.size() < 4) {
        error = fmt::format("mesh '{}' of link '{}' has fewer than 4 points: nothing to collide with", shape.mesh,
                            link.name.text);
        return false;
      }
      const std::size_t id = ids.size();
      ids[mesh_key(shape)] = id;
      std::string vertices;
      for (const Eigen::Vector3d& p : found->second)
        vertices += (vertices.empty() ? "" : " ") + mjcf_vector(p.cwiseProduct(shape.mesh_scale));
      if (!opened) out += "  <asset>\n";
      opened = true;
      out += fmt::format("    <mesh name=\"m{}\" vertex=\"{}\"/>\n", id, vertices);
    }
  }
  if (opened) out += "  </asset>\n";
  return true;
}

std::string mjcf_geometry(const CollisionShape& shape, const MeshIds& ids) {
  switch (shape.kind) {
    case CollisionShape::Kind::Box: return fmt::format("type=\"box\" size=\"{}\"", mjcf_vector(0.5 * shape.size));
    case CollisionShape::Kind::Sphere: return fmt::format("type=\"sphere\" size=\"{}\"", mjcf_number(shape.size.x()));
    case CollisionShape::Kind::Cylinder:
      return fmt::format("type=\"cylinder\" size=\"{} {}\"", mjcf_number(shape.size.x()), mjcf_number(0.5 * shape.size.y()));
    case CollisionShape::Kind::Capsule:
      return fmt::format("type=\"capsule\" size=\"{} {}\"", mjcf_number(shape.size.x()), mjcf_number(0.5 * shape.size.y()));
    case CollisionShape::Kind::Mesh: break;
  }
  return fmt::format("type=\"mesh\" mesh=\"m{}\"", ids.at(mesh_key(shape)));
}

}  // namespace assetlint::backends::mujoco
