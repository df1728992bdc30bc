#pragma once
// `asset-lint --list-rules` and `asset-lint rule ID`.
#include <ostream>
#include <string>

namespace assetlint::cli {

void list_rules(std::ostream& out);
// Prints the rule's page, default severity, fix and options; 2 when there is no such rule.
int show_rule(const std::string& id, std::ostream& out, std::ostream& err);

}  // namespace assetlint::cli
