#pragma once
// What the drive rules share: which joints are driven, the two inertias a drive is judged
// on, the solver step and PhysX's drive row (docs/physics.md).
#include <memory>
#include <optional>
#include <string>

#include "engine/settings.h"
#include "model/asset.h"
#include "physics/articulation.h"
#include "physics/drive.h"
#include "physics/drive_row.h"
#include "physics/joint_space_matrix.h"
#include "physics/linkage.h"
#include "physics/servo_step.h"

namespace assetlint::rules {

// Which inertia a joint's drive is judged on: one decision that drive-natural-frequency,
// drive-damping-ratio and armature-excessive share, so a natural frequency and a damping ratio
// never rest on different inertias (docs/physics.md "Which inertia a drive is judged on").
//   Unit:         an acceleration drive, I = 1;
//   JointSpace:   an MJCF model: M₀ᵢᵢ, the inertia MuJoCo computes dampratio on;
//   LighterLink:  a mimic-coupled gripper drive (the guide's setting), or a drive whose
//                 articulation is unknown: the guide's lighter-link estimate;
//   Articulation: any other PhysX drive: 1/r, what its drive row sees (an arm's joint moves
//                 its whole distal subtree, far more than the neighbouring link).
enum class InertiaBasis { Unit, JointSpace, LighterLink, Articulation };

struct JudgedInertia {
  InertiaBasis basis = InertiaBasis::LighterLink;
  bool known = false;
  double value = 0;     // kg·m² (kg for prismatic), armature included
  double armature = 0;  // the joint's own, included in value
  // JointSpace on a joint that mimics or loop closures tie to others (MJCF): the inertia of
  // the mechanism they make along the drive (physics/linkage.h), not the joint's own M₀ᵢᵢ.
  bool mechanism = false;
  // Why the guide's lighter link stands in for the articulation ("articulation: unknown (…)").
  std::string fallback;
  std::vector<std::string> unknown_links;  // when not known: the massless links to blame
  std::string reason;                      // when not known and no link is to blame
  // "the guide's lighter-link I", "the articulation's I", "M₀ᵢᵢ", "I = 1 (acceleration drive)"
  std::string label() const;
  std::string why_unknown() const;  // "no mass authored on 'a', 'b'" / the reason
};

// True where the guide's lighter-link figure applies: a gripper's drive (physics::drives_gripper),
// or the configured [gripper] driven_joint.
bool guide_applies(const Asset& asset, const Settings& settings, const Joint& joint);

struct DrivenJoint {
  const Joint* joint = nullptr;
  const Drive* drive = nullptr;
  double stiffness = 0;  // model units
  double damping = 0;    // model units (unauthored: 0, USD's default)
  physics::EffectiveInertia inertia;         // the guide's lighter-link estimate (+ armature)
  physics::ArticulatedInertia articulated;   // 1/r, what PhysX's row sees (armature included)
  // Why the lighter link's tensor cannot be trusted (a placeholder, a radius of gyration that
  // does not fit): the verdict still stands, but no fix is computed from it. Empty when trusted.
  std::string inertia_doubt;
  JudgedInertia judged;     // the inertia every verdict on this drive rests on
  double inertia_used = 0;  // judged.value (1 for acceleration drives)
  bool damping_known() const { return drive->damping_unknown.empty(); }
  // What the solver itself divides the drive's force by, for "is it stable?": MuJoCo's M₀ᵢᵢ,
  // PhysX's articulated 1/r when known; else the judged inertia. It differs from `judged` only
  // for a mimic-coupled gripper, whose judged figure is the guide's lighter link.
  double solver_inertia() const;
  physics::SimulationRate rate;

  bool acceleration() const { return drive->type == DriveType::Acceleration; }
  // The drive row on an inertia (acceleration drives: the inertia only scales the force).
  physics::DriveRow row(double inertia) const;
  // The row on the articulated inertia when known, else on the lighter link.
  physics::DriveRow verdict_row() const;
  bool verdict_on_articulation() const { return articulated.known; }
  // "lighter link 3.37e-6 kg·m² ('left_inner_finger' about 'left_inner_finger_joint'), the guide's
  // estimate; articulation 8.57e-5 kg·m²" or "…; articulation: unknown (unauthored mass: base_link, …)"
  std::string inertias_text() const;
  // The judged I for messages: "the guide's I = 3.37e-6 kg·m² (…)", "I = 0.52 kg·m² (M₀ᵢᵢ)"
  std::string inertia_text() const;
  const char* inertia_unit() const;  // "kg·m²" or "kg"
};

// Everything the drive rules need from one asset, built once per rule run (O(n)).
class DriveModel {
 public:
  DriveModel(const Asset& asset, const Settings& settings);
  // A joint with an applied spring drive (stiffness > 0), not a mimic, single DOF.
  std::optional<DrivenJoint> spring_drive(const Joint& joint) const;
  // The shared decision (JudgedInertia) for any single-DOF joint, driven or not; a force drive
  // is assumed (acceleration drives are judged on I = 1 by spring_drive).
  JudgedInertia judged_inertia(const Joint& joint) const;
  const physics::Articulation& articulation() const { return *articulation_; }
  const physics::SimulationRate& rate() const { return rate_; }
  // MJCF: the mechanism a drive on `joint` moves (the joints mimics and loop closures tie to
  // it; physics/linkage.h) with the armatures `armatures` counts; not tied() when nothing ties the joint.
  physics::Mechanism mechanism(const Joint& joint, physics::Armatures armatures = {}) const;

 private:
  const Asset& asset_;
  const Settings& settings_;
  std::shared_ptr<const physics::Articulation> articulation_;
  physics::SimulationRate rate_;
  double gyration_scale_;  // physics::gyration_scale, for the lighter link's doubt
  // The whole joint-space matrix, formed the first time a tied mechanism needs it.
  mutable std::unique_ptr<physics::JointSpaceMatrix> matrix_;
};

// The drive as MuJoCo steps it, on `inertia`: the reader folds the joint's own damping into
// the drive's, and MuJoCo's Euler integrator treats the two apart.
physics::Servo mujoco_servo(const DrivenJoint& driven, double inertia);

// "'finger_joint'": the joint's name without its USD prim path, for short primary messages.
std::string short_name(const Joint& joint);

// "'base_link', 'left_outer_knuckle'" (at most `limit` names, then "and N more").
std::string name_list(const std::vector<std::string>& names, std::size_t limit = 4);

// The joint's force bound: the drive's maxForce, else the URDF effort limit.
const Quantity* max_force_of(const Joint& joint);
// The force limit PhysX applies: maxForce with the forces flag (omni.physx sets it for USD;
// Isaac's URDF importer writes USD), unlimited when none is known.
physics::ForceLimit force_limit_of(const Joint& joint);

// Unit of a drive gain as PhysX reads it, for values the file does not hold.
Unit stiffness_unit(const Joint& joint);
Unit damping_unit(const Joint& joint);

// A gain as the file writes it (config values in PhysX units).
std::string describe_gain(const OptQuantity& q, double model_value, Unit physx_unit);

// Continuous, or revolute with no finite bound on either side (USD writes ±inf): a wheel.
bool turns_without_limits(const Joint& joint);

// A drive on a joint that turns without limits with damping at least kVelocityDriveRatio times
// critical: driven by velocity (a wheel), its small stiffness only nudging it. Nobody asks
// it to reach or hold a position.
inline constexpr double kVelocityDriveRatio = 10.0;
bool velocity_drive(const DrivenJoint& driven);

// The target delta of the guide's stiffness method (radians); angular joints only,
// since [gripper] target_delta_deg is an angle.
std::optional<double> target_delta(const Joint& joint, const Settings& settings);

}  // namespace assetlint::rules
