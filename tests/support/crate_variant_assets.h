#pragma once
// Crate layers with physics in variant sets, written by the test crate writer: the crate
// fixtures under fixtures/usdc/variants are these bytes (the fixture test regenerates them
// with ASSET_LINT_UPDATE_EXPECTED=1).
#include <string>
#include <vector>

namespace assetlint::test {

struct CrateAsset {
  std::string path;  // relative to fixtures/
  std::string bytes;
};

// - usdc/variants/simready/gripper.usd: a SimReady-style gripper, PhysX/Newton/MuJoCo variant
//   sets selecting "Disabled"; PhysX's "Enabled" brings in a crate payload, MuJoCo's a text one,
//   Newton's carries its physics in the variant itself with a nested "NewtonSolver" set;
// - usdc/variants/simready/runnables/physics/physx.usd: PhysX's payload (the guide's original
//   5700 N·m/rad finger drive);
// - usdc/variants/isaac_arm.usd: an Isaac-style arm whose "Physics" variant set selects "PhysX",
//   the variant holding joints, drives and masses, with float, double, token and string values;
// - usdc/variants/edge_cases.usd: variant specs in less common places (properties on a variant,
//   a set on a prim inside a variant, explicit/appended/deleted list ops, payloads, a reference,
//   an empty selection).
std::vector<CrateAsset> crate_variant_assets();

}  // namespace assetlint::test
