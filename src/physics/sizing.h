#pragma once
// The guide's sizing steps that are not about the drive row itself (PHYSICS.md §2–3):
// a stiffness from a force budget, the rotor behind an armature, the close time.
namespace assetlint::physics {

// k = τ_max / Δ: the stiffness whose spring alone still delivers the max force
// `target_delta` (rad or m) before the target.
double stiffness_for_force(double max_force, double target_delta);

// I_rotor = armature / G²: the motor rotor inertia an armature implies behind a
// gearbox of ratio G (reflected inertia armature = G²·I_rotor).
double rotor_inertia_for_armature(double armature, double gear_ratio);

// Time for one finger to travel half the stroke at the spec's finger speed (s).
double close_time(double stroke, double finger_speed);

}  // namespace assetlint::physics
