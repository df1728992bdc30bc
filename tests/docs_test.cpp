// Every rule the tool can report has its documentation page, and the page has the
// sections users rely on.
#include <catch2/catch.hpp>

#include <regex>
#include <vector>

#include "cli/command_table.h"
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

// User documentation speaks to users: the project's own history (issue numbers, work sessions,
// the development corpus's path) belongs in docs/corpus-review.md, not in the pages users read.
TEST_CASE("README and rule pages carry no development history", "[docs]") {
  const std::regex history(R"((\b[Ii]ssues? \d)|(\b[Ss]ession \d)|(\.\./shared))");
  std::vector<std::filesystem::path> pages{assetlint::test::source_dir() / "README.md"};
  for (const auto& entry : std::filesystem::directory_iterator(assetlint::test::source_dir() / "docs" / "rules"))
    pages.push_back(entry.path());
  for (const auto& page : pages) {
    const std::string text = assetlint::test::read_file(page);
    std::smatch match;
    INFO(page.filename().string());
    if (std::regex_search(text, match, history)) FAIL_CHECK("'" << match.str() << "' at offset " << match.position());
  }
}

// README's usage block is where a new user looks first: every command is on it, one line each.
TEST_CASE("README's usage block lists every command", "[docs][cli-commands]") {
  const std::string readme = assetlint::test::read_file(assetlint::test::source_dir() / "README.md");
  const std::string heading = "## Usage\n\n<!-- illustrative: the commands' synopsis -->\n```\n";
  const auto start = readme.find(heading);
  REQUIRE(start != std::string::npos);
  const std::string block = readme.substr(start, readme.find("\n```", start + heading.size()) - start);
  for (const assetlint::cli::CommandInfo& command : assetlint::cli::command_table()) {
    INFO(command.name);
    CHECK(block.find("\n" + std::string(command.synopsis) + " ") != std::string::npos);
  }
}
