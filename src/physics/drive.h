#pragma once
// The guide's drive arithmetic (PHYSICS.md §2) over the model.
#include <string>
#include <vector>

#include "engine/settings.h"
#include "model/asset.h"
#include "physics/articulation.h"
#include "physics/step.h"

namespace assetlint::physics {

double natural_frequency(double stiffness, double inertia);              // sqrt(k / I), rad/s
double damping_ratio(double damping, double stiffness, double inertia);  // d / (2·sqrt(k·I))
double damping_for_ratio(double ratio, double stiffness, double inertia);  // 2·dr·sqrt(k·I)
double stiffness_for_frequency(double frequency, double inertia);        // I·nf²
double inertia_for_frequency(double stiffness, double frequency);        // k / nf²: the least I that keeps nf
double inertial_time_constant(double inertia, double damping);          // I / d, s: how soon a damped joint's speed settles

// The joints that move together: a driven joint and every mimic that follows it
// (for a mimic joint: the joint it follows and that joint's mimics).
std::vector<const Joint*> coupled_joints(const Asset& asset, const Joint& joint);

// What the guide calls the inertia "i" of a drive: the lighter of the joint's two bodies
// about the joint axis (parallel-axis shifted; links welded by fixed joints count as one
// body, a body welded to the world never counts), the lightest over the mimic-coupled set
// reflected to this joint with gearing², plus the joint's armature. A crude, conservative
// estimate: the drive row sees the articulated inertia instead (articulation.h).
struct EffectiveInertia {
  bool known = false;
  double value = 0.0;         // kg·m² (kg for prismatic): link + armature
  double link_inertia = 0.0;  // the lighter body about the axis, reflected, without armature
  double armature = 0.0;
  double gearing = 1.0;         // how far `via` moves per unit of this joint
  const Link* link = nullptr;   // which link (of the lighter body)
  const Joint* via = nullptr;   // about which joint's axis
  std::vector<std::string> unknown_links;  // coupled links whose mass, inertia or COM is not authored
  std::string describe() const;  // "3.37e-6 kg·m² (link 'left_inner_finger' about 'left_inner_finger_joint')"
};
EffectiveInertia effective_inertia(const Articulation& articulation, const Asset& asset, const Joint& joint);

// The inertia of a mimic-coupled mechanism along its one free direction (docs/physics.md
// "Mimic-coupled joints"): Jᵀ·M·J with J the gearings to `joint` (1 for itself, a mimic's
// multiplier), the mimic constraints taken as rigid and every other joint held still.
// For a joint without mimics this is its inertia with the rest of the tree held, not 1/r.
ArticulatedInertia mechanism_inertia(const Articulation& articulation, const Asset& asset, const Joint& joint);
EffectiveInertia effective_inertia(const Asset& asset, const Joint& joint);


}  // namespace assetlint::physics
