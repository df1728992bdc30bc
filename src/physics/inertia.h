#pragma once
// Inertia helpers (PHYSICS.md §2): principal moments, and a link's inertia about a
// joint axis shifted with the parallel-axis theorem.
#include <Eigen/Geometry>

#include "model/asset.h"

namespace assetlint::physics {

// Eigenvalues of a symmetric inertia tensor, ascending.
Eigen::Vector3d principal_moments(const Eigen::Matrix3d& inertia);

// Moment of inertia of a link about a joint's axis line (kg·m²): the COM inertia
// projected on the axis plus m·d², d being the COM's distance from the axis line.
// `joint_in_link` places the joint frame in the link frame; `axis` is in the joint frame.
double inertia_about_axis(const Inertial& inertial, const Eigen::Isometry3d& joint_in_link, const Eigen::Vector3d& axis);

// Distance (m) from the link's COM to the joint axis line.
double axis_distance(const Inertial& inertial, const Eigen::Isometry3d& joint_in_link, const Eigen::Vector3d& axis);

}  // namespace assetlint::physics
