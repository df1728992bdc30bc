#include "physics/sizing.h"

#include <cmath>

namespace assetlint::physics {

double stiffness_for_force(double max_force, double target_delta) { return max_force / target_delta; }

double rotor_inertia_for_armature(double armature, double gear_ratio) { return armature / (gear_ratio * gear_ratio); }

double close_time(double stroke, double finger_speed) { return stroke / 2.0 / finger_speed; }

double round_up_to_multiple(double value, double step) {
  if (!(step > 0)) return value;
  // 3.0000000001 stays 3 when it is 3 up to rounding noise.
  const double multiples = value / step;
  const double nearest = std::round(multiples);
  if (std::abs(multiples - nearest) < 1e-9 * std::max(1.0, std::abs(nearest))) return nearest * step;
  return std::ceil(multiples) * step;
}

}  // namespace assetlint::physics
