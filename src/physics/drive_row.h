#pragma once
// One joint drive as PhysX's articulation solver builds and solves it (docs/physics.md
// "The drive row"): the implicit factor x, the force it holds at a hard stop under each
// solver, and a one-degree-of-freedom frame stepper that `simulate` and the reference
// tests share. Units are the model's (N·m, rad, kg·m², s; N, m, kg for prismatic joints).
#include <limits>
#include <optional>

#include "model/asset.h"
#include "physics/step.h"

namespace assetlint::physics {

// The row of one driven DOF for one frame, before the joint's error is known.
struct DriveRow {
  Solver solver = Solver::TGS;
  double dt = 0;         // s, the frame
  double h = 0;          // s, the step the row is built with: TGS dt/N, PGS dt
  int substeps = 1;      // TGS: N sub-steps of h per frame; PGS: 1
  int iterations = 1;    // drive solves per frame: TGS N (one per sub-step), PGS position + velocity iterations
  double stiffness = 0;  // k, N·m/rad
  double damping = 0;    // d, N·m·s/rad
  DriveType type = DriveType::Force;
  double response = 0;   // r, rad/s per N·m·s: the DOF's unit response, 1 / articulated inertia

  double a() const { return h * (h * stiffness + damping); }
  // x = 1/(1 + a·r) for force drives, 1/(1 + a) for acceleration drives.
  double x() const;
  // PhysX's per-row coefficients (DyCpuGpuArticulation.h computeImplicitDriveParams*).
  double bias_coefficient() const;     // impulse per rad of remaining error: k·x·h (÷ r for acceleration drives)
  double velocity_multiplier() const;  // impulse per rad/s of joint velocity: −x·a (÷ r)
  double impulse_multiplier() const;   // carried share of the accumulated impulse: TGS 1, PGS 1 − x
};

// The row for a drive at this rate; `inertia` is the articulated inertia 1/r the row
// sees (kg·m², kg for prismatic joints).
DriveRow drive_row(const SimulationRate& rate, double stiffness, double damping, DriveType type, double inertia);

// What the drive's maxForce bounds (PhysX clamps the impulse accumulated over a frame):
// with the articulation's eDRIVE_LIMITS_ARE_FORCES flag (omni.physx sets it for USD)
// maxForce·dt, so the frame's average force ≤ maxForce; without it maxForce itself is
// the impulse bound.
struct ForceLimit {
  double max_force = std::numeric_limits<double>::infinity();  // N·m (N)
  bool limits_are_forces = true;
  double max_impulse(double dt) const { return limits_are_forces ? max_force * dt : max_force; }
  double max_average_force(double dt) const { return max_impulse(dt) / dt; }
};

// The average force a drive holds over a frame against a hard stop (a contact keeps the
// joint still) with the target `delta` beyond it. TGS: x·k·Δ; PGS restarts every frame
// and reaches (1 − (1 − x)^M)·k·Δ after its M solves (x at h = dt); acceleration
// drives scale by the articulated inertia. Capped by the force limit.
struct Hold {
  double spring = 0;     // k·Δ, the explicit spring force (k·Δ/r for acceleration drives)
  double uncapped = 0;   // what the row delivers before the force limit
  double force = 0;      // min(uncapped, max average force)
  bool capped = false;   // the force limit decides
  double fraction() const { return spring > 0 ? force / spring : 0.0; }
};
Hold static_hold(const DriveRow& row, double delta, const ForceLimit& limit = {});

struct JointState {
  double position = 0;  // rad (m)
  double velocity = 0;  // rad/s (m/s)
};
struct DriveTarget {
  double position = 0;
  double velocity = 0;
};
// What bounds the motion besides the drive.
struct FrameLimits {
  ForceLimit force;
  double max_velocity = std::numeric_limits<double>::infinity();  // |v| clamp after every solve
  // A hard stop: the joint cannot move past this position, on the side of it where it
  // starts (a rigid contact: any velocity into the stop is removed).
  std::optional<double> stop;
  // Which motion the stop bounds: +1 upward, −1 downward, 0 the side the joint starts on
  // each frame (a joint resting exactly on it then counts as below it).
  int stop_direction = 0;
};
struct FrameResult {
  JointState state;     // at the end of the frame
  double impulse = 0;   // drive impulse accumulated over the frame, N·m·s
  double average_force(double dt) const { return impulse / dt; }
};

// One frame of PhysX's drive on a single DOF of articulated inertia 1/r, other joints
// free. TGS: N sub-steps of h, one solve each, the accumulated impulse carried and
// clamped; PGS: the row built at h = dt, M solves with the accumulated impulse scaled by
// 1 − x each, then one position update. The row is built from the error at the frame's
// start, as PhysX builds it once per frame.
// `load`: a constant external torque (force) on the joint, integrated into the velocity
// once per frame before the solves, as PhysX integrates external forces (a payload, gravity).
FrameResult step_frame(const DriveRow& row, const FrameLimits& limits, JointState state, DriveTarget target,
                       double load = 0);

// The textbook explicit spring at the same h, for comparison: N (TGS) or 1 (PGS) steps of
// semi-implicit Euler, F = k·(target − q) + d·(v_target − v) with the force clamped to
// maxForce, v += h·F/I, q += h·v. It diverges once h·nf > 2 where the row stays stable.
FrameResult explicit_frame(const DriveRow& row, const FrameLimits& limits, JointState state, DriveTarget target,
                           double load = 0);

// Whether that explicit spring is stable at the row's h, clamps aside: semi-implicit Euler on
// I·q̈ = −k·q − d·q̇ is stable when h·d/I < 2 and h²·k/I + 2·h·d/I < 4 (undamped: h·nf < 2);
// I = 1 for acceleration drives. Outside it only the force and velocity clamps bound it.
bool explicit_stable(const DriveRow& row);

}  // namespace assetlint::physics
