#pragma once
// What the drive rules share: which joints are driven, their inertia and the
// simulation rate they are judged against.
#include <optional>
#include <string>

#include "engine/settings.h"
#include "model/asset.h"
#include "physics/drive.h"

namespace assetlint::rules {

struct DrivenJoint {
  const Joint* joint = nullptr;
  const Drive* drive = nullptr;
  double stiffness = 0;  // model units
  double damping = 0;    // model units (unauthored: 0, USD's default)
  physics::EffectiveInertia inertia;
  double inertia_used = 0;  // I of the formulas: 1 for acceleration drives
  physics::SimulationRate rate;
  std::string inertia_text() const;  // how I was obtained, for messages
};

// A joint with an applied spring drive (stiffness > 0), not a mimic, single DOF.
std::optional<DrivenJoint> spring_drive(const Asset& asset, const Joint& joint, const Settings& settings);

// The joint's force bound: the drive's maxForce, else the URDF effort limit.
const Quantity* max_force_of(const Joint& joint);

// Unit of a drive gain as PhysX reads it, for values the file does not hold.
Unit stiffness_unit(const Joint& joint);
Unit damping_unit(const Joint& joint);

// A gain as the file writes it (config values in PhysX units).
std::string describe_gain(const OptQuantity& q, double model_value, Unit physx_unit);

// The target delta of the guide's stiffness method (radians); angular joints only,
// since [gripper] target_delta_deg is an angle.
std::optional<double> target_delta(const Joint& joint, const Settings& settings);

}  // namespace assetlint::rules
