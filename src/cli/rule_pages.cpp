#include "cli/rule_pages.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "commands/exit_status.h"
#include "report/rule_docs.h"
#include "rules/registry.h"
#include "util/numbers.h"
#include "util/spelling.h"

namespace assetlint::cli {

void list_rules(std::ostream& out, bool json) {
  if (json) {
    nlohmann::ordered_json rules = nlohmann::ordered_json::array();
    for (const RuleInfo* rule : rules::catalog()) {
      nlohmann::ordered_json options = nlohmann::ordered_json::array();
      for (const auto& option : rule->options)
        options.push_back({{"name", std::string(option.name)},
                           {"default", option.default_value},
                           {"description", std::string(option.description)}});
      rules.push_back({{"id", std::string(rule->id)},
                       {"severity", std::string(severity_name(rule->default_severity))},
                       {"fixable", rule->fixable},
                       {"summary", std::string(rule->summary)},
                       {"options", std::move(options)}});
    }
    out << rules.dump(2) << "\n";
    return;
  }
  std::size_t width = 0;
  for (const RuleInfo* rule : rules::catalog()) width = std::max(width, rule->id.size());
  for (const RuleInfo* rule : rules::catalog()) {
    out << fmt::format("{:<{}}  {:<7}  {:<7}  {}\n", rule->id, width, severity_name(rule->default_severity),
                       rule->fixable ? "fixable" : "", rule->summary);
  }
}

int show_rule(const std::string& id, std::ostream& out, std::ostream& err) {
  const RuleInfo* rule = rules::find_rule(id);
  if (!rule) {
    std::vector<std::string> ids;
    for (const RuleInfo* known : rules::catalog()) ids.emplace_back(known->id);
    if (auto nearest = nearest_spelling(id, ids))
      err << fmt::format("asset-lint: error: unknown rule '{}'; did you mean '{}'?\n", id, *nearest);
    else
      err << fmt::format("asset-lint: error: unknown rule '{}'; `asset-lint --list-rules` lists them\n", id);
    return commands::kExitError;
  }
  for (const auto& [doc_id, page] : rule_docs()) {
    if (doc_id == id) {
      out << page;
      if (!page.empty() && page.back() != '\n') out << "\n";
      break;
    }
  }
  out << fmt::format("\nDefault severity: {}. Fix: {}.\n", severity_name(rule->default_severity),
                     rule->fixable ? "available" : "none");
  if (!rule->options.empty()) {
    out << "Options ([rules." << rule->id << "] in asset-lint.toml):\n";
    for (const auto& option : rule->options)
      out << fmt::format("  {} = {}  {}\n", option.name, format_number(option.default_value, 6), option.description);
  }
  return commands::kExitClean;
}

int run_rule_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  constexpr const char* kUsage =
      "usage: asset-lint rule RULE-ID   print a rule's documentation, default severity, fix and options\n"
      "       asset-lint rule --all     print every rule's documentation\n"
      "       asset-lint --list-rules   list the rules (--output-format json for a machine-readable list)\n";
  if (args.size() == 2 && (args[1] == "--help" || args[1] == "-h")) {
    out << kUsage;
    return commands::kExitClean;
  }
  if (args.size() == 2 && args[1] == "--all") {
    bool first = true;
    for (const RuleInfo* rule : rules::catalog()) {
      if (!first) out << "\n";
      first = false;
      show_rule(std::string(rule->id), out, err);
    }
    return commands::kExitClean;
  }
  if (args.size() != 2 || args[1].starts_with("-")) {
    err << "asset-lint: error: " << kUsage;
    return commands::kExitError;
  }
  return show_rule(args[1], out, err);
}

}  // namespace assetlint::cli
