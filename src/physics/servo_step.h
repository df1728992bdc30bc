#pragma once
// One MuJoCo timestep of a position servo, I·q̈ = −k·q − c·q̇, as the integrator takes it
// (docs/physics.md "MuJoCo's integrators"). MuJoCo keeps the spring explicit under every
// integrator; which damping it solves implicitly is what decides whether a stiff, heavily
// damped servo past h·nf = 2 decays or diverges:
//   Euler:                 the joint's own damping implicit, the actuator's kv explicit;
//   implicit/implicitfast: both implicit (they linearise every velocity-dependent force);
//   RK4:                   both explicit, a fourth-order Taylor step.
#include <optional>
#include <string_view>

#include "model/asset.h"

namespace assetlint::physics {

enum class MujocoIntegrator { Euler, RK4, Implicit, ImplicitFast };
std::string_view integrator_name(MujocoIntegrator integrator);  // MJCF's keyword: "implicitfast"
std::optional<MujocoIntegrator> parse_integrator(std::string_view keyword);  // case-sensitive, as MuJoCo's

// The servo in model units (kg·m², N·m/rad, N·m·s/rad; or kg, N/m, N·s/m).
struct Servo {
  double inertia = 0;           // what the step divides by, armature included
  double stiffness = 0;         // k: the actuator's kp
  double joint_damping = 0;     // the joint's `damping`
  double actuator_damping = 0;  // the actuator's kv

  double damping() const { return joint_damping + actuator_damping; }  // c, both together
  double damping_ratio() const;                                        // ζ = c / (2·sqrt(k·I))
};

// A MuJoCo joint's servo on `inertia`: the MJCF reader folds the joint's own damping into
// the drive's `damping`, and MuJoCo's Euler integrator treats the two apart.
Servo mujoco_servo(const Joint& joint, double stiffness, double damping, double inertia);

// The linear map (q, q̇) → (q', q̇') of one step, and how fast it grows or decays.
struct StepMap {
  double qq = 1, qv = 0, vq = 0, vv = 1;  // q' = qq·q + qv·q̇; q̇' = vq·q + vv·q̇
  // The largest eigenvalue modulus: below 1 every state decays, above 1 one grows.
  double spectral_radius() const;
  bool stable() const { return spectral_radius() < 1.0; }
};

// The damping the integrator solves implicitly, and the rest.
double implicit_damping(MujocoIntegrator integrator, const Servo& servo);
double explicit_damping(MujocoIntegrator integrator, const Servo& servo);

StepMap servo_step(MujocoIntegrator integrator, double h, const Servo& servo);

// The continuous servo's slowest decay rate, rad/s: ζ ≥ 1 gives the slow real pole
// ω·(ζ − sqrt(ζ² − 1)) (≈ k/c when heavily damped), ζ < 1 the envelope ζ·ω.
double slowest_decay_rate(const Servo& servo);

// What one step of the integrator does to a disturbance of the servo: the one stability verdict
// the drive rules give an MJCF model. Decays: the step map's spectral radius is below 1 and the
// servo has damping. Grows: a mode with |λ| ≥ 1 (beyond rounding). Undamped: no damping at all,
// so the spring oscillates for ever however the step treats it (semi-implicit Euler keeps it on
// the unit circle, RK4 only shrinks it numerically).
enum class StepVerdict { Decays, Grows, Undamped };
StepVerdict step_verdict(MujocoIntegrator integrator, double h, const Servo& servo);

}  // namespace assetlint::physics
