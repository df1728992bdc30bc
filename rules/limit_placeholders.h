#pragma once
// Round limit values repeated across joints: what an author writes when the real number
// is unknown (effort="1000" on a gripper's driven joint and every mimic, velocity="100"
// on every joint of a hand). Their meaning is "not set", not a spec.
#include <cstddef>
#include <string_view>
#include <unordered_map>

#include "engine/rule.h"
#include "model/asset.h"

namespace assetlint::rules {

// Whether `value` is 10^n for some whole n ≥ min_exponent.
bool is_power_of_ten(double value, int min_exponent);

// How many movable single-DOF joints hold each value of `field` (effort or velocity),
// counted once per check so that asking for every joint stays linear in the joints.
class SharedValues {
 public:
  SharedValues(const Asset& asset, OptQuantity Joint::*field);
  // The movable single-DOF joints other than `joint` whose field holds the same value.
  std::size_t others(const Joint& joint) const;

 private:
  OptQuantity Joint::*field_;
  std::unordered_map<double, std::size_t> count_;
};

// Movable single-DOF joints in the asset.
std::size_t movable_joint_count(const Asset& asset);

// A URDF velocity limit that is a round 10^n (n ≥ 2) on every movable joint: joint-max-velocity
// reports it once per file as a placeholder; other rules defer to that finding.
bool velocity_placeholder_on_every_joint(const Asset& asset, const Joint& joint, const SharedValues& velocities,
                                         std::size_t movable_joints);

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
