#pragma once
// The guide's drive arithmetic (PHYSICS.md §2) over the model.
#include <string>
#include <vector>

#include "engine/settings.h"
#include "model/asset.h"

namespace assetlint::physics {

double natural_frequency(double stiffness, double inertia);              // sqrt(k / I), rad/s
double damping_ratio(double damping, double stiffness, double inertia);  // d / (2·sqrt(k·I))
double damping_for_ratio(double ratio, double stiffness, double inertia);  // 2·dr·sqrt(k·I)
double stiffness_for_frequency(double frequency, double inertia);        // I·nf²
// Fraction of the explicit spring force k·Δ that PhysX's implicit drive delivers:
// 1 / (1 + (dt·nf)²), damping ignored.
double implicit_fraction(double dt, double frequency);

// The joints that move together: a driven joint and every mimic that follows it
// (for a mimic joint: the joint it follows and that joint's mimics).
std::vector<const Joint*> coupled_joints(const Asset& asset, const Joint& joint);

// What the guide calls the inertia "i" of a drive: the lighter of the joint's two links
// about the joint axis at the joint (parallel-axis shifted), the lightest over the
// mimic-coupled set, plus the joint's armature.
struct EffectiveInertia {
  bool known = false;
  double value = 0.0;         // kg·m² (kg for prismatic): link + armature
  double link_inertia = 0.0;  // the lighter link about the axis, without armature
  double armature = 0.0;
  const Link* link = nullptr;   // which link
  const Joint* via = nullptr;   // about which joint's axis
  std::vector<std::string> unknown_links;  // links whose mass or inertia is not authored
  std::string describe() const;  // "3.37e-6 kg·m² (link 'left_inner_finger' about 'finger_joint' + armature 0)"
};
EffectiveInertia effective_inertia(const Asset& asset, const Joint& joint);

// Time step and solver iterations in effect, and where each came from: the stage's
// PhysicsScene / articulation when authored, else configuration, else PhysX defaults.
struct SimulationRate {
  double timesteps_per_second = 60.0;
  std::string rate_origin = "PhysX default";
  double position_iterations = 32.0;
  std::string iterations_origin = "PhysX default";
  std::string solver = "TGS";
  double dt() const { return 1.0 / timesteps_per_second; }
  double optimistic_bound() const { return timesteps_per_second * position_iterations; }
  std::string describe() const;  // "250 Hz (asset-lint.toml:3) × 64 iterations (robot.usda:40)"
};
SimulationRate effective_simulation(const Asset& asset, const Settings& settings);

}  // namespace assetlint::physics
