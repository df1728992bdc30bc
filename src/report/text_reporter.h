#pragma once
#include <ostream>
#include <vector>

#include "pipeline/lint.h"
#include "pipeline/run.h"

namespace assetlint {

struct TextOptions {
  bool color = false;
  bool show_summary = true;
};

// One line per finding, `path:line:col: severity: message [rule-id]`, then a summary.
void write_text(std::ostream& out, const std::vector<FileReport>& reports, const TextOptions& options,
                const RunProblems& problems = {});

}  // namespace assetlint
