#include "rules/drive_support.h"

#include <fmt/format.h>

#include <cmath>

#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {

std::optional<DrivenJoint> spring_drive(const Asset& asset, const Joint& joint, const Settings& settings) {
  if (!is_single_dof(joint.type) || joint.is_mimic() || !joint.drive) return std::nullopt;
  const Drive& drive = *joint.drive;
  if (!drive.stiffness || drive.stiffness->value <= 0 || std::isinf(drive.stiffness->value)) return std::nullopt;
  DrivenJoint d;
  d.joint = &joint;
  d.drive = &drive;
  d.stiffness = drive.stiffness->value;
  d.damping = drive.damping ? drive.damping->value : 0.0;
  d.inertia = physics::effective_inertia(asset, joint);
  d.inertia_used = drive.type == DriveType::Acceleration ? 1.0 : d.inertia.value;
  d.rate = physics::effective_simulation(asset, settings);
  return d;
}

std::string DrivenJoint::inertia_text() const {
  if (drive->type == DriveType::Acceleration) return "I = 1 (acceleration drive)";
  return fmt::format("I = {}", inertia.describe());
}

const Quantity* max_force_of(const Joint& joint) {
  if (joint.drive && joint.drive->max_force) return &*joint.drive->max_force;
  if (joint.effort) return &*joint.effort;
  return nullptr;
}

Unit stiffness_unit(const Joint& joint) {
  return is_angular(joint.type) ? Unit::NewtonMeterPerRadian : Unit::NewtonPerMeter;
}
Unit damping_unit(const Joint& joint) {
  return is_angular(joint.type) ? Unit::NewtonMeterSecondPerRadian : Unit::NewtonSecondPerMeter;
}

std::string describe_gain(const OptQuantity& q, double model_value, Unit physx_unit) {
  return describe(model_value, q ? q->unit : physx_unit, 4);
}

std::optional<double> target_delta(const Joint& joint, const Settings& settings) {
  if (!is_angular(joint.type)) return std::nullopt;
  return radians_from_degrees(settings.gripper.target_delta_deg.value);
}

}  // namespace assetlint::rules
