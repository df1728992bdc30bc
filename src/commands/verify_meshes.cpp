#include "commands/verify_meshes.h"

#include <fmt/format.h>

#include <filesystem>

#include "config/project_root.h"
#include "formats/mesh/mesh_points.h"
#include "formats/xacro/packages.h"

namespace assetlint::commands {
namespace {

// A `package://pkg/rest` mesh the checked tree does not hold, found as `check` finds $(find pkg)
// for a xacro file: the package holding the asset and those around it, then ROS_PACKAGE_PATH.
std::optional<std::string> package_file(const std::string& filename, const std::string& asset, const std::string& root) {
  if (!filename.starts_with("package://")) return std::nullopt;
  const std::string rest = filename.substr(10);
  const auto slash = rest.find('/');
  const auto package = xacro::find_ros_package(rest.substr(0, slash), asset, root);
  if (!package || slash == std::string::npos) return std::nullopt;
  return (std::filesystem::path(*package) / rest.substr(slash + 1)).lexically_normal().string();
}

}  // namespace

bool read_collision_meshes(const std::string& path, const Asset& asset, const Settings& settings,
                           const std::vector<std::string>& links, verify::MeshPoints& meshes, std::string& error) {
  const std::string asset_dir = std::filesystem::path(path).parent_path().string();
  const std::string root = config::checked_root(path, settings);
  const ReadPolicy reads = config::read_policy(path, settings);
  for (const std::string& filename : verify::collision_meshes(asset, links)) {
    auto file = mesh::resolve_mesh(filename, asset_dir.empty() ? "." : asset_dir,
                                   root.empty() ? (asset_dir.empty() ? "." : asset_dir) : root, error);
    if (!file) file = package_file(filename, path, root);
    if (!file) return false;
    if (auto refused = reads.refusal(*file)) {
      error = fmt::format("mesh '{}' {}", filename, *refused);
      return false;
    }
    auto points = mesh::read_points(*file, error);
    if (!points) return false;
    meshes[filename] = std::move(*points);
  }
  for (const Link& link : asset.links)
    for (const CollisionShape& shape : link.collisions)
      if (shape.kind == CollisionShape::Kind::Mesh && !shape.points.empty()) meshes[shape.mesh] = shape.points;
  return true;
}

}  // namespace assetlint::commands
