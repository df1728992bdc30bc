#include "engine/settings.h"

#include <algorithm>
#include <charconv>

namespace assetlint {

std::optional<MujocoVersion> parse_mujoco_version(std::string_view text) {
  int parts[3] = {0, 0, 0};
  int count = 0;
  const char* at = text.data();
  const char* end = text.data() + text.size();
  while (count < 3) {
    const auto [next, error] = std::from_chars(at, end, parts[count]);
    if (error != std::errc() || next == at) return std::nullopt;
    ++count;
    at = next;
    if (at == end) break;
    if (*at != '.') return std::nullopt;
    ++at;
  }
  if (at != end || count < 2) return std::nullopt;
  return MujocoVersion{parts[0], parts[1]};
}

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

namespace {

// How specific a selector is, as ruff ranks them: an exact id beats any glob, and a glob
// with a longer literal prefix beats a shorter one (`mimic-*` beats `*`).
std::size_t specificity(std::string_view pattern) {
  const std::size_t wildcard = pattern.find_first_of("*?");
  return wildcard == std::string_view::npos ? std::string_view::npos : wildcard;
}

// The specificity of the most specific pattern matching `rule_id`; nullopt when none does.
std::optional<std::size_t> best_match(const std::vector<std::string>& patterns, std::string_view rule_id) {
  std::optional<std::size_t> best;
  for (const auto& pattern : patterns)
    if (glob_match(pattern, rule_id)) best = std::max(best.value_or(0), specificity(pattern));
  return best;
}

}  // namespace

bool RuleSelection::enabled(std::string_view rule_id) const {
  // No select list selects every rule, as the least specific selector (`*`) would.
  const std::optional<std::size_t> selected = select.empty() ? std::optional<std::size_t>(0) : best_match(select, rule_id);
  if (!selected) return false;
  const std::optional<std::size_t> ignored = best_match(ignore, rule_id);
  // The more specific selector wins; on a tie, ignore does.
  return !ignored || *selected > *ignored;
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
