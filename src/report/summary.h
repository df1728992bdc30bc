#pragma once
#include <cstddef>
#include <vector>

#include "pipeline/lint.h"

namespace assetlint {

struct Summary {
  std::size_t files = 0;
  std::size_t errors = 0;
  std::size_t warnings = 0;
  std::size_t infos = 0;
  std::size_t fixable = 0;         // safe fixes
  std::size_t unsafe_fixable = 0;  // fixes that need --unsafe-fixes
  std::size_t total() const { return errors + warnings + infos; }
};

Summary summarize(const std::vector<FileReport>& reports);

// 1-based end position (exclusive end, like LSP/SARIF regions) of a span.
LineColumn end_position(const FileReport& report, const Span& span);

}  // namespace assetlint
