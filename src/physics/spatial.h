#pragma once
// Spatial (6-D) algebra for rigid bodies, [angular; linear] ordering: what the articulation
// and the joint-space mass matrix are built from.
#include <Eigen/Geometry>

namespace assetlint::physics {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

inline Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// Spatial inertia about the body origin.
inline Matrix6 spatial_inertia(double mass, const Eigen::Vector3d& com, const Eigen::Matrix3d& about_com) {
  const Eigen::Matrix3d c = skew(com);
  Matrix6 inertia;
  inertia.topLeftCorner<3, 3>() = about_com + mass * c * c.transpose();
  inertia.topRightCorner<3, 3>() = mass * c;
  inertia.bottomLeftCorner<3, 3>() = mass * c.transpose();
  inertia.bottomRightCorner<3, 3>() = mass * Eigen::Matrix3d::Identity();
  return inertia;
}

// Motion transform from parent to child coordinates, the child frame placed in the parent at `pose`.
inline Matrix6 motion_transform(const Eigen::Isometry3d& pose) {
  const Eigen::Matrix3d e = pose.linear().transpose();
  Matrix6 x = Matrix6::Zero();
  x.topLeftCorner<3, 3>() = e;
  x.bottomRightCorner<3, 3>() = e;
  x.bottomLeftCorner<3, 3>() = -e * skew(pose.translation());
  return x;
}

}  // namespace assetlint::physics
