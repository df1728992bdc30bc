#pragma once
// The kv MuJoCo derives from a servo's damping ratio (physics/dampratio.h): for a
// position-like actuator on a joint with gear g and biasprm[2] = ζ > 0,
//   kv = 2·ζ·√(kp·I/g²),
// I the joint's inertia at the reference pose (qpos0), armature included: M₀ = Mᵢᵢ up to
// MuJoCo 3.14, 1/(M⁻¹)ᵢᵢ from 3.15. On the joint this is a damping kv·g² = 2·ζ·√(kp·g²·I):
// ratio ζ on the joint's own stiffness and that inertia. The joint's own damping adds to it,
// as it does to an authored kv.
#include <vector>

#include "formats/mjcf/mjcf_actuators.h"
#include "formats/mjcf/mjcf_values.h"
#include "model/asset.h"
#include "physics/dampratio.h"

namespace assetlint::mjcf {

// Sets each requested drive's damping as `rule` derives it (unauthored, with its derivation
// in drive.damping_origin, and the other rule's kv in drive.damping_other_release when it
// differs by more than 10 %); where the inertia is unknown (a body that matters takes its
// mass from geoms), the damping stays unset, drive.damping_unknown says why, and an
// mjcf-unsupported note at the damping ratio says so. Run after the whole model is read.
void derive_dampratio_damping(const std::vector<DampRatio>& requests, physics::DampRatioRule rule, Values& values,
                              Asset& asset);

}  // namespace assetlint::mjcf
