#pragma once
// Where each link is at the zero configuration, in the frame of the asset's roots: the
// common frame in which two files' axes, centres of mass and inertias can be compared
// whatever link frames each format uses (URDF: the joint frame; USD, MJCF: the body's).
#include <Eigen/Geometry>
#include <map>
#include <string>

#include "model/asset.h"

namespace assetlint {

// Pose of every link reachable from a root (a link that is no joint's child, or whose
// joint hangs from the world), roots at the identity.
std::map<std::string, Eigen::Isometry3d, std::less<>> link_poses(const Asset& asset);

}  // namespace assetlint
