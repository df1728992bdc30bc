#pragma once
#include <ostream>
#include <vector>

#include "pipeline/lint.h"
#include "pipeline/run.h"

namespace assetlint {

// The stable JSON interface documented in docs/output-formats.md (version 1).
void write_json(std::ostream& out, const std::vector<FileReport>& reports, const RunProblems& problems = {});

}  // namespace assetlint
