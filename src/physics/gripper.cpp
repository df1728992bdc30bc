#include "physics/gripper.h"

#include <fmt/format.h>

#include <cmath>

#include "physics/drive.h"
#include "util/numbers.h"

namespace assetlint::physics {

const Joint* spec_joint(const Asset& asset, const Settings& settings) {
  if (settings.gripper.driven_joint) return asset.find_joint(settings.gripper.driven_joint->value);
  const Joint* only = nullptr;
  for (const Joint& joint : asset.joints) {
    if (!is_single_dof(joint.type) || joint.is_mimic()) continue;
    if (only) return nullptr;  // several: the spec cannot say which
    only = &joint;
  }
  return only;
}

std::optional<RequiredForce> required_force(const Asset& asset, const Settings& settings, const Joint& driven) {
  const GripperSpec& g = settings.gripper;
  if (!g.payload_kg || !g.friction || !g.lever_arm_m) return std::nullopt;
  RequiredForce f;
  f.grip_force = g.payload_kg->value * g.gravity.value / g.friction->value;
  f.per_finger = f.grip_force / 2.0;
  f.per_joint = f.per_finger * g.lever_arm_m->value;
  // Each coupled joint needs the per-joint torque; through a mimic of gearing g the driver
  // supplies |g| times it (virtual work), so the driver needs Σ|g|·τ.
  const std::vector<const Joint*> set = coupled_joints(asset, driven);
  f.joints = set.size();
  for (const Joint* member : set)
    f.gearing_sum += member != set.front() && member->mimic ? std::abs(member->mimic->multiplier.value) : 1.0;
  f.required = f.per_joint * f.gearing_sum;
  f.derivation = fmt::format(
      "{} kg × {} m/s² / μ {} = {} N grip, {} N per finger × {} m lever arm = {} N·m per joint × {} "
      "driven through '{}' = {} N·m",
      format_number(g.payload_kg->value), format_number(g.gravity.value), format_number(g.friction->value),
      format_number(f.grip_force, 4), format_number(f.per_finger, 4), format_number(g.lever_arm_m->value),
      format_number(f.per_joint, 3),
      std::abs(f.gearing_sum - static_cast<double>(f.joints)) < 1e-9
          ? fmt::format("{} joint{}", f.joints, f.joints == 1 ? "" : "s")
          : fmt::format("Σ|gearing| {} over {} joints", format_number(f.gearing_sum, 4), f.joints),
      driven.name.text, format_number(f.required, 3));
  return f;
}

std::optional<RequiredVelocity> required_velocity(const Settings& settings, const Joint& driven) {
  const GripperSpec& g = settings.gripper;
  if (!g.finger_speed_m_s || !g.stroke_m || !driven.lower || !driven.upper) return std::nullopt;
  const double range = driven.upper->value - driven.lower->value;
  if (range <= 0) return std::nullopt;
  RequiredVelocity v;
  v.close_time = g.stroke_m->value / 2.0 / g.finger_speed_m_s->value;
  v.velocity = range / v.close_time;
  const char* unit = is_angular(driven.type) ? "rad" : "m";
  v.derivation = fmt::format("{} m stroke / 2 per finger at {} m/s closes in {} s; {} {} range / {} s = {} {}/s",
                             format_number(g.stroke_m->value), format_number(g.finger_speed_m_s->value),
                             format_number(v.close_time, 3), format_number(range, 4), unit,
                             format_number(v.close_time, 3), format_number(v.velocity, 4), unit);
  return v;
}

}  // namespace assetlint::physics
