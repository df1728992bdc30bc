#include "report/statistics.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>

#include "rules/registry.h"

namespace assetlint {

std::vector<RuleCount> count_by_rule(const std::vector<FileReport>& reports) {
  std::map<std::string, RuleCount> by_rule;
  for (const auto& report : reports) {
    for (const auto& d : report.diagnostics) {
      RuleCount& c = by_rule[d.rule];
      c.rule = d.rule;
      ++c.count;
      if (d.fix && d.fix->applicability == Applicability::Safe) ++c.fixable;
    }
  }
  std::vector<RuleCount> out;
  for (auto& [rule, count] : by_rule) out.push_back(std::move(count));
  std::stable_sort(out.begin(), out.end(), [](const RuleCount& a, const RuleCount& b) { return a.count > b.count; });
  return out;
}

namespace {
std::string_view summary_of(const std::string& rule) {
  const RuleInfo* info = rules::find_rule(rule);
  return info ? info->summary : std::string_view();
}
}  // namespace

void write_statistics_text(std::ostream& out, const std::vector<FileReport>& reports) {
  const auto counts = count_by_rule(reports);
  std::size_t count_width = 1, rule_width = 0;
  bool any_fixable = false;
  for (const auto& c : counts) {
    count_width = std::max(count_width, std::to_string(c.count).size());
    rule_width = std::max(rule_width, c.rule.size());
    any_fixable = any_fixable || c.fixable;
  }
  for (const auto& c : counts) {
    const std::string marker = c.fixable ? "[*] " : any_fixable ? "    " : "";
    out << fmt::format("{:>{}}  {:<{}}  {}{}\n", c.count, count_width, c.rule, rule_width, marker, summary_of(c.rule));
  }
}

void write_statistics_json(std::ostream& out, const std::vector<FileReport>& reports) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& c : count_by_rule(reports))
    list.push_back({{"rule", c.rule}, {"count", c.count}, {"fixable", c.fixable}, {"summary", summary_of(c.rule)}});
  out << list.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
}

}  // namespace assetlint
