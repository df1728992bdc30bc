#include "physics/dampratio.h"

#include <cmath>
#include <tuple>

namespace assetlint::physics {

DampRatioRule dampratio_rule(const MujocoVersion& version) {
  return std::tie(version.major, version.minor) >= std::make_tuple(3, 15) ? DampRatioRule::OperationalSpace
                                                                           : DampRatioRule::JointSpaceDiagonal;
}

const char* dampratio_rule_versions(DampRatioRule rule) {
  return rule == DampRatioRule::OperationalSpace ? "MuJoCo 3.15 and later" : "MuJoCo 3.3 to 3.14";
}

double dampratio_kv(double ratio, double kp, double joint_inertia, double gear) {
  return 2 * ratio * std::sqrt(kp * joint_inertia / (gear * gear));
}

}  // namespace assetlint::physics
