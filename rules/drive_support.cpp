#include "rules/drive_support.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "physics/gripper.h"
#include "physics/inertia.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {

DriveModel::DriveModel(const Asset& asset, const Settings& settings)
    : asset_(asset), settings_(settings), articulation_(physics::shared_articulation(asset)), rate_(physics::effective_simulation(asset, settings)),
      gyration_scale_(physics::gyration_scale(asset)) {}

physics::Mechanism DriveModel::mechanism(const Joint& joint, physics::Armatures armatures) const {
  if (asset_.format != SourceFormat::Mjcf || physics::tied_joints(asset_, {&joint}).size() < 2) return {};
  if (!matrix_) matrix_ = std::make_unique<physics::JointSpaceMatrix>(*articulation_);
  return physics::drive_mechanism(*matrix_, asset_, joint, armatures);
}

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
  if (drive.type == DriveType::Acceleration) {
    d.judged.basis = InertiaBasis::Unit;
    d.judged.known = true;
    d.judged.value = 1.0;
  } else {
    d.judged = judged_inertia(joint);
  }
  d.inertia_used = d.judged.value;
  if (drive.type != DriveType::Acceleration && d.inertia.known && d.inertia.link)
    d.inertia_doubt = physics::inertia_doubt(asset_, *d.inertia.link, articulation_->sole_rotation_axis(*d.inertia.link),
                                            gyration_scale_);
  d.rate = rate_;
  return d;
}

bool guide_applies(const Asset& asset, const Settings& settings, const Joint& joint) {
  // Named as written in the file, or by its last path element for a USD prim.
  if (settings.gripper.driven_joint &&
      (settings.gripper.driven_joint->value == joint.name.text || settings.gripper.driven_joint->value == short_path(joint.name.text)))
    return true;
  return physics::drives_gripper(asset, joint);
}

JudgedInertia DriveModel::judged_inertia(const Joint& joint) const {
  JudgedInertia judged;
  judged.armature = joint.armature ? joint.armature->value : 0.0;
  const auto take = [&](const physics::ArticulatedInertia& inertia, InertiaBasis basis) {
    judged.basis = basis;
    judged.known = inertia.known;
    judged.value = inertia.value;
    judged.unknown_links = inertia.unknown_links;
    judged.reason = inertia.reason;
  };
  if (asset_.format == SourceFormat::Mjcf) {
    // The joints that mimics and loop closures tie to this one move with it: the drive moves
    // the whole mechanism, and its inertia along the drive is what the drive sees.
    // Not when the reader noted a load the model leaves out (a damped linkage, a rope): the
    // rules then judge M₀ᵢᵢ and say what it leaves out.
    const physics::Mechanism tied = joint.is_mimic() || joint.hidden_load ? physics::Mechanism{} : mechanism(joint);
    // A mechanism that cannot be solved for a reason other than a missing mass (a loop across
    // two trees): the joint's own M₀ᵢᵢ, as MuJoCo's dampratio takes it.
    judged.mechanism = tied.tied() && (tied.inertia.known || !tied.inertia.unknown_links.empty());
    take(judged.mechanism ? tied.inertia : articulation_->joint_space_inertia(joint), InertiaBasis::JointSpace);
    return judged;
  }
  const physics::ArticulatedInertia articulated = articulation_->inertia(joint);
  if (!guide_applies(asset_, settings_, joint) && articulated.known) {
    take(articulated, InertiaBasis::Articulation);
    return judged;
  }
  const physics::EffectiveInertia lighter = physics::effective_inertia(*articulation_, asset_, joint);
  judged.basis = InertiaBasis::LighterLink;
  judged.known = lighter.known;
  judged.value = lighter.value;
  judged.unknown_links = lighter.unknown_links;
  if (!guide_applies(asset_, settings_, joint)) {
    judged.fallback = articulated.unknown_links.empty()
                          ? fmt::format("articulation: unknown ({})", articulated.reason)
                          : fmt::format("articulation: unknown (unauthored mass: {})", name_list(articulated.unknown_links));
  }
  return judged;
}

std::string JudgedInertia::label() const {
  switch (basis) {
    case InertiaBasis::Unit: return "I = 1 (acceleration drive)";
    case InertiaBasis::JointSpace: return mechanism ? "M₀ along the mechanism the drive moves" : "M₀ᵢᵢ";
    case InertiaBasis::LighterLink: return "the guide's lighter-link I";
    case InertiaBasis::Articulation: return "the articulation's I";
  }
  return "";
}

std::string JudgedInertia::why_unknown() const {
  if (!unknown_links.empty()) return fmt::format("no mass authored on {}", name_list(unknown_links));
  return reason.empty() ? std::string("no link mass") : reason;
}

double DrivenJoint::solver_inertia() const {
  if (judged.basis == InertiaBasis::LighterLink && articulated.known) return articulated.value;
  return judged.value;
}

physics::DriveRow DrivenJoint::row(double inertia) const {
  return physics::drive_row(rate, stiffness, damping, drive->type, inertia);
}

physics::DriveRow DrivenJoint::verdict_row() const {
  return row(articulated.known ? articulated.value : inertia.value);
}

const char* DrivenJoint::inertia_unit() const { return joint->type == JointType::Prismatic ? "kg" : "kg·m²"; }

std::string DrivenJoint::inertia_text() const {
  if (acceleration()) return "the guide's I = 1 (acceleration drive)";
  if (judged.basis == InertiaBasis::LighterLink) return fmt::format("the guide's I = {}", inertia.describe());
  return fmt::format("I = {} {} ({})", format_number(judged.value, 3), inertia_unit(), judged.label());
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
  if (judged.basis == InertiaBasis::JointSpace) {
    // An MJCF model: what MuJoCo divides by, M₀ᵢᵢ; 1/r stays in the notes for comparison.
    const char* symbol = judged.mechanism ? "M₀ along the mechanism" : "M₀ᵢᵢ";
    const std::string m0 = judged.known ? fmt::format("{} {} {}", symbol, format_number(judged.value, 3), inertia_unit())
                                        : fmt::format("{}: unknown ({})", symbol, judged.why_unknown());
    lighter = m0 + (judged.mechanism ? " (MuJoCo's joint-space inertia at qpos0 over the joints that mimics and loop "
                                       "closures tie to it, as those constraints let them move, armature included); "
                                     : " (MuJoCo's joint-space inertia at qpos0, armature included); ") +
              lighter;
  }
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

bool turns_without_limits(const Joint& joint) {
  if (joint.type == JointType::Continuous) return true;
  return !(joint.lower && joint.upper && std::isfinite(joint.lower->value) && std::isfinite(joint.upper->value));
}

bool velocity_drive(const DrivenJoint& driven) {
  if (driven.acceleration() || !is_angular(driven.joint->type) || !turns_without_limits(*driven.joint)) return false;
  if (driven.stiffness <= 0 || driven.inertia_used <= 0) return false;
  return driven.damping >= kVelocityDriveRatio * physics::damping_for_ratio(1.0, driven.stiffness, driven.inertia_used);
}

}  // namespace assetlint::rules
