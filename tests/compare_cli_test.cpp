// `asset-lint compare` on the command line: exit status, report formats, --fix-side.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "test_support.h"

using assetlint::test::read_file;
using assetlint::test::run_cli;
using assetlint::test::TempDir;
using assetlint::test::write_file;

namespace {

const auto kFixtures = assetlint::test::fixtures_dir();

// The URDF fixture with finger_joint's upper limit written in degrees.
std::string slipped_urdf() {
  std::string text = read_file(kFixtures / "robotiq_2f85" / "robotiq_2f85.urdf");
  const std::string from = R"(<limit lower="0" upper="0.820305" effort="24")";
  text.replace(text.find(from), from.size(), R"(<limit lower="0" upper="47" effort="24")");
  return text;
}

}  // namespace

TEST_CASE("compare exits 0 when the files agree and 1 with a named slip", "[compare][cli]") {
  TempDir dir;
  write_file(dir.path() / "gripper.urdf", read_file(kFixtures / "robotiq_2f85" / "robotiq_2f85.urdf"));
  write_file(dir.path() / "gripper.xml", read_file(kFixtures / "mjcf" / "robotiq_2f85" / "robotiq_2f85.xml"));
  auto same = run_cli({"compare", "gripper.urdf", "gripper.xml"}, dir.path());
  INFO(same.out << same.err);
  CHECK(same.exit_code == 0);

  write_file(dir.path() / "gripper.urdf", slipped_urdf());
  auto differ = run_cli({"compare", "gripper.urdf", "gripper.xml"}, dir.path());
  INFO(differ.out << differ.err);
  CHECK(differ.exit_code == 1);
  CHECK(differ.out.find("gripper.urdf:61:29: error: upper limit of 'finger_joint' differs: 47 rad vs 0.8203 rad: a "
                        "degree/radian slip (ratio 180/π) [compare-mismatch]") != std::string::npos);
  CHECK(differ.out.find("  gripper.xml:27:45: note: the counterpart in gripper.xml (MJCF)") != std::string::npos);

  auto json = run_cli({"compare", "--output-format", "json", "gripper.urdf", "gripper.xml"}, dir.path());
  CHECK(json.exit_code == 1);
  const auto parsed = nlohmann::json::parse(json.out);
  CHECK(parsed.dump().find("compare-mismatch") != std::string::npos);
}

TEST_CASE("compare --fix-side rewrites the named file in its own units", "[compare][cli]") {
  TempDir dir;
  write_file(dir.path() / "gripper.urdf", slipped_urdf());
  write_file(dir.path() / "gripper.xml", read_file(kFixtures / "mjcf" / "robotiq_2f85" / "robotiq_2f85.xml"));
  CHECK(run_cli({"compare", "--fix", "gripper.urdf", "gripper.xml"}, dir.path()).exit_code == 2);  // no side named
  auto fixed = run_cli({"compare", "--fix-side", "gripper.urdf", "--fix", "gripper.urdf", "gripper.xml"}, dir.path());
  INFO(fixed.out << fixed.err);
  CHECK(fixed.exit_code == 0);
  CHECK(read_file(dir.path() / "gripper.urdf").find(R"(upper="0.820305" effort="24")") != std::string::npos);
  // And the other way round: the MJCF side gets the URDF's value in degrees.
  write_file(dir.path() / "gripper.urdf", slipped_urdf());
  auto other = run_cli({"compare", "--fix-side", "gripper.xml", "--fix", "gripper.urdf", "gripper.xml"}, dir.path());
  CHECK(other.exit_code == 0);
  CHECK(read_file(dir.path() / "gripper.xml").find(R"(<joint name="finger_joint" range="0 2692.9"/>)") != std::string::npos);
}
