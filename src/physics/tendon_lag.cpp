#include "physics/tendon_lag.h"

namespace assetlint::physics {

std::optional<double> tendon_time_constant(double kp, double kv, std::span<const TendonJointDamper> joints) {
  if (!(kp > 0)) return std::nullopt;
  double admittance = 0;  // Σ cᵢ²/dᵢ: the tendon's speed per unit force
  bool moves = false;
  bool undamped_joint = false;
  for (const TendonJointDamper& joint : joints) {
    if (joint.coef == 0) continue;
    moves = true;
    if (!(joint.damping > 0)) undamped_joint = true;
    else admittance += joint.coef * joint.coef / joint.damping;
  }
  if (!moves) return std::nullopt;
  const double joints_damper = undamped_joint ? 0.0 : 1.0 / admittance;
  const double damper = (kv > 0 ? kv : 0.0) + joints_damper;
  if (!(damper > 0)) return std::nullopt;  // nothing damps the tendon: no lag to speak of
  return damper / kp;
}

}  // namespace assetlint::physics
