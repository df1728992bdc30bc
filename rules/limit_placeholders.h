#pragma once
// Round limit values repeated across joints: what an author writes when the real number
// is unknown (effort="1000" on a gripper's driven joint and every mimic, velocity="100"
// on every joint of a hand). Their meaning is "not set", not a spec.
#include <vector>

#include "model/asset.h"

namespace assetlint::rules {

// Whether `value` is 10^n for some whole n ≥ min_exponent.
bool is_power_of_ten(double value, int min_exponent);

// The movable single-DOF joints other than `joint` whose `field` (effort or velocity)
// holds the same value as `joint`'s.
std::vector<const Joint*> joints_sharing(const Asset& asset, const Joint& joint, OptQuantity Joint::*field);

// Movable single-DOF joints in the asset.
std::size_t movable_joint_count(const Asset& asset);

}  // namespace assetlint::rules
