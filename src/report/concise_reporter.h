#pragma once
#include <ostream>
#include <vector>

#include "pipeline/lint.h"

namespace assetlint {

// One line per finding, `path:line:col: rule-id message`; no markers, no summary.
void write_concise(std::ostream& out, const std::vector<FileReport>& reports);

}  // namespace assetlint
