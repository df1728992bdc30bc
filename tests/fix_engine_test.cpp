// The fixer's building blocks and its loop: edit conflicts and application, unified
// diffs, fix selection, re-lint rounds, dropped fixes, convergence, edit scope.
#include <catch2/catch.hpp>

#include <filesystem>

#include "engine/file_system.h"
#include "fix/diff.h"
#include "fix/edits.h"
#include "fix/fixer.h"
#include "test_support.h"

using namespace assetlint;
using namespace assetlint::fix;

namespace {

Edit edit(std::size_t offset, std::size_t length, std::string replacement, FileId file = 0) {
  return Edit{file, offset, length, std::move(replacement)};
}

// A small URDF with one unsafe-fixable finding (upper="47" in degrees) and nothing else.
const std::string kDegrees = R"(<?xml version="1.0"?>
<!-- a comment -->
<robot name="r">
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="finger"><inertial><mass value="0.1"/><inertia ixx="1e-5" ixy="0" ixz="0" iyy="1e-5" iyz="0" izz="1e-5"/></inertial></link>
  <joint name="j" type="revolute">
    <parent link="base"/><child link="finger"/>
    <limit lower="0" upper="47" effort="10" velocity="2"/>
  </joint>
</robot>
)";

// A FileSystem holding files in memory only.
class MemoryFiles final : public FileSystem {
 public:
  std::map<std::string, std::string> files;
  std::optional<std::string> read(const std::string& path, std::string& error) const override {
    if (auto it = files.find(path); it != files.end()) return it->second;
    error = "No such file or directory";
    return std::nullopt;
  }
};

std::size_t offset_of(const std::string& text, const std::string& needle) {
  const auto pos = text.find(needle);
  REQUIRE(pos != std::string::npos);
  return pos;
}

}  // namespace

TEST_CASE("fix: edits conflict when they overlap or touch at the same offset", "[fix]") {
  CHECK(edits_conflict(edit(0, 5, "x"), edit(4, 2, "y")));
  CHECK(edits_conflict(edit(4, 2, "y"), edit(0, 5, "x")));
  CHECK(edits_conflict(edit(3, 0, "a"), edit(3, 0, "b")));    // two insertions at one place
  CHECK(edits_conflict(edit(3, 0, "a"), edit(3, 4, "b")));    // insertion where an edit starts
  CHECK(edits_conflict(edit(7, 0, "a"), edit(3, 4, "b")));    // insertion where an edit ends
  CHECK(edits_conflict(edit(2, 6, "a"), edit(4, 0, "b")));    // insertion inside an edit
  CHECK(edits_conflict(edit(2, 3, "a"), edit(2, 3, "a")));    // the same edit twice
  CHECK_FALSE(edits_conflict(edit(0, 5, "x"), edit(5, 2, "y")));  // adjacent replacements
  CHECK_FALSE(edits_conflict(edit(0, 2, "x"), edit(8, 2, "y")));
  CHECK_FALSE(edits_conflict(edit(0, 5, "x", 0), edit(0, 5, "y", 1)));  // different files
  CHECK(edit_lists_conflict({edit(0, 1, ""), edit(10, 1, "")}, {edit(10, 2, "")}));
  CHECK_FALSE(edit_lists_conflict({edit(0, 1, ""), edit(10, 1, "")}, {edit(5, 2, "")}));
}

TEST_CASE("fix: apply_edits replaces exactly the edited bytes", "[fix]") {
  const std::string text = "\xEF\xBB\xBFline one\r\nlower=\"47\" upper='90'\r\n\0tail";
  CHECK(apply_edits(text, {}) == text);
  const std::size_t a = text.find("47"), b = text.find("90");
  // Given out of order; one shrinks, one grows.
  CHECK(apply_edits(text, {edit(b, 2, "1.5708"), edit(a, 2, "0")}) ==
        "\xEF\xBB\xBFline one\r\nlower=\"0\" upper='1.5708'\r\n\0tail");
  CHECK(apply_edits("abc", {edit(0, 0, "<"), edit(3, 0, ">")}) == "<abc>");
  CHECK(apply_edits("abc", {edit(0, 3, "")}) == "");
  CHECK_THROWS_AS(apply_edits("abc", {edit(2, 2, "x")}), std::invalid_argument);
  CHECK_THROWS_AS(apply_edits("abcdef", {edit(0, 3, "x"), edit(2, 2, "y")}), std::invalid_argument);
  CHECK(edits_fit({edit(0, 3, "x"), edit(3, 1, "y")}, "abcd"));
  CHECK_FALSE(edits_fit({edit(0, 3, "x"), edit(2, 1, "y")}, "abcd"));
  CHECK_FALSE(edits_fit({edit(4, 1, "x")}, "abcd"));
  CHECK(edits_fit({edit(4, 0, "x")}, "abcd"));
}

TEST_CASE("fix: unified_diff matches diff -u", "[fix]") {
  CHECK(unified_diff("same\n", "same\n", "a/x", "b/x").empty());
  std::string before, after;
  for (int i = 1; i <= 20; ++i) {
    before += "line " + std::to_string(i) + "\n";
    after += (i == 5 ? "LINE 5" : i == 16 ? "LINE 16" : "line " + std::to_string(i)) + "\n";
  }
  after += "line 21\n";
  // Changes 10 lines apart (> 2×3 context) make two hunks; the insertion at the end
  // joins the second.
  CHECK(unified_diff(before, after, "a/f.urdf", "b/f.urdf") ==
        "--- a/f.urdf\n+++ b/f.urdf\n"
        "@@ -2,7 +2,7 @@\n line 2\n line 3\n line 4\n-line 5\n+LINE 5\n line 6\n line 7\n line 8\n"
        "@@ -13,8 +13,9 @@\n line 13\n line 14\n line 15\n-line 16\n+LINE 16\n line 17\n line 18\n line 19\n"
        " line 20\n+line 21\n");
  // Changes at most 2×3 lines apart share one hunk.
  CHECK(unified_diff("1\n2\n3\n4\n5\n6\n7\n8\n9\n", "1\nX\n3\n4\n5\n6\n7\nY\n9\n", "a", "b") ==
        "--- a\n+++ b\n@@ -1,9 +1,9 @@\n 1\n-2\n+X\n 3\n 4\n 5\n 6\n 7\n-8\n+Y\n 9\n");
  // Single-line ranges drop the count; an empty side names the line before it.
  CHECK(unified_diff("a\n", "b\n", "a", "b") == "--- a\n+++ b\n@@ -1 +1 @@\n-a\n+b\n");
  CHECK(unified_diff("", "new\n", "a", "b") == "--- a\n+++ b\n@@ -0,0 +1 @@\n+new\n");
  // No newline at the end; CRLF kept as it is.
  CHECK(unified_diff("x\r\ny", "x\r\nz", "a", "b") ==
        "--- a\n+++ b\n@@ -1,2 +1,2 @@\n x\r\n-y\n\\ No newline at end of file\n+z\n\\ No newline at end of file\n");
}

TEST_CASE("fix: fix_file applies unsafe fixes only when asked, in memory", "[fix]") {
  MemoryFiles files;
  files.files["robot.urdf"] = kDegrees;
  const FixResult safe_only = fix_file("robot.urdf", Settings{}, FixOptions{}, files);
  REQUIRE_FALSE(safe_only.error);
  CHECK_FALSE(safe_only.changed());
  CHECK(safe_only.applied == 0);
  CHECK(safe_only.remaining.diagnostics.size() == 1);

  FixOptions unsafe;
  unsafe.unsafe = true;
  const FixResult r = fix_file("robot.urdf", Settings{}, unsafe, files);
  REQUIRE_FALSE(r.error);
  REQUIRE(r.files.size() == 1);
  CHECK(r.files[0].path == "robot.urdf");
  CHECK(r.files[0].original == kDegrees);
  std::string expected = kDegrees;
  expected.replace(expected.find("upper=\"47\"") + 7, 2, "0.820305");
  CHECK(r.files[0].fixed == expected);
  CHECK(r.files[0].fixes == 1);
  CHECK(r.applied == 1);
  CHECK(r.rounds.size() == 1);
  CHECK(r.remaining.diagnostics.empty());
  CHECK(r.internal_errors.empty());
  CHECK(files.files["robot.urdf"] == kDegrees);  // nothing written
}

TEST_CASE("fix: display fixes are never applied", "[fix]") {
  CHECK(fix_applies(Fix{"t", Applicability::Safe, {}}, false));
  CHECK_FALSE(fix_applies(Fix{"t", Applicability::Unsafe, {}}, false));
  CHECK(fix_applies(Fix{"t", Applicability::Unsafe, {}}, true));
  CHECK_FALSE(fix_applies(Fix{"t", Applicability::Display, {}}, true));

  MemoryFiles files;
  files.files["robot.urdf"] = kDegrees;
  FixOptions options;
  options.unsafe = true;
  options.on_report = [](FileReport& report) {
    for (auto& d : report.diagnostics)
      if (d.fix) d.fix->applicability = Applicability::Display;
  };
  const FixResult r = fix_file("robot.urdf", Settings{}, options, files);
  CHECK_FALSE(r.changed());
  CHECK(r.applied == 0);
}

TEST_CASE("fix: overlapping fixes wait for the next round, the first by position wins", "[fix]") {
  MemoryFiles files;
  files.files["robot.urdf"] = kDegrees;
  const std::size_t comment = offset_of(kDegrees, "a comment");
  FixOptions options;  // safe fixes only: the degrees fix stays out
  int round = 0;
  options.on_report = [&](FileReport& report) {
    // Two fixes on the comment's "a" in round 1; only the first (by position, then rule)
    // goes in; the second then no longer matches the text and is not offered again.
    if (round++ > 0) return;
    Diagnostic d1{"test-a", Severity::Warning, report.source(0).span(0, comment, 1), "m1",
                  Fix{"capital", Applicability::Safe, {Edit{0, comment, 1, "A"}}}, {}, {}, {}};
    Diagnostic d2{"test-b", Severity::Warning, report.source(0).span(0, comment, 1), "m2",
                  Fix{"article", Applicability::Safe, {Edit{0, comment, 9, "the comment"}}}, {}, {}, {}};
    report.diagnostics.push_back(d2);
    report.diagnostics.push_back(d1);
  };
  const FixResult r = fix_file("robot.urdf", Settings{}, options, files);
  REQUIRE_FALSE(r.error);
  REQUIRE(r.files.size() == 1);
  REQUIRE(r.rounds.size() == 1);
  // "capital" (test-a sorts before test-b at the same offset); "article" overlaps it.
  REQUIRE(r.rounds[0].applied.size() == 1);
  CHECK(r.rounds[0].applied[0].rule == "test-a");
  std::string expected = kDegrees;
  expected[comment] = 'A';
  CHECK(r.files[0].fixed == expected);
}

TEST_CASE("fix: a fix that would make the file unparsable is dropped, the others kept", "[fix]") {
  MemoryFiles files;
  files.files["robot.urdf"] = kDegrees;
  const std::size_t robot = offset_of(kDegrees, "<robot");
  FixOptions options;
  options.unsafe = true;
  options.on_report = [&](FileReport& report) {
    // Offered every round, as a rule would keep offering it.
    const std::size_t at = report.source(0).text().find("<robot");
    report.diagnostics.push_back({"test-break", Severity::Warning, report.source(0).span(0, at, 6), "m",
                                  Fix{"rename the root", Applicability::Safe, {Edit{0, at + 1, 5, "robt"}}}, {}, {}, {}});
  };
  const FixResult r = fix_file("robot.urdf", Settings{}, options, files);
  REQUIRE_FALSE(r.error);
  REQUIRE(r.internal_errors.size() == 1);
  CHECK(r.internal_errors[0] == "fix 'rename the root' [test-break] would make robot.urdf unparsable; skipped");
  REQUIRE(r.files.size() == 1);
  std::string expected = kDegrees;
  expected.replace(expected.find("upper=\"47\"") + 7, 2, "0.820305");
  CHECK(r.files[0].fixed == expected);
  CHECK(r.files[0].fixed.substr(robot, 6) == "<robot");
  CHECK(r.applied == 1);
}

TEST_CASE("fix: fixes that keep changing the file stop after the round cap, with nothing to write", "[fix]") {
  MemoryFiles files;
  files.files["robot.urdf"] = kDegrees;
  FixOptions options;
  options.on_report = [&](FileReport& report) {
    // Toggles the comment between "a comment" and "b comment" forever.
    const std::string& text = report.source(0).text();
    const std::size_t at = text.find(" comment -->") - 1;
    report.diagnostics.push_back({"test-toggle", Severity::Warning, report.source(0).span(0, at, 1), "m",
                                  Fix{"toggle", Applicability::Safe, {Edit{0, at, 1, text[at] == 'a' ? "b" : "a"}}}, {}, {}, {}});
  };
  const FixResult r = fix_file("robot.urdf", Settings{}, options, files);
  REQUIRE(r.error);
  // The toggle comes back to the text it started from: the message names the cycle.
  CHECK(r.error->starts_with("fixes for robot.urdf undo each other and never converge: test-toggle writes "));
  CHECK(r.error->find(", then test-toggle writes ") != std::string::npos);
  CHECK(r.error->ends_with("; nothing written"));
  CHECK(r.files.empty());
  CHECK(r.rounds.size() == 10);
  CHECK(r.remaining.diagnostics.size() == r.initial.diagnostics.size());

  options.max_rounds = 1;
  options.on_report = nullptr;
  options.unsafe = true;
  files.files["robot.urdf"] = test::read_file(test::fixtures_dir() / "fix" / "units-velocity-implausible" /
                                              "cascade_after_degrees.urdf");
  const FixResult capped = fix_file("robot.urdf", Settings{}, options, files);
  REQUIRE(capped.error);
  CHECK(capped.error->find("did not converge after 1 rounds") != std::string::npos);
  options.max_rounds = 2;
  CHECK_FALSE(fix_file("robot.urdf", Settings{}, options, files).error);
}

TEST_CASE("fix: fixes with edits outside their file are internal errors", "[fix]") {
  MemoryFiles files;
  files.files["robot.urdf"] = kDegrees;
  FixOptions options;
  options.on_report = [&](FileReport& report) {
    report.diagnostics.push_back({"test-range", Severity::Warning, report.source(0).span(0, 0, 1), "m",
                                  Fix{"past the end", Applicability::Safe,
                                      {Edit{0, report.source(0).text().size(), 1, "x"}}}, {}, {}, {}});
    report.diagnostics.push_back({"test-file", Severity::Warning, report.source(0).span(0, 0, 1), "m",
                                  Fix{"no such file", Applicability::Safe, {Edit{7, 0, 0, "x"}}}, {}, {}, {}});
  };
  const FixResult r = fix_file("robot.urdf", Settings{}, options, files);
  REQUIRE_FALSE(r.error);
  CHECK_FALSE(r.changed());
  CHECK(r.internal_errors == std::vector<std::string>{
                                 "fix 'past the end' [test-range] has edits outside the text of robot.urdf; skipped",
                                 "fix 'no such file' [test-file] has edits outside the text of robot.urdf; skipped"});
}

TEST_CASE("fix: the edit scope keeps fixes inside the checked tree", "[fix]") {
  test::TempDir dir;
  const auto root = dir.path() / "assets";
  std::filesystem::create_directories(root / "robot" / "parts");
  std::filesystem::create_directories(dir.path() / "elsewhere");
  const std::string file = (root / "robot" / "r.urdf").string();
  const EditScope scope = default_scope(file);
  CHECK(scope(file));
  CHECK(scope((root / "robot" / "parts" / "x.usda").string()));
  CHECK(scope((root / "robot" / "parts" / ".." / "y.usda").string()));
  CHECK_FALSE(scope((root / "other.usda").string()));
  CHECK_FALSE(scope((root / "robot" / ".." / "other.usda").string()));
  CHECK_FALSE(scope((dir.path() / "elsewhere" / "x.usda").string()));
  CHECK_FALSE(scope((root / "robot2" / "x.usda").string()));  // a prefix is not a parent
  // A link inside the tree that leads out of it is outside.
  std::filesystem::create_directory_symlink(dir.path() / "elsewhere", root / "robot" / "escape");
  CHECK_FALSE(scope((root / "robot" / "escape" / "x.usda").string()));
  const EditScope tree = tree_scope(root.string());
  CHECK(tree((root / "other.usda").string()));
  CHECK_FALSE(tree((dir.path() / "elsewhere" / "x.usda").string()));
  CHECK(path_within((root / "robot" / "r.urdf").string(), root.string()));

  // The fixer leaves a fix alone when any of its edits is out of scope.
  MemoryFiles files;
  files.files["robot.urdf"] = kDegrees;
  FixOptions options;
  options.unsafe = true;
  options.scope = [](const std::string&) { return false; };
  const FixResult r = fix_file("robot.urdf", Settings{}, options, files);
  CHECK_FALSE(r.changed());
  REQUIRE(r.notes.size() == 1);
  CHECK(r.notes[0] ==
        "fix 'read the limits as degrees and write them in radians: [0, 0.820305]' [units-angle-degrees] would edit robot.urdf, outside the "
        "files being fixed; skipped");
}

TEST_CASE("fix: an unreadable file is an error with nothing to write", "[fix]") {
  MemoryFiles files;
  const FixResult r = fix_file("missing.urdf", Settings{}, FixOptions{}, files);
  REQUIRE(r.error);
  CHECK(r.error->find("cannot read 'missing.urdf'") != std::string::npos);
  CHECK(r.files.empty());
}

TEST_CASE("fix: unit fixes go first, fixes that read other joints' values wait for them", "[fix]") {
  // The mimic joint's fixes are computed from finger_joint's limits and velocity, which
  // are written in degrees: they must wait until those are converted, or they would
  // copy 46 "rad" and 166 "rad/s" into the mimic joint.
  MemoryFiles files;
  files.files["robot.urdf"] =
      test::read_file(test::fixtures_dir() / "fix" / "mimic-limit-conflict" / "reference_in_degrees.urdf");
  FixOptions options;
  options.unsafe = true;
  const FixResult r = fix_file("robot.urdf", Settings{}, options, files);
  REQUIRE_FALSE(r.error);
  std::vector<std::vector<std::string>> rules;
  for (const auto& round : r.rounds) {
    rules.emplace_back();
    for (const auto& applied : round.applied) rules.back().push_back(applied.rule);
  }
  CHECK(rules == std::vector<std::vector<std::string>>{
                     {"units-angle-degrees"}, {"units-velocity-implausible"},
                     {"mimic-limit-conflict", "mimic-max-velocity"}});
  REQUIRE(r.files.size() == 1);
  CHECK(r.files[0].fixed.find("<limit lower=\"0\" upper=\"0.802851\" effort=\"24\" velocity=\"2.897\"/>") !=
        std::string::npos);
  CHECK(r.files[0].fixed.find("<limit lower=\"-0.8757\" upper=\"0\" effort=\"4\" velocity=\"2.897\"/>") !=
        std::string::npos);
}
