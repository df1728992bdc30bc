#include "cli/rule_pages.h"

#include <fmt/format.h>

#include "commands/exit_status.h"
#include "report/rule_docs.h"
#include "rules/registry.h"
#include "util/numbers.h"

namespace assetlint::cli {

void list_rules(std::ostream& out) {
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

}  // namespace assetlint::cli
