#pragma once
// Where a gripper's fingers are and which way they close, from the model alone: the driven
// joint and its mimic set, the finger pads (the most distal collision geometry on each side)
// and the gap between them at any opening. Engine-neutral: scenes are built from it and
// every backend reports the same pads.
#include <Eigen/Geometry>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "model/asset.h"

namespace assetlint::verify {

// The extent of a set of shapes along a direction: [low, high] of their support.
struct Extent {
  double low = 0, high = 0;
};

// The points of a mesh shape, in the mesh file's frame (scale not applied); the shape's
// mesh name indexes them. Filled by the caller: from mesh files (formats/mesh/mesh_points.h)
// and from the shapes' inline points.
using MeshPoints = std::map<std::string, std::vector<Eigen::Vector3d>, std::less<>>;

// Support of one shape posed at `pose` (its link's pose) along unit direction `u`.
double support(const CollisionShape& shape, const Eigen::Isometry3d& link_pose, const Eigen::Vector3d& u,
               const MeshPoints& meshes);

struct GripperLayout {
  const Joint* driven = nullptr;
  std::vector<const Joint*> mimics;  // the joints following `driven`
  std::string root;                  // the base link (welded to the mount)
  double open = 0, closed = 0;       // driven joint positions: the larger gap, the smaller
  // In the base frame: side 0 moves along +closing when the gripper closes, side 1 along −closing;
  // approach points from the base toward the pads; lateral = approach × closing, so that
  // (closing, lateral, approach) is right-handed.
  Eigen::Vector3d closing = Eigen::Vector3d::UnitX();
  Eigen::Vector3d approach = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d lateral = Eigen::Vector3d::UnitY();
  std::array<std::string, 2> pads;  // the pad link of each side
  std::vector<std::string> moving_links;  // links the driven joint moves (its mimic set's subtrees)

  // Positions of every joint of the mimic set when the driven joint is at q (others 0).
  std::map<std::string, double, std::less<>> positions(double q) const;
  // Link poses in the base frame at driven position q.
  std::map<std::string, Eigen::Isometry3d, std::less<>> poses(const Asset& asset, double q) const;
  // The gap between the pads along `closing`, from link poses (base or world frame alike).
  double gap(const Asset& asset, const std::map<std::string, Eigen::Isometry3d, std::less<>>& poses,
             const MeshPoints& meshes) const;
  double gap_at(const Asset& asset, double q, const MeshPoints& meshes) const;
  // The driven position at which the gap is `width` (bisection; the gap is taken as monotonic
  // over the stroke); nullopt when the width is outside the stroke's gaps.
  std::optional<double> opening_for(const Asset& asset, double width, const MeshPoints& meshes) const;
  // The extent of a pad link's shapes along `u` at link poses `poses`.
  Extent pad_extent(const Asset& asset, int side, const std::map<std::string, Eigen::Isometry3d, std::less<>>& poses,
                    const Eigen::Vector3d& u, const MeshPoints& meshes) const;
};

// Builds the layout of `driven`; nullopt with `error` naming what is missing (a finite range,
// collision geometry on the moving links, two sides that close on each other).
std::optional<GripperLayout> gripper_layout(const Asset& asset, const Joint& driven,
                                            std::string& error);

// Every mesh file named by a collision shape of `links` (in first-use order); inline meshes
// (CollisionShape::points) are not files and not listed.
std::vector<std::string> collision_meshes(const Asset& asset, const std::vector<std::string>& links);

}  // namespace assetlint::verify
