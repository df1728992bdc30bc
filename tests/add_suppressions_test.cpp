// --add-suppressions: a comment in each file's own syntax before the element or statement
// of every finding, byte-exact, and a second run changes nothing.
#include <catch2/catch.hpp>

#include "test_support.h"

using assetlint::test::read_file;
using assetlint::test::report_dir;
using assetlint::test::replace_once;
using assetlint::test::run_cli;
using assetlint::test::TempDir;
using assetlint::test::write_file;

namespace {

// Runs --add-suppressions twice on `name`; returns the text after the first run and checks
// that the second changes nothing and the check is then clean.
std::string add_twice(const std::filesystem::path& dir, const std::string& name, const std::string& select,
                      const std::string& expected_err) {
  auto first = run_cli({"--add-suppressions", "--select", select, name}, dir);
  CHECK(first.exit_code == 0);
  CHECK(first.err == expected_err);
  CHECK(first.out == "No problems found in 1 file.\n");
  const std::string after = read_file(dir / name);
  auto second = run_cli({"--add-suppressions", "--select", select, name}, dir);
  CHECK(second.exit_code == 0);
  CHECK(second.err.empty());
  CHECK(read_file(dir / name) == after);
  CHECK(run_cli({name}, dir).out.find("unused-suppression") == std::string::npos);
  return after;
}

}  // namespace

TEST_CASE("add-suppressions: URDF gets an XML comment before the element of each finding", "[add-suppressions]") {
  TempDir dir;
  const std::string original = read_file(report_dir() / "gripper.urdf");
  write_file(dir.path() / "gripper.urdf", original);
  const std::string after = add_twice(dir.path(), "gripper.urdf", "limits-inverted,mimic-max-velocity",
                                      "asset-lint: added 2 suppression comments to gripper.urdf\n");
  std::string expected = replace_once(original, "    <limit lower=\"0.82\"",
                                  "    <!-- asset-lint: ignore[limits-inverted] -->\n    <limit lower=\"0.82\"");
  expected = replace_once(expected, "    <limit lower=\"-0.82\"",
                      "    <!-- asset-lint: ignore[mimic-max-velocity] -->\n    <limit lower=\"-0.82\"");
  CHECK(after == expected);
}

TEST_CASE("add-suppressions: USDA gets a # comment before the statement, one per statement", "[add-suppressions]") {
  TempDir dir;
  const std::string original = read_file(report_dir() / "joints.usda");
  write_file(dir.path() / "joints.usda", original);
  const std::string after = add_twice(dir.path(), "joints.usda", "stale-schema-attribute",
                                      "asset-lint: added 2 suppression comments to joints.usda\n");
  std::string expected = replace_once(original, "        float physxJoint:jointFriction",
                                  "        # asset-lint: ignore[stale-schema-attribute]\n"
                                  "        float physxJoint:jointFriction");
  expected = replace_once(expected, "        float drive:angular:physics:damping = 5000",
                      "        # asset-lint: ignore[stale-schema-attribute]\n"
                      "        float drive:angular:physics:damping = 5000");
  CHECK(after == expected);
}

TEST_CASE("add-suppressions: CRLF files keep CRLF, an element inside a line gets an inline comment",
          "[add-suppressions]") {
  TempDir dir;
  const std::string crlf =
      "<robot name=\"r\">\r\n  <link name=\"a\"/>\r\n  <link name=\"b\"/>\r\n"
      "  <joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>"
      "<limit lower=\"1\" upper=\"0\" effort=\"1\" velocity=\"1\"/></joint>\r\n"
      "  <joint name=\"k\" type=\"revolute\">\r\n    <parent link=\"b\"/>\r\n    <child link=\"a\"/>\r\n"
      "    <limit lower=\"2\" upper=\"0\" effort=\"1\" velocity=\"1\"/>\r\n  </joint>\r\n</robot>\r\n";
  write_file(dir.path() / "crlf.urdf", crlf);
  const std::string after = add_twice(dir.path(), "crlf.urdf", "limits-inverted",
                                      "asset-lint: added 2 suppression comments to crlf.urdf\n");
  std::string expected = replace_once(crlf, "<limit lower=\"1\"", "<!-- asset-lint: ignore[limits-inverted] --> <limit lower=\"1\"");
  expected = replace_once(expected, "    <limit lower=\"2\"",
                      "    <!-- asset-lint: ignore[limits-inverted] -->\r\n    <limit lower=\"2\"");
  CHECK(after == expected);
}

TEST_CASE("add-suppressions: several rules on one element share one comment", "[add-suppressions]") {
  TempDir dir;
  const std::string urdf =
      "<robot name=\"r\">\n  <link name=\"a\"/>\n  <link name=\"b\"/>\n  <link name=\"c\"/>\n"
      "  <joint name=\"j\" type=\"revolute\">\n    <parent link=\"a\"/>\n    <child link=\"b\"/>\n"
      "    <limit lower=\"0\" upper=\"1\" effort=\"1\" velocity=\"3\"/>\n  </joint>\n"
      "  <joint name=\"m\" type=\"revolute\">\n    <parent link=\"b\"/>\n    <child link=\"c\"/>\n"
      "    <limit lower=\"1\" upper=\"0\" effort=\"1\" velocity=\"1\"/>\n    <mimic joint=\"j\"/>\n  </joint>\n"
      "</robot>\n";
  write_file(dir.path() / "two.urdf", urdf);
  const std::string after = add_twice(dir.path(), "two.urdf", "limits-inverted,mimic-max-velocity",
                                      "asset-lint: added 1 suppression comment to two.urdf\n");
  CHECK(after == replace_once(urdf, "    <limit lower=\"1\"",
                          "    <!-- asset-lint: ignore[limits-inverted, mimic-max-velocity] -->\n    <limit lower=\"1\""));
}

TEST_CASE("add-suppressions: does not combine with --fix", "[add-suppressions]") {
  auto r = run_cli({"--add-suppressions", "--fix", "gripper.urdf"}, report_dir());
  CHECK(r.exit_code == 2);
  CHECK(r.err ==
        "asset-lint: error: --add-suppressions edits files itself; it does not combine with --fix, --diff or "
        "standard input\n");
}

TEST_CASE("add-suppressions: MJCF default classes are told apart by their class, in one run", "[add-suppressions]") {
  TempDir dir;
  const std::string mjcf =
      "<mujoco model=\"two_classes\">\n  <option timestep=\"0.0166667\"/>\n  <default>\n"
      "    <default class=\"a\">\n      <joint axis=\"1 0 0\" range=\"0 47\" armature=\"0.005\"/>\n    </default>\n"
      "    <default class=\"b\">\n      <joint axis=\"1 0 0\" range=\"0 47\" armature=\"0.004\"/>\n    </default>\n"
      "  </default>\n  <worldbody>\n    <body name=\"base\">\n"
      "      <inertial pos=\"0 0 0.03\" mass=\"0.636\" diaginertia=\"0.00095 0.00094 0.00043\"/>\n"
      "      <body name=\"f1\" pos=\"0 -0.03 0.05\">\n"
      "        <inertial pos=\"0 0 0.01\" mass=\"0.0127\" diaginertia=\"2.1e-6 2.1e-6 1.3e-6\"/>\n"
      "        <joint name=\"j1\" class=\"a\"/>\n      </body>\n"
      "      <body name=\"f2\" pos=\"0 0.03 0.05\">\n"
      "        <inertial pos=\"0 0 0.01\" mass=\"0.0127\" diaginertia=\"2.1e-6 2.1e-6 1.3e-6\"/>\n"
      "        <joint name=\"j2\" class=\"b\"/>\n      </body>\n    </body>\n  </worldbody>\n</mujoco>\n";
  write_file(dir.path() / "two.xml", mjcf);
  auto baseline = run_cli({"--select", "armature-excessive", "--write-baseline", "b.json", "two.xml"}, dir.path());
  CHECK(baseline.err == "asset-lint: wrote 2 findings (2 entries) to baseline 'b.json'\n");
  const std::string keys = read_file(dir.path() / "b.json");
  CHECK(keys.find("\"element\": \"default 'a'\",\n      \"attribute\": \"joint.armature\"") != std::string::npos);
  CHECK(keys.find("\"element\": \"default 'b'\",\n      \"attribute\": \"joint.armature\"") != std::string::npos);
  const std::string after = add_twice(dir.path(), "two.xml", "armature-excessive",
                                      "asset-lint: added 2 suppression comments to two.xml\n");
  std::string expected = replace_once(mjcf, "      <joint axis=\"1 0 0\" range=\"0 47\" armature=\"0.005\"/>",
                                      "      <!-- asset-lint: ignore[armature-excessive] -->\n"
                                      "      <joint axis=\"1 0 0\" range=\"0 47\" armature=\"0.005\"/>");
  expected = replace_once(expected, "      <joint axis=\"1 0 0\" range=\"0 47\" armature=\"0.004\"/>",
                          "      <!-- asset-lint: ignore[armature-excessive] -->\n"
                          "      <joint axis=\"1 0 0\" range=\"0 47\" armature=\"0.004\"/>");
  CHECK(after == expected);
}

TEST_CASE("add-suppressions: an MJCF fragment both checked alone and <include>d is done in one run",
          "[add-suppressions]") {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "parts");
  const std::string model =
      "<mujoco model=\"m\">\n  <compiler angle=\"radian\"/>\n  <worldbody>\n"
      "    <include file=\"parts/arm.xml\"/>\n  </worldbody>\n</mujoco>\n";
  // Its finding shows only in the including model; checked alone it is an include fragment.
  const std::string arm =
      "<mujoco>\n  <body name=\"upper\">\n    <inertial pos=\"0 0 0\" mass=\"1\" diaginertia=\"0.01 0.01 0.01\"/>\n"
      "    <joint name=\"shoulder\" type=\"hinge\" range=\"1 -1\" limited=\"true\"/>\n  </body>\n</mujoco>\n";
  write_file(dir.path() / "model.xml", model);
  write_file(dir.path() / "parts" / "arm.xml", arm);
  const std::string expected = replace_once(arm, "    <joint name=\"shoulder\"",
                                            "    <!-- asset-lint: ignore[limits-inverted] -->\n    <joint name=\"shoulder\"");
  auto first = run_cli({"--add-suppressions", "."}, dir.path());
  CHECK(first.err == "asset-lint: added 1 suppression comment to parts/arm.xml\n");
  CHECK(first.out == "No problems found in 2 files.\n");
  CHECK(first.exit_code == 0);
  CHECK(read_file(dir.path() / "parts" / "arm.xml") == expected);
  CHECK(read_file(dir.path() / "model.xml") == model);
  auto second = run_cli({"--add-suppressions", "."}, dir.path());
  CHECK(second.err.empty());
  CHECK(second.exit_code == 0);
  CHECK(read_file(dir.path() / "parts" / "arm.xml") == expected);
  auto check = run_cli({"."}, dir.path());
  CHECK(check.exit_code == 0);
  CHECK(check.out == "No problems found in 2 files.\n");
}
