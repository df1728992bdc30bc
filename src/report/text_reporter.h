#pragma once
#include <ostream>
#include <vector>

#include "pipeline/lint.h"
#include "pipeline/run.h"

namespace assetlint {

struct TextOptions {
  bool color = false;
  bool show_summary = true;
  bool show_source = false;  // `full`: the source line under each finding, its span underlined
};

// One line per finding, `path:line:col: severity: message [rule-id]`, its notes and help,
// then a summary.
void write_text(std::ostream& out, const std::vector<FileReport>& reports, const TextOptions& options,
                const RunProblems& problems = {});

}  // namespace assetlint
