#pragma once
// What `asset-lint simulate` reports about a trajectory (docs/simulate.md "Reports"):
// settling times, overshoot, error, forces, clamps, oscillation and divergence.
#include <optional>
#include <vector>

namespace assetlint::commands {

// The joint at the end of one frame.
struct Sample {
  double time = 0;      // s
  double position = 0;  // rad (m)
  double velocity = 0;  // rad/s (m/s)
  double force = 0;     // N·m (N): the drive's average force over the frame
};

struct Limits {
  double max_force = 0;     // ∞ when unbounded
  double max_velocity = 0;  // ∞ when unbounded
};

struct Metrics {
  std::optional<double> time_to_90;   // s: first time within 10 % of the step of the target, for good
  std::optional<double> time_to_98;
  double overshoot = 0;               // beyond the target, as a fraction of the step
  double steady_state_error = 0;      // |target − final position|
  double peak_force = 0;              // max |force|
  double final_force = 0;
  double force_clamped_time = 0;      // s with |force| at max force
  double velocity_clamped_time = 0;   // s with |velocity| at max velocity
  int velocity_sign_changes = 0;      // oscillation
  bool diverged = false;              // left ±10 steps around the target or non-finite
  std::optional<double> diverged_at;  // s
  bool stalled = false;               // ends short of 90 % with the force at its limit
};

// `from` → `target` over `samples` taken every `frame` seconds.
Metrics measure(const std::vector<Sample>& samples, double from, double target, double frame, const Limits& limits);

}  // namespace assetlint::commands
