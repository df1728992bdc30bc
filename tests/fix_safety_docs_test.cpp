// Fix safety has one source of truth, the rules' own fixes: the docs that speak of it are held
// to what the tool does. docs/rules.md's index is the table `--list-rules --output-format json`
// and the fixes over every fixture give; docs/fixing.md's examples of safe and unsafe fixes
// name rules whose fixes are of that kind; docs/output-formats.md's examples on gripper.urdf
// are the tool's output for the commands they name.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "test_support.h"

using assetlint::test::read_file;
using assetlint::test::run_cli;
using assetlint::test::source_dir;

namespace {

// Each rule's fix applicabilities ("safe", "unsafe") over every fixture.
std::map<std::string, std::set<std::string>> observed_applicability() {
  const auto run = run_cli({"--output-format", "json", "--exit-zero", "fixtures"});
  REQUIRE(run.exit_code == 0);
  std::map<std::string, std::set<std::string>> seen;
  const auto report = nlohmann::json::parse(run.out);
  for (const auto& d : report["diagnostics"])
    if (d.contains("fix")) seen[d["rule"].get<std::string>()].insert(d["fix"]["applicability"].get<std::string>());
  return seen;
}

std::string fix_column(const std::set<std::string>& kinds) {
  if (kinds == std::set<std::string>{"safe"}) return "safe";
  if (kinds == std::set<std::string>{"unsafe"}) return "unsafe";
  return "safe or unsafe";
}

// The section of `markdown` from `heading` to the next heading of any level.
std::string section(const std::string& markdown, const std::string& heading) {
  const auto start = markdown.find(heading);
  REQUIRE(start != std::string::npos);
  const auto end = markdown.find("\n#", start + heading.size());
  return markdown.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

}  // namespace

TEST_CASE("docs/rules.md: the index is the rule metadata and the fixes' applicability", "[docs][fix-safety]") {
  const auto listed = nlohmann::json::parse(run_cli({"--list-rules", "--output-format", "json"}).out);
  const auto seen = observed_applicability();
  std::string expected = "| rule | default severity | fix | summary |\n|---|---|---|---|\n";
  for (const auto& rule : listed) {
    const std::string id = rule["id"];
    INFO(id);
    std::string fix;
    if (const auto it = seen.find(id); it != seen.end()) fix = fix_column(it->second);
    // A fixable rule whose fix no fixture exercises (compare-mismatch writes through `compare`):
    // the index says what its code declares.
    else if (rule["fixable"].get<bool>()) fix = "unsafe";
    CHECK(rule["fixable"].get<bool>() == !fix.empty());
    expected += "| [" + id + "](rules/" + id + ".md) | " + rule["severity"].get<std::string>() + " | " + fix + " | " +
                rule["summary"].get<std::string>() + " |\n";
  }
  const std::string page = read_file(source_dir() / "docs" / "rules.md");
  const auto start = page.find("| rule | default severity | fix | summary |\n");
  REQUIRE(start != std::string::npos);
  const std::string table = page.substr(start, page.find("\n\n", start) + 1 - start);
  INFO("the table docs/rules.md should hold:\n" << expected);
  CHECK(table == expected);
}

TEST_CASE("docs/fixing.md: its examples of safe and unsafe fixes are of that kind", "[docs][fix-safety]") {
  const auto seen = observed_applicability();
  const std::string page = section(read_file(source_dir() / "docs" / "fixing.md"), "## Which fixes are applied");
  const std::regex rule_id("`([a-z]+(?:-[a-z]+)+)`");
  std::size_t named = 0;
  for (const auto& [marker, kind] : {std::pair{"| `(fixable)` |", "safe"}, std::pair{"| `(unsafe fix)` |", "unsafe"}}) {
    const auto at = page.find(marker);
    REQUIRE(at != std::string::npos);
    const std::string row = page.substr(at, page.find('\n', at) - at);
    for (std::sregex_iterator it(row.begin(), row.end(), rule_id), end; it != end; ++it) {
      const std::string id = (*it)[1];
      if (id.starts_with("unsafe-") || id.starts_with("fix")) continue;  // flags, not rules
      INFO(kind << " example: " << id);
      REQUIRE(seen.count(id));
      CHECK(seen.at(id).count(kind));
      ++named;
    }
  }
  CHECK(named >= 2);
}

// The report examples of docs/output-formats.md that name a command on fixtures/report's
// gripper.urdf: "`asset-lint --output-format json gripper.urdf` on the file above:" before a
// fenced block.
TEST_CASE("docs/output-formats.md: the gripper.urdf examples are the tool's output", "[docs][fix-safety]") {
  const std::string page = read_file(source_dir() / "docs" / "output-formats.md");
  const std::regex command("`asset-lint((?:[ \\n][^`]+)?)[ \\n]gripper\\.urdf`[^`\\n]*:\\n\\n```(\\w*)\\n");
  std::size_t compared = 0;
  for (std::sregex_iterator it(page.begin(), page.end(), command), end; it != end; ++it) {
    std::istringstream words((*it)[1].str());
    std::vector<std::string> args;
    for (std::string word; words >> word;) args.push_back(word);
    args.push_back("gripper.urdf");
    const auto body_start = static_cast<std::size_t>(it->position() + it->length());
    const std::string body = page.substr(body_start, page.find("```\n", body_start) - body_start);
    const auto run = run_cli(args, assetlint::test::report_dir());
    INFO((*it)[0].str());
    if ((*it)[2] == "json") CHECK(nlohmann::json::parse(body) == nlohmann::json::parse(run.out));
    else CHECK(body == run.out);
    ++compared;
  }
  CHECK(compared >= 3);
}
