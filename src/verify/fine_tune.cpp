#include "verify/fine_tune.h"

#include <cmath>

namespace assetlint::verify {

FineTuneResult fine_tune(const DriveSpec& today, const std::function<bool(const DriveSpec&)>& passes,
                         double tolerance) {
  FineTuneResult result;
  result.lowest = today;
  const auto trial = [&](const DriveSpec& drive) {
    const bool ok = passes(drive);
    result.trials.push_back({drive, ok});
    return ok;
  };
  result.baseline_passed = trial(today);
  if (!result.baseline_passed) {
    result.notes.push_back("today's drive fails a scene: nothing can be lowered; fix the failures first");
    return result;
  }
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
