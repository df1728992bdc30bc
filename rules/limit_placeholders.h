#pragma once
// Round limit values repeated across joints: what an author writes when the real number
// is unknown (effort="1000" on a gripper's driven joint and every mimic, velocity="100"
// on every joint of a hand). Their meaning is "not set", not a spec.
#include <string_view>
#include <vector>

#include "engine/rule.h"
#include "model/asset.h"

namespace assetlint::rules {

// Whether `value` is 10^n for some whole n ≥ min_exponent.
bool is_power_of_ten(double value, int min_exponent);

// The movable single-DOF joints other than `joint` whose `field` (effort or velocity)
// holds the same value as `joint`'s.
std::vector<const Joint*> joints_sharing(const Asset& asset, const Joint& joint, OptQuantity Joint::*field);

// Movable single-DOF joints in the asset.
std::size_t movable_joint_count(const Asset& asset);

// A drive with stiffness or damping > 0 (applied in USD, or from [drives.<joint>]).
bool has_active_drive(const Joint& joint);

// What drive-max-force and joint-max-velocity know about the joint they judge.
struct LimitCheck {
  const Asset& asset;
  const Settings& settings;
  const Joint& joint;
  bool usd;
  bool driven;  // a drive or the spec moves it; a URDF joint nothing drives is not "driven"
  Reporter& out;
  std::string label() const;  // "driven revolute joint 'J0'" / "revolute joint 'J0'"
};

// A URDF limit ≤ 0 (`what`: "effort" or "velocity"): 0 and Gazebo's −1 are conventions
// whose meaning depends on the consumer (`consumers` says how each reads it); any other
// negative number is a slip. A warning when judged against a spec or a slip, else an info.
Diagnostic& report_sentinel(const LimitCheck& c, const Quantity& q, std::string_view what, bool judged,
                            std::string_view consumers, std::string_view bound_kind);

}  // namespace assetlint::rules
