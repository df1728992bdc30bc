#pragma once
#include <ostream>
#include <string>
#include <vector>

#include "pipeline/lint.h"

namespace assetlint {

struct RuleCount {
  std::string rule;
  std::size_t count = 0;
  std::size_t fixable = 0;  // with a safe fix
};

// Findings per rule, most frequent first (ties by rule id).
std::vector<RuleCount> count_by_rule(const std::vector<FileReport>& reports);

// `--statistics`: one line per rule, `count  rule-id  [*] summary` ([*]: some have a safe fix).
void write_statistics_text(std::ostream& out, const std::vector<FileReport>& reports);
// The same as a JSON array of {rule, count, fixable, summary}.
void write_statistics_json(std::ostream& out, const std::vector<FileReport>& reports);

}  // namespace assetlint
