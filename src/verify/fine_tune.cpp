#include "verify/fine_tune.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "util/numbers.h"

namespace assetlint::verify {
namespace {

std::string mm(double metres) { return format_number(metres * 1000, 3) + " mm"; }

// The drive value that moves the threshold a scene missed, in the order the misses matter: a
// divergence spoils every other number, a grip under the weight is why the box slips.
std::string what_to_change(const SceneResult& r, const DriveSpec& today) {
  const SceneMetrics& m = r.metrics;
  if (m.diverged && *m.diverged)
    return "lower the stiffness, or step finer ([simulation] timesteps_per_second): the drive is too stiff for the "
           "step";
  if (r.spec.kind == SceneKind::Close) {
    if (m.close_time_s && m.spec_close_time_s && *m.close_time_s < *m.spec_close_time_s)
      return fmt::format("lower the max velocity{}: the fingers close in {} s, faster than the spec's {} s",
                         today.max_velocity ? "" : " (the drive has none)", format_number(*m.close_time_s, 3),
                         format_number(*m.spec_close_time_s, 3));
    return "raise the max velocity, or the max force if the drive runs at it: the fingers close too slowly";
  }
  if (m.grip_force_n && m.required_grip_force_n && *m.grip_force_n < *m.required_grip_force_n)
    return fmt::format("raise the max force: the grip {} N is under the {} N that holds the payload (m·g/μ)",
                       format_number(*m.grip_force_n, 4), format_number(*m.required_grip_force_n, 4));
  if (m.slip_m && std::any_of(r.failures.begin(), r.failures.end(), [](const auto& f) { return f.starts_with("slip"); }))
    return fmt::format("raise the max force: the box slips {} between the pads", mm(*m.slip_m));
  if (m.jitter_m_s && std::any_of(r.failures.begin(), r.failures.end(), [](const auto& f) { return f.starts_with("jitter"); }))
    return fmt::format("raise the damping: the fingers and the box shake at {} mm/s", format_number(*m.jitter_m_s * 1000, 3));
  if (m.peak_penetration_m)
    return fmt::format("lower the max force, or step finer: the pads sink up to {} into the box", mm(*m.peak_penetration_m));
  return "see the failures above";
}

}  // namespace

FineTuneResult failing_baseline(const DriveSpec& today, const std::vector<SceneResult>& scenes) {
  FineTuneResult result;
  result.lowest = today;
  result.trials.push_back({today, false});
  const SceneResult* first = nullptr;
  for (const SceneResult& s : scenes) {
    if (!s.ran || s.passed) continue;
    if (!first) first = &s;
    if (s.metrics.diverged && *s.metrics.diverged) {
      first = &s;
      break;
    }
  }
  if (!first) return result;
  result.notes.push_back(fmt::format("today's drive already fails '{}' ({}): nothing is lowered", first->spec.name,
                                     first->failures.front()));
  result.notes.push_back("change first: " + what_to_change(*first, today));
  return result;
}

FineTuneResult fine_tune(const DriveSpec& today, const std::function<bool(const DriveSpec&)>& passes,
                         double tolerance) {
  FineTuneResult result;
  result.lowest = today;
  const auto trial = [&](const DriveSpec& drive) {
    const bool ok = passes(drive);
    result.trials.push_back({drive, ok});
    return ok;
  };
  result.baseline_passed = true;
  result.trials.push_back({today, true});
  // The lowest max force at today's stiffness.
  if (today.max_force && *today.max_force > 0) {
    double low = 0, high = *today.max_force;
    while (high - low > tolerance * *today.max_force) {
      DriveSpec drive = result.lowest;
      drive.max_force = 0.5 * (low + high);
      (trial(drive) ? high : low) = *drive.max_force;
    }
    result.lowest.max_force = high;
  } else {
    result.notes.push_back("the drive has no max force to lower");
  }
  // The lowest stiffness at that force, critically damped as today's is damped: d ∝ √k.
  double low = 0, high = today.stiffness;
  const auto with_stiffness = [&](double k) {
    DriveSpec drive = result.lowest;
    drive.stiffness = k;
    drive.damping = today.damping * std::sqrt(k / today.stiffness);
    return drive;
  };
  while (high - low > tolerance * today.stiffness) {
    const double mid = 0.5 * (low + high);
    (trial(with_stiffness(mid)) ? high : low) = mid;
  }
  result.lowest = with_stiffness(high);
  return result;
}

}  // namespace assetlint::verify
