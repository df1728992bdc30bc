// The MJCF reader and the rules over the real models in ../shared/corpus/mjcf (MuJoCo
// Menagerie, MuJoCo's humanoid); skipped when the corpus is absent.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <sstream>

#include "pipeline/discovery.h"
#include "pipeline/lint.h"
#include "formats/mjcf/mjcf_reader.h"
#include "test_support.h"

using namespace assetlint;

namespace {

std::filesystem::path mjcf_corpus() {
  const auto dir = test::corpus_dir();
  return dir.empty() || !std::filesystem::is_directory(dir / "mjcf") ? std::filesystem::path() : dir / "mjcf";
}

Settings corpus_settings() {
  Settings settings;
  settings.trees.push_back(mjcf_corpus().string());
  return settings;
}

}  // namespace

TEST_CASE("every corpus MJCF is read without a crash, with located findings", "[corpus][mjcf]") {
  const auto dir = mjcf_corpus();
  if (dir.empty()) {
    WARN("../shared/corpus/mjcf is absent: MJCF corpus test skipped");
    return;
  }
  const PathExpansion found = expand_paths({dir.string()});
  CHECK(found.files.size() >= 12);
  std::map<std::string, std::size_t> per_rule;
  for (const auto& file : found.files) {
    INFO(file);
    const FileReport report = lint_file(file, corpus_settings());
    REQUIRE_FALSE(report.error.has_value());
    for (const auto& d : report.diagnostics) {
      CHECK(d.span.line >= 1);
      CHECK(d.span.column >= 1);
      CHECK(d.rule != "parse-error");
      ++per_rule[d.rule];
    }
  }
  std::ostringstream counts;
  for (const auto& [rule, n] : per_rule) counts << rule << " " << n << "\n";
  WARN("findings per rule over " << found.files.size() << " MJCF files:\n" << counts.str());
}

TEST_CASE("corpus MJCF: degrees by default, includes, default classes and couplings", "[corpus][mjcf]") {
  const auto dir = mjcf_corpus();
  if (dir.empty()) {
    WARN("../shared/corpus/mjcf is absent: skipped");
    return;
  }
  std::string error;
  // Cassie writes no <compiler angle>: its ranges are degrees.
  auto cassie = read_asset((dir / "agility_cassie" / "cassie.xml").string(), corpus_settings(), error);
  REQUIRE(cassie);
  REQUIRE(cassie->usable);
  const Joint* any_limited = nullptr;
  for (const Joint& j : cassie->asset.joints)
    if (j.upper && j.upper->is_authored()) any_limited = &j;
  REQUIRE(any_limited);
  CHECK(any_limited->upper->unit == Unit::Degree);

  // ALOHA's position actuators come from an included file and default classes.
  auto aloha = read_asset((dir / "aloha" / "aloha.xml").string(), corpus_settings(), error);
  REQUIRE(aloha);
  REQUIRE(aloha->usable);
  CHECK(aloha->asset.sources.size() >= 2);
  std::size_t driven = 0, mimics = 0;
  for (const Joint& j : aloha->asset.joints) {
    if (j.drive && j.drive->stiffness && j.drive->stiffness->value > 0) ++driven;
    if (j.mimic) ++mimics;
  }
  CHECK(driven >= 12);
  CHECK(mimics == 2);

  // UR5e: affine <general> actuators set through nested classes.
  auto ur5e = read_asset((dir / "universal_robots_ur5e" / "ur5e.xml").string(), corpus_settings(), error);
  REQUIRE(ur5e);
  std::size_t ur_driven = 0;
  for (const Joint& j : ur5e->asset.joints)
    if (j.drive && j.drive->stiffness && j.drive->stiffness->value > 0 && j.drive->max_force) ++ur_driven;
  CHECK(ur_driven == 6);
}
