#include "rules/drive_support.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "physics/inertia.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {

DriveModel::DriveModel(const Asset& asset, const Settings& settings)
    : asset_(asset), articulation_(physics::shared_articulation(asset)), rate_(physics::effective_simulation(asset, settings)) {}

std::optional<DrivenJoint> DriveModel::spring_drive(const Joint& joint) const {
  if (!is_single_dof(joint.type) || joint.is_mimic() || !joint.drive) return std::nullopt;
  const Drive& drive = *joint.drive;
  if (!drive.stiffness || drive.stiffness->value <= 0 || std::isinf(drive.stiffness->value)) return std::nullopt;
  DrivenJoint d;
  d.joint = &joint;
  d.drive = &drive;
  d.stiffness = drive.stiffness->value;
  d.damping = drive.damping ? drive.damping->value : 0.0;
  d.inertia = physics::effective_inertia(*articulation_, asset_, joint);
  d.articulated = articulation_->inertia(joint);
  d.inertia_used = drive.type == DriveType::Acceleration ? 1.0 : d.inertia.value;
  if (drive.type != DriveType::Acceleration && d.inertia.known && d.inertia.link)
    d.inertia_doubt = physics::inertia_doubt(asset_, *d.inertia.link, articulation_->sole_rotation_axis(*d.inertia.link));
  d.rate = rate_;
  return d;
}

physics::DriveRow DrivenJoint::row(double inertia) const {
  return physics::drive_row(rate, stiffness, damping, drive->type, inertia);
}

physics::DriveRow DrivenJoint::verdict_row() const {
  return row(articulated.known ? articulated.value : inertia.value);
}

const char* DrivenJoint::inertia_unit() const { return joint->type == JointType::Prismatic ? "kg" : "kg·m²"; }

std::string DrivenJoint::inertia_text() const {
  if (acceleration()) return "I = 1 (acceleration drive)";
  return fmt::format("I = {}", inertia.describe());
}

std::string DrivenJoint::inertias_text() const {
  std::string lighter;
  if (inertia.known) {
    lighter = fmt::format("lighter link {} {} ('{}' about '{}'{}{}), the guide's estimate", format_number(inertia.value, 3),
                          inertia_unit(), inertia.link->name.text, inertia.via->name.text,
                          std::abs(inertia.gearing) != 1.0 ? fmt::format(", gearing² {}", format_number(inertia.gearing * inertia.gearing, 3))
                                                 : std::string(),
                          inertia.armature > 0 ? fmt::format(", armature {} included", format_number(inertia.armature, 3))
                                               : std::string());
    if (!inertia.unknown_links.empty())
      lighter += fmt::format(" (lightest of the links with authored mass; not authored: {})", name_list(inertia.unknown_links));
  } else {
    lighter = "lighter link: unknown";
  }
  std::string articulation;
  if (articulated.known)
    articulation = fmt::format("articulation {} {}", format_number(articulated.value, 3), inertia_unit());
  else if (!articulated.unknown_links.empty())
    articulation = fmt::format("articulation: unknown (unauthored mass: {})", name_list(articulated.unknown_links));
  else
    articulation = fmt::format("articulation: unknown ({})", articulated.reason);
  return lighter + "; " + articulation;
}

std::string short_name(const Joint& joint) { return "'" + short_path(joint.name.text) + "'"; }

std::string name_list(const std::vector<std::string>& names, std::size_t limit) {
  std::string list;
  for (std::size_t i = 0; i < names.size() && i < limit; ++i) list += (i ? ", '" : "'") + names[i] + "'";
  if (names.size() > limit) list += fmt::format(" and {} more", names.size() - limit);
  return list;
}

const Quantity* max_force_of(const Joint& joint) {
  if (joint.drive && joint.drive->max_force) return &*joint.drive->max_force;
  if (joint.effort) return &*joint.effort;
  return nullptr;
}

physics::ForceLimit force_limit_of(const Joint& joint) {
  physics::ForceLimit limit;
  if (const Quantity* force = max_force_of(joint); force && force->value > 0 && std::isfinite(force->value))
    limit.max_force = force->value;
  return limit;
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

physics::Servo mujoco_servo(const DrivenJoint& driven, double inertia) {
  return physics::mujoco_servo(*driven.joint, driven.stiffness, driven.damping, inertia);
}

}  // namespace assetlint::rules
