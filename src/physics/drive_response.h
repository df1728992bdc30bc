#pragma once
// The arithmetic of a position drive's response that `verify`'s drive tests judge and explain
// (docs/verify.md "Drive tests"): the step a joint is given, the second-order servo's
// overshoot, the droop gravity leaves and the stiffness that bounds it, and the most kinetic
// energy a scene may hold before its integration is said to have created energy.

namespace assetlint::physics {

// The step from mid-range: 30° or a quarter of the range, whichever is smaller, for a revolute
// joint (30° without a finite range); a quarter of the range for a prismatic one (none: 0).
double drive_step_size(double range, bool angular);

// A linear second-order servo I·q̈ = k·(target − q) − d·q̇ stepped from rest: its overshoot,
// a fraction of the step, exp(−π·ζ/√(1 − ζ²)) for ζ < 1, and none from ζ = 1 on.
double second_order_overshoot(double damping_ratio);

// The static error a spring of stiffness k leaves under a load τ: τ / k (rad or m).
double static_droop(double load, double stiffness);
// The least stiffness that keeps the droop under a load τ within `droop`: τ / droop.
double stiffness_for_droop(double load, double droop);

// With every other drive held at a constant target, only the tested drive and gravity feed a
// scene: the drive's force is at most F (its max force, else the spring's pull across the
// travel, k·s), so its stored potential and its target's travel each add at most F·s, and
// gravity at most the work `gravity_work` its bodies can release over their reach. Kinetic
// energy beyond 2·F·s + gravity_work was made by the integration.
double drive_energy_budget(double force, double travel, double gravity_work);

}  // namespace assetlint::physics

namespace assetlint::physics {

// A critically damped servo (ζ = 1) settles to within 2 % of its step in about 5.83/ω: the
// natural frequency that settles in `time`, and back.
double frequency_to_settle(double time);
double critically_damped_settle_time(double frequency);

}  // namespace assetlint::physics
