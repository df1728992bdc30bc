// `asset-lint tune --apply / --diff`: exact bytes, idempotence, a new asset-lint.toml,
// USD per-degree values and mimic velocity removal.
#include <catch2/catch.hpp>

#include "config/toml_edit.h"
#include "test_support.h"

using namespace assetlint;
using assetlint::test::read_file;
using assetlint::test::run_cli;
using assetlint::test::write_file;

namespace {

const std::vector<std::string> kGuideFlags = {
    "--payload-kg", "5",   "--friction", "0.3",   "--gravity", "10",    "--lever-arm-m",      "0.04",
    "--torque-margin", "1", "--finger-speed-m-s", "0.15", "--stroke-m", "0.085", "--target-delta-deg", "5",
    "--rate", "250", "--position-iterations", "64"};

std::vector<std::string> tune(const std::string& asset, std::vector<std::string> extra) {
  std::vector<std::string> args = {"tune", asset};
  args.insert(args.end(), kGuideFlags.begin(), kGuideFlags.end());
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

// The URDF fixture with a weak effort and velocity, as a badly tuned asset would have.
std::string weak_urdf() {
  std::string text = read_file(test::fixtures_dir() / "robotiq_2f85" / "robotiq_2f85.urdf");
  const std::string limit = R"(<limit lower="0" upper="0.820305" effort="24" velocity="2.9"/>)";
  const auto at = text.find(limit);
  REQUIRE(at != std::string::npos);
  text.replace(at, limit.size(), R"(<limit lower="0" upper="0.820305" effort="12" velocity="1"/>)");
  return text;
}

const std::filesystem::path kDemoXacro =
    test::fixtures_dir() / "xacro" / "demo_gripper_description" / "urdf" / "demo_gripper.urdf.xacro";

// The guide's gripper as a ROS package's xacro file: its driven joint's effort from a property,
// its velocity from an argument, a weak drive as a badly tuned asset would have.
std::string guide_xacro() {
  std::string text = read_file(test::fixtures_dir() / "robotiq_2f85" / "robotiq_2f85.urdf");
  text = test::replace_once(text, "<robot name=\"robotiq_2f85_guide\">",
                            "<robot name=\"robotiq_2f85_guide\" xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n"
                            "  <xacro:property name=\"finger_effort\" value=\"12\"/>\n"
                            "  <xacro:arg name=\"finger_velocity\" default=\"1\"/>");
  return test::replace_once(
      text, R"(<limit lower="0" upper="0.820305" effort="24" velocity="2.9"/>)",
      R"x(<limit lower="0" upper="0.820305" effort="${finger_effort}" velocity="$(arg finger_velocity)"/>)x");
}

}  // namespace

TEST_CASE("toml edit: values rewritten in place, keys added after the table's last, comments kept", "[tune]") {
  const std::string text =
      "# project settings\n[gripper]\npayload_kg = 5\n\n[drives.finger_joint]  # J0\nstiffness = 5700   # the "
      "original\narmature = 0\n\n[drives.other]\nstiffness = 1\n";
  auto edit = config::set_table_numbers(text, "drives", "finger_joint",
                                        {{"stiffness", "275", true}, {"damping", "0.06089", true}, {"max_force", "24", false}});
  REQUIRE_FALSE(edit.error);
  CHECK(edit.text ==
        "# project settings\n[gripper]\npayload_kg = 5\n\n[drives.finger_joint]  # J0\nstiffness = 275   # the "
        "original\narmature = 0\ndamping = 0.06089\n\n[drives.other]\nstiffness = 1\n");
  CHECK(edit.changes == std::vector<std::string>{"[drives.finger_joint] stiffness = 275 (was 5700)",
                                                 "[drives.finger_joint] damping = 0.06089"});
  // Twice: nothing changes.
  auto again = config::set_table_numbers(edit.text, "drives", "finger_joint", {{"stiffness", "275", true}, {"damping", "0.06089", true}});
  CHECK(again.text == edit.text);
  CHECK(again.changes.empty());
  // A missing table is appended; CRLF files keep CRLF; names that are not bare keys are quoted.
  auto added = config::set_table_numbers("[gripper]\r\npayload_kg = 5\r\n", "drives", "/robot/joints/j0", {{"stiffness", "1", true}});
  CHECK(added.text == "[gripper]\r\npayload_kg = 5\r\n\r\n[drives.\"/robot/joints/j0\"]\r\nstiffness = 1\r\n");
  auto inline_table = config::set_table_numbers("drives = { j0 = { stiffness = 1 } }\n", "drives", "j0", {{"stiffness", "2", true}});
  CHECK(inline_table.error);
}

TEST_CASE("tune --diff and --apply on URDF: <limit> and [drives.<joint>], byte-exact and idempotent", "[tune][cli]") {
  test::TempDir dir;
  write_file(dir.path() / "gripper.urdf", weak_urdf());
  write_file(dir.path() / "asset-lint.toml", "# gripper\n[drives.finger_joint]\nstiffness = 5700 # the original\n");
  auto diff = run_cli(tune("gripper.urdf", {"--diff"}), dir.path());
  CHECK(diff.exit_code == 1);
  CHECK(diff.out ==
        "--- a/gripper.urdf\n+++ b/gripper.urdf\n@@ -58,7 +58,7 @@\n"
        "     <parent link=\"base_link\"/>\n     <child link=\"left_outer_knuckle\"/>\n     <axis xyz=\"1 0 0\"/>\n"
        "-    <limit lower=\"0\" upper=\"0.820305\" effort=\"12\" velocity=\"1\"/>\n"
        "+    <limit lower=\"0\" upper=\"0.820305\" effort=\"24\" velocity=\"2.9\"/>\n"
        "   </joint>\n   <joint name=\"left_inner_knuckle_joint\" type=\"revolute\">\n"
        "     <origin xyz=\"0 -0.0127 0.0614\" rpy=\"0 0 0\"/>\n"
        "--- a/asset-lint.toml\n+++ b/asset-lint.toml\n@@ -1,3 +1,4 @@\n # gripper\n [drives.finger_joint]\n"
        "-stiffness = 5700 # the original\n+stiffness = 275 # the original\n+damping = 0.06089\n");
  CHECK(read_file(dir.path() / "gripper.urdf") == weak_urdf());  // --diff writes nothing

  auto applied = run_cli(tune("gripper.urdf", {"--apply"}), dir.path());
  CHECK(applied.exit_code == 0);
  CHECK(applied.err ==
        "asset-lint tune: gripper.urdf: <limit effort> 12 → 24\n"
        "asset-lint tune: gripper.urdf: <limit velocity> 1 → 2.9\n"
        "asset-lint tune: asset-lint.toml: [drives.finger_joint] stiffness = 275 (was 5700)\n"
        "asset-lint tune: asset-lint.toml: [drives.finger_joint] damping = 0.06089\n");
  CHECK(read_file(dir.path() / "asset-lint.toml") ==
        "# gripper\n[drives.finger_joint]\nstiffness = 275 # the original\ndamping = 0.06089\n");
  const std::string urdf = read_file(dir.path() / "gripper.urdf");
  CHECK(urdf == read_file(test::fixtures_dir() / "robotiq_2f85" / "robotiq_2f85.urdf"));

  auto again = run_cli(tune("gripper.urdf", {"--apply"}), dir.path());
  CHECK(again.exit_code == 0);
  CHECK(again.err == "asset-lint tune: nothing to change\n");
  CHECK(read_file(dir.path() / "gripper.urdf") == urdf);
  CHECK(run_cli(tune("gripper.urdf", {"--diff"}), dir.path()).exit_code == 0);
}

TEST_CASE("tune --apply creates asset-lint.toml beside a URDF that has none", "[tune][cli]") {
  test::TempDir dir;
  for (auto up = dir.path().parent_path(); !up.empty() && up != up.root_path(); up = up.parent_path())
    if (std::filesystem::exists(up / "asset-lint.toml")) {
      WARN("skipped: " << (up / "asset-lint.toml") << " above the temporary directory would be the nearest");
      return;
    }
  std::filesystem::create_directories(dir.path() / "robot");
  write_file(dir.path() / "robot" / "gripper.urdf", weak_urdf());
  auto diff = run_cli(tune("robot/gripper.urdf", {"--diff"}), dir.path());
  CHECK(diff.exit_code == 1);
  CHECK(diff.out.find("--- /dev/null\n+++ b/robot/asset-lint.toml\n@@ -0,0 +1,3 @@\n+[drives.finger_joint]\n"
                      "+stiffness = 275\n+damping = 0.06089\n") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir.path() / "robot" / "asset-lint.toml"));
  CHECK(run_cli(tune("robot/gripper.urdf", {"--apply"}), dir.path()).exit_code == 0);
  CHECK(read_file(dir.path() / "robot" / "asset-lint.toml") == "[drives.finger_joint]\nstiffness = 275\ndamping = 0.06089\n");
}

TEST_CASE("tune --apply on USD: per-degree gains, max force and velocity, none on the mimics", "[tune][cli]") {
  test::TempDir dir;
  std::string text = read_file(test::fixtures_dir() / "usda" / "robotiq_2f85" / "robotiq_2f85.usda");
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    text.replace(at, from.size(), to);
  };
  replace("drive:angular:physics:stiffness = 4.8", "drive:angular:physics:stiffness = 99.48");
  replace("            float drive:angular:physics:maxForce = 24\n", "");
  replace("physxJoint:maxJointVelocity = 166.16", "physxJoint:maxJointVelocity = 50");
  // One mimic with the max joint velocity the guide says to leave unset.
  replace("prepend apiSchemas = [\"PhysxMimicJointAPI:rotX\"]\n        )\n        {\n            uniform token "
          "physics:axis = \"X\"\n            rel physics:body0 = </robotiq_2f85/base_link>\n            rel "
          "physics:body1 = </robotiq_2f85/left_inner_knuckle>",
          "prepend apiSchemas = [\"PhysxMimicJointAPI:rotX\", \"PhysxJointAPI\"]\n        )\n        {\n            "
          "float physxJoint:maxJointVelocity = 10000\n            uniform token physics:axis = \"X\"\n            rel "
          "physics:body0 = </robotiq_2f85/base_link>\n            rel physics:body1 = </robotiq_2f85/left_inner_knuckle>");
  write_file(dir.path() / "gripper.usda", text);
  auto applied = run_cli(tune("gripper.usda", {"--apply"}), dir.path());
  CHECK(applied.exit_code == 0);
  CHECK(applied.err ==
        "asset-lint tune: gripper.usda: drive:angular:physics:maxForce = 24\n"
        "asset-lint tune: gripper.usda: drive:angular:physics:stiffness 99.48 → 4.8\n"
        "asset-lint tune: gripper.usda: drive:angular:physics:damping 0.00106 → 0.001063\n"
        "asset-lint tune: gripper.usda: physxJoint:maxJointVelocity 50 → 166\n"
        "asset-lint tune: gripper.usda: physxJoint:maxJointVelocity removed from mimic "
        "'/robotiq_2f85/joints/left_inner_knuckle_joint'\n");
  const std::string after = read_file(dir.path() / "gripper.usda");
  CHECK(after.find("            float drive:angular:physics:damping = 0.001063\n"
                   "            float drive:angular:physics:maxForce = 24\n"
                   "            float drive:angular:physics:stiffness = 4.8\n") != std::string::npos);
  CHECK(after.find("float physxJoint:maxJointVelocity = 166\n") != std::string::npos);
  CHECK(after.find("10000") == std::string::npos);
  auto again = run_cli(tune("gripper.usda", {"--apply"}), dir.path());
  CHECK(again.err == "asset-lint tune: nothing to change\n");
  CHECK(read_file(dir.path() / "gripper.usda") == after);
}

TEST_CASE("tune --apply on MJCF: the actuator's kp, kv and whole forcerange, no velocity, class values kept",
          "[tune][cli][mjcf]") {
  test::TempDir dir;
  std::string text = read_file(test::fixtures_dir() / "mjcf" / "robotiq_2f85" / "robotiq_2f85.xml");
  const std::string actuator = R"(kp="275" kv="0.06073" forcerange="-24 24")";
  const auto at = text.find(actuator);
  REQUIRE(at != std::string::npos);
  const std::string weak = R"(kp="99.48" kv="0.06073" forcerange="-12 12")";
  text.replace(at, actuator.size(), weak);
  write_file(dir.path() / "gripper.xml", text);
  const std::string velocity_note =
      "asset-lint tune: note: MuJoCo has no joint velocity limit: the recommended 2.9 rad/s for joint 'finger_joint' "
      "is not written\n";
  auto applied = run_cli(tune("gripper.xml", {"--apply"}), dir.path());
  CHECK(applied.exit_code == 0);
  CHECK(applied.err == velocity_note +
                           "asset-lint tune: gripper.xml: <actuator kp> 99.48 → 275\n"
                           "asset-lint tune: gripper.xml: <actuator kv> 0.06073 → 0.06089\n"
                           "asset-lint tune: gripper.xml: <actuator forcerange> -12 12 → -24 24\n");
  std::string expected = text;
  expected.replace(at, weak.size(), R"(kp="275" kv="0.06089" forcerange="-24 24")");
  CHECK(read_file(dir.path() / "gripper.xml") == expected);
  auto again = run_cli(tune("gripper.xml", {"--apply"}), dir.path());
  CHECK(again.err == velocity_note + "asset-lint tune: nothing to change\n");

  // kp from a default class that a second actuator uses too: not edited, and said so.
  std::string shared = expected;
  const std::string own_kp = R"(<position name="fingers" joint="finger_joint" kp="275")";
  const auto kp_at = shared.find(own_kp);
  REQUIRE(kp_at != std::string::npos);
  shared.replace(kp_at, own_kp.size(), R"(<position name="fingers" class="servo" joint="finger_joint")");
  shared.replace(shared.find("  <default>\n"), 12,
                 "  <default>\n    <default class=\"servo\"><position kp=\"99.48\"/></default>\n");
  shared.replace(shared.find("  </actuator>"), 13,
                 "    <position name=\"spare\" class=\"servo\" joint=\"right_outer_knuckle_joint\"/>\n  </actuator>");
  write_file(dir.path() / "shared.xml", shared);
  auto kept = run_cli(tune("shared.xml", {"--apply", "--joint", "finger_joint"}), dir.path());
  INFO(kept.out);
  CHECK(kept.err.find("asset-lint tune: note: kp of joint 'finger_joint' is written once, in default class 'servo', "
                      "which 2 elements use: not edited; give its actuator its own kp\n") != std::string::npos);
  CHECK(read_file(dir.path() / "shared.xml").find("<position kp=\"99.48\"/>") != std::string::npos);
}

TEST_CASE("tune reads a .xacro top file, with --xacro-arg, and shows values at their xacro lines", "[tune][xacro][cli]") {
  const auto derived = run_cli(tune(kDemoXacro.string(), {"--joint", "left_finger_joint"}));
  INFO(derived.out << derived.err);
  REQUIRE(derived.exit_code == 0);
  CHECK(derived.err.find("expand it first") == std::string::npos);
  // The joint's limits are written once, in the macro file, whatever finger the macro makes.
  CHECK(derived.out.find("demo_gripper_macro.xacro:19") != std::string::npos);
  CHECK(derived.out.find("demo_gripper.urdf.xacro:") == std::string::npos);

  const auto prefixed =
      run_cli(tune(kDemoXacro.string(), {"--joint", "r_left_finger_joint", "--xacro-arg", "prefix:=r_"}));
  INFO(prefixed.out << prefixed.err);
  CHECK(prefixed.exit_code == 0);
  CHECK(run_cli(tune(kDemoXacro.string(), {"--joint", "r_left_finger_joint"})).err.find(
            "--joint names joint 'r_left_finger_joint', which the asset does not have") != std::string::npos);
  CHECK(run_cli({"tune", kDemoXacro.string(), "--xacro-arg", "prefix"}).exit_code == 2);
}

TEST_CASE("tune --apply on xacro writes through the xacro source, an argument's value only with a note",
          "[tune][xacro][cli]") {
  test::TempDir dir;
  const auto package = dir.path() / "guide_gripper";
  std::filesystem::create_directories(package / "urdf");
  write_file(package / "package.xml", "<?xml version=\"1.0\"?>\n<package format=\"2\">\n  <name>guide_gripper</name>\n"
                                      "  <version>0.1.0</version>\n</package>\n");
  write_file(package / "urdf" / "gripper.urdf.xacro", guide_xacro());
  const std::string original = read_file(package / "urdf" / "gripper.urdf.xacro");
  const auto diff = run_cli(tune("guide_gripper/urdf/gripper.urdf.xacro", {"--diff"}), dir.path());
  INFO(diff.out << diff.err);
  CHECK(diff.exit_code == 1);
  CHECK(diff.out.find("-  <xacro:property name=\"finger_effort\" value=\"12\"/>\n"
                      "+  <xacro:property name=\"finger_effort\" value=\"24\"/>\n") != std::string::npos);
  CHECK(diff.out.find("+++ b/guide_gripper/urdf/asset-lint.toml") != std::string::npos);
  CHECK(diff.err.find("asset-lint tune: note: <limit velocity> 1 → 2.9 not written: the value depends on the xacro "
                      "argument finger_velocity; asset-lint does not rewrite arguments\n") != std::string::npos);
  CHECK(read_file(package / "urdf" / "gripper.urdf.xacro") == original);

  const auto applied = run_cli(tune("guide_gripper/urdf/gripper.urdf.xacro", {"--apply"}), dir.path());
  INFO(applied.out << applied.err);
  CHECK(applied.exit_code == 0);
  CHECK(applied.err.find("asset-lint tune: guide_gripper/urdf/gripper.urdf.xacro: <limit effort> 12 → 24\n") !=
        std::string::npos);
  CHECK(read_file(package / "urdf" / "gripper.urdf.xacro") ==
        test::replace_once(original, "value=\"12\"", "value=\"24\""));
  CHECK(read_file(package / "urdf" / "asset-lint.toml").find("[drives.finger_joint]\nstiffness = ") != std::string::npos);
  // The derivation shows the value where it is written: the property's line.
  CHECK(applied.out.find("gripper.urdf.xacro:7") != std::string::npos);

  // The argument given on the command line: the recommended velocity is what it is set to.
  const auto again = run_cli(
      tune("guide_gripper/urdf/gripper.urdf.xacro", {"--apply", "--xacro-arg", "finger_velocity:=2.9"}),
      dir.path());
  INFO(again.out << again.err);
  CHECK(again.exit_code == 0);
  CHECK(again.err == "asset-lint tune: nothing to change\n");
}
