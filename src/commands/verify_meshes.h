#pragma once
// The collision meshes `verify` reads: each file named by the shapes of some links, resolved as
// `check` resolves it (relative, package:// through the checked tree and ROS_PACKAGE_PATH),
// read once; shapes with inline points are taken as they are.
#include <string>
#include <vector>

#include "engine/settings.h"
#include "model/asset.h"
#include "verify/gripper_layout.h"

namespace assetlint::commands {

// False with `error` (naming the mesh) when a file cannot be found, is outside the tree, or cannot be read.
bool read_collision_meshes(const std::string& path, const Asset& asset, const Settings& settings,
                           const std::vector<std::string>& links, verify::MeshPoints& meshes, std::string& error);

}  // namespace assetlint::commands
