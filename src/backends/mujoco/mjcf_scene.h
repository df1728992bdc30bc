#pragma once
// A verification scene as MJCF for MuJoCo 2.2.2, written from asset-lint's model whatever the
// input format (docs/verify.md "The translation"). Bodies, joints and geoms get generated names
// (b0, j0, g0, m0) so that names from the asset never collide or need escaping.
#include <string>
#include <vector>

#include "verify/scene.h"

namespace assetlint::backends::mujoco {

// The contact and solver settings every scene uses.
inline constexpr const char* kIntegrator = "implicit";
inline constexpr const char* kCone = "elliptic";
inline constexpr double kImpratio = 10;
inline constexpr double kMountMass = 1.0;  // kg: the free body welded to the mocap mount
// kg/m³: a link without an authored mass takes it from its collision shapes at this density,
// as PhysX does for a body whose mass is not authored.
inline constexpr double kShapeDensity = 1000.0;

// Whether the model gives the link a mass (else the engine derives it from its shapes).
bool has_authored_mass(const Link& link);

// The generated names the runner looks up.
std::string body_name(const Asset& asset, const Link& link);   // "b<index>"
std::string joint_name(const Asset& asset, const Joint& joint);  // "j<index>"

// The MJCF text of `scene`; on failure (a moving link without mass) empty with `error` set.
std::string scene_mjcf(const verify::VerifyPlan& plan, const verify::SceneSpec& scene, std::string& error);

}  // namespace assetlint::backends::mujoco
