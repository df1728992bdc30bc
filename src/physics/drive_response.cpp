#include "physics/drive_response.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace assetlint::physics {

double drive_step_size(double range, bool angular) {
  const double quarter = std::isfinite(range) && range > 0 ? range / 4 : 0.0;
  if (!angular) return quarter;
  const double thirty = std::numbers::pi / 6;
  return quarter > 0 ? std::min(thirty, quarter) : thirty;
}

double second_order_overshoot(double damping_ratio) {
  if (damping_ratio >= 1) return 0;
  if (damping_ratio <= 0) return 1;
  return std::exp(-std::numbers::pi * damping_ratio / std::sqrt(1 - damping_ratio * damping_ratio));
}

double static_droop(double load, double stiffness) { return std::abs(load) / stiffness; }
double stiffness_for_droop(double load, double droop) { return std::abs(load) / droop; }

double drive_energy_budget(double force, double travel, double gravity_work) {
  return 2 * std::abs(force) * std::abs(travel) + gravity_work;
}

}  // namespace assetlint::physics

namespace assetlint::physics {
namespace {
// (1 + ωt)·e^(−ωt) = 0.02 at ωt = 5.834: the critically damped step's 2 % settling.
constexpr double kCriticalSettle = 5.834;
}  // namespace

double frequency_to_settle(double time) { return kCriticalSettle / time; }
double critically_damped_settle_time(double frequency) { return kCriticalSettle / frequency; }

}  // namespace assetlint::physics
