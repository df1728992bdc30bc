// The checked tree of a file (which layers USD composition may read), and what a run
// says when a layer it needs was not read.
#include <catch2/catch.hpp>

#include <filesystem>

#include "config/project_root.h"
#include "test_support.h"

using namespace assetlint;
using assetlint::test::run_cli;
using assetlint::test::TempDir;
using assetlint::test::write_file;
namespace fs = std::filesystem;

namespace {

const char* kPayload = R"(#usda 1.0
(
    defaultPrim = "robot"
    metersPerUnit = 1
)

def Xform "robot" (
    prepend apiSchemas = ["PhysicsArticulationRootAPI"]
)
{
    def Xform "base" (
        prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsMassAPI"]
    )
    {
        float physics:mass = 1
        float3 physics:diagonalInertia = (0.01, 0.01, 0.01)
    }
    def Xform "finger" (
        prepend apiSchemas = ["PhysicsRigidBodyAPI"]
    )
    {
    }
    def PhysicsRevoluteJoint "joint" (
        prepend apiSchemas = ["PhysicsDriveAPI:angular"]
    )
    {
        uniform token physics:axis = "X"
        rel physics:body0 = </robot/base>
        rel physics:body1 = </robot/finger>
        float physics:lowerLimit = 0
        float physics:upperLimit = 45
        float drive:angular:physics:stiffness = 1
        float drive:angular:physics:damping = 0.01
    }
}
)";

const char* kConfiguration = R"(#usda 1.0
(
    defaultPrim = "robot"
    metersPerUnit = 1
    subLayers = [
        @../payloads/physics.usda@
    ]
)
)";

// configuration/robot.usda sublayers ../payloads/physics.usda, as the vendor's Isaac assets do.
fs::path vendor_layout(const fs::path& dir) {
  fs::create_directories(dir / "payloads");
  fs::create_directories(dir / "configuration");
  write_file(dir / "payloads" / "physics.usda", kPayload);
  write_file(dir / "configuration" / "robot.usda", kConfiguration);
  return dir / "configuration" / "robot.usda";
}

}  // namespace

TEST_CASE("checked root: --root, then the git work tree, then asset-lint.toml, then the named tree", "[root]") {
  TempDir tmp;
  const fs::path dir = fs::canonical(tmp.path());
  const fs::path file = vendor_layout(dir / "project");
  Settings settings;
  settings.trees = {(dir / "project" / "configuration").string()};
  CHECK(config::checked_root(file.string(), settings) == (dir / "project" / "configuration").string());

  write_file(dir / "project" / "asset-lint.toml", "");
  CHECK(config::checked_root(file.string(), settings) == (dir / "project").string());

  fs::create_directories(dir / ".git");
  CHECK(config::checked_root(file.string(), settings) == dir.string());

  settings.root = (dir / "project" / "payloads").string();
  CHECK(config::checked_root(file.string(), settings) == (dir / "project" / "payloads").string());
}

TEST_CASE("checked root: a file outside every named tree composes within its own directory", "[root]") {
  TempDir tmp;
  const fs::path file = vendor_layout(fs::canonical(tmp.path()));
  Settings settings;
  settings.trees = {"/nonexistent-tree"};
  CHECK(config::checked_root(file.string(), settings).empty());
}

TEST_CASE("checked root: a layered asset checked from its own folder reads its payloads in a project", "[root][cli]") {
  TempDir tmp;
  vendor_layout(tmp.path());
  write_file(tmp.path() / "asset-lint.toml", "");
  const auto r = run_cli({"--select", "layer-unresolved", "robot.usda"}, tmp.path() / "configuration");
  CHECK(r.out == "No problems found in 1 file.\n");
  CHECK(r.exit_code == 0);
}

TEST_CASE("checked root: a skipped layer that held the joints is a warning naming the lost checks", "[root][cli]") {
  TempDir tmp;
  vendor_layout(tmp.path());
  const auto r = run_cli({"robot.usda"}, tmp.path() / "configuration");
  CHECK(r.exit_code == 1);
  CHECK(r.out ==
        "robot.usda:6:9: warning: layer '../payloads/physics.usda' is outside the checked tree; skipped "
        "[layer-unresolved]\n"
        "  note: the checked tree is '.' (the git work tree, else the directory of asset-lint.toml, else the directory named); --root DIR or "
        "--allow-outside-root reads layers beyond it\n"
        "  note: no joint of the stage was read: the joint, drive, mimic and inertia rules checked nothing there\n"
        "Found 1 problem (0 errors, 1 warning, 0 infos) in 1 file.\n");

  // --root names the project: the payload is read, and what it holds is checked.
  const auto rooted = run_cli({"--root", "..", "--select", "layer-unresolved", "robot.usda"}, tmp.path() / "configuration");
  CHECK(rooted.out == "No problems found in 1 file.\n");
}

TEST_CASE("checked root: a read layer stack whose bodies lack mass names the drive checks it cost", "[root][cli]") {
  TempDir tmp;
  vendor_layout(tmp.path());
  // The finger's mass lives in a layer that is missing.
  write_file(tmp.path() / "payloads" / "physics.usda",
             std::string(kPayload).replace(std::string(kPayload).find("    metersPerUnit = 1\n"), 0,
                                           "    subLayers = [@./masses.usda@]\n"));
  write_file(tmp.path() / "asset-lint.toml", "");
  const auto r = run_cli({"--select", "layer-unresolved", "configuration/robot.usda"}, tmp.path());
  CHECK(r.exit_code == 1);
  CHECK(r.out.find("payloads/physics.usda:4:18: warning: layer './masses.usda' cannot be read") != std::string::npos);
  CHECK(r.out.find("  note: drive-natural-frequency, drive-implicit-attenuation and drive-damping-ratio not checked "
                   "for '/robot/joint': no layer read gives a mass to '/robot/finger'\n") != std::string::npos);
}

TEST_CASE("checked root: the compliant vendor-layout stack checked from configuration/ reports the copied gains",
          "[root][cli]") {
  const fs::path configuration = test::fixtures_dir() / "usda" / "robotiq_compliant" / "configuration";
  const auto r = run_cli({"gripper_config_physics_compliant.usda"}, configuration);
  CHECK(r.exit_code == 1);
  CHECK(r.out.find("[layer-unresolved]") == std::string::npos);
  CHECK(r.out.find("../payloads/gripper_physics_compliant.usda:") != std::string::npos);
  CHECK(r.out.find("[mimic-copied-drive-gains]") != std::string::npos);
  CHECK(r.out.find("naturalFrequency 5000") != std::string::npos);
}
