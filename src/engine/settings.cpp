#include "engine/settings.h"

namespace assetlint {

bool glob_match(std::string_view pattern, std::string_view text) {
  // Iterative '*' / '?' matcher with single-star backtracking: linear in practice.
  std::size_t p = 0, t = 0, star = std::string_view::npos, mark = 0;
  while (t < text.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == text[t])) {
      ++p;
      ++t;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      mark = t;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      t = ++mark;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

bool RuleSelection::enabled(std::string_view rule_id) const {
  auto matches_any = [&](const std::vector<std::string>& patterns) {
    for (const auto& pattern : patterns)
      if (glob_match(pattern, rule_id)) return true;
    return false;
  };
  if (!select.empty() && !matches_any(select)) return false;
  return !matches_any(ignore);
}

std::optional<double> Settings::rule_option(std::string_view rule, std::string_view option) const {
  auto r = rule_options.find(rule);
  if (r == rule_options.end()) return std::nullopt;
  auto o = r->second.find(option);
  if (o == r->second.end()) return std::nullopt;
  return o->second;
}

Severity Settings::severity_for(std::string_view rule, Severity default_severity) const {
  auto it = severity_overrides.find(rule);
  return it == severity_overrides.end() ? default_severity : it->second;
}

}  // namespace assetlint
