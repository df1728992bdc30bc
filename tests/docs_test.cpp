// Every rule the tool can report has its documentation page, and the page has the
// sections users rely on.
#include <catch2/catch.hpp>

#include "rules/registry.h"
#include "test_support.h"

TEST_CASE("every registered rule has docs/rules/<id>.md with the fixed sections", "[docs]") {
  for (const assetlint::RuleInfo* rule : assetlint::rules::catalog()) {
    const auto page = assetlint::test::source_dir() / "docs" / "rules" / (std::string(rule->id) + ".md");
    INFO("rule " << rule->id);
    REQUIRE(std::filesystem::exists(page));
    const std::string text = assetlint::test::read_file(page);
    CHECK(text.rfind("# " + std::string(rule->id), 0) == 0);
    for (const char* section : {"## What it checks", "## Why it matters", "## Example", "## Fix", "## Options"})
      CHECK(text.find(section) != std::string::npos);
    for (const auto& option : rule->options) CHECK(text.find(std::string(option.name)) != std::string::npos);
  }
}

TEST_CASE("docs/rules holds no page for a rule that does not exist", "[docs]") {
  for (const auto& entry : std::filesystem::directory_iterator(assetlint::test::source_dir() / "docs" / "rules")) {
    INFO(entry.path().string());
    CHECK(assetlint::rules::find_rule(entry.path().stem().string()) != nullptr);
  }
}
