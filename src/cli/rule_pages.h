#pragma once
// `asset-lint --list-rules` and `asset-lint rule ID`.
#include <ostream>
#include <string>
#include <vector>

namespace assetlint::cli {

// One line per rule; with `json`, an array of {id, severity, fixable, origin, summary, options}.
void list_rules(std::ostream& out, bool json = false);
// Prints the rule's page, default severity, fix and options; 2 when there is no such rule.
int show_rule(const std::string& id, std::ostream& out, std::ostream& err);
// `asset-lint rule RULE-ID | --all | --help`.
int run_rule_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace assetlint::cli
