#pragma once
// The vertices of a link's mesh colliders, with the shape's scale, for the geometry rules: each
// file resolved as the format names it (URDF package:// and relative paths, MJCF meshdir) and
// read once per run (mesh::cached_points); inline vertices (USD points, MJCF vertex) as the
// reader gave them. Files that cannot be found or read are gathered, each with the reason, so a
// rule can say once what it left out.
#include <Eigen/Geometry>
#include <optional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/settings.h"
#include "model/asset.h"

namespace assetlint::rules {

class ColliderPoints {
 public:
  ColliderPoints(const Asset& asset, const Settings& settings);

  // The shape's vertices in its frame, metres; nullptr for a primitive, or a mesh not read
  // (the reason in unread()).
  std::shared_ptr<const std::vector<Eigen::Vector3d>> of(const CollisionShape& shape);

  // The box around the shape in its link's frame (a mesh: around its vertices, scale applied);
  // nullopt for a mesh not read or a shape without extent.
  std::optional<Eigen::AlignedBox3d> box_in_link(const CollisionShape& shape);
  // The box around all of a link's shapes that could be placed; nullopt when none could.
  std::optional<Eigen::AlignedBox3d> box_in_link(const std::vector<CollisionShape>& shapes);

  // Mesh file as written -> why it could not be read.
  const std::map<std::string, std::string>& unread() const { return unread_; }

 private:
  const Settings& settings_;
  std::string path_, directory_;
  std::map<std::string, std::string> unread_;
};

}  // namespace assetlint::rules
