// `asset-lint tune`: the guide's derivation (PHYSICS.md §3) number by number, on the
// URDF and the USDA Robotiq fixtures, through the library and the command line.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "commands/tune_derivation.h"
#include "pipeline/lint.h"
#include "test_support.h"

using namespace assetlint;
using assetlint::test::run_cli;

namespace {

const std::string kUrdf = "fixtures/robotiq_2f85/robotiq_2f85.urdf";
const std::string kUsda = "fixtures/usda/robotiq_2f85/robotiq_2f85.usda";

// The guide's inputs, as flags.
const std::vector<std::string> kGuideFlags = {
    "--payload-kg", "5",   "--friction", "0.3",   "--gravity", "10",    "--lever-arm-m",      "0.04",
    "--torque-margin", "1", "--finger-speed-m-s", "0.15", "--stroke-m", "0.085", "--target-delta-deg", "5",
    "--rate", "250", "--position-iterations", "64"};

commands::SpecFlags guide_flags() {
  commands::SpecFlags f;
  f.payload_kg = 5;
  f.friction = 0.3;
  f.gravity = 10;
  f.lever_arm_m = 0.04;
  f.torque_margin = 1;
  f.finger_speed_m_s = 0.15;
  f.stroke_m = 0.085;
  f.target_delta_deg = 5;
  f.rate = 250;
  f.position_iterations = 64;
  return f;
}

const commands::TuneStep& step(const commands::TuneDerivation& d, std::string_view name) {
  for (const auto& s : d.steps)
    if (s.name == name) return s;
  FAIL("no step " << name);
  throw;
}
double result(const commands::TuneDerivation& d, std::string_view name) {
  const auto& s = step(d, name);
  REQUIRE(s.result);
  return s.result->value;
}

// The URDF fixture with the guide's original stiffness 5700 N·m/rad from configuration.
struct GuideUrdf {
  Settings settings;
  LoadedAsset loaded;
  commands::TuneDerivation derivation;
  explicit GuideUrdf(std::optional<double> armature = std::nullopt) {
    settings.drives["finger_joint"].stiffness = Configured<double>{5700.0, "asset-lint.toml:2"};
    if (armature) {
      settings.drives["finger_joint"].armature = Configured<double>{*armature, "asset-lint.toml:3"};
      settings.drives["finger_joint"].gear_ratio = Configured<double>{50.0, "asset-lint.toml:4"};
    }
    settings = commands::with_spec_flags(settings, guide_flags());
    loaded = load_asset((test::source_dir() / kUrdf).string(), settings);
    REQUIRE(loaded.read.usable);
    std::string error;
    const Joint* joint = commands::tune_joint(loaded.read.asset, settings, std::nullopt, error);
    REQUIRE(joint);
    derivation = commands::derive(kUrdf, loaded.read, settings, *joint);
  }
};

// The guide's numbers (PHYSICS.md §3) in the JSON summary.
void check_guide_summary(const nlohmann::json& s) {
  CHECK(s["grip_force_n"].get<double>() == Approx(166.667).epsilon(1e-5));
  CHECK(s["force_per_finger_n"].get<double>() == Approx(83.333).epsilon(1e-5));
  CHECK(s["torque_per_joint_nm"].get<double>() == 4.0);
  CHECK(s["max_drive_force_nm"].get<double>() == 24.0);
  CHECK(s["close_time_s"].get<double>() == Approx(0.2833).epsilon(1e-3));
  CHECK(s["max_joint_velocity_rad_s"].get<double>() == Approx(2.895).epsilon(1e-3));
  CHECK(s["effective_inertia_kgm2"].get<double>() == Approx(3.37e-6).epsilon(1e-6));
  CHECK(s["current_natural_frequency_rad_s"].get<double>() == Approx(4.113e4).epsilon(1e-3));
  CHECK(s["stiffness_nm_per_rad"].get<double>() == Approx(275.0).epsilon(1e-3));
  CHECK(s["natural_frequency_rad_s"].get<double>() == Approx(9.03e3).epsilon(1e-3));
  CHECK(s["damping_nms_per_rad"].get<double>() == Approx(0.0609).epsilon(2e-3));
  CHECK(s["sim_rate_hz"].get<double>() == 250.0);
  CHECK(s["position_iterations"].get<double>() == 64.0);
}

}  // namespace

TEST_CASE("tune: the guide's numbers on the URDF fixture", "[tune]") {
  GuideUrdf g;
  const auto& d = g.derivation;
  CHECK(d.joint->name.text == "finger_joint");
  CHECK(d.mimics.size() == 5);
  CHECK(result(d, "grip_force") == Approx(166.667).epsilon(1e-5));
  CHECK(result(d, "force_per_finger") == Approx(83.333).epsilon(1e-5));
  CHECK(result(d, "torque_per_joint") == 4.0);  // 3.33 rounded up to the 1 N·m margin
  CHECK(step(d, "torque_per_joint").notes.front() == "3.33 N·m rounded up to a multiple of 1 N·m: 4 N·m.");
  CHECK(result(d, "max_drive_force") == 24.0);
  CHECK(result(d, "close_time") == Approx(0.28333).epsilon(1e-4));
  CHECK(result(d, "max_joint_velocity") == Approx(2.895).epsilon(1e-3));
  CHECK(*step(d, "max_joint_velocity").result->usd_value == Approx(165.9).epsilon(1e-3));
  CHECK(result(d, "effective_inertia") == Approx(3.37e-6).epsilon(1e-6));
  CHECK(result(d, "current_natural_frequency") == Approx(4.113e4).epsilon(1e-3));
  CHECK(result(d, "stiffness") == Approx(275.0).epsilon(1e-3));
  CHECK(*step(d, "stiffness").result->usd_value == Approx(4.8).epsilon(1e-3));
  CHECK(result(d, "natural_frequency") == Approx(9.03e3).epsilon(1e-3));
  CHECK(result(d, "damping") == Approx(0.0609).epsilon(2e-3));
  // Every input names where it came from.
  const auto& grip = step(d, "grip_force");
  REQUIRE(grip.inputs.size() == 3);
  CHECK(grip.inputs[0].origin == "--payload-kg");
  CHECK(grip.inputs[1].origin == "--gravity");
  const auto& velocity = step(d, "max_joint_velocity");
  CHECK(velocity.inputs[1].origin.ends_with("robotiq_2f85.urdf:61"));  // <limit upper>
  CHECK(step(d, "current_natural_frequency").inputs[0].origin == "asset-lint.toml:2");
  CHECK(d.recommended.max_force == 24.0);
  CHECK(*d.recommended.stiffness == Approx(275.0).epsilon(1e-3));
}

TEST_CASE("tune: armature 5e-3 gives 234 rad/s and a 2e-6 kg·m² rotor at G = 50", "[tune]") {
  GuideUrdf g(5e-3);
  const auto& d = g.derivation;
  CHECK(result(d, "armature_natural_frequency") == Approx(234.4).epsilon(1e-3));
  CHECK(result(d, "rotor_inertia") == Approx(2e-6).epsilon(1e-9));
  CHECK(step(d, "rotor_inertia").inputs[1].origin == "asset-lint.toml:4");
}

TEST_CASE("tune: missing spec inputs name their key and flag, other steps still print", "[tune]") {
  Settings settings;
  auto loaded = load_asset((test::source_dir() / kUrdf).string(), settings);
  REQUIRE(loaded.read.usable);
  std::string error;
  const Joint* joint = commands::tune_joint(loaded.read.asset, settings, std::nullopt, error);
  REQUIRE(joint);
  const auto d = commands::derive(kUrdf, loaded.read, settings, *joint);
  const auto& grip = step(d, "grip_force");
  CHECK_FALSE(grip.result);
  REQUIRE(grip.missing.size() == 2);
  CHECK(grip.missing[0].key == "[gripper] payload_kg");
  CHECK(grip.missing[0].flag == "--payload-kg");
  CHECK(grip.missing[1].flag == "--friction");
  // The inertia comes from the asset alone; the stiffness from the asset's effort (24 N·m).
  CHECK(result(d, "effective_inertia") == Approx(3.37e-6).epsilon(1e-6));
  CHECK(result(d, "stiffness") == Approx(275.0).epsilon(1e-3));
  CHECK(step(d, "stiffness").inputs[0].origin.ends_with("robotiq_2f85.urdf:61"));
}

TEST_CASE("tune: the command prints every step and the JSON summary", "[tune][cli]") {
  test::TempDir dir;
  test::write_file(dir.path() / "asset-lint.toml", "[drives.finger_joint]\nstiffness = 5700\n");
  std::vector<std::string> args = {"tune", kUrdf, "--config", (dir.path() / "asset-lint.toml").string()};
  args.insert(args.end(), kGuideFlags.begin(), kGuideFlags.end());
  auto text = run_cli(args);
  CHECK(text.exit_code == 0);
  CHECK(text.err.empty());
  CHECK(text.out.find("1. grip force (both fingers): F = m·g / μ\n") != std::string::npos);
  CHECK(text.out.find("   → 166.7 N\n") != std::string::npos);
  CHECK(text.out.find("   → 275 N·m/rad (USD: 4.8 N·m/deg)\n") != std::string::npos);
  CHECK(text.out.find("   → 41130 rad/s\n") != std::string::npos);
  args.insert(args.end(), {"--output-format", "json"});
  auto json = run_cli(args);
  REQUIRE(json.exit_code == 0);
  const auto doc = nlohmann::json::parse(json.out);
  check_guide_summary(doc["summary"]);
  CHECK(doc["steps"][0]["inputs"][0]["origin"] == "--payload-kg");
  // The drive row tune's numbers rest on: h = dt/N, the articulated inertia 1/r of the
  // finger joint (the other joints free) and x at the recommended k and d.
  const auto& s = doc["summary"];
  CHECK(s["step_h_s"].get<double>() == Approx(1.0 / 16000).epsilon(1e-12));
  CHECK(s["articulated_inertia_kgm2"].get<double>() == Approx(8.569e-5).epsilon(1e-3));
  CHECK(s["implicit_factor"].get<double>() == Approx(0.9461).epsilon(1e-3));
  CHECK(text.out.find("12. implicit factor of PhysX's drive row at that drive: x = 1 / (1 + h·(h·k + d) / I)\n"
                      "     h = 6.25e-5 s          the step the row is built with, from TGS, h = 1/16000 s\n") !=
        std::string::npos);
  // On the guide's lighter link x = 0.408, PhysX's own x for k 275, d 0.061 (docs/physx-reference.md).
  CHECK(text.out.find("On the guide's lighter link (3.37e-6 kg·m²): x = 0.408; h·nf = 0.565.") != std::string::npos);
}

TEST_CASE("tune: the USDA fixture gives the same numbers, with per-degree values to author", "[tune][cli]") {
  test::TempDir dir;
  std::string text = test::read_file(test::source_dir() / kUsda);
  // The guide's original 5700 N·m/rad, written per degree.
  const auto at = text.find("drive:angular:physics:stiffness = 4.8");
  REQUIRE(at != std::string::npos);
  text.replace(at, 37, "drive:angular:physics:stiffness = 99.48");
  test::write_file(dir.path() / "gripper.usda", text);
  std::vector<std::string> args = {"tune", "gripper.usda", "--output-format", "json"};
  args.insert(args.end(), kGuideFlags.begin(), kGuideFlags.end());
  auto r = run_cli(args, dir.path());
  REQUIRE(r.exit_code == 0);
  const auto doc = nlohmann::json::parse(r.out);
  CHECK(doc["joint"] == "/robotiq_2f85/joints/finger_joint");
  check_guide_summary(doc["summary"]);
  for (const auto& step : doc["steps"]) {
    if (step["name"] == "stiffness") CHECK(step["result"]["usd_value"].get<double>() == Approx(4.8).epsilon(1e-3));
    if (step["name"] == "max_joint_velocity")
      CHECK(step["result"]["usd_value"].get<double>() == Approx(165.9).epsilon(1e-3));
    if (step["name"] == "current_natural_frequency") CHECK(step["inputs"][0]["as_written"] == "99.48 N·m/deg");
  }
}

TEST_CASE("tune: bad input is one line naming it, exit 2", "[tune][cli]") {
  auto missing_joint = run_cli({"tune", kUrdf, "--joint", "no_such_joint"});
  CHECK(missing_joint.exit_code == 2);
  CHECK(missing_joint.err == "asset-lint tune: error: " + kUrdf +
                                 ": --joint names joint 'no_such_joint', which the asset does not have\n");
  auto mimic = run_cli({"tune", kUrdf, "--joint", "left_inner_knuckle_joint"});
  CHECK(mimic.exit_code == 2);
  CHECK(mimic.err == "asset-lint tune: error: " + kUrdf +
                         ": --joint names 'left_inner_knuckle_joint', a mimic of 'finger_joint': name the joint it "
                         "follows\n");
  for (const char* bad : {"0", "-5", "nan", "inf", "abc"}) {
    auto r = run_cli({"tune", kUrdf, "--payload-kg", bad});
    CHECK(r.exit_code == 2);
    CHECK(r.err == std::string("asset-lint tune: error: --payload-kg must be a finite number > 0, got '") + bad + "'\n");
  }
  auto rate = run_cli({"tune", kUrdf, "--rate", "0"});
  CHECK(rate.exit_code == 2);
  CHECK(rate.err == "asset-lint tune: error: --rate must be a finite number > 0, got '0'\n");
  auto no_file = run_cli({"tune", "no/such.urdf"});
  CHECK(no_file.exit_code == 2);
  CHECK(no_file.err == "asset-lint tune: error: no such file: 'no/such.urdf'\n");
  test::TempDir dir;
  test::write_file(dir.path() / "two.urdf", R"(<robot name="two">
  <link name="a"/><link name="b"/><link name="c"/>
  <joint name="j1" type="revolute"><parent link="a"/><child link="b"/><limit lower="0" upper="1" effort="1" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="b"/><child link="c"/><limit lower="0" upper="1" effort="1" velocity="1"/></joint>
</robot>
)");
  auto ambiguous = run_cli({"tune", "two.urdf"}, dir.path());
  CHECK(ambiguous.exit_code == 2);
  CHECK(ambiguous.err == "asset-lint tune: error: two.urdf: 2 joints could be the driven one ('j1', 'j2'); name it "
                         "with --joint or [gripper] driven_joint in asset-lint.toml\n");
  test::write_file(dir.path() / "fixed.urdf", R"(<robot name="f"><link name="a"/><link name="b"/>
  <joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint></robot>
)");
  auto none = run_cli({"tune", "fixed.urdf"}, dir.path());
  CHECK(none.exit_code == 2);
  CHECK(none.err == "asset-lint tune: error: fixed.urdf: the asset has no driven joint (no revolute or prismatic "
                    "joint that is not a mimic)\n");
}

TEST_CASE("tune on MJCF: MuJoCo's bound and one MuJoCo step instead of PhysX's row", "[tune][cli][mjcf]") {
  // The guide's gripper in MJCF at its own 4 ms timestep and MuJoCo's default Euler integrator.
  std::vector<std::string> args = {"tune", "fixtures/mjcf/robotiq_2f85/robotiq_2f85.xml", "--output-format", "json"};
  for (std::size_t i = 0; i + 1 < kGuideFlags.size(); i += 2)
    if (kGuideFlags[i] != "--rate" && kGuideFlags[i] != "--position-iterations")
      args.insert(args.end(), {kGuideFlags[i], kGuideFlags[i + 1]});
  auto r = run_cli(args);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto doc = nlohmann::json::parse(r.out);
  // The spec side of the guide is format-blind: the same force, stiffness and damping.
  CHECK(doc["summary"]["max_drive_force_nm"].get<double>() == 24.0);
  CHECK(doc["summary"]["stiffness_nm_per_rad"].get<double>() == Approx(275.0).epsilon(1e-3));
  CHECK(doc["summary"]["damping_nms_per_rad"].get<double>() == Approx(0.0609).epsilon(2e-3));
  bool stepped = false;
  for (const auto& step : doc["steps"]) {
    CHECK(step["name"] != "implicit_factor");
    if (step["result"].is_object()) CHECK_FALSE(step["result"].contains("usd_value"));  // USD's units mean nothing here
    if (step["name"] == "natural_frequency")
      CHECK(step["notes"][0].get<std::string>().find("above 1/timestep = 250 rad/s: MuJoCo steps the spring once per "
                                                     "timestep; unless the integrator damps it stably") !=
            std::string::npos);
    if (step["name"] != "mujoco_step") continue;
    stepped = true;
    // 275 N·m/rad and critical damping on 8.57e-5 kg·m² at 4 ms: h·nf = 7.2, Euler's explicit kv.
    CHECK(step["result"]["value"].get<double>() == Approx(52.23).epsilon(1e-3));
    CHECK(step["notes"][1] == "It grows every step: MuJoCo needs a smaller <option timestep> or more armature.");
  }
  CHECK(stepped);
}
