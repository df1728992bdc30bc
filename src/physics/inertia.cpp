#include "physics/inertia.h"

#include <Eigen/Eigenvalues>

namespace assetlint::physics {

Eigen::Vector3d principal_moments(const Eigen::Matrix3d& inertia) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertia, Eigen::EigenvaluesOnly);
  return solver.eigenvalues();
}

double axis_distance(const Inertial& inertial, const Eigen::Isometry3d& joint_in_link, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d direction = (joint_in_link.linear() * axis).normalized();
  const Eigen::Vector3d offset = inertial.com - joint_in_link.translation();
  return (offset - offset.dot(direction) * direction).norm();
}

double inertia_about_axis(const Inertial& inertial, const Eigen::Isometry3d& joint_in_link, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d direction = (joint_in_link.linear() * axis).normalized();
  const double about_com = direction.dot(inertial.inertia * direction);
  const double distance = axis_distance(inertial, joint_in_link, axis);
  return about_com + inertial.mass.value * distance * distance;
}

}  // namespace assetlint::physics
