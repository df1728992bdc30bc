#pragma once
// Which links move: the rigid bodies a simulator builds from links welded by fixed joints.
#include <string>
#include <vector>

#include "model/asset.h"

namespace assetlint {

struct RigidBody {
  const Joint* joint = nullptr;           // the movable joint whose child starts the body
  std::vector<const Link*> links;         // the child link and every link welded to it by fixed joints
};

// One body per movable (non-fixed) joint. Links reached from a root only through
// fixed joints do not move and are in no body.
std::vector<RigidBody> moving_bodies(const Asset& asset);

}  // namespace assetlint
