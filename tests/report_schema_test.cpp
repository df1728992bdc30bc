// The JUnit report validated with xmllint against tests/schemas/junit.xsd (the subset of
// JUnit XML that Jenkins' and GitLab's readers accept), for each kind of run a CI job sees.
// Without xmllint (Debian libxml2-utils) the test warns and skips.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "test_support.h"

using assetlint::test::on_path;
using assetlint::test::read_file;
using assetlint::test::run_cli;
using assetlint::test::run_shell;
using assetlint::test::shell_quote;
using assetlint::test::TempDir;
using assetlint::test::write_file;

namespace {

const std::filesystem::path& schema() {
  static const auto path = assetlint::test::source_dir() / "tests" / "schemas" / "junit.xsd";
  return path;
}

// xmllint's verdict on `document` against the schema: its exit status; its output in `output`.
int validate(const std::string& document, const TempDir& dir, std::string& output) {
  const auto file = dir.path() / "report.xml";
  write_file(file, document);
  return run_shell("xmllint --noout --schema " + shell_quote(schema().string()) + " " + shell_quote(file.string()),
                   dir.path() / "xmllint.log", output);
}

}  // namespace

TEST_CASE("report: JUnit output validates against the readers' schema in every kind of run", "[report][junit-schema]") {
  if (!on_path("xmllint")) {
    WARN("xmllint not installed (apt-get install libxml2-utils); skipping the JUnit schema test");
    return;
  }
  TempDir dir;
  write_file(dir.path() / "broken.urdf", "<robot name=\"r\">\n  <link name=\"a\">\n</robot>\n");
  // A joint name with a character XML must escape and an ISO-8859-1 byte, which is not UTF-8.
  std::string latin1 = read_file(assetlint::test::report_dir() / "gripper.urdf");
  latin1 = assetlint::test::replace_once(latin1, "<?xml version=\"1.0\"?>",
                                         "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>");
  for (int i = 0; i < 2; ++i) latin1 = assetlint::test::replace_once(latin1, "\"finger_joint\"", "\"j\xE9&amp;\"");
  write_file(dir.path() / "latin1.urdf", latin1);
  struct Run {
    const char* what;
    std::vector<std::string> args;
    int exit_code;
    const char* expected_in_report;
  };
  const auto report = assetlint::test::report_dir().string();
  const auto clean = (assetlint::test::fixtures_dir() / "ci" / "arm.urdf").string();
  const Run runs[] = {
      {"clean", {clean}, 0, "failures=\"0\" errors=\"0\""},
      {"findings", {report + "/gripper.urdf", report + "/joints.usda"}, 1, "<failure message="},
      {"I/O error", {(dir.path() / "missing.urdf").string(), clean}, 2, "type=\"io-error\""},
      {"ISO-8859-1 names", {(dir.path() / "latin1.urdf").string()}, 1, "j\xEF\xBF\xBD&amp;"},
      {"parse error", {(dir.path() / "broken.urdf").string()}, 1, "parse-error"},
  };
  for (const Run& run : runs) {
    INFO(run.what);
    std::vector<std::string> args = {"--output-format", "junit"};
    args.insert(args.end(), run.args.begin(), run.args.end());
    const auto result = run_cli(args, dir.path());
    INFO(result.err);
    CHECK(result.exit_code == run.exit_code);
    CHECK(result.out.find(run.expected_in_report) != std::string::npos);
    std::string verdict;
    CHECK(validate(result.out, dir, verdict) == 0);
    INFO(verdict);
    CHECK(verdict.find("validates") != std::string::npos);
  }
}

TEST_CASE("report: the JUnit schema rejects a case with two outcomes and a suite without counts", "[report][junit-schema]") {
  if (!on_path("xmllint")) {
    WARN("xmllint not installed (apt-get install libxml2-utils); skipping the JUnit schema test");
    return;
  }
  TempDir dir;
  const std::string valid = read_file(assetlint::test::report_dir() / "expected.junit.xml");
  std::string verdict;
  REQUIRE(validate(valid, dir, verdict) == 0);
  // Readers show only the first outcome of a case: a second one is a lost finding.
  const std::string failure = "<failure message=\"x\" type=\"error\">x</failure>";
  const auto second_failure =
      assetlint::test::replace_once(valid, "</failure>\n", "</failure>\n      " + failure + "\n");
  CHECK(validate(second_failure, dir, verdict) != 0);
  CHECK(verdict.find("failure") != std::string::npos);
  const auto no_tests = assetlint::test::replace_once(valid, "<testsuite name=\"gripper.urdf\" tests=\"4\"",
                                                      "<testsuite name=\"gripper.urdf\"");
  CHECK(validate(no_tests, dir, verdict) != 0);
  const auto bad_line = assetlint::test::replace_once(valid, "line=\"9\"", "line=\"0\"");
  CHECK(validate(bad_line, dir, verdict) != 0);
}
