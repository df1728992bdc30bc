#pragma once
// How fast a heavily damped servo on a fixed tendon brings the tendon to its target, when the
// tendon spans several joints (docs/physics.md "A servo on a tendon of several joints").
#include <optional>
#include <span>

namespace assetlint::physics {

// One joint of the tendon: its coefficient in the tendon's length (times the actuator's gear)
// and its own viscous damping (model units).
struct TendonJointDamper {
  double coef = 0;
  double damping = 0;
};

// The servo drives the length L = Σ cᵢ·qᵢ with force F = kp·(L* − L) − kv·L̇. Far above critical
// damping inertia is negligible and each joint moves at q̇ᵢ = cᵢ·F / dᵢ, so L̇ = F·Σ cᵢ²/dᵢ: the
// joints' dampers act on the tendon like one damper of 1 / Σ(cᵢ²/dᵢ), beside the actuator's kv.
// The length then approaches its target with the time constant (kv + 1 / Σ cᵢ²/dᵢ) / kp, however
// the force splits among the joints. A joint without damping is limited by its inertia instead:
// its term is then no damper at all. Nothing when kp ≤ 0.
std::optional<double> tendon_time_constant(double kp, double kv, std::span<const TendonJointDamper> joints);

}  // namespace assetlint::physics
