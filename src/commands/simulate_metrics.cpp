#include "commands/simulate_metrics.h"

#include <algorithm>
#include <cmath>

namespace assetlint::commands {
namespace {

// Within this share of a limit counts as at the limit (the stepper clamps exactly).
constexpr double kAtLimit = 1e-6;

std::optional<double> settled_within(const std::vector<Sample>& samples, double target, double band) {
  // The first time after which the position never leaves the band again.
  std::optional<double> since;
  for (const Sample& s : samples) {
    const bool inside = std::isfinite(s.position) && std::abs(target - s.position) <= band;
    if (inside && !since) since = s.time;
    if (!inside) since.reset();
  }
  return since;
}

}  // namespace

Metrics measure(const std::vector<Sample>& samples, double from, double target, double frame, const Limits& limits) {
  Metrics m;
  if (samples.empty()) return m;
  const double step = target - from;
  const double size = std::abs(step);
  const double direction = step >= 0 ? 1.0 : -1.0;
  if (size > 0) {
    m.time_to_90 = settled_within(samples, target, 0.10 * size);
    m.time_to_98 = settled_within(samples, target, 0.02 * size);
  }
  double previous_velocity = 0;
  for (const Sample& s : samples) {
    if (!std::isfinite(s.position) || !std::isfinite(s.velocity) || std::abs(s.position - target) > 10.0 * std::max(size, 1e-9)) {
      m.diverged = true;
      m.diverged_at = s.time;
      break;
    }
    if (size > 0) m.overshoot = std::max(m.overshoot, direction * (s.position - target) / size);
    m.peak_force = std::max(m.peak_force, std::abs(s.force));
    if (std::isfinite(limits.max_force) && std::abs(s.force) >= limits.max_force * (1 - kAtLimit))
      m.force_clamped_time += frame;
    if (std::isfinite(limits.max_velocity) && std::abs(s.velocity) >= limits.max_velocity * (1 - kAtLimit))
      m.velocity_clamped_time += frame;
    // A sign change of a velocity that is more than noise.
    const double noise = 1e-9 * std::max(1.0, size / frame);
    if (std::abs(s.velocity) > noise) {
      if (previous_velocity != 0 && (s.velocity > 0) != (previous_velocity > 0)) ++m.velocity_sign_changes;
      previous_velocity = s.velocity;
    }
  }
  const Sample& last = samples.back();
  m.steady_state_error = std::abs(target - last.position);
  m.final_force = last.force;
  if (m.diverged) {
    m.time_to_90.reset();
    m.time_to_98.reset();
  }
  m.stalled = !m.diverged && size > 0 && m.steady_state_error > 0.10 * size && std::isfinite(limits.max_force) &&
              std::abs(last.force) >= limits.max_force * (1 - kAtLimit);
  return m;
}

}  // namespace assetlint::commands
