#pragma once
// The gripper of a model, as the rules about grasping find it: its driven joint and the joints
// that mimic it, of which two sit on separate branches (two fingers that close on each other).
#include "model/asset.h"

namespace assetlint::rules {

// Whether `upper` moves `lower`: it is the joint of a link on the way from `lower` to the root.
bool moves(const Asset& asset, const Joint& upper, const Joint& lower);

// The gripper's driven joint: a single-DOF joint other joints mimic, with nothing below it moving
// on its own (physics::drives_gripper), whose coupled joints include two on separate branches
// (a telescoping chain of mimics holds nothing). nullptr when the model has none.
const Joint* gripper_drive(const Asset& asset);

}  // namespace assetlint::rules
