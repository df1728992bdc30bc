// Unit tests of the rules' numbers: exact messages, positions, fix edits and how
// Settings (selection, rule options, severity overrides) change what is reported.
// Every case edits one literal of a small clean gripper (driven finger_joint, 0..47°,
// 24 N·m, 2.9 rad/s, and a mimic finger_tip_joint with gearing -1).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "pipeline/lint.h"

using namespace assetlint;

namespace {

// Line numbers below refer to this text: driven <limit> on line 27, the mimic's <limit>
// on line 33 and its <mimic> on line 34.
const std::string kGripper = R"(<?xml version="1.0"?>
<robot name="gripper">
  <link name="base_link">
    <inertial>
      <mass value="0.636"/>
      <inertia ixx="0.00095" ixy="0" ixz="0" iyy="0.00094" iyz="0" izz="0.00043"/>
    </inertial>
  </link>
  <link name="knuckle">
    <inertial>
      <origin xyz="0 0.03 0.01"/>
      <mass value="0.0311"/>
      <inertia ixx="2.2e-5" ixy="0" ixz="0" iyy="2.0e-5" iyz="0" izz="4.1e-6"/>
    </inertial>
  </link>
  <link name="finger">
    <inertial>
      <origin xyz="0 0 0.01"/>
      <mass value="0.0127"/>
      <inertia ixx="2.1e-6" ixy="0" ixz="0" iyy="2.1e-6" iyz="0" izz="1.3e-6"/>
    </inertial>
  </link>
  <joint name="finger_joint" type="revolute">
    <parent link="base_link"/>
    <child link="knuckle"/>
    <axis xyz="1 0 0"/>
    <limit lower="0" upper="0.820305" effort="24" velocity="2.9"/>
  </joint>
  <joint name="finger_tip_joint" type="revolute">
    <parent link="knuckle"/>
    <child link="finger"/>
    <axis xyz="1 0 0"/>
    <limit lower="-0.820305" upper="0" effort="4" velocity="2.9"/>
    <mimic joint="finger_joint" multiplier="-1" offset="0"/>
  </joint>
</robot>
)";

const std::string kDrivenLimit = R"(<limit lower="0" upper="0.820305" effort="24" velocity="2.9"/>)";
const std::string kMimicLimit = R"(<limit lower="-0.820305" upper="0" effort="4" velocity="2.9"/>)";
const std::string kMimic = R"(<mimic joint="finger_joint" multiplier="-1" offset="0"/>)";

// kGripper with the one occurrence of `from` replaced by `to`.
std::string with(const std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  REQUIRE(text.find(from, at + 1) == std::string::npos);
  std::string out = text;
  out.replace(at, from.size(), to);
  return out;
}
std::string gripper(const std::string& from, const std::string& to) { return with(kGripper, from, to); }

// Byte offset of `needle` inside the first occurrence of `context` in `text`.
std::size_t offset_of(const std::string& text, const std::string& context, const std::string& needle) {
  const auto c = text.find(context);
  REQUIRE(c != std::string::npos);
  const auto n = context.find(needle);
  REQUIRE(n != std::string::npos);
  return c + n;
}

FileReport lint(const std::string& text, const Settings& settings = Settings{}) {
  FileReport report = lint_text("x.urdf", text, settings);
  REQUIRE_FALSE(report.error);
  return report;
}

// Settings that run only the given rules (the mimic follows every edit of finger_joint's
// range, so mimic-limit-conflict would join any change of it).
Settings only(std::vector<std::string> rules) {
  Settings settings;
  settings.selection.select = std::move(rules);
  return settings;
}

std::vector<Diagnostic> of_rule(const FileReport& report, const std::string& rule) {
  std::vector<Diagnostic> out;
  for (const auto& d : report.diagnostics)
    if (d.rule == rule) out.push_back(d);
  return out;
}

std::vector<std::string> rule_ids(const FileReport& report) {
  std::vector<std::string> ids;
  for (const auto& d : report.diagnostics) ids.push_back(d.rule);
  return ids;
}

}  // namespace

TEST_CASE("the base gripper of the rule tests lints clean", "[rules]") {
  CHECK(lint(kGripper).diagnostics.empty());
}

TEST_CASE("units-angle-degrees: the guide's upper=\"47\" and its fix to 0.820305 rad", "[rules]") {
  const std::string text = gripper(kDrivenLimit, R"(<limit lower="0" upper="47" effort="24" velocity="2.9"/>)");
  const FileReport report = lint(text, only({"units-angle-degrees"}));
  REQUIRE(report.diagnostics.size() == 1);
  const Diagnostic& d = report.diagnostics[0];
  CHECK(d.rule == "units-angle-degrees");
  CHECK(d.severity == Severity::Error);
  CHECK(d.span.line == 27);
  CHECK(d.span.column == 29);
  CHECK(d.span.offset == offset_of(text, R"(upper="47")", "47"));
  CHECK(d.span.length == 2);
  CHECK(d.message == "limits [0, 47] of revolute joint 'finger_joint' look like degrees");
  REQUIRE(d.notes.size() == 1);
  CHECK(d.notes[0].message ==
        "URDF limits are radians: 47 rad is 7.48 turns, beyond the 12.57 rad threshold (option min_magnitude_rad)");
  CHECK_FALSE(d.notes[0].span.valid());
  REQUIRE(d.fix);
  CHECK(d.fix->title == "read the limits as degrees and write them in radians: [0, 0.820305]");
  CHECK(d.fix->applicability == Applicability::Unsafe);
  // 0 is 0 in both units: only the degree-looking limit is rewritten.
  REQUIRE(d.fix->edits.size() == 1);
  CHECK(d.fix->edits[0].offset == offset_of(text, R"(upper="47")", "47"));
  CHECK(d.fix->edits[0].length == 2);
  CHECK(d.fix->edits[0].replacement == "0.820305");
  CHECK(text.substr(d.fix->edits[0].offset, d.fix->edits[0].length) == "47");
}

TEST_CASE("units-angle-degrees: positions and edit offsets with a UTF-8 BOM and CRLF line endings", "[rules]") {
  std::string text = "\xEF\xBB\xBF";
  for (char c : gripper(kDrivenLimit, R"(<limit lower="-90" upper="90" effort="24" velocity="2.9"/>)")) {
    if (c == '\n') text += '\r';
    text += c;
  }
  const FileReport report = lint(text, only({"units-angle-degrees"}));
  REQUIRE(report.diagnostics.size() == 1);
  const Diagnostic& d = report.diagnostics[0];
  CHECK(d.rule == "units-angle-degrees");
  // A tie in magnitude points at upper; the column counts neither the BOM nor the '\r'.
  CHECK(d.span.line == 27);
  CHECK(d.span.column == 31);
  CHECK(d.message == "limits [-90, 90] of revolute joint 'finger_joint' look like degrees");
  REQUIRE(d.notes.size() == 1);
  CHECK(d.notes[0].message ==
        "URDF limits are radians: 90 rad is 14.3 turns, beyond the 12.57 rad threshold (option min_magnitude_rad)");
  CHECK(d.fix->title == "read the limits as degrees and write them in radians: [-1.5708, 1.5708]");
  REQUIRE(d.fix);
  REQUIRE(d.fix->edits.size() == 2);
  // Byte offsets include the BOM and every '\r' before the literal.
  CHECK(d.fix->edits[0].offset == offset_of(text, R"(lower="-90")", "-90"));
  CHECK(d.fix->edits[0].replacement == "-1.5708");
  CHECK(d.fix->edits[1].offset == offset_of(text, R"(upper="90")", "90"));
  CHECK(d.fix->edits[1].replacement == "1.5708");
}

TEST_CASE("units-angle-degrees: multiples of pi and small ranges are radians", "[rules]") {
  const Settings settings = only({"units-*"});
  CHECK(lint(gripper(kDrivenLimit, R"(<limit lower="-31.4" upper="31.4" effort="24" velocity="3"/>)"), settings)
            .diagnostics.empty());
  CHECK(lint(gripper(kDrivenLimit, R"(<limit lower="-9.424778" upper="9.424778" effort="24" velocity="6"/>)"), settings)
            .diagnostics.empty());
  CHECK(lint(gripper(kDrivenLimit, R"(<limit lower="-15.707963" upper="15.707963" effort="24" velocity="6"/>)"),
             settings)
            .diagnostics.empty());
  // Just above 4π and not a multiple of π: degrees.
  const auto report = lint(gripper(kDrivenLimit, R"(<limit lower="0" upper="13" effort="24" velocity="2.9"/>)"));
  REQUIRE(of_rule(report, "units-angle-degrees").size() == 1);
  REQUIRE(of_rule(report, "units-angle-degrees")[0].fix->edits.size() == 1);
  CHECK(of_rule(report, "units-angle-degrees")[0].fix->edits[0].replacement == "0.226893");
}

TEST_CASE("units-angle-degrees: the min_magnitude_rad option lowers the threshold", "[rules]") {
  const std::string text = gripper(kDrivenLimit, R"(<limit lower="0" upper="1.5" effort="24" velocity="2.9"/>)");
  CHECK(lint(text, only({"units-angle-degrees"})).diagnostics.empty());

  Settings settings = only({"units-angle-degrees"});
  settings.rule_options["units-angle-degrees"]["min_magnitude_rad"] = 1.0;
  const FileReport report = lint(text, settings);
  REQUIRE(report.diagnostics.size() == 1);
  const Diagnostic& d = report.diagnostics[0];
  CHECK(d.rule == "units-angle-degrees");
  CHECK(d.message == "limits [0, 1.5] of revolute joint 'finger_joint' look like degrees");
  CHECK(d.notes.at(0).message ==
        "URDF limits are radians: 1.5 rad is 0.239 turns, beyond the 1 rad threshold (option min_magnitude_rad)");
  REQUIRE(d.fix);
  REQUIRE(d.fix->edits.size() == 1);
  CHECK(d.fix->edits[0].replacement == "0.0261799");
}

TEST_CASE("mimic-max-velocity: a mimic limited to 1.0 rad/s under a 2.9 rad/s joint, unsafe fix to 2.9", "[rules]") {
  const std::string text = gripper(kMimicLimit, R"(<limit lower="-0.820305" upper="0" effort="4" velocity="1.0"/>)");
  const FileReport report = lint(text);
  REQUIRE(report.diagnostics.size() == 1);
  const Diagnostic& d = report.diagnostics[0];
  CHECK(d.rule == "mimic-max-velocity");
  CHECK(d.severity == Severity::Warning);
  CHECK(d.span.line == 33);
  CHECK(d.span.column == 61);
  CHECK(d.message == "mimic revolute joint 'finger_tip_joint' is limited below the velocity its gearing demands");
  REQUIRE(d.notes.size() == 3);
  CHECK(d.notes[0].message == "Its own limit is 1 rad/s; it must reach 2.9 rad/s.");
  CHECK(d.notes[1].message == "'finger_joint' is limited to 2.9 rad/s; through |multiplier -1| this joint must reach "
                              "2.9 rad/s.");
  REQUIRE(d.fix);
  CHECK(d.fix->title == "raise the limit to 2.9 rad/s");
  CHECK(d.fix->applicability == Applicability::Unsafe);  // raising a limit changes the robot
  REQUIRE(d.fix->edits.size() == 1);
  CHECK(d.fix->edits[0].offset == offset_of(text, R"(velocity="1.0")", "1.0"));
  CHECK(d.fix->edits[0].length == 3);
  CHECK(d.fix->edits[0].replacement == "2.9");
}

TEST_CASE("mimic-max-velocity: the needed speed scales with |multiplier|", "[rules]") {
  // Gearing 2 under 2.9 rad/s needs 5.8 rad/s; 5.8 itself is enough.
  const std::string geared = gripper(kMimic, R"(<mimic joint="finger_joint" multiplier="2" offset="0"/>)");
  const std::string limit3 = R"(<limit lower="-2" upper="2" effort="4" velocity="3"/>)";
  const FileReport report = lint(with(geared, kMimicLimit, limit3));
  const auto found = of_rule(report, "mimic-max-velocity");
  REQUIRE(found.size() == 1);
  CHECK(found[0].fix->edits.at(0).replacement == "5.8");
  CHECK(found[0].fix->title == "raise the limit to 5.8 rad/s");
  const std::string limit58 = R"(<limit lower="-2" upper="2" effort="4" velocity="5.8"/>)";
  CHECK(of_rule(lint(with(geared, kMimicLimit, limit58)), "mimic-max-velocity").empty());
}

TEST_CASE("mimic-limit-conflict: the ros-industrial 2F-85 mimic limits [0, 0.8757] under gearing -1", "[rules]") {
  std::string text = gripper(kDrivenLimit, R"(<limit lower="0" upper="0.8" effort="24" velocity="2"/>)");
  text = with(text, kMimicLimit, R"(<limit lower="0" upper="0.8757" effort="4" velocity="2"/>)");
  const FileReport report = lint(text);
  REQUIRE(report.diagnostics.size() == 1);
  const Diagnostic& d = report.diagnostics[0];
  CHECK(d.rule == "mimic-limit-conflict");
  CHECK(d.severity == Severity::Error);
  CHECK(d.span.line == 33);
  CHECK(d.span.column == 19);
  CHECK(d.message == "'finger_tip_joint' must reach [-0.8, 0] rad to follow 'finger_joint', outside its limits [0, "
                     "0.8757] rad");
  REQUIRE(d.notes.size() == 3);
  CHECK(d.notes[0].message ==
        "'finger_joint' moves over [0, 0.8] rad; the mimic (multiplier -1, offset 0) maps that to [-0.8, 0] rad.");
  // A sign error first (issue 15): the mirrored limits [-0.8757, 0] hold the mapped range.
  REQUIRE(d.fix);
  CHECK(d.fix->title == "mirror the limits of 'finger_tip_joint' to [-0.8757, 0] rad");
  CHECK(d.fix->applicability == Applicability::Unsafe);
  REQUIRE(d.fix->edits.size() == 2);
  CHECK(d.fix->edits[0].offset == offset_of(text, R"(<limit lower="0" upper="0.8757")", "0"));
  CHECK(d.fix->edits[0].replacement == "-0.8757");
  CHECK(d.fix->edits[1].offset == offset_of(text, R"(<limit lower="0" upper="0.8757")", "0.8757"));
  CHECK(d.fix->edits[1].replacement == "0");
}

TEST_CASE("mimic-limit-conflict: offsets shift the mapped range, tolerance option", "[rules]") {
  // q = 1·q_ref + 0.1 maps [0, 0.820305] to [0.1, 0.920305], above upper 0.820305.
  std::string text = gripper(kMimic, R"(<mimic joint="finger_joint" multiplier="1" offset="0.1"/>)");
  text = with(text, kMimicLimit, R"(<limit lower="0" upper="0.820305" effort="4" velocity="2.9"/>)");
  const auto found = of_rule(lint(text), "mimic-limit-conflict");
  REQUIRE(found.size() == 1);
  CHECK(found[0].message == "'finger_tip_joint' must reach [0.1, 0.920305] rad to follow 'finger_joint', outside its "
                             "limits [0, 0.820305] rad");
  // No sign error; the follower holds the leader over [0, 0.720305]: narrow the leader rather
  // than push the follower past its stops.
  REQUIRE(found[0].fix);
  REQUIRE(found[0].fix->edits.size() == 1);
  CHECK(found[0].fix->edits[0].offset == offset_of(text, R"(upper="0.820305" effort="24")", "0.820305"));
  CHECK(found[0].fix->edits[0].replacement == "0.720305");
  CHECK(found[0].fix->title == "narrow the limits of 'finger_joint' to [0, 0.720305] rad");

  // 5e-5 rad of overhang is inside the default tolerance (1e-4) but not inside 1e-6.
  const std::string close = gripper(kMimicLimit, R"(<limit lower="-0.820255" upper="0" effort="4" velocity="2.9"/>)");
  CHECK(of_rule(lint(close), "mimic-limit-conflict").empty());
  Settings strict;
  strict.rule_options["mimic-limit-conflict"]["tolerance"] = 1e-6;
  strict.rule_options["mimic-limit-conflict"]["rounding_fraction"] = 0;
  const auto strict_found = of_rule(lint(close, strict), "mimic-limit-conflict");
  REQUIRE(strict_found.size() == 1);
  CHECK(strict_found[0].fix->title == "narrow the limits of 'finger_joint' to [0, 0.820255] rad");
}

TEST_CASE("limits-inverted: lower above upper, with a swap fix", "[rules]") {
  const std::string text = gripper(kDrivenLimit, R"(<limit lower="0.820305" upper="0" effort="24" velocity="2.9"/>)");
  const FileReport report = lint(text);
  REQUIRE(report.diagnostics.size() == 1);
  const Diagnostic& d = report.diagnostics[0];
  CHECK(d.rule == "limits-inverted");
  CHECK(d.span.line == 27);
  CHECK(d.span.column == 19);
  CHECK(d.message ==
        "revolute joint 'finger_joint' has lower limit 0.8203 rad above upper limit 0 rad");
  CHECK(d.notes.at(0).message == "The joint has no valid position: every pose violates one of its limits.");
  REQUIRE(d.fix);
  CHECK(d.fix->applicability == Applicability::Unsafe);
  REQUIRE(d.fix->edits.size() == 2);
  CHECK(d.fix->edits[0].offset == offset_of(text, R"(lower="0.820305")", "0.820305"));
  CHECK(d.fix->edits[0].replacement == "0");
  CHECK(d.fix->edits[1].offset == offset_of(text, R"(upper="0" effort="24")", "0"));
  CHECK(d.fix->edits[1].replacement == "0.820305");
}

TEST_CASE("units-velocity-implausible: 166 (deg/s) on the 0.82 rad finger, fix to 2.897 rad/s", "[rules]") {
  const std::string text = gripper(kDrivenLimit, R"(<limit lower="0" upper="0.820305" effort="24" velocity="166"/>)");
  // The mimic (2.9 rad/s) is now below 166: silence mimic-max-velocity to isolate the rule.
  Settings settings;
  settings.selection.select = {"units-velocity-implausible"};
  const FileReport report = lint(text, settings);
  REQUIRE(report.diagnostics.size() == 1);
  const Diagnostic& d = report.diagnostics[0];
  CHECK(d.rule == "units-velocity-implausible");
  CHECK(d.severity == Severity::Warning);
  CHECK(d.span.line == 27);
  CHECK(d.span.column == 61);
  CHECK(d.message == "velocity limit 166 rad/s of revolute joint 'finger_joint' is implausibly fast");
  REQUIRE(d.notes.size() == 2);
  CHECK(d.notes[0].message == "It would cross its 0.8203 rad range in 4.94 ms (less than 20 ms).");
  CHECK(d.notes[1].message == "Read as deg/s it is 2.897 rad/s and takes 283 ms: it was probably written in deg/s.");
  REQUIRE(d.fix);
  CHECK(d.fix->title == "convert the velocity limit from deg/s to rad/s: write 2.897 rad/s");
  CHECK(d.fix->applicability == Applicability::Unsafe);
  REQUIRE(d.fix->edits.size() == 1);
  CHECK(d.fix->edits[0].offset == offset_of(text, R"(velocity="166")", "166"));
  CHECK(d.fix->edits[0].length == 3);
  CHECK(d.fix->edits[0].replacement == "2.897");
  // Without the selection, the mimic's 2.9 rad/s is reported too: 2.9 < |−1| × 166.
  CHECK(rule_ids(lint(text)) == std::vector<std::string>{"units-velocity-implausible", "mimic-max-velocity"});
}

TEST_CASE("units-velocity-implausible: placeholders and a legit fast joint, max_angular_velocity option", "[rules]") {
  Settings only;
  only.selection.select = {"units-velocity-*"};
  for (const std::string velocity : {"1000", "1e9"}) {
    const auto report = lint(
        gripper(kDrivenLimit, R"(<limit lower="0" upper="0.820305" effort="24" velocity=")" + velocity + R"("/>)"),
        only);
    REQUIRE(report.diagnostics.size() == 1);
    CHECK(report.diagnostics[0].message.find("is a placeholder, not a measured limit") != std::string::npos);
    CHECK(report.diagnostics[0].severity == Severity::Info);
    CHECK_FALSE(report.diagnostics[0].fix);
  }
  // 30 rad/s over 0.5 rad: 16.7 ms, faster than 20 ms, but under the 50 rad/s bound.
  const std::string legit = gripper(kDrivenLimit, R"(<limit lower="0" upper="0.5" effort="24" velocity="30"/>)");
  CHECK(lint(legit, only).diagnostics.empty());
  Settings lower_bound = only;
  lower_bound.rule_options["units-velocity-implausible"]["max_angular_velocity"] = 20.0;
  const auto report = lint(legit, lower_bound);
  REQUIRE(report.diagnostics.size() == 1);
  REQUIRE(report.diagnostics[0].fix);
  CHECK(report.diagnostics[0].fix->edits.at(0).replacement == "0.5236");  // 30 deg/s
}

TEST_CASE("inertia-invalid: triangle inequality numbers and the triangle_tolerance option", "[rules]") {
  const std::string text = gripper(R"(iyy="2.0e-5")", R"(iyy="4e-6")");
  const FileReport report = lint(text);
  REQUIRE(report.diagnostics.size() == 1);
  const Diagnostic& d = report.diagnostics[0];
  CHECK(d.rule == "inertia-invalid");
  CHECK(d.severity == Severity::Error);
  CHECK(d.span.line == 13);
  CHECK(d.span.column == 7);
  CHECK(d.message == "inertia of link 'knuckle' violates the triangle inequality");
  REQUIRE(d.notes.size() == 3);
  CHECK(d.notes[0].message == "Principal moments [4e-6, 4.1e-6, 2.2e-5] kg·m²: 2.2e-5 > 4e-6 + 4.1e-6.");
  // MuJoCo's compiler refuses the file on it: the finding says so.
  CHECK(d.notes[2].message ==
        "MuJoCo's compiler refuses the file at this link: \"inertia must satisfy A + B >= C; use 'balanceinertia' to "
        "fix\" (mjCBody::Compile).");
  CHECK_FALSE(d.fix);

  Settings loose;
  loose.rule_options["inertia-invalid"]["triangle_tolerance"] = 2.0;  // 2.2e-5 <= 8.1e-6 × 3
  CHECK(lint(text, loose).diagnostics.empty());
}

TEST_CASE("inertia-invalid: a non-positive-definite tensor reports its principal moments", "[rules]") {
  // [[2.2e-5, 3e-5], [3e-5, 2e-5]] has eigenvalues 2.1e-5 ± 3.0017e-5.
  const auto report = lint(gripper(R"(ixy="0" ixz="0" iyy="2.0e-5")", R"(ixy="3e-5" ixz="0" iyy="2.0e-5")"));
  REQUIRE(report.diagnostics.size() == 1);
  CHECK(report.diagnostics[0].message == "inertia of link 'knuckle' has a negative principal moment -9.017e-6 kg·m²");
  REQUIRE(!report.diagnostics[0].notes.empty());
  CHECK(report.diagnostics[0].notes[0].message ==
        "Principal moments [-9.017e-6, 4.1e-6, 5.102e-5] kg·m² (mass 0.0311 kg); every moment of a real body is "
        "positive.");
}

TEST_CASE("inertia-invalid: a massless or missing inertial on a moving link", "[rules]") {
  const auto zero = lint(gripper(R"(<mass value="0.0127"/>)", R"(<mass value="0"/>)"));
  REQUIRE(zero.diagnostics.size() == 1);
  CHECK(zero.diagnostics[0].span.line == 19);
  CHECK(zero.diagnostics[0].message == "link 'finger' moves but its mass is 0 kg");
  REQUIRE(zero.diagnostics[0].notes.size() == 2);
  CHECK(zero.diagnostics[0].notes[0].message ==
        "It is part of the body moved by revolute joint 'finger_tip_joint', and no link of that body has a positive "
        "mass.");
  CHECK(zero.diagnostics[0].notes[1].message.rfind("MuJoCo refuses the file: its compiler rejects a moving body "
                                                   "without mass",
                                                   0) == 0);

  // A root link without mass does not move: nothing to report.
  CHECK(lint(gripper(R"(<mass value="0.636"/>)", R"(<mass value="0"/>)")).diagnostics.empty());
}

TEST_CASE("drive-max-force: sentinels and placeholders are infos without a spec, mimics are not driven", "[rules]") {
  const std::string zero = gripper(kDrivenLimit, R"(<limit lower="0" upper="0.820305" effort="0" velocity="2.9"/>)");
  const auto report = lint(zero);
  REQUIRE(report.diagnostics.size() == 1);
  const Diagnostic& sentinel = report.diagnostics[0];
  CHECK(sentinel.rule == "drive-max-force");
  // The joint the mimic follows: its effort is the grip, so even without a spec a warning.
  CHECK(sentinel.severity == Severity::Warning);
  CHECK(sentinel.span.line == 27);
  CHECK(sentinel.span.column == 47);
  CHECK(sentinel.span.offset == offset_of(zero, R"(effort="0")", "0"));
  // No [drives] table and no spec: the joint is not called driven.
  CHECK(sentinel.message == "effort 0 N·m of revolute joint 'finger_joint' is a sentinel: unbounded in Isaac Sim, zero elsewhere");
  REQUIRE(sentinel.notes.size() == 2);
  CHECK(sentinel.notes[0].message.find("Isaac Sim's URDF importer reads effort ≤ 0 as no limit") == 0);
  CHECK(sentinel.notes[1].message.find("It is the joint the gripper's mimic joints follow") == 0);

  CHECK(lint(gripper(kMimicLimit, R"(<limit lower="-0.820305" upper="0" effort="0" velocity="2.9"/>)")).diagnostics.empty());

  // 1000 alone on the driven joint (the mimic says 4): neither ≥ placeholder_force nor repeated.
  const std::string thousand =
      gripper(kDrivenLimit, R"(<limit lower="0" upper="0.820305" effort="1000" velocity="2.9"/>)");
  CHECK(lint(thousand).diagnostics.empty());
  Settings settings;
  settings.rule_options["drive-max-force"]["placeholder_force"] = 1000.0;
  const auto placeholder = lint(thousand, settings);
  REQUIRE(placeholder.diagnostics.size() == 1);
  CHECK(placeholder.diagnostics[0].severity == Severity::Warning);  // the mimic's leader: the grip
  CHECK(placeholder.diagnostics[0].message == "effort 1000 N·m of revolute joint 'finger_joint' looks like a placeholder");
  CHECK(placeholder.diagnostics[0].notes.at(0).message ==
        "At or above placeholder_force 1000, the bound is effectively no bound.");

  // The same round 1000 on the mimic too: the ros-industrial pattern, found without the option.
  const std::string both = gripper(kMimicLimit, R"(<limit lower="-0.820305" upper="0" effort="1000" velocity="2.9"/>)");
  std::string repeated = both;
  repeated.replace(repeated.find(R"(effort="24")"), 11, R"(effort="1000")");
  const auto pattern = lint(repeated);
  REQUIRE(pattern.diagnostics.size() == 1);
  CHECK(pattern.diagnostics[0].message == "effort 1000 N·m of revolute joint 'finger_joint' looks like a placeholder");
  CHECK(pattern.diagnostics[0].notes.at(0).message ==
        "The same round 1000 is on 1 other joint of the file: a value written for every joint, not a motor's rating.");
}

TEST_CASE("severity overrides change only the named rules", "[rules]") {
  std::string text = gripper(kDrivenLimit, R"(<limit lower="0" upper="47" effort="0" velocity="2.9"/>)");
  Settings settings = only({"units-angle-degrees", "drive-max-force"});
  settings.severity_overrides["drive-max-force"] = Severity::Error;
  settings.severity_overrides["units-angle-degrees"] = Severity::Info;
  const auto report = lint(text, settings);
  REQUIRE(rule_ids(report) == std::vector<std::string>{"units-angle-degrees", "drive-max-force"});
  CHECK(report.diagnostics[0].severity == Severity::Info);
  CHECK(report.diagnostics[1].severity == Severity::Error);
  const auto plain = lint(text, only({"units-angle-degrees", "drive-max-force"}));
  CHECK(plain.diagnostics.at(0).severity == Severity::Error);
  // effort 0 on the joint a mimic follows: the grip itself, a warning even without a spec
  CHECK(plain.diagnostics.at(1).severity == Severity::Warning);
}

TEST_CASE("selection: --select and --ignore globs over check and reader rules", "[rules]") {
  // A mimic that is both too slow (1.0 rad/s) and outside the mapped range ([0, 0.8757] under -1).
  const std::string text =
      gripper(kMimicLimit, R"(<limit lower="0" upper="0.8757" effort="4" velocity="1.0"/>)");
  CHECK(rule_ids(lint(text)) == std::vector<std::string>{"mimic-limit-conflict", "mimic-max-velocity"});

  Settings ignore;
  ignore.selection.ignore = {"mimic-*"};
  CHECK(lint(text, ignore).diagnostics.empty());

  Settings select;
  select.selection.select = {"mimic-max-*"};
  CHECK(rule_ids(lint(text, select)) == std::vector<std::string>{"mimic-max-velocity"});

  Settings both;
  both.selection.select = {"mimic-*"};
  both.selection.ignore = {"mimic-limit-conflict"};
  CHECK(rule_ids(lint(text, both)) == std::vector<std::string>{"mimic-max-velocity"});

  // Reader rules obey the selection too.
  const std::string prefixed = "log: robot_description\n" + kGripper;
  CHECK(rule_ids(lint(prefixed)) == std::vector<std::string>{"parse-error"});
  Settings no_parse;
  no_parse.selection.ignore = {"parse-*"};
  CHECK(lint(prefixed, no_parse).diagnostics.empty());
}

TEST_CASE("parse-error: trailing NUL bytes and text before <?xml are located exactly", "[rules]") {
  const auto one = lint(kGripper + std::string(1, '\0'));
  REQUIRE(one.diagnostics.size() == 1);
  CHECK(one.diagnostics[0].rule == "parse-error");
  CHECK(one.diagnostics[0].span.line == 37);
  CHECK(one.diagnostics[0].span.column == 1);
  CHECK(one.diagnostics[0].span.offset == kGripper.size());
  CHECK(one.diagnostics[0].message == "1 NUL byte after the root element; strict XML parsers reject the file");

  const auto two = lint(kGripper + std::string(2, '\0') + "\n");
  REQUIRE(two.diagnostics.size() == 1);
  CHECK(two.diagnostics[0].span.length == 2);
  CHECK(two.diagnostics[0].message == "2 NUL bytes after the root element; strict XML parsers reject the file");

  const auto prefixed = lint("  junk\n" + kGripper);
  REQUIRE(prefixed.diagnostics.size() == 1);
  CHECK(prefixed.diagnostics[0].span.line == 1);
  CHECK(prefixed.diagnostics[0].span.column == 3);
  CHECK(prefixed.diagnostics[0].span.length == 4);
  CHECK(prefixed.diagnostics[0].message ==
        "text before the XML document: 'junk'; an XML file must start with '<?xml' or an element");
}

TEST_CASE("structure rules: undefined links and mimic references name the right literal", "[rules]") {
  const std::string orphan = gripper(R"(<parent link="knuckle"/>)", R"(<parent link="palm"/>)");
  const auto undefined = of_rule(lint(orphan), "structure-undefined-link");
  REQUIRE(undefined.size() == 1);
  CHECK(undefined[0].span.line == 30);
  CHECK(undefined[0].span.column == 19);
  CHECK(undefined[0].message == "parent link 'palm' of revolute joint 'finger_tip_joint' is not defined");

  const std::string chain_text =
      gripper(kMimic, R"(<mimic joint="finger_tip_joint" multiplier="1" offset="0"/>)");
  const auto itself = of_rule(lint(chain_text), "structure-mimic-reference");
  REQUIRE(itself.size() == 1);
  CHECK(itself[0].span.line == 34);
  CHECK(itself[0].span.column == 19);
  CHECK(itself[0].message == "revolute joint 'finger_tip_joint' mimics itself");

  const auto missing = lint(gripper(kMimic, R"(<mimic joint="knuckle_joint" multiplier="-1" offset="0"/>)"));
  REQUIRE(of_rule(missing, "structure-mimic-reference").size() == 1);
  CHECK(of_rule(missing, "structure-mimic-reference")[0].message ==
        "revolute joint 'finger_tip_joint' mimics joint 'knuckle_joint', which is not defined");
}
