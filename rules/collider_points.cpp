#include "rules/collider_points.h"

#include <filesystem>

#include "config/project_root.h"
#include "formats/mesh/mesh_cache.h"
#include "formats/mesh/mesh_points.h"

namespace assetlint::rules {

ColliderPoints::ColliderPoints(const Asset& asset, const Settings& settings)
    : settings_(settings), path_(asset.source(0).path()),
      directory_(std::filesystem::path(path_).parent_path().string()) {}

std::shared_ptr<const std::vector<Eigen::Vector3d>> ColliderPoints::of(const CollisionShape& shape) {
  if (shape.kind != CollisionShape::Kind::Mesh) return nullptr;
  if (!shape.points.empty()) return std::make_shared<const std::vector<Eigen::Vector3d>>(shape.points);
  if (unread_.count(shape.mesh)) return nullptr;
  const std::string base = directory_.empty() ? "." : directory_;
  const std::string root = config::checked_root(path_, settings_);
  std::string error;
  const auto file = mesh::resolve_mesh(shape.mesh, base, root.empty() ? base : root, error);
  if (!file) {
    unread_[shape.mesh] = error;
    return nullptr;
  }
  if (auto refused = config::read_policy(path_, settings_).refusal(*file)) {
    unread_[shape.mesh] = *refused;
    return nullptr;
  }
  auto points = mesh::cached_points(*file, error);
  if (!points) {
    unread_[shape.mesh] = error;
    return nullptr;
  }
  if (shape.mesh_scale == Eigen::Vector3d::Ones()) return points;
  auto scaled = std::make_shared<std::vector<Eigen::Vector3d>>(*points);
  for (auto& p : *scaled) p = p.cwiseProduct(shape.mesh_scale);
  return scaled;
}

}  // namespace assetlint::rules
