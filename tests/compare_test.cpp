// `asset-lint compare`: name pairing, the three Robotiq fixtures agreeing, each planted
// unit slip found and named, and the Robotiq corpus pair.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <regex>
#include <sstream>

#include "commands/compare.h"
#include "commands/compare_names.h"
#include "report/text_reporter.h"
#include "test_support.h"

using namespace assetlint;
using namespace assetlint::commands;

namespace {

const Settings& no_settings(const std::string&) {
  static const Settings settings;
  return settings;
}

std::string rendered(const FileReport& report) {
  std::ostringstream out;
  write_text(out, {report}, TextOptions{false, false});
  return out.str();
}

FileReport compare(const std::vector<std::string>& paths, CompareOptions options = {}) {
  std::string error;
  FileReport report = compare_files(paths, no_settings, options, error);
  INFO(error);
  REQUIRE(error.empty());
  return report;
}

const std::string kUrdf = (test::fixtures_dir() / "robotiq_2f85" / "robotiq_2f85.urdf").string();
const std::string kUsda = (test::fixtures_dir() / "usda" / "robotiq_2f85" / "robotiq_2f85.usda").string();
const std::string kMjcf = (test::fixtures_dir() / "mjcf" / "robotiq_2f85" / "robotiq_2f85.xml").string();

// A copy of `source` in `dir` with `from` replaced by `to` (which must occur).
std::string planted(const test::TempDir& dir, const std::string& source, const std::string& from, const std::string& to) {
  std::string text = test::read_file(source);
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), to);
  const auto path = dir.path() / std::filesystem::path(source).filename();
  test::write_file(path, text);
  return path.string();
}

}  // namespace

TEST_CASE("names pair exactly, by last path component, then without shared prefixes and suffixes", "[compare]") {
  const NameMatch m = match_names({"finger_joint", "/robot/joints/wrist", "extra"},
                                  {"/g/joints/finger_joint", "wrist", "other_x", "mapped"}, {{"extra", "mapped"}});
  REQUIRE(m.pairs.size() == 3);
  CHECK(m.pairs[0] == std::pair<std::size_t, std::size_t>{0, 0});
  CHECK(m.pairs[1] == std::pair<std::size_t, std::size_t>{1, 1});
  CHECK(m.pairs[2] == std::pair<std::size_t, std::size_t>{2, 3});
  CHECK(m.only_a.empty());
  CHECK(m.only_b == std::vector<std::size_t>{2});
  // Every name of the first file starts with "robotiq_85_"; suffixes go too.
  const NameMatch prefixed = match_names({"robotiq_85_left_knuckle_joint", "robotiq_85_right_knuckle_joint", "robotiq_85_tip"},
                                         {"left_knuckle", "Right_Knuckle_Link", "base"}, {});
  REQUIRE(prefixed.pairs.size() == 2);
  CHECK(prefixed.pairs[0] == std::pair<std::size_t, std::size_t>{0, 0});
  CHECK(prefixed.pairs[1] == std::pair<std::size_t, std::size_t>{1, 1});
  CHECK(prefixed.only_a == std::vector<std::size_t>{2});
}

TEST_CASE("the URDF, USDA and MJCF Robotiq fixtures describe the same gripper", "[compare]") {
  // The USDA fixture writes degrees to 5 digits (166.16 deg/s for 2.9 rad/s): 1e-4.
  CompareOptions loose;
  loose.rtol = 1e-4;
  const FileReport three = compare({kUrdf, kUsda, kMjcf}, loose);
  INFO(rendered(three));
  CHECK(three.diagnostics.empty());

  std::string error;
  std::vector<ComparisonSummary> summaries;
  compare_files({kUrdf, kMjcf}, no_settings, loose, error, &summaries);
  REQUIRE(summaries.size() == 1);
  const auto lines = summary_lines(summaries.front());
  REQUIRE(lines.size() == 3);
  CHECK(lines[0] == "compare: robotiq_2f85.urdf (URDF) and robotiq_2f85.xml (MJCF)");
  CHECK(summaries.front().joints_paired > 0);
  CHECK(summaries.front().values_compared > summaries.front().joints_paired);
  CHECK(lines[2] == fmt::format("  all {} compared values agree", summaries.front().values_compared));
}

TEST_CASE("compare finds each planted slip and names it", "[compare]") {
  test::TempDir dir;
  CompareOptions loose;
  loose.rtol = 1e-4;
  SECTION("limits in degrees in the URDF") {
    const auto urdf = planted(dir, kUrdf, R"(<limit lower="0" upper="0.820305" effort="24")", R"(<limit lower="0" upper="47" effort="24")");
    const FileReport r = compare({urdf, kMjcf}, loose);
    INFO(rendered(r));
    REQUIRE(r.diagnostics.size() == 1);
    CHECK(r.diagnostics[0].message ==
          "upper limit of 'finger_joint' differs: 47 rad vs 0.8203 rad: a degree/radian slip (ratio 180/π)");
    CHECK(r.source(r.diagnostics[0].span.file).path() == urdf);
    REQUIRE(r.diagnostics[0].notes.size() == 4);
    CHECK(r.source(r.diagnostics[0].notes[0].span.file).path() == kMjcf);
    CHECK(r.diagnostics[0].notes[2].message.find("47 deg as written (0.820305 rad in model units)") != std::string::npos);
  }
  SECTION("stiffness per radian written into USD's per-degree field") {
    const auto usda = planted(dir, kUsda, "drive:angular:physics:stiffness = 4.8", "drive:angular:physics:stiffness = 275");
    const FileReport r = compare({kMjcf, usda}, loose);
    INFO(rendered(r));
    REQUIRE(r.diagnostics.size() == 1);
    CHECK(r.diagnostics[0].message ==
          "drive stiffness of 'finger_joint' differs: 275 N·m/rad vs 15760 N·m/rad: a degree/radian slip (ratio 180/π)");
  }
  SECTION("flipped gearing") {
    const auto usda = planted(dir, kUsda, "physxMimicJoint:rotX:gearing = 1", "physxMimicJoint:rotX:gearing = -1");
    const FileReport r = compare({kUrdf, usda}, loose);
    INFO(rendered(r));
    REQUIRE(r.diagnostics.size() == 1);
    CHECK(r.diagnostics[0].message == "mimic multiplier of 'left_inner_finger_joint' differs: -1 vs 1: a sign flip");
    CHECK(r.diagnostics[0].notes.back().message.starts_with("USD gearing is −(URDF multiplier)"));
  }
  SECTION("armature lost") {
    const auto mjcf = planted(dir, kMjcf, R"(<joint name="finger_joint" range="0 47"/>)",
                              R"(<joint name="finger_joint" range="0 47" armature="0.005"/>)");
    const FileReport r = compare({mjcf, kUsda}, loose);
    INFO(rendered(r));
    REQUIRE(r.diagnostics.size() == 1);
    CHECK(r.diagnostics[0].message == "armature of 'finger_joint' differs: 0.005 kg·m² vs 0 kg·m²");
  }
  SECTION("mass times 1000") {
    const auto urdf = planted(dir, kUrdf, R"(<mass value="0.636"/>)", R"(<mass value="636"/>)");
    const FileReport r = compare({urdf, kMjcf}, loose);
    INFO(rendered(r));
    REQUIRE(r.diagnostics.size() == 1);
    CHECK(r.diagnostics[0].message == "mass of link 'base_link' differs: 636 kg vs 0.636 kg: a factor of 1000 (mm/m or g/kg)");
  }
  SECTION("a missing mimic") {
    const auto mjcf = planted(dir, kMjcf,
                              R"(<joint joint1="right_inner_knuckle_joint" joint2="finger_joint" polycoef="0 1 0 0 0"/>)", "");
    const FileReport r = compare({kUrdf, mjcf}, loose);
    INFO(rendered(r));
    REQUIRE(r.diagnostics.size() == 1);
    CHECK(r.diagnostics[0].message == "'right_inner_knuckle_joint' follows 'finger_joint' in URDF only");
  }
}

TEST_CASE("compare pairs the Robotiq corpus URDF with Robotiq's USD stack", "[compare][corpus]") {
  const auto dir = test::corpus_dir();
  if (dir.empty()) {
    WARN("../shared/corpus is absent: skipped");
    return;
  }
  const auto urdf = (dir / "urdf" / "robotiq2f85__rosindustrial_arg2f_85_model.urdf").string();
  const auto usda = (dir / "usda" / "robotiq_2f85" / "configuration" / "Robotiq_2F_85_config_physics_parallel_grip.usda").string();
  // The configuration layer composes payloads beside its own directory: the stack is the tree.
  Settings settings;
  settings.trees.push_back((dir / "usda" / "robotiq_2f85").string());
  std::string error;
  std::vector<ComparisonSummary> summaries;
  const FileReport r =
      compare_files({urdf, usda}, [&](const std::string&) -> const Settings& { return settings; }, {}, error, &summaries);
  REQUIRE(error.empty());
  REQUIRE(summaries.size() == 1);
  // The few lines at the head of the report say what differs: the ros-industrial URDF's
  // 2 rad/s and 1000 N·m placeholders against Robotiq's tuned values, its 0.8 rad stroke
  // against USD's 47°, the lost armature, and the right inner finger flipped (axis and
  // multiplier both negated: a sign flip each).
  const std::vector<std::string> lines = summary_lines(summaries.front());
  CHECK(lines == std::vector<std::string>{
                     "compare: robotiq2f85__rosindustrial_arg2f_85_model.urdf (URDF) and "
                     "Robotiq_2F_85_config_physics_parallel_grip.usda (USD)",
                     "  paired 4 movable joints and 8 links by name; 2 joints and 3 links only in the URDF, 2 joints "
                     "and 1 link only in the USD",
                     "  15 of 25 compared values differ: max velocity ×4, upper limit ×4, armature ×2, lower limit ×2, "
                     "axis ×1 (a sign flip), max force ×1, mimic multiplier ×1 (a sign flip)"});
  std::size_t mismatches = 0;
  for (const Diagnostic& d : r.diagnostics) mismatches += d.rule == "compare-mismatch";
  CHECK(mismatches == summaries.front().differing());
}
