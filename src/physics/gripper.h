#pragma once
// The guide's derivations from a gripper's spec sheet (PHYSICS.md §2–3).
#include <optional>
#include <string>

#include "engine/settings.h"
#include "model/asset.h"

namespace assetlint::physics {

// The joint the [gripper] spec is about: `driven_joint` when configured, else the
// asset's only driven joint (non-mimic, single degree of freedom, not fixed).
const Joint* spec_joint(const Asset& asset, const Settings& settings);

struct RequiredForce {
  double grip_force = 0;       // N, both fingers: m·g/μ
  double per_finger = 0;       // N
  double torque = 0;           // N·m: per finger × lever arm
  double per_joint = 0;        // N·m: torque rounded up to [gripper] torque_margin (when set)
  std::size_t joints = 0;      // the drive moves itself plus its mimics
  double required = 0;         // N·m on the driven joint
  std::string derivation;      // "5 kg × 10 m/s² / μ 0.3 = 166.7 N; …"
};
// Needs payload_kg, friction and lever_arm_m.
std::optional<RequiredForce> required_force(const Asset& asset, const Settings& settings, const Joint& driven);

struct RequiredVelocity {
  double close_time = 0;  // s: (stroke / 2) / finger speed
  double velocity = 0;    // rad/s (m/s): joint range / close time
  std::string derivation;
};
// Needs finger_speed_m_s, stroke_m and the joint's finite range.
std::optional<RequiredVelocity> required_velocity(const Settings& settings, const Joint& driven);

}  // namespace assetlint::physics
