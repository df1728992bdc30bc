#pragma once
// The drive tests' scene as MJCF for MuJoCo 2.2.2, written from asset-lint's model whatever the
// input format (docs/verify.md "Drive tests"): the whole robot, its base welded to the world,
// gravity along −z of the base, one affine position actuator per tested joint with a drive (one
// without is held at its start by a joint equality), mimics as joint equalities, no contacts. Generated names as in mjcf_scene.h: b<link>, j<joint>;
// actuator k drives plan.joints' k-th joint with a drive.
#include <string>
#include <vector>

#include "verify/drive_plan.h"

namespace assetlint::backends::mujoco {

// The MJCF text; empty with `error` set when a moving link has neither mass nor shapes.
// `actuated` receives, per actuator, its index into plan.joints.
std::string drive_scene_mjcf(const verify::DrivePlan& plan, std::vector<std::size_t>& actuated, std::string& error);

}  // namespace assetlint::backends::mujoco
