#pragma once
// `asset-lint check`: lints the files a run names and hands the reports to the writer
// the command line chose.
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "pipeline/discovery.h"
#include "pipeline/lint.h"
#include "pipeline/run.h"

namespace assetlint::commands {

using WriteReport = std::function<void(const std::vector<FileReport>&, const RunProblems&)>;

struct CheckOptions {
  unsigned jobs = 1;
  Severity fail_on = Severity::Warning;  // the least severe finding that fails the run
  std::string baseline;        // --baseline: report only findings not recorded in this file
  std::string write_baseline;  // --write-baseline: record the findings in this file instead of reporting them
};

// Names the expansion's errors on `err`, warns about directories without assets;
// returns them for the report.
RunProblems announce_expansion(const PathExpansion& expansion, std::ostream& err);

// Lints `expansion.files`, writes the reports with `write_report`, names every I/O
// error on `err` (and in the report) and warns about directories without assets.
// With a baseline, drops the findings it records and names its stale entries on `err`;
// with write_baseline, writes the baseline file and no report.
// Returns 2 when a path, file or baseline could not be read (or written), 1 when findings
// at or above `options.fail_on` remain, 0 otherwise.
int run_check(const PathExpansion& expansion, const SettingsFor& settings, const CheckOptions& options,
              std::ostream& err, const WriteReport& write_report);

}  // namespace assetlint::commands
