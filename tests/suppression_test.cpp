// Inline suppressions (URDF elements, USDA prims and statements, whole files), the
// unused-suppression rule, and per-file-ignores in asset-lint.toml.
#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "pipeline/lint.h"
#include "formats/suppressions.h"
#include "util/path_glob.h"
#include "test_support.h"

using namespace assetlint;
using test::read_file;
using test::run_cli;
using test::write_file;

namespace {

std::vector<std::string> rules_of(const FileReport& report) {
  std::vector<std::string> ids;
  for (const auto& d : report.diagnostics) ids.push_back(d.rule);
  return ids;
}

const Diagnostic* find(const FileReport& report, std::string_view rule) {
  for (const auto& d : report.diagnostics)
    if (d.rule == rule) return &d;
  return nullptr;
}

std::string gripper() { return read_file(test::fixtures_dir() / "report" / "gripper.urdf"); }

std::string insert_before(std::string text, const std::string& anchor, const std::string& what) {
  const auto at = text.find(anchor);
  REQUIRE(at != std::string::npos);
  return text.insert(at, what);
}

}  // namespace

TEST_CASE("suppress: the XML scanner covers the element after the comment, through its end tag", "[suppress]") {
  const std::string text =
      "<?xml version=\"1.0\"?>\n"
      "<!-- asset-lint: ignore-file[a] -->\n"
      "<robot>\n"
      "  <!-- asset-lint: ignore[b, c-*] -->\n"
      "  <joint name=\"x\" note=\"a > b\">\n"
      "    <limit/>\n"
      "  </joint>\n"
      "  <!-- asset-lint: ignore[d] --><link name=\"self\"/>\n"
      "  <!-- asset-lint: ignore[e] -->\n"
      "</robot>\n";
  const auto found = find_suppressions(text, CommentSyntax::Xml);
  REQUIRE(found.size() == 4);
  CHECK(found[0].file_level);
  CHECK_FALSE(found[0].problem);
  CHECK(found[1].patterns == std::vector<std::string>{"b", "c-*"});
  CHECK(text.substr(found[1].begin, found[1].end - found[1].begin) ==
        "<joint name=\"x\" note=\"a > b\">\n    <limit/>\n  </joint>");
  CHECK(text.substr(found[2].begin, found[2].end - found[2].begin) == "<link name=\"self\"/>");
  CHECK(found[3].begin == found[3].end);  // only an end tag follows: covers nothing
  // A comment that only mentions the tool is not a directive.
  CHECK(find_suppressions("<!-- checked by asset-lint: see docs --><r/>", CommentSyntax::Xml).empty());
  const auto malformed = find_suppressions("<!-- asset-lint: ignore --><r/>", CommentSyntax::Xml);
  REQUIRE(malformed.size() == 1);
  CHECK(malformed[0].problem);
}

TEST_CASE("suppress: the USDA scanner covers a prim to its brace, a statement with its metadata", "[suppress]") {
  const std::string text =
      "#usda 1.0\n"
      "# asset-lint: ignore-file[a]\n"
      "def Xform \"r\" {\n"
      "    # asset-lint: ignore[b]\n"
      "    def Xform \"j\" (\n"
      "        doc = \"}\"\n"
      "    )\n"
      "    {\n"
      "        float x = 1\n"
      "    }\n"
      "    # asset-lint: ignore[c]\n"
      "    float y = 2 (\n"
      "        doc = \"# asset-lint: ignore[not-a-comment]\"\n"
      "    )\n"
      "    # asset-lint: ignore[d]\n"
      "    float[] z = [1,\n"
      "                 2]  # trailing comment\n"
      "    float w = 3\n"
      "}\n";
  const auto found = find_suppressions(text, CommentSyntax::Usda);
  REQUIRE(found.size() == 4);
  CHECK(found[0].file_level);
  CHECK_FALSE(found[0].problem);
  CHECK(found[1].target == "prim");
  CHECK(text.substr(found[1].begin, found[1].end - found[1].begin) ==
        "def Xform \"j\" (\n        doc = \"}\"\n    )\n    {\n        float x = 1\n    }");
  CHECK(found[2].target == "statement");
  CHECK(text.substr(found[2].begin, found[2].end - found[2].begin) ==
        "float y = 2 (\n        doc = \"# asset-lint: ignore[not-a-comment]\"\n    )");
  CHECK(text.substr(found[3].begin, found[3].end - found[3].begin) == "float[] z = [1,\n                 2]");
  // ignore-file after the first prim is misplaced.
  const auto late = find_suppressions("#usda 1.0\ndef X \"a\" {\n}\n# asset-lint: ignore-file[a]\n", CommentSyntax::Usda);
  REQUIRE(late.size() == 1);
  CHECK(late[0].problem);
}

TEST_CASE("suppress: path globs for per-file-ignores", "[suppress]") {
  CHECK(path_glob_match("legacy/**", "legacy/a/b.urdf"));
  CHECK(path_glob_match("**/*.usda", "a/b/c.usda"));
  CHECK(path_glob_match("**/*.usda", "c.usda"));
  CHECK(path_glob_match("a/**/c.urdf", "a/c.urdf"));
  CHECK(path_glob_match("a/**/c.urdf", "a/x/y/c.urdf"));
  CHECK_FALSE(path_glob_match("a/*.urdf", "a/x/c.urdf"));
  CHECK(path_glob_match("*.urdf", "deep/dir/c.urdf"));  // no '/': the file name alone
  CHECK_FALSE(path_glob_match("legacy/*", "other/legacy/x.urdf"));
}

TEST_CASE("suppress: a URDF element suppression removes its findings and only those", "[suppress]") {
  Settings settings;
  const auto plain = lint_text("g.urdf", gripper(), settings);
  REQUIRE(rules_of(plain) == std::vector<std::string>{"limits-inverted", "mimic-max-velocity"});

  auto text = insert_before(gripper(), "<joint name=\"finger_joint\"", "<!-- asset-lint: ignore[limits-inverted] -->\n  ");
  CHECK(rules_of(lint_text("g.urdf", text, settings)) == std::vector<std::string>{"mimic-max-velocity"});
  // The same comment before the other joint suppresses nothing there: reported as unused.
  text = insert_before(gripper(), "<joint name=\"inner_finger_joint\"",
                       "<!-- asset-lint: ignore[limits-inverted] -->\n  ");
  const auto misplaced = lint_text("g.urdf", text, settings);
  CHECK(rules_of(misplaced) ==
        std::vector<std::string>{"limits-inverted", "unused-suppression", "mimic-max-velocity"});
  const Diagnostic* unused = find(misplaced, "unused-suppression");
  REQUIRE(unused);
  CHECK(unused->severity == Severity::Warning);
  CHECK(unused->message == "unused suppression of limits-inverted: no such finding in the element that follows");
  REQUIRE(unused->fix);
  CHECK(unused->fix->applicability == Applicability::Safe);
  // The fix deletes the comment's whole line.
  const Edit& e = unused->fix->edits.at(0);
  CHECK(e.replacement.empty());
  CHECK(text.substr(e.offset, e.length) == "  <!-- asset-lint: ignore[limits-inverted] -->\n");
}

TEST_CASE("suppress: globs, ignore-file, --select and unknown rule ids", "[suppress]") {
  Settings settings;
  auto text = insert_before(gripper(), "<robot", "<!-- asset-lint: ignore-file[limits-*, mimic-*] -->\n");
  CHECK(lint_text("g.urdf", text, settings).diagnostics.empty());

  // A suppression of a rule that --select left out is not judged.
  text = insert_before(gripper(), "<robot", "<!-- asset-lint: ignore-file[inertia-invalid] -->\n");
  Settings only_limits;
  only_limits.selection.select = {"limits-inverted", "unused-suppression"};
  CHECK(rules_of(lint_text("g.urdf", text, only_limits)) == std::vector<std::string>{"limits-inverted"});
  CHECK(rules_of(lint_text("g.urdf", text, settings)) ==
        std::vector<std::string>{"unused-suppression", "limits-inverted", "mimic-max-velocity"});

  // Unknown ids are reported whatever runs; the fix that drops them is unsafe (likely a typo).
  text = insert_before(gripper(), "<robot", "<!-- asset-lint: ignore-file[limits-inverted, limits-invrted] -->\n");
  const auto typo = lint_text("g.urdf", text, only_limits);
  const Diagnostic* unknown = find(typo, "unused-suppression");
  REQUIRE(unknown);
  CHECK(unknown->message == "suppression names unknown rule limits-invrted; `asset-lint --list-rules` lists them");
  REQUIRE(unknown->fix);
  CHECK(unknown->fix->applicability == Applicability::Unsafe);
  CHECK(unknown->fix->edits.at(0).replacement == "limits-inverted");
  CHECK(find(typo, "limits-inverted") == nullptr);

  // In a file with a parse error the same finding offers no edit: comments may not end where they seem to.
  const auto broken = lint_text("g.urdf", text + "\x01", only_limits);
  const Diagnostic* unfixable = find(broken, "unused-suppression");
  REQUIRE(unfixable);
  CHECK_FALSE(unfixable->fix);
  REQUIRE(unfixable->notes.size() == 1);
  CHECK(unfixable->notes[0].message == "No fix is offered while the file has a parse error: fix that first.");

  // unused-suppression can itself be ignored for the file.
  text = insert_before(gripper(), "<robot",
                       "<!-- asset-lint: ignore-file[unused-suppression] -->\n"
                       "<!-- asset-lint: ignore-file[inertia-invalid] -->\n");
  CHECK(rules_of(lint_text("g.urdf", text, settings)) ==
        std::vector<std::string>{"limits-inverted", "mimic-max-velocity"});
}

TEST_CASE("suppress: USDA prim and attribute suppressions, also in a composed layer", "[suppress]") {
  const auto dir = test::fixtures_dir() / "suppressions";
  Settings settings;
  const auto report = lint_file((dir / "prim_and_attribute.usda").string(), settings);
  // The attribute suppression and the prim suppression remove both stale-schema findings;
  // the suppression before an attribute that has no finding is reported, and so is the
  // unused mimic-* in the prim's list (the fix keeps the used part).
  std::vector<std::string> messages;
  for (const auto& d : report.diagnostics) messages.push_back(fmt::format("{}:{} {}", d.span.line, d.rule, d.message));
  INFO(fmt::format("{}", fmt::join(messages, "\n")));
  CHECK(find(report, "stale-schema-attribute") == nullptr);
  std::vector<const Diagnostic*> unused;
  for (const auto& d : report.diagnostics)
    if (d.rule == "unused-suppression") unused.push_back(&d);
  REQUIRE(unused.size() == 2);
  CHECK(unused[0]->span.line == 44);
  CHECK(unused[0]->message ==
        "unused suppression of stale-schema-attribute: no such finding in the statement that follows");
  CHECK(unused[1]->span.line == 49);
  CHECK(unused[1]->message == "unused suppression of mimic-*: no such finding in the prim that follows");
  REQUIRE(unused[1]->fix);
  CHECK(unused[1]->fix->edits.at(0).replacement == "stale-schema-attribute");

  // Checking the stack from its root layer: the finding is in physics.usda, and so is the comment.
  const auto stack = lint_file((dir / "layers" / "robot.usda").string(), settings);
  std::vector<const Diagnostic*> stale;
  for (const auto& d : stack.diagnostics) {
    CHECK(d.rule != "unused-suppression");
    if (d.rule == "stale-schema-attribute") stale.push_back(&d);
  }
  // The suppressed finding at line 41 is gone; the one in the follower prim (line 52) stays.
  REQUIRE(stale.size() == 1);
  CHECK(stale[0]->span.line == 52);
  CHECK(stack.source(stale[0]->span.file).path().ends_with("physics.usda"));
}

TEST_CASE("suppress: --fix removes unused suppressions", "[suppress]") {
  test::TempDir dir;
  const auto text = insert_before(gripper(), "<link name=\"base_link\"", "<!-- asset-lint: ignore[inertia-invalid] -->\n  ");
  write_file(dir.path() / "g.urdf", text);
  auto r = run_cli({"--fix", "--select", "unused-suppression,inertia-invalid", "g.urdf"}, dir.path());
  CHECK(r.exit_code == 0);
  CHECK(read_file(dir.path() / "g.urdf") == gripper());
}

TEST_CASE("suppress: per-file-ignores in asset-lint.toml", "[suppress]") {
  test::TempDir dir;
  std::filesystem::create_directories(dir.path() / "assets" / "legacy" / "old");
  write_file(dir.path() / "assets" / "legacy" / "old" / "g.urdf", gripper());
  write_file(dir.path() / "assets" / "g.urdf", gripper());
  write_file(dir.path() / "asset-lint.toml",
             "[per-file-ignores]\n"
             "\"assets/legacy/**\" = [\"limits-*\"]\n"
             "\"g.urdf\" = [\"mimic-max-velocity\"]\n");
  auto r = run_cli({"--output-format", "concise", "assets"}, dir.path());
  CHECK(r.exit_code == 1);
  CHECK(r.out.find("assets/g.urdf:9:19: limits-inverted") != std::string::npos);
  CHECK(r.out.find("legacy/old/g.urdf:9:19") == std::string::npos);
  CHECK(r.out.find("mimic-max-velocity") == std::string::npos);
  // Globs are relative to the configuration file, whatever the working directory.
  auto from_below = run_cli({"--output-format", "concise", "legacy"}, dir.path() / "assets");
  CHECK(from_below.exit_code == 0);
  CHECK(from_below.out.empty());

  // A per-file-ignored rule is not judged by unused-suppression.
  write_file(dir.path() / "assets" / "legacy" / "old" / "g.urdf",
             insert_before(gripper(), "<robot", "<!-- asset-lint: ignore-file[limits-inverted] -->\n"));
  CHECK(run_cli({"assets/legacy"}, dir.path()).exit_code == 0);

  write_file(dir.path() / "asset-lint.toml", "[per-file-ignores]\n\"*.urdf\" = [\n  \"no-such-rule\",\n]\n");
  auto unknown = run_cli({"assets"}, dir.path());
  CHECK(unknown.exit_code == 2);
  CHECK(unknown.err == "asset-lint: error: asset-lint.toml:3:3: 'no-such-rule' matches no rule\n");
  write_file(dir.path() / "asset-lint.toml", "per-file-ignores = [\"x\"]\n");
  CHECK(run_cli({"assets"}, dir.path()).exit_code == 2);
}

TEST_CASE("suppress: the scanners survive truncated and odd input", "[suppress]") {
  const std::vector<std::pair<std::filesystem::path, CommentSyntax>> inputs = {
      {test::fixtures_dir() / "suppressions" / "element.urdf", CommentSyntax::Xml},
      {test::fixtures_dir() / "suppressions" / "prim_and_attribute.usda", CommentSyntax::Usda},
  };
  for (const auto& [path, syntax] : inputs) {
    const std::string text = read_file(path);
    // Every prefix: unterminated comments, strings, tags and prims.
    for (std::size_t n = 0; n <= text.size(); ++n) {
      const std::string_view prefix(text.data(), n);
      for (const auto& s : find_suppressions(prefix, syntax)) {
        INFO(path.filename().string() << " cut at " << n);
        CHECK(s.begin <= s.end);
        CHECK(s.end <= n);
        CHECK(s.comment_offset + s.comment_length <= n);
      }
    }
  }
  // CDATA, DOCTYPE with an internal subset, processing instructions.
  const std::string xml =
      "<?xml version=\"1.0\"?><!DOCTYPE robot [<!ENTITY x \"<!-- asset-lint: ignore[a] -->\">]>\n"
      "<robot><![CDATA[<!-- asset-lint: ignore[b] -->]]>\n"
      "<!-- asset-lint: ignore[c] --><?pi x?><link/></robot>";
  const auto found = find_suppressions(xml, CommentSyntax::Xml);
  REQUIRE(found.size() == 1);
  CHECK(found[0].patterns == std::vector<std::string>{"c"});
  CHECK(xml.substr(found[0].begin, found[0].end - found[0].begin) == "<link/>");
  // over and class prims, and a block comment directive.
  const std::string usda =
      "#usda 1.0\n/* asset-lint: ignore[a] */\nover \"x\" {\n  float y = 1\n}\n# asset-lint: ignore[b]\nclass \"c\" {\n}\n";
  const auto usd = find_suppressions(usda, CommentSyntax::Usda);
  REQUIRE(usd.size() == 2);
  CHECK(usd[0].target == "prim");
  CHECK(usda.substr(usd[0].begin, usd[0].end - usd[0].begin) == "over \"x\" {\n  float y = 1\n}");
  CHECK(usda.substr(usd[1].begin, usd[1].end - usd[1].begin) == "class \"c\" {\n}");
}

TEST_CASE("path globs with many stars match a long path by dynamic programming", "[suppressions]") {
  // A backtracking matcher takes exponential time on these (seconds per file); the
  // table-driven one is O(|pattern| · |path|). The answers must still be exact.
  std::string path;
  for (int i = 0; i < 40; ++i) path += "dir" + std::to_string(i) + "/";
  const std::string name = "x" + std::string(60, 'a') + "x";
  CHECK_FALSE(path_glob_match("**/**/**/**/x*x*x*x*x*x*y.urdf", path + name + ".urdf"));
  CHECK(path_glob_match("**/**/**/**/x*x*y.urdf", path + "xaxbxy.urdf"));
  CHECK_FALSE(path_glob_match("****************z", std::string(200, 'a')));
  CHECK(path_glob_match("****************a", std::string(200, 'a')));
  CHECK(path_glob_match("a/**/b/**/c.urdf", "a/b/c.urdf"));
  CHECK(path_glob_match("a/**/b/**/c.urdf", "a/x/b/y/z/c.urdf"));
  CHECK_FALSE(path_glob_match("a/**/b/**/c.urdf", "a/xb/c.urdf"));
  CHECK(path_glob_match("**", "any/thing"));
  CHECK_FALSE(path_glob_match("?", "/"));
}

TEST_CASE("suppress: an end-of-line comment covers the element or statement it follows", "[suppress]") {
  const std::string xml =
      "<robot>\n"
      "  <joint name=\"j\">\n"
      "    <limit lower=\"1\"/>  <!-- asset-lint: ignore[a] -->\n"
      "    <mimic joint=\"k\"/>\n"
      "  </joint> <!-- asset-lint: ignore[b] -->\n"
      "  <link name=\"l\"> <!-- asset-lint: ignore[c] -->\n"
      "    <inertial/>\n"
      "  </link>\n"
      "</robot>\n";
  const auto in_xml = find_suppressions(xml, CommentSyntax::Xml);
  REQUIRE(in_xml.size() == 3);
  auto covered = [](const std::string& text, const SuppressionComment& s) {
    return text.substr(s.begin, s.end - s.begin);
  };
  CHECK(covered(xml, in_xml[0]) == "<limit lower=\"1\"/>");
  CHECK(covered(xml, in_xml[1]) == "<joint name=\"j\">\n    <limit lower=\"1\"/>  <!-- asset-lint: ignore[a] -->\n"
                                   "    <mimic joint=\"k\"/>\n  </joint>");
  CHECK(covered(xml, in_xml[2]) == "<link name=\"l\"> <!-- asset-lint: ignore[c] -->\n    <inertial/>\n  </link>");

  const std::string usda =
      "#usda 1.0\n"
      "def Xform \"a\" {  # asset-lint: ignore[p]\n"
      "    float x = 1  # asset-lint: ignore[s]\n"
      "    float[] y = [1,\n"
      "        2]  # asset-lint: ignore[t]\n"
      "    float z = 3\n"
      "}\n";
  const auto in_usda = find_suppressions(usda, CommentSyntax::Usda);
  REQUIRE(in_usda.size() == 3);
  CHECK(in_usda[0].target == "prim");
  CHECK(covered(usda, in_usda[0]).starts_with("def Xform \"a\" {"));
  CHECK(covered(usda, in_usda[0]).ends_with("float z = 3\n}"));
  CHECK(in_usda[1].target == "statement");
  CHECK(covered(usda, in_usda[1]) == "float x = 1  ");
  CHECK(covered(usda, in_usda[2]) == "float[] y = [1,\n        2]  ");
}

TEST_CASE("suppress: an end-of-line suppression silences its own line's finding, and --fix keeps it", "[suppress]") {
  test::TempDir dir;
  const std::string urdf = test::replace_once(gripper(), "velocity=\"2.9\"/>",
                                              "velocity=\"2.9\"/>  <!-- asset-lint: ignore[limits-inverted] -->");
  write_file(dir.path() / "g.urdf", urdf);
  auto r = run_cli({"--select", "limits-inverted,unused-suppression", "g.urdf"}, dir.path());
  CHECK(r.exit_code == 0);
  CHECK(r.out == "No problems found in 1 file.\n");
  auto fixed = run_cli({"--fix", "--select", "limits-inverted,unused-suppression", "g.urdf"}, dir.path());
  CHECK(fixed.exit_code == 0);
  CHECK(read_file(dir.path() / "g.urdf") == urdf);
}
