#include "physics/gripper.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "physics/drive.h"
#include "physics/sizing.h"
#include "util/numbers.h"

namespace assetlint::physics {

namespace {

// Whether a joint that moves on its own (single degree of freedom, no mimic) hangs below
// `from`'s child link.
bool moves_on_its_own_below(const Asset& asset, const Joint& from) {
  std::vector<const Link*> pending{asset.side_link(from, 1)};
  std::vector<const Link*> seen;
  while (!pending.empty()) {
    const Link* link = pending.back();
    pending.pop_back();
    if (!link || std::find(seen.begin(), seen.end(), link) != seen.end()) continue;
    seen.push_back(link);
    for (const Joint* next : asset.joints_at(link->name.text)) {
      if (next->parent.text != link->name.text) continue;
      if (is_single_dof(next->type) && !next->is_mimic()) return true;
      pending.push_back(asset.side_link(*next, 1));
    }
  }
  return false;
}

}  // namespace

bool drives_gripper(const Asset& asset, const Joint& joint) {
  const std::vector<const Joint*> followers = asset.mimic_followers(joint.name.text);
  if (std::none_of(followers.begin(), followers.end(), [&](const Joint* f) { return f != &joint; })) return false;
  if (moves_on_its_own_below(asset, joint)) return false;
  return std::none_of(followers.begin(), followers.end(),
                      [&](const Joint* f) { return moves_on_its_own_below(asset, *f); });
}

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

double grip_force(double payload_kg, double gravity, double friction) { return payload_kg * gravity / friction; }

double round_up_torque(double torque, const GripperSpec& spec) {
  if (!spec.torque_margin) return torque;
  const double margin = spec.torque_margin->value;
  // A torque already on the grid (within rounding noise) stays where it is.
  return std::ceil(torque / margin * (1 - 1e-12)) * margin;
}

std::optional<RequiredForce> required_force(const Asset& asset, const Settings& settings, const Joint& driven) {
  const GripperSpec& g = settings.gripper;
  if (!g.payload_kg || !g.friction) return std::nullopt;
  const auto coupled = coupled_joints(asset, driven);
  bool any_angular = false;
  for (const Joint* joint : coupled) any_angular = any_angular || is_angular(joint->type);
  if (any_angular && !g.lever_arm_m) return std::nullopt;

  RequiredForce f;
  f.grip_force = grip_force(g.payload_kg->value, g.gravity.value, g.friction->value);
  f.per_finger = f.grip_force / 2.0;
  f.joints = coupled.size();
  f.unit = is_angular(driven.type) ? Unit::NewtonMeter : Unit::Newton;
  f.steps.push_back(fmt::format("Grip: {} kg × {} m/s² / μ {} = {} N, {} N per finger.", format_number(g.payload_kg->value),
                                format_number(g.gravity.value), format_number(g.friction->value),
                                format_number(f.grip_force, 4), format_number(f.per_finger, 4)));
  if (any_angular) {
    f.per_joint_torque = f.per_finger * g.lever_arm_m->value;
    f.rounded_torque = round_up_torque(f.per_joint_torque, g);
    std::string step = fmt::format("Per revolute joint: {} N × {} m lever arm = {} N·m", format_number(f.per_finger, 4),
                                   format_number(g.lever_arm_m->value), format_number(f.per_joint_torque, 3));
    if (g.torque_margin)
      step += fmt::format(", rounded up to a multiple of torque_margin {} N·m ({}): {} N·m", format_number(g.torque_margin->value),
                          g.torque_margin->origin, format_number(f.rounded_torque, 4));
    f.steps.push_back(step + ".");
  }
  bool any_linear = false;
  for (const Joint* joint : coupled) {
    // The driven joint moves with gearing 1; a mimic's load reaches it through its gearing.
    const double gearing = joint == &driven || !joint->mimic ? 1.0 : std::fabs(joint->mimic->multiplier.value);
    const double own = is_angular(joint->type) ? f.rounded_torque : f.per_finger;
    any_linear = any_linear || !is_angular(joint->type);
    f.gearing_sum += gearing;
    f.required += gearing * own;
  }
  if (any_linear) f.steps.push_back(fmt::format("Per prismatic finger: the per-finger force itself, {} N.", format_number(f.per_finger, 4)));
  const std::size_t mimics = f.joints - 1;
  f.steps.push_back(fmt::format("'{}' drives {} joint{} (itself{}), Σ|gearing| = {}: it needs {} {}.", driven.name.text,
                                f.joints, f.joints == 1 ? "" : "s",
                                mimics == 0 ? "" : fmt::format(" and {} mimic{}", mimics, mimics == 1 ? "" : "s"),
                                format_number(f.gearing_sum, 4), format_number(f.required, 4), unit_symbol(f.unit)));
  for (const std::string& step : f.steps) f.derivation += (f.derivation.empty() ? "" : " ") + step;
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
