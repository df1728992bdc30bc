#pragma once
// The guide's derivations from a gripper's spec sheet (PHYSICS.md §2–3).
#include <optional>
#include <string>
#include <vector>

#include "engine/settings.h"
#include "model/asset.h"

namespace assetlint::physics {

// The joint the [gripper] spec is about: `driven_joint` when configured, else the
// asset's only driven joint (non-mimic, single degree of freedom, not fixed).
const Joint* spec_joint(const Asset& asset, const Settings& settings);

// Whether `joint` drives a gripper: mimic joints follow it, and nothing below it or below its
// followers moves on its own. A movable joint there that is no mimic makes the coupling
// something else: the wheels under a rover's rocker differential (the other
// rocker and the averaging bar mimic one side), the knee under a hip whose armour plates mimic it.
bool drives_gripper(const Asset& asset, const Joint& joint);

// A per-joint torque rounded up to a multiple of `[gripper] torque_margin` (N·m), as the
// guide rounds 3.33 N·m up to 4; unchanged when the margin is unset. `tune --torque-margin`
// sets the same key, so both go through here.
double round_up_torque(double torque, const GripperSpec& spec);

// F = m·g/μ: the squeeze (sum of both fingers' normal forces) whose friction holds the payload.
double grip_force(double payload_kg, double gravity, double friction);

struct RequiredForce {
  double grip_force = 0;         // N, both fingers: m·g/μ
  double per_finger = 0;         // N
  double per_joint_torque = 0;   // N·m: per finger × lever arm (revolute joints of the set)
  double rounded_torque = 0;     // N·m: per_joint_torque rounded up to the torque margin
  std::size_t joints = 0;        // the drive moves itself plus its mimics
  double gearing_sum = 0;        // Σ|gearing| over the set (the driven joint counts 1)
  double required = 0;           // on the driven joint: N·m (revolute) or N (prismatic)
  Unit unit = Unit::NewtonMeter;
  std::vector<std::string> steps;  // the derivation, one sentence each
  std::string derivation;          // the steps joined
};
// Needs payload_kg and friction, and lever_arm_m when a revolute joint is in the coupled
// set. A prismatic finger needs the per-finger force itself (no lever arm). The driven
// joint needs Σ |gearing_j| · (per-joint force or torque of j) over itself and its mimics.
std::optional<RequiredForce> required_force(const Asset& asset, const Settings& settings, const Joint& driven);

struct RequiredVelocity {
  double close_time = 0;  // s: (stroke / 2) / finger speed
  double velocity = 0;    // rad/s (m/s): joint range / close time
  std::string derivation;
};
// Needs finger_speed_m_s, stroke_m and the joint's finite range.
std::optional<RequiredVelocity> required_velocity(const Settings& settings, const Joint& driven);

}  // namespace assetlint::physics
