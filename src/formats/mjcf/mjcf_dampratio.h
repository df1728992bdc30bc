#pragma once
// The kv MuJoCo derives from a servo's damping ratio (mj_setConst in engine_setconst.c):
// for a position-like actuator with biasprm[2] = ζ > 0,
//   kv = 2·ζ·√(kp·M),  M = Σ over the dofs it moves of dof_M0 / g²,
// dof_M0 being the joint-space inertia diagonal at the reference pose (qpos0), armature
// included, and g the transmission (the gear of a joint actuator). On the joint this is a
// damping kv·g² = 2·ζ·√(kp·g²·M₀): ratio ζ on the joint's own stiffness and inertia. The
// joint's own damping adds to it, as it does to an authored kv.
#include <vector>

#include "formats/mjcf/mjcf_actuators.h"
#include "formats/mjcf/mjcf_values.h"
#include "model/asset.h"

namespace assetlint::mjcf {

// Sets each requested drive's damping, derived (unauthored, with its derivation in
// drive.damping_origin); where the inertia is unknown (a body the joint moves takes its mass
// from geoms), the damping stays unset, drive.damping_unknown says why, and an
// mjcf-unsupported note at the damping ratio says so. Run after the whole model is read.
void derive_dampratio_damping(const std::vector<DampRatio>& requests, Values& values, Asset& asset);

}  // namespace assetlint::mjcf
