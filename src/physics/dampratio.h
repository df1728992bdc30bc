#pragma once
// The damping MuJoCo's compiler derives from a position servo's damping ratio
// (<position dampratio=ζ>, or a <general> whose biasprm[2] > 0; mj_setConst in
// engine_setconst.c writes the result into biasprm[2]):
//   kv = 2·ζ·√(kp·m),
// m the inertia the actuator reflects at the reference pose qpos0. MuJoCo 3.15.0 changed m
// (its changelog lists it among the breaking changes):
//   3.3 to 3.14: m = Σⱼ dof_M0ⱼ / Jⱼ² over the dofs the actuator's moment J reaches: on a
//     joint with gear g, M₀/g², M₀ = Mᵢᵢ the joint-space diagonal (every other joint held);
//   3.15 and later: m = (J·M⁻¹·Jᵀ)⁻¹, the operational-space inertia, averaged over the
//     actuator's force outputs: on a joint (one output), 1/(g²·(M⁻¹)ᵢᵢ) (every other joint,
//     a floating base included, free).
// 1/(M⁻¹)ᵢᵢ ≤ Mᵢᵢ, so from 3.15 a servo on a coupled joint derives the smaller kv; the two
// agree on a joint whose motion couples to no other.
#include <string>

#include "engine/settings.h"

namespace assetlint::physics {

enum class DampRatioRule {
  JointSpaceDiagonal,  // MuJoCo 3.3 to 3.14
  OperationalSpace,    // MuJoCo 3.15 and later
};

DampRatioRule dampratio_rule(const MujocoVersion& version);

// "MuJoCo 3.15 and later" or "MuJoCo 3.3 to 3.14".
const char* dampratio_rule_versions(DampRatioRule rule);

// kv (in the actuator's units) for damping ratio ζ and stiffness kp on a joint with gear g
// whose inertia under the rule is `joint_inertia` (M₀ or 1/(M⁻¹)ᵢᵢ, kg·m² or kg): the
// reflected inertia is joint_inertia/g².
double dampratio_kv(double ratio, double kp, double joint_inertia, double gear);

}  // namespace assetlint::physics
