#pragma once
// Everything a run is configured with: which rules, their options and severities.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/diagnostic.h"

namespace assetlint {

// Rule selection with globs (`mimic-*`): a rule runs when it matches a select
// pattern (all rules when there is none) and no ignore pattern.
struct RuleSelection {
  std::vector<std::string> select;
  std::vector<std::string> ignore;
  bool enabled(std::string_view rule_id) const;
};

bool glob_match(std::string_view pattern, std::string_view text);

struct Settings {
  RuleSelection selection;
  std::map<std::string, Severity, std::less<>> severity_overrides;
  std::map<std::string, std::map<std::string, double, std::less<>>, std::less<>> rule_options;

  std::optional<double> rule_option(std::string_view rule, std::string_view option) const;
  Severity severity_for(std::string_view rule, Severity default_severity) const;
};

}  // namespace assetlint
