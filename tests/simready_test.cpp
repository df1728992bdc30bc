// docs/simready.md maps SimReady's requirements onto asset-lint's rules: every row that names a
// rule and a fixture must hold, the fixture flagged at warning or error by that rule with the
// requirement's id in the finding's data.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <regex>
#include <sstream>

#include "test_support.h"

using namespace assetlint::test;

namespace {

struct Row {
  std::vector<std::string> ids;  // "DJ.004", "DJ.006"
  std::string rule;
  std::string fixture;  // relative to fixtures/
};

std::vector<Row> covered_rows() {
  std::vector<Row> rows;
  std::istringstream page(read_file(source_dir() / "docs" / "simready.md"));
  const std::regex row(R"(^\| ((?:DJ|GR)\.\d{3}[^|]*)\|[^|]*\| ([a-z-]+) \|[^|]*\| `fixtures/([^`]+)` \|$)");
  const std::regex id(R"((DJ|GR)\.\d{3})");
  for (std::string line; std::getline(page, line);) {
    std::smatch m;
    if (!std::regex_match(line, m, row)) continue;
    Row r;
    const std::string ids = m[1].str();
    for (std::sregex_iterator it(ids.begin(), ids.end(), id), end; it != end; ++it) r.ids.push_back(it->str());
    r.rule = m[2].str();
    r.fixture = m[3].str();
    rows.push_back(std::move(r));
  }
  return rows;
}

}  // namespace

TEST_CASE("docs/simready.md: every covered requirement's fixture is flagged", "[simready][docs]") {
  const auto rows = covered_rows();
  REQUIRE(rows.size() >= 6);
  for (const Row& row : rows) {
    INFO(row.ids.front() << " → " << row.rule << " on " << row.fixture);
    REQUIRE(std::filesystem::exists(fixtures_dir() / row.fixture));
    const auto result = run_cli({"--output-format", "json", row.fixture}, fixtures_dir());
    const auto doc = nlohmann::json::parse(result.out);
    for (const std::string& id : row.ids) {
      bool flagged = false;
      for (const auto& d : doc["diagnostics"]) {
        if (d["rule"] != row.rule || d["severity"] == "info" || !d.contains("related")) continue;
        for (const auto& related : d["related"]) flagged |= related == "SimReady " + id;
      }
      CHECK(flagged);
    }
  }
}

TEST_CASE("docs/simready.md: SARIF carries the requirement ids", "[simready]") {
  const auto sarif = nlohmann::json::parse(
      run_cli({"--output-format", "sarif", "rules/mimic-constraint-invalid/gearing_zero.usda"}, fixtures_dir()).out);
  const auto& results = sarif["runs"][0]["results"];
  REQUIRE(results.size() == 1);
  CHECK(results[0]["properties"]["related"] == nlohmann::json::array({"SimReady DJ.007"}));
}
