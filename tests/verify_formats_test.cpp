// `asset-lint verify` on USD and MJCF grippers: the gripper of fixtures/verify/two_finger
// written as USD (fixtures/verify/two_finger_usd: Cube colliders turned and scaled, a
// PhysxMimicJointAPI follower, the drive on the joint) and as MJCF
// (fixtures/verify/two_finger_mjcf: box geoms, a visual-only geom on each finger, an equality
// coupling, a position actuator) runs the same scenes with the same answers as the URDF one
// (tests/verify_support.h): 20 N holds the box at every width, 5 N slips. The USD one's crate
// twin (two_finger.usd) gives the same report.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>

#include "test_support.h"
#include "verify_support.h"

using assetlint::test::read_file;
using assetlint::test::replace_once;
using assetlint::test::run_cli;
using assetlint::test::write_file;

namespace {

const std::filesystem::path kVerify = assetlint::test::fixtures_dir() / "verify";

using Edit = std::function<std::string(std::string)>;
std::string same(std::string t) { return t; }

// A fixture gripper copied to a temporary directory, its asset edited by `edit`.
struct Gripper {
  assetlint::test::TempDir dir;
  std::string file;
  Gripper(const std::string& fixture, const std::string& asset, const Edit& edit = same) : file(asset) {
    write_file(dir.path() / asset, edit(read_file(kVerify / fixture / asset)));
    write_file(dir.path() / "asset-lint.toml", read_file(kVerify / fixture / "asset-lint.toml"));
  }
  assetlint::test::CommandResult run() const {
    return run_cli({"verify", file, "--output-format", "json"}, dir.path());
  }
};

void check_holds(const Gripper& gripper) {
  const auto r = gripper.run();
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  assetlint::test::check_two_finger_holds(nlohmann::json::parse(r.out));
}

void check_slips(const Gripper& gripper) {
  const auto r = gripper.run();
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 1);
  assetlint::test::check_two_finger_slips(nlohmann::json::parse(r.out));
}

std::string usd_weak(std::string t) {
  t = replace_once(t, "drive:linear:physics:stiffness = 4000", "drive:linear:physics:stiffness = 1000");
  t = replace_once(t, "drive:linear:physics:damping = 40", "drive:linear:physics:damping = 20");
  return replace_once(t, "drive:linear:physics:maxForce = 20", "drive:linear:physics:maxForce = 5");
}

std::string mjcf_weak(std::string t) {
  return replace_once(t, "kp=\"4000\" kv=\"40\" forcelimited=\"true\" forcerange=\"-20 20\"",
                      "kp=\"1000\" kv=\"20\" forcelimited=\"true\" forcerange=\"-5 5\"");
}

// Each finger's Cube replaced by a Mesh collider with the same 10 × 20 × 60 mm box as points.
std::string usd_mesh_pads(std::string t) {
  const std::string cube = R"(        def Cube "pad" (
            prepend apiSchemas = ["PhysicsCollisionAPI"]
        )
        {
            double size = 0.02
            double3 xformOp:translate = (0, 0, 0.01)
            quatf xformOp:orient = (0.70710677, 0, 0, 0.70710677)
            float3 xformOp:scale = (1, 0.5, 3)
            uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:orient", "xformOp:scale"]
        })";
  const std::string mesh = R"(        def Mesh "pad" (
            prepend apiSchemas = ["PhysicsCollisionAPI", "PhysicsMeshCollisionAPI"]
        )
        {
            uniform token physics:approximation = "convexHull"
            point3f[] points = [(-0.5, -1, -3), (0.5, -1, -3), (-0.5, 1, -3), (0.5, 1, -3),
                                (-0.5, -1, 3), (0.5, -1, 3), (-0.5, 1, 3), (0.5, 1, 3)]
            int[] faceVertexCounts = [4, 4, 4, 4, 4, 4]
            int[] faceVertexIndices = [0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5]
            double3 xformOp:translate = (0, 0, 0.01)
            float3 xformOp:scale = (0.01, 0.01, 0.01)
            uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:scale"]
        })";
  for (int i = 0; i < 2; ++i) t = replace_once(t, cube, mesh);
  return t;
}

// Each finger's pad a mesh geom of meshes/pad.obj, written in millimetres and scaled to metres.
std::string mjcf_mesh_pads(std::string t) {
  t = replace_once(t, "<compiler angle=\"degree\"/>",
                   "<compiler angle=\"degree\" meshdir=\"meshes\"/>\n  <asset>\n"
                   "    <mesh file=\"pad.obj\" scale=\"0.001 0.001 0.001\"/>\n  </asset>");
  t = replace_once(t, "<geom name=\"left_pad\" type=\"box\" size=\"0.005 0.01 0.03\"/>",
                   "<geom name=\"left_pad\" type=\"mesh\" mesh=\"pad\"/>");
  return replace_once(t, "<geom name=\"right_pad\" type=\"box\" size=\"0.01 0.005 0.03\" axisangle=\"0 0 1 90\"/>",
                      "<geom name=\"right_pad\" type=\"mesh\" mesh=\"pad\"/>");
}

const char* kPadObj = R"(# a 10 x 20 x 60 mm box about its centre
v -5 -10 -30
v 5 -10 -30
v -5 10 -30
v 5 10 -30
v -5 -10 30
v 5 -10 30
v -5 10 30
v 5 10 30
f 1 3 4 2
f 5 6 8 7
f 1 2 6 5
f 3 7 8 4
f 1 5 7 3
f 2 4 8 6
)";

}  // namespace

TEST_CASE("verify USD: twice the required squeeze holds at every width, half of it slips", "[verify][usd]") {
  check_holds(Gripper("two_finger_usd", "two_finger.usda"));
  check_slips(Gripper("two_finger_usd", "two_finger.usda", usd_weak));
}

TEST_CASE("verify MJCF: twice the required squeeze holds at every width, half of it slips", "[verify][mjcf]") {
  check_holds(Gripper("two_finger_mjcf", "two_finger.xml"));
  check_slips(Gripper("two_finger_mjcf", "two_finger.xml", mjcf_weak));
}

TEST_CASE("verify USD: a NewtonMimicAPI follower is coupled as the PhysX mimic is", "[verify][usd]") {
  // Newton's joint0 = coef0 + coef1·joint1 is the model's own convention: coef1 = 1 where PhysX's gearing is −1.
  check_holds(Gripper("two_finger_usd", "two_finger.usda", [](std::string t) {
    t = replace_once(t, "prepend apiSchemas = [\"PhysxMimicJointAPI:rotX\"]", "prepend apiSchemas = [\"NewtonMimicAPI\"]");
    t = replace_once(t, "rel physxMimicJoint:rotX:referenceJoint", "rel newton:mimicJoint");
    return replace_once(t, "float physxMimicJoint:rotX:gearing = -1", "float newton:mimicCoef1 = 1");
  }));
}

TEST_CASE("verify USD: Mesh colliders collide as the hull of their scaled points", "[verify][usd]") {
  check_holds(Gripper("two_finger_usd", "two_finger.usda", usd_mesh_pads));
}

TEST_CASE("verify MJCF: mesh geoms read their file from meshdir, scaled", "[verify][mjcf]") {
  Gripper gripper("two_finger_mjcf", "two_finger.xml", mjcf_mesh_pads);
  std::filesystem::create_directories(gripper.dir.path() / "meshes");
  write_file(gripper.dir.path() / "meshes" / "pad.obj", kPadObj);
  check_holds(gripper);
}

TEST_CASE("verify: a finger without collision geometry is an error naming its link", "[verify][usd][mjcf]") {
  SECTION("USD: the left pad without PhysicsCollisionAPI") {
    Gripper gripper("two_finger_usd", "two_finger.usda", [](std::string t) {
      return replace_once(t, "        def Cube \"pad\" (\n            prepend apiSchemas = [\"PhysicsCollisionAPI\"]\n        )",
                          "        def Cube \"pad\"");
    });
    const auto r = gripper.run();
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("no collision geometry on a finger") != std::string::npos);
    CHECK(r.err.find("'/two_finger/left_finger' (moved by joint '/two_finger/finger_joint') has no collision shapes") !=
          std::string::npos);
  }
  SECTION("MJCF: the right pad visual-only") {
    Gripper gripper("two_finger_mjcf", "two_finger.xml", [](std::string t) {
      return replace_once(t, "<geom name=\"right_pad\" type=\"box\"", "<geom name=\"right_pad\" class=\"visual\" type=\"box\"");
    });
    const auto r = gripper.run();
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("no collision geometry on a finger") != std::string::npos);
    CHECK(r.err.find("'right_finger'") != std::string::npos);
  }
}

TEST_CASE("verify USD: a crate layer gives the same JSON as its USDA twin", "[verify][usd]") {
  // two_finger.usd is two_finger.usda written as a binary crate layer by OpenUSD 22.11
  // (tests/usd_reference/export_layers.mjs --to-crate).
  const Gripper crate("two_finger_usd", "two_finger.usd"), text("two_finger_usd", "two_finger.usda");
  const auto a = crate.run(), b = text.run();
  INFO(a.out << a.err);
  REQUIRE(a.exit_code == 0);
  REQUIRE(b.exit_code == 0);
  auto crate_report = nlohmann::json::parse(a.out);
  const auto text_report = nlohmann::json::parse(b.out);
  CHECK(crate_report["file"] == "two_finger.usd");
  crate_report["file"] = text_report["file"];
  CHECK(crate_report == text_report);
  assetlint::test::check_two_finger_holds(crate_report);
}

TEST_CASE("verify USD: two runs give byte-identical JSON, the drive's origin is the stage", "[verify][usd]") {
  Gripper gripper("two_finger_usd", "two_finger.usda");
  const auto a = gripper.run(), b = gripper.run();
  CHECK(a.exit_code == 0);
  CHECK(a.out == b.out);
  const auto text = run_cli({"verify", "two_finger.usda"}, gripper.dir.path());
  CHECK(text.out.find("stiffness 4000 N/m (two_finger.usda:") != std::string::npos);
  CHECK(text.out.find("max velocity 0.1 m/s (two_finger.usda:") != std::string::npos);
}
