#pragma once
// Mass properties of homogeneous solids, and of several rigidly joined parts: what a
// simulator derives for a body from its collision shapes when the file gives no inertia.
#include <Eigen/Geometry>
#include <vector>

namespace assetlint::physics {

// The shape's own frame has its centroid at the origin; the axis of a capsule or cylinder
// is z. Sizes are radii and half-lengths:
//   Sphere {r}, Capsule {r, half length of the cylindrical part}, Cylinder {r, half height},
//   Box {half extents x, y, z}, Ellipsoid {semi-axes x, y, z}.
enum class Solid { Sphere, Capsule, Cylinder, Box, Ellipsoid };

struct SolidShape {
  Solid kind = Solid::Sphere;
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
};

// m³.
double solid_volume(const SolidShape& shape);

// Principal moments (kg·m²) of the solid of `mass` kg about its centroid, along the shape's
// own x, y, z. A capsule is a cylinder plus two hemispheres whose centroids sit 3r/8 beyond
// the cylinder's ends.
Eigen::Vector3d solid_principal_moments(const SolidShape& shape, double mass);

// One rigid part: its mass, its centroid and its inertia tensor about that centroid, both in
// the frame the parts share.
struct MassPart {
  double mass = 0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

// The parts as one body: total mass, common centroid, and the tensor about it (each part's
// own tensor shifted by the parallel-axis theorem). Needs a positive total mass.
MassPart combine_parts(const std::vector<MassPart>& parts);

}  // namespace assetlint::physics
