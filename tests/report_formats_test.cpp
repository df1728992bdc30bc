// The machine-readable report formats (concise, sarif, github, junit), --statistics,
// --exit-zero, --quiet and --output-file, through the real binary.
// Golden files live in fixtures/report/; ASSET_LINT_UPDATE_EXPECTED=1 rewrites them.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>
#include <tinyxml2.h>

#include <cstdlib>
#include <filesystem>
#include <set>

#include "report/github_reporter.h"
#include "report/junit_reporter.h"
#include "report/sarif_reporter.h"
#include "rules/registry.h"
#include "test_support.h"

using assetlint::test::read_file;
using assetlint::test::report_dir;
using assetlint::test::run_cli;
using assetlint::test::write_file;

namespace {

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// The SARIF's originalUriBaseIds hold the absolute working directory: a placeholder in goldens.
std::string normalize(std::string text) {
  return replace_all(std::move(text), "file://" + report_dir().generic_string() + "/", "file:///SRCROOT/");
}

void check_golden(const std::string& actual, const std::string& name) {
  const auto path = report_dir() / name;
  if (std::getenv("ASSET_LINT_UPDATE_EXPECTED")) write_file(path, actual);
  INFO("golden " << path.string());
  REQUIRE(std::filesystem::exists(path));
  CHECK(actual == read_file(path));
}

// The goldens pin a few long-standing rules, so that other rules' wording or new rules
// do not churn them.
const std::vector<std::string> kInputs = {
    "--select", "limits-inverted,mimic-max-velocity,stale-schema-attribute,unused-suppression", "gripper.urdf",
    "joints.usda"};
constexpr std::size_t kSelectedRules = 4;

std::vector<std::string> with_inputs(std::vector<std::string> args) {
  args.insert(args.end(), kInputs.begin(), kInputs.end());
  return args;
}

// Where Sarif.Multitool is: $ASSET_LINT_SARIF_MULTITOOL, or the project-local npm install
// that scripts/bootstrap.sh makes (tools/node_modules). Empty when absent.
std::filesystem::path sarif_multitool() {
  if (const char* env = std::getenv("ASSET_LINT_SARIF_MULTITOOL"); env && *env) return env;
  const auto local = assetlint::test::source_dir() / "tools" / "node_modules" / "@microsoft" /
                     "sarif-multitool-linux" / "Sarif.Multitool";
  return std::filesystem::exists(local) ? local : std::filesystem::path();
}

}  // namespace

TEST_CASE("report: each format's exact output on the fixtures", "[report]") {
  for (const char* format : {"text", "concise", "github", "junit", "sarif", "json"}) {
    INFO("format " << format);
    auto r = run_cli(with_inputs({"--output-format", format}), report_dir());
    CHECK(r.exit_code == 1);
    CHECK(r.err.empty());
    const std::string ext = std::string(format) == "junit"  ? "xml"
                            : std::string(format) == "sarif" ? "sarif"
                            : std::string(format) == "json"  ? "json"
                                                             : "txt";
    std::string actual = normalize(r.out);
    if (std::string(format) == "sarif") {
      // The rule descriptors carry every docs page and change with each new rule: they
      // (and the ruleIndex into them) are checked field by field below, not pinned here.
      auto doc = nlohmann::ordered_json::parse(actual);
      doc["runs"][0]["tool"]["driver"].erase("rules");
      for (auto& result : doc["runs"][0]["results"]) result.erase("ruleIndex");
      actual = doc.dump(2) + "\n";
    }
    check_golden(actual, std::string("expected.") + format + "." + ext);
  }
  auto stats = run_cli(with_inputs({"--statistics"}), report_dir());
  CHECK(stats.exit_code == 1);
  check_golden(stats.out, "expected.statistics.txt");
}

TEST_CASE("report: concise is one line per finding, no markers, no summary", "[report]") {
  auto r = run_cli({"--output-format", "concise", "gripper.urdf"}, report_dir());
  CHECK(r.exit_code == 1);
  CHECK(r.out.find("gripper.urdf:9:19: limits-inverted revolute joint 'finger_joint'") == 0);
  CHECK(r.out.find("(fixable)") == std::string::npos);
  CHECK(r.out.find("Found") == std::string::npos);
  assetlint::test::TempDir dir;  // the gripper without the guide's story configuration beside it
  assetlint::test::write_file(dir.path() / "gripper.urdf",
                              read_file(assetlint::test::fixtures_dir() / "robotiq_2f85" / "robotiq_2f85.urdf"));
  auto clean = run_cli({"--output-format", "concise", "gripper.urdf"}, dir.path());
  CHECK(clean.exit_code == 0);
  CHECK(clean.out.empty());
}

TEST_CASE("report: SARIF 2.1.0 field by field", "[report]") {
  auto r = run_cli(with_inputs({"--output-format", "sarif"}), report_dir());
  REQUIRE(r.exit_code == 1);
  const auto doc = nlohmann::json::parse(r.out);
  CHECK(doc["version"] == "2.1.0");
  CHECK(doc["$schema"].get<std::string>().find("sarif-2.1.0") != std::string::npos);
  REQUIRE(doc["runs"].size() == 1);
  const auto& run = doc["runs"][0];
  CHECK(run["columnKind"] == "unicodeCodePoints");
  CHECK(run["originalUriBaseIds"]["%SRCROOT%"]["uri"] == "file://" + report_dir().generic_string() + "/");
  const auto& driver = run["tool"]["driver"];
  CHECK(driver["name"] == "asset-lint");
  CHECK(driver["semanticVersion"] == ASSET_LINT_VERSION);
  // Every rule of the catalog, in catalog order, documented.
  const auto& catalog = assetlint::rules::catalog();
  REQUIRE(driver["rules"].size() == catalog.size());
  for (std::size_t i = 0; i < catalog.size(); ++i) {
    const auto& rule = driver["rules"][i];
    INFO("rule " << catalog[i]->id);
    CHECK(rule["id"] == std::string(catalog[i]->id));
    CHECK(rule["shortDescription"]["text"] == std::string(catalog[i]->summary));
    CHECK_FALSE(rule["fullDescription"]["text"].get<std::string>().empty());
    CHECK(rule["help"]["markdown"].get<std::string>().rfind("# " + std::string(catalog[i]->id), 0) == 0);
    const char* level = catalog[i]->default_severity == assetlint::Severity::Error     ? "error"
                        : catalog[i]->default_severity == assetlint::Severity::Warning ? "warning"
                                                                                        : "note";
    CHECK(rule["defaultConfiguration"]["level"] == level);
  }

  const auto& results = run["results"];
  REQUIRE(results.size() == 4);
  for (const auto& result : results) {
    const std::size_t index = result["ruleIndex"];
    CHECK(driver["rules"][index]["id"] == result["ruleId"]);
  }
  const auto& inverted = results[0];
  CHECK(inverted["ruleId"] == "limits-inverted");
  CHECK(inverted["level"] == "error");
  CHECK(inverted["message"]["text"].get<std::string>().find("lower limit 0.82 rad above upper limit 0 rad") !=
        std::string::npos);
  const auto& location = inverted["locations"][0]["physicalLocation"];
  CHECK(location["artifactLocation"]["uri"] == "gripper.urdf");
  CHECK(location["artifactLocation"]["uriBaseId"] == "%SRCROOT%");
  CHECK(location["region"]["startLine"] == 9);
  CHECK(location["region"]["startColumn"] == 19);
  CHECK(location["region"]["endLine"] == 9);
  CHECK(location["region"]["endColumn"] == 23);
  // The unsafe swap: two replacements in one artifact change.
  REQUIRE(inverted["fixes"].size() == 1);
  const auto& change = inverted["fixes"][0]["artifactChanges"][0];
  CHECK(change["artifactLocation"]["uri"] == "gripper.urdf");
  REQUIRE(change["replacements"].size() == 2);
  CHECK(change["replacements"][0]["deletedRegion"]["byteOffset"] == 480);
  CHECK(change["replacements"][0]["deletedRegion"]["byteLength"] == 4);
  CHECK(change["replacements"][0]["insertedContent"]["text"] == "0");
  CHECK(change["replacements"][1]["insertedContent"]["text"] == "0.82");
  CHECK(inverted["properties"]["applicability"] == "unsafe");

  CHECK(results[1]["ruleId"] == "mimic-max-velocity");
  CHECK(results[1]["level"] == "warning");
  // Infos are SARIF notes; findings without a fix carry no fixes.
  CHECK(results[2]["level"] == "note");
  CHECK(results[2]["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] == "joints.usda");
  CHECK_FALSE(results[2].contains("fixes"));
}

TEST_CASE("report: SARIF URIs are relative, forward-slashed and percent-encoded", "[report]") {
  bool relative = false;
  CHECK(assetlint::sarif_uri("./a/b c.urdf", "/w", relative) == "a/b%20c.urdf");
  CHECK(relative);
  CHECK(assetlint::sarif_uri("/w/sub/x.urdf", "/w", relative) == "sub/x.urdf");
  CHECK(relative);
  CHECK(assetlint::sarif_uri("/elsewhere/x#1.urdf", "/w", relative) == "file:///elsewhere/x%231.urdf");
  CHECK_FALSE(relative);
  CHECK(assetlint::sarif_uri("d\xC3\xA9j\xC3\xA0.usda", "/w", relative) == "d%C3%A9j%C3%A0.usda");
  CHECK(assetlint::first_paragraph("# id\n\nFirst line\nsecond line.\n\n## What\n") == "First line second line.");
}

TEST_CASE("report: the official SARIF validator accepts the output", "[report][sarif-validator]") {
  const auto tool = sarif_multitool();
  if (tool.empty()) {
    WARN("Sarif.Multitool not found (scripts/bootstrap.sh installs it into tools/node_modules when npm is "
         "available, or set ASSET_LINT_SARIF_MULTITOOL); skipping the validator check");
    return;
  }
  assetlint::test::TempDir dir;
  const auto sarif = dir.path() / "out.sarif";
  auto r = run_cli(with_inputs({"--output-format", "sarif", "--output-file", sarif.string()}), report_dir());
  REQUIRE(r.exit_code == 1);
  const auto log = dir.path() / "validation.sarif";
  // The validator is a .NET single-file app; invariant globalization spares it libicu.
  const std::string command = "DOTNET_SYSTEM_GLOBALIZATION_INVARIANT=1 timeout 120 '" + tool.string() +
                              "' validate '" + sarif.string() + "' --output '" + log.string() +
                              "' >'" + (dir.path() / "stdout").string() + "' 2>&1";
  const int status = std::system(command.c_str());
  INFO(read_file(dir.path() / "stdout"));
  REQUIRE(std::filesystem::exists(log));
  const auto validation = nlohmann::json::parse(read_file(log));
  std::vector<std::string> problems;
  for (const auto& result : validation["runs"][0]["results"]) {
    const std::string level = result.value("level", "warning");
    // SARIF2005 asks for tool.driver.informationUri, which is only written when the build
    // names a homepage (-DASSET_LINT_HOMEPAGE=...); asset-lint does not invent one.
    const std::string rule = result["ruleId"];
    if (rule == "SARIF2005" && std::string(ASSET_LINT_HOMEPAGE).empty()) continue;
    if (level == "error" || level == "warning")
      problems.push_back(result["ruleId"].get<std::string>() + " " + level + ": " +
                         result["message"].dump());
  }
  std::string joined;
  for (const auto& p : problems) joined += p + "\n";
  INFO(joined);
  CHECK(problems.empty());
  CHECK(status == 0);
}

TEST_CASE("report: github workflow commands and their escaping", "[report]") {
  CHECK(assetlint::github_escape_data("100% a\r\nb: c, d") == "100%25 a%0D%0Ab: c, d");
  CHECK(assetlint::github_escape_property("dir,1/a:b%.urdf") == "dir%2C1/a%3Ab%25.urdf");
  assetlint::test::TempDir dir;
  write_file(dir.path() / "a,b:c.urdf", read_file(report_dir() / "gripper.urdf"));
  auto r = run_cli({"--output-format", "github", "a,b:c.urdf"}, dir.path());
  CHECK(r.exit_code == 1);
  CHECK(r.out.rfind("::error file=a%2Cb%3Ac.urdf,line=9,col=19,endLine=9,endColumn=23,"
                    "title=asset-lint (limits-inverted)::revolute joint 'finger_joint' has lower limit 0.82 rad",
                    0) == 0);
  CHECK(r.out.find("\n::warning file=a%2Cb%3Ac.urdf,line=14,col=60,") != std::string::npos);
  auto notes = run_cli({"--output-format", "github", "--select", "stale-*", "joints.usda"}, report_dir());
  CHECK(notes.out.rfind("::notice file=joints.usda,line=40,col=15,", 0) == 0);
}

TEST_CASE("report: JUnit XML parses back, one case per finding with file and line, one per clean rule", "[report]") {
  auto r = run_cli(with_inputs({"--output-format", "junit"}), report_dir());
  REQUIRE(r.exit_code == 1);
  tinyxml2::XMLDocument doc;
  REQUIRE(doc.Parse(r.out.c_str(), r.out.size()) == tinyxml2::XML_SUCCESS);
  const auto* root = doc.FirstChildElement("testsuites");
  REQUIRE(root);
  CHECK(root->UnsignedAttribute("failures") == 4);
  CHECK(root->UnsignedAttribute("errors") == 0);
  const auto* suite = root->FirstChildElement("testsuite");
  REQUIRE(suite);
  CHECK(std::string(suite->Attribute("name")) == "gripper.urdf");
  // Two findings (limits-inverted, mimic-max-velocity) and the two rules without one.
  CHECK(suite->UnsignedAttribute("tests") == kSelectedRules);
  CHECK(suite->UnsignedAttribute("failures") == 2);
  std::size_t cases = 0, failures = 0;
  std::vector<std::string> names;
  for (const auto* tc = suite->FirstChildElement("testcase"); tc; tc = tc->NextSiblingElement("testcase")) {
    ++cases;
    names.emplace_back(tc->Attribute("name"));
    CHECK(std::string(tc->Attribute("classname")) == "gripper.urdf");
    std::size_t in_case = 0;
    for (const auto* f = tc->FirstChildElement("failure"); f; f = f->NextSiblingElement("failure")) {
      ++failures;
      ++in_case;
      CHECK(std::string(tc->Attribute("file")) == "gripper.urdf");
      if (names.back() == "limits-inverted (9:19)") {
        CHECK(tc->UnsignedAttribute("line") == 9);
        CHECK(std::string(f->Attribute("type")) == "error");
        CHECK(std::string(f->GetText()).rfind("gripper.urdf:9:19: revolute joint 'finger_joint'", 0) == 0);
        CHECK(std::string(f->Attribute("message")).find("'finger_joint'") != std::string::npos);
      }
    }
    CHECK(in_case <= 1);  // readers show only a testcase's first failure
  }
  CHECK(names == std::vector<std::string>{"limits-inverted (9:19)", "mimic-max-velocity (14:60)",
                                          "stale-schema-attribute", "unused-suppression"});
  CHECK(cases == kSelectedRules);
  CHECK(failures == 2);
  const auto* usda = suite->NextSiblingElement("testsuite");
  REQUIRE(usda);
  CHECK(std::string(usda->Attribute("name")) == "joints.usda");
  CHECK(usda->UnsignedAttribute("failures") == 2);
  CHECK(root->UnsignedAttribute("tests") == suite->UnsignedAttribute("tests") + usda->UnsignedAttribute("tests"));

  // Without --select every rule of the catalog without a finding is a passing testcase.
  auto all = run_cli({"--output-format", "junit", "--select", "limits-inverted,mimic-*,structure-*", "gripper.urdf"},
                     report_dir());
  tinyxml2::XMLDocument full;
  REQUIRE(full.Parse(all.out.c_str(), all.out.size()) == tinyxml2::XML_SUCCESS);
  const auto* only = full.FirstChildElement("testsuites")->FirstChildElement("testsuite");
  std::set<std::string> rules_seen;
  std::size_t testcases = 0;
  for (const auto* tc = only->FirstChildElement("testcase"); tc; tc = tc->NextSiblingElement("testcase")) {
    ++testcases;
    const std::string name = tc->Attribute("name");
    rules_seen.insert(name.substr(0, name.find(' ')));
  }
  CHECK(only->UnsignedAttribute("tests") == testcases);
  for (const auto* rule : assetlint::rules::catalog()) {
    const bool selected =
        rule->id == "limits-inverted" || rule->id.starts_with("mimic-") || rule->id.starts_with("structure-");
    CHECK(rules_seen.count(std::string(rule->id)) == (selected ? 1u : 0u));
  }
  CHECK(assetlint::xml_escape("a<b & \"c\" 'd'\x01") == "a&lt;b &amp; &quot;c&quot; &apos;d&apos;?");
}

TEST_CASE("report: --statistics counts findings per rule, most frequent first", "[report]") {
  assetlint::test::TempDir dir;
  for (const char* name : {"a.urdf", "b.urdf"}) write_file(dir.path() / name, read_file(report_dir() / "gripper.urdf"));
  write_file(dir.path() / "c.usda", read_file(report_dir() / "joints.usda"));
  auto r = run_cli({"--statistics", "--select", "limits-inverted,stale-schema-attribute", "."}, dir.path());
  CHECK(r.exit_code == 1);
  CHECK(r.out ==
        "2  limits-inverted         A joint's lower limit is above its upper limit, or equal limits lock a joint whose mirror twin moves\n"
        "2  stale-schema-attribute  Attributes authored for a USD API schema that is not applied (or was deleted): "
        "PhysX ignores them\n");
  auto json = run_cli({"--statistics", "--output-format", "json", "a.urdf"}, dir.path());
  const auto doc = nlohmann::json::parse(json.out);
  REQUIRE(doc.size() == 2);
  CHECK(doc[0]["rule"] == "limits-inverted");
  CHECK(doc[0]["count"] == 1);
  CHECK(doc[1]["rule"] == "mimic-max-velocity");
  CHECK(doc[1]["fixable"] == 0);  // raising a velocity limit is an unsafe fix (issue 15)
  CHECK(run_cli({"--statistics", "--output-format", "sarif", "a.urdf"}, dir.path()).exit_code == 2);
}

namespace {
std::size_t count_lines_starting(const std::string& text, std::string_view prefix) {
  std::size_t n = 0;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t nl = std::min(text.find('\n', at), text.size());
    if (std::string_view(text).substr(at, nl - at).starts_with(prefix)) ++n;
    at = nl + 1;
  }
  return n;
}
}  // namespace

TEST_CASE("report: --exit-zero, --quiet and --output-file", "[report]") {
  auto zero = run_cli({"--exit-zero", "gripper.urdf"}, report_dir());
  CHECK(zero.exit_code == 0);
  CHECK(zero.out.find("limits-inverted") != std::string::npos);
  // Errors still exit 2.
  CHECK(run_cli({"--exit-zero", "gripper.urdf", "missing.urdf"}, report_dir()).exit_code == 2);

  auto quiet = run_cli({"--quiet", "gripper.urdf"}, report_dir());
  CHECK(quiet.exit_code == 1);
  CHECK(quiet.out.find("Found") == std::string::npos);
  // Two findings, each a primary line plus its notes and help; no summary.
  CHECK(std::count_if(quiet.out.begin(), quiet.out.end(), [](char c) { return c == '\n'; }) ==
        static_cast<long>(2 + count_lines_starting(quiet.out, "  ")));
  {
    assetlint::test::TempDir clean_dir;  // the gripper without the guide's story configuration
    assetlint::test::write_file(clean_dir.path() / "gripper.urdf",
                                read_file(assetlint::test::fixtures_dir() / "robotiq_2f85" / "robotiq_2f85.urdf"));
    CHECK(run_cli({"-q", "gripper.urdf"}, clean_dir.path()).out.empty());
  }

  assetlint::test::TempDir dir;
  const auto file = dir.path() / "report.json";
  auto to_file = run_cli({"--output-format", "json", "--output-file", file.string(), "gripper.urdf"}, report_dir());
  CHECK(to_file.exit_code == 1);
  CHECK(to_file.out.empty());
  CHECK(nlohmann::json::parse(read_file(file))["summary"]["problems"] == 2);
  auto bad = run_cli({"--output-file", (dir.path() / "no" / "dir" / "x").string(), "gripper.urdf"}, report_dir());
  CHECK(bad.exit_code == 2);
  CHECK(bad.err.find("cannot write") != std::string::npos);
}
