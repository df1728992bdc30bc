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

std::optional<Eigen::AlignedBox3d> ColliderPoints::box_in_link(const CollisionShape& shape) {
  std::vector<Eigen::Vector3d> corners;
  if (shape.kind == CollisionShape::Kind::Mesh) {
    const auto points = of(shape);
    if (!points || points->empty()) return std::nullopt;
    Eigen::AlignedBox3d own;
    for (const auto& p : *points) own.extend(p);
    for (int i = 0; i < 8; ++i) corners.push_back(own.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i)));
  } else {
    Eigen::Vector3d half = Eigen::Vector3d::Zero();
    const Eigen::Vector3d& s = shape.size;
    switch (shape.kind) {
      case CollisionShape::Kind::Box: half = s / 2; break;
      case CollisionShape::Kind::Sphere: half = Eigen::Vector3d::Constant(s.x()); break;
      case CollisionShape::Kind::Cylinder: half = {s.x(), s.x(), s.y() / 2}; break;
      case CollisionShape::Kind::Capsule: half = {s.x(), s.x(), s.y() / 2 + s.x()}; break;
      case CollisionShape::Kind::Mesh: break;
    }
    for (int i = 0; i < 8; ++i)
      corners.emplace_back(i & 1 ? half.x() : -half.x(), i & 2 ? half.y() : -half.y(), i & 4 ? half.z() : -half.z());
  }
  Eigen::AlignedBox3d box;
  for (const auto& c : corners) box.extend(shape.pose * c);
  if (!box.sizes().allFinite() || !(box.sizes().maxCoeff() > 0)) return std::nullopt;
  return box;
}

std::optional<Eigen::AlignedBox3d> ColliderPoints::box_in_link(const std::vector<CollisionShape>& shapes) {
  std::optional<Eigen::AlignedBox3d> all;
  for (const CollisionShape& shape : shapes)
    if (auto box = box_in_link(shape)) all = all ? all->extend(*box) : *box;
  return all;
}

}  // namespace assetlint::rules
