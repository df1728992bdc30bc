#pragma once
// `asset-lint check`: lints the files a run names and hands the reports to the writer
// the command line chose.
#include <functional>
#include <ostream>
#include <vector>

#include "pipeline/discovery.h"
#include "pipeline/lint.h"

namespace assetlint::commands {

using WriteReport = std::function<void(const std::vector<FileReport>&)>;

struct CheckOptions {
  unsigned jobs = 1;
};

// Lints `expansion.files`, writes the reports with `write_report`, names every I/O
// error on `err`. Returns 2 when a path or file could not be read, 1 when findings
// remain, 0 otherwise.
int run_check(const PathExpansion& expansion, const SettingsFor& settings, const CheckOptions& options,
              std::ostream& err, const WriteReport& write_report);

}  // namespace assetlint::commands
