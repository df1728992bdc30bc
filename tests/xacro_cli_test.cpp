// .xacro files through the CLI: discovery, `expand`, findings at xacro lines in every format,
// suppressions in the xacro source, fixes through xacro.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "test_support.h"

using namespace assetlint;
namespace fs = std::filesystem;

namespace {

// A copy of the demo gripper package (its top file includes its macro file with $(find)).
fs::path copy_package(const test::TempDir& dir) {
  const fs::path package = dir.path() / "demo_gripper_description";
  fs::copy(test::fixtures_dir() / "xacro" / "demo_gripper_description", package, fs::copy_options::recursive);
  return package;
}

}  // namespace

TEST_CASE("xacro CLI: a directory run checks the top-level file only, at xacro lines", "[xacro][cli]") {
  test::TempDir dir;
  const fs::path package = copy_package(dir);
  const auto files = test::run_cli({"--show-files", "."}, package);
  CHECK(files.out == "urdf/demo_gripper.urdf.xacro\n");

  const auto run = test::run_cli({"."}, package);
  CHECK(run.exit_code == 1);
  CHECK(run.out.find("urdf/demo_gripper_macro.xacro:19:31: error: limits [0, 47] of revolute joint 'left_finger_joint'") !=
        std::string::npos);
  CHECK(run.out.find("note: in macro 'finger' called at demo_gripper_macro.xacro:31:5") != std::string::npos);
  CHECK(run.out.find("urdf/demo_gripper.urdf.xacro:5:3: note: in macro 'demo_gripper' called at demo_gripper.urdf.xacro:5:3") !=
        std::string::npos);

  // [xacro] entry_points names the tops when discovery cannot tell.
  test::write_file(package / "asset-lint.toml", "[xacro]\nentry_points = [\"urdf/demo_gripper_macro.xacro\"]\n");
  CHECK(test::run_cli({"--show-files", "."}, package).out == "urdf/demo_gripper_macro.xacro\n");
}

TEST_CASE("xacro CLI: JSON notes and SARIF related locations carry the macro chain", "[xacro][cli]") {
  test::TempDir dir;
  const fs::path package = copy_package(dir);
  const auto json_run = test::run_cli({"--output-format", "json", "urdf/demo_gripper.urdf.xacro"}, package);
  const auto json = nlohmann::json::parse(json_run.out);
  bool chain = false;
  for (const auto& finding : json.is_array() ? json : json["diagnostics"]) {
    for (const auto& note : finding["notes"])
      chain = chain || (note.dump().find("in macro 'finger' called at") != std::string::npos &&
                        note.dump().find("demo_gripper_macro.xacro") != std::string::npos);
  }
  CHECK(chain);
  const auto sarif = test::run_cli({"--output-format", "sarif", "urdf/demo_gripper.urdf.xacro"}, package);
  const auto log = nlohmann::json::parse(sarif.out);
  const auto& result = log["runs"][0]["results"][0];
  CHECK(result["locations"][0]["physicalLocation"]["artifactLocation"]["uri"].get<std::string>().ends_with(
      "demo_gripper_macro.xacro"));
  REQUIRE(result.contains("relatedLocations"));
  CHECK(result["relatedLocations"].dump().find("demo_gripper.urdf.xacro") != std::string::npos);
}

TEST_CASE("xacro CLI: expand prints the URDF, with arguments", "[xacro][cli]") {
  test::TempDir dir;
  const fs::path package = copy_package(dir);
  const auto plain = test::run_cli({"expand", "urdf/demo_gripper.urdf.xacro"}, package);
  CHECK(plain.exit_code == 0);
  CHECK(plain.out.find("<joint name=\"right_finger_joint\" type=\"revolute\">") != std::string::npos);
  CHECK(plain.out.find("<origin xyz=\"0 -0.0306 0.0549\" rpy=\"0 0 3.141592653589793\"/>") != std::string::npos);
  const auto prefixed = test::run_cli({"expand", "urdf/demo_gripper.urdf.xacro", "--xacro-arg", "prefix:=l_"}, package);
  CHECK(prefixed.out.find("<link name=\"l_base_link\">") != std::string::npos);
  test::write_file(package / "asset-lint.toml", "[xacro]\nargs = { prefix = \"cfg_\" }\n");
  CHECK(test::run_cli({"expand", "urdf/demo_gripper.urdf.xacro"}, package).out.find("cfg_base_link") != std::string::npos);
  // A finding on a value that depends on an argument names it.
  const auto check = test::run_cli({"urdf/demo_gripper.urdf.xacro", "--xacro-arg", "prefix:=l_"}, package);
  CHECK(check.out.find("urdf/demo_gripper_macro.xacro") != std::string::npos);

  const auto broken = test::run_cli({"expand", "urdf/demo_gripper_macro.xacro", "--xacro-arg", "x"}, package);
  CHECK(broken.exit_code == 2);

  const fs::path written = dir.path() / "generated" / "urdf" / "gripper.urdf";  // directories made as xacro makes them
  CHECK(test::run_cli({"expand", "urdf/demo_gripper.urdf.xacro", "-o", written.string()}, package).exit_code == 0);
  CHECK(test::read_file(written).find("<joint name=\"cfg_right_finger_joint\"") != std::string::npos);
}

TEST_CASE("xacro CLI: a suppression comment in the macro file covers every expansion", "[xacro][cli]") {
  test::TempDir dir;
  const fs::path package = copy_package(dir);
  const fs::path macro = package / "urdf" / "demo_gripper_macro.xacro";
  test::write_file(macro, test::replace_once(test::read_file(macro), "      <limit lower=\"0\" upper=\"47\"",
                                             "      <!-- asset-lint: ignore[units-angle-degrees] -->\n      <limit lower=\"0\" upper=\"47\""));
  const auto run = test::run_cli({"urdf/demo_gripper.urdf.xacro"}, package);
  CHECK(run.out.find("units-angle-degrees") == std::string::npos);
}

TEST_CASE("xacro CLI: --fix rewrites the literal in the macro once, and the re-lint is clean of it", "[xacro][cli][fix]") {
  test::TempDir dir;
  const fs::path package = copy_package(dir);
  const fs::path macro = package / "urdf" / "demo_gripper_macro.xacro";
  const std::string before = test::read_file(macro);
  const auto diff = test::run_cli({"--diff", "--unsafe-fixes", "urdf/demo_gripper.urdf.xacro"}, package);
  CHECK(diff.out.find("-      <limit lower=\"0\" upper=\"47\" effort=\"${knuckle_effort}\" velocity=\"2.9\"/>") != std::string::npos);
  CHECK(diff.out.find("+      <limit lower=\"0\" upper=\"0.820305\" effort=\"${knuckle_effort}\" velocity=\"2.9\"/>") !=
        std::string::npos);
  CHECK(test::read_file(macro) == before);

  test::run_cli({"--fix", "--unsafe-fixes", "urdf/demo_gripper.urdf.xacro"}, package);
  CHECK(test::read_file(macro) == test::replace_once(before, "upper=\"47\"", "upper=\"0.820305\""));
  const auto relint = test::run_cli({"urdf/demo_gripper.urdf.xacro"}, package);
  CHECK(relint.out.find("units-angle-degrees") == std::string::npos);
}

TEST_CASE("xacro CLI: a value computed by an expression is never rewritten, and the finding says why", "[xacro][cli][fix]") {
  test::TempDir dir;
  const fs::path package = copy_package(dir);
  const fs::path macro = package / "urdf" / "demo_gripper_macro.xacro";
  test::write_file(macro, test::replace_once(test::read_file(macro), "upper=\"47\"", "upper=\"${40 + 7}\""));
  const auto run = test::run_cli({"urdf/demo_gripper.urdf.xacro"}, package);
  CHECK(run.out.find("note: the value is computed by '${40 + 7}' in the xacro source") != std::string::npos);
  CHECK(run.out.find("No fix through xacro: the value is computed by '${40 + 7}'; asset-lint does not rewrite expressions") !=
        std::string::npos);
}

TEST_CASE("xacro CLI: a value from a property is fixed at the property's definition when every use gets the fix",
          "[xacro][cli][fix]") {
  test::TempDir dir;
  const fs::path package = copy_package(dir);
  const fs::path macro = package / "urdf" / "demo_gripper_macro.xacro";
  std::string source = test::replace_once(test::read_file(macro), "upper=\"47\"", "upper=\"${knuckle_upper}\"");
  source = test::replace_once(source, "  <xacro:property name=\"knuckle_effort\" value=\"24\"/>",
                              "  <xacro:property name=\"knuckle_effort\" value=\"24\"/>\n"
                              "  <xacro:property name=\"knuckle_upper\" value=\"47\"/>");
  test::write_file(macro, source);
  const auto run = test::run_cli({"urdf/demo_gripper.urdf.xacro"}, package);
  CHECK(run.out.find("the value of property 'knuckle_upper', defined at") != std::string::npos);

  test::run_cli({"--fix", "--unsafe-fixes", "urdf/demo_gripper.urdf.xacro"}, package);
  // Both fingers use the property and both get the same fix: the definition is rewritten, once.
  CHECK(test::read_file(macro) ==
        test::replace_once(source, "name=\"knuckle_upper\" value=\"47\"", "name=\"knuckle_upper\" value=\"0.820305\""));
  const auto relint = test::run_cli({"urdf/demo_gripper.urdf.xacro"}, package);
  CHECK(relint.out.find("units-angle-degrees") == std::string::npos);
}

TEST_CASE("xacro CLI: a property whose other uses need no fix is left alone, and the finding says why",
          "[xacro][cli][fix]") {
  test::TempDir dir;
  const fs::path package = copy_package(dir);
  const fs::path macro = package / "urdf" / "demo_gripper_macro.xacro";
  std::string source = test::replace_once(test::read_file(macro), "upper=\"47\"", "upper=\"${knuckle_upper}\"");
  source = test::replace_once(source, "effort=\"${knuckle_effort}\"", "effort=\"${knuckle_upper}\"");
  source = test::replace_once(source, "  <xacro:property name=\"knuckle_effort\" value=\"24\"/>",
                              "  <xacro:property name=\"knuckle_effort\" value=\"24\"/>\n"
                              "  <xacro:property name=\"knuckle_upper\" value=\"47\"/>");
  test::write_file(macro, source);
  const auto run = test::run_cli({"--unsafe-fixes", "urdf/demo_gripper.urdf.xacro"}, package);
  CHECK(run.out.find("No fix through xacro: property 'knuckle_upper' is used 4 times and not every use gets this fix") !=
        std::string::npos);
  test::run_cli({"--fix", "--unsafe-fixes", "urdf/demo_gripper.urdf.xacro"}, package);
  CHECK(test::read_file(macro) == source);
}

// A person edits the macro file, and the editor and the hooks name it: it is checked through the
// top-level file of its package that includes it, at its own lines.
TEST_CASE("xacro CLI: an include-only macro file is checked through its includer", "[xacro][cli][xacro-includers]") {
  test::TempDir dir;
  const fs::path package = copy_package(dir);
  const auto direct = test::run_cli({"urdf/demo_gripper_macro.xacro"}, package);
  CHECK(direct.exit_code == 1);
  CHECK(direct.out.find("urdf-invalid") == std::string::npos);
  CHECK(direct.out.rfind("urdf/demo_gripper_macro.xacro:19:31: error: limits [0, 47] of revolute joint 'left_finger_joint'", 0) ==
        0);
  CHECK(direct.out.find("urdf/demo_gripper.urdf.xacro:5:3: note: in macro 'demo_gripper' called at") != std::string::npos);
  CHECK(direct.out.find("in 1 file.") != std::string::npos);

  // The editor's path: the unsaved buffer is what the includer expands.
  const std::string macro = test::read_file(package / "urdf" / "demo_gripper_macro.xacro");
  const auto buffer = test::run_cli_with_input({"check", "-", "--stdin-filename", "urdf/demo_gripper_macro.xacro"}, package,
                                               test::replace_once(macro, "upper=\"47\"", "upper=\"0.82\""));
  CHECK(buffer.exit_code == 0);
  CHECK(buffer.out.find("No problems found in 1 file.") != std::string::npos);
  const auto stale = test::run_cli_with_input({"check", "-", "--stdin-filename", "urdf/demo_gripper_macro.xacro"}, package,
                                              macro);
  CHECK(stale.out.find("demo_gripper_macro.xacro:19:31: error:") != std::string::npos);

  // Fixes go through it too, and the top-level file named beside it adds no repeats.
  const auto diff = test::run_cli({"--diff", "--unsafe-fixes", "urdf/demo_gripper_macro.xacro"}, package);
  CHECK(diff.out.find("+      <limit lower=\"0\" upper=\"0.820305\"") != std::string::npos);
  const auto both = test::run_cli({"urdf/demo_gripper_macro.xacro", "urdf/demo_gripper.urdf.xacro"}, package);
  CHECK(both.out.find("Found 2 problems") != std::string::npos);

  // A library nothing includes says so instead of checking a robot that is not there.
  test::write_file(package / "urdf" / "spare_macros.xacro",
                   "<robot xmlns:xacro=\"http://ros.org/wiki/xacro\">\n  <xacro:macro name=\"m\"><link name=\"a\"/></xacro:macro>\n</robot>\n");
  const auto orphan = test::run_cli({"urdf/spare_macros.xacro"}, package);
  CHECK(orphan.exit_code == 2);
  CHECK(orphan.err.find("only defines macros and properties, and no top-level .xacro file in '.' includes it") !=
        std::string::npos);
}
