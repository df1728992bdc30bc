#include "physics/gripper.h"

#include <fmt/format.h>

#include "physics/drive.h"
#include "physics/sizing.h"
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
  f.torque = f.per_finger * g.lever_arm_m->value;
  f.per_joint = round_up_to_multiple(f.torque, g.torque_margin ? g.torque_margin->value : 0.0);
  f.joints = coupled_joints(asset, driven).size();
  f.required = f.per_joint * static_cast<double>(f.joints);
  f.derivation = fmt::format(
      "{} kg × {} m/s² / μ {} = {} N grip, {} N per finger × {} m lever arm = {} N·m per joint × {} joint{} "
      "driven through '{}' = {} N·m",
      format_number(g.payload_kg->value), format_number(g.gravity.value), format_number(g.friction->value),
      format_number(f.grip_force, 4), format_number(f.per_finger, 4), format_number(g.lever_arm_m->value),
      f.per_joint == f.torque
          ? format_number(f.per_joint, 3)
          : fmt::format("{} (rounded up to {})", format_number(f.torque, 3), format_number(f.per_joint, 3)),
      f.joints, f.joints == 1 ? "" : "s", driven.name.text, format_number(f.required, 3));
  return f;
}

std::optional<RequiredVelocity> required_velocity(const Settings& settings, const Joint& driven) {
  const GripperSpec& g = settings.gripper;
  if (!g.finger_speed_m_s || !g.stroke_m || !driven.lower || !driven.upper) return std::nullopt;
  const double range = driven.upper->value - driven.lower->value;
  if (range <= 0) return std::nullopt;
  RequiredVelocity v;
  v.close_time = close_time(g.stroke_m->value, g.finger_speed_m_s->value);
  v.velocity = range / v.close_time;
  const char* unit = is_angular(driven.type) ? "rad" : "m";
  v.derivation = fmt::format("{} m stroke / 2 per finger at {} m/s closes in {} s; {} {} range / {} s = {} {}/s",
                             format_number(g.stroke_m->value), format_number(g.finger_speed_m_s->value),
                             format_number(v.close_time, 3), format_number(range, 4), unit,
                             format_number(v.close_time, 3), format_number(v.velocity, 4), unit);
  return v;
}

}  // namespace assetlint::physics
