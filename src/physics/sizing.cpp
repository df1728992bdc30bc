#include "physics/sizing.h"

namespace assetlint::physics {

double stiffness_for_force(double max_force, double target_delta) { return max_force / target_delta; }

double rotor_inertia_for_armature(double armature, double gear_ratio) { return armature / (gear_ratio * gear_ratio); }

double close_time(double stroke, double finger_speed) { return stroke / 2.0 / finger_speed; }

}  // namespace assetlint::physics
