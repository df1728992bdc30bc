#pragma once
// `asset-lint compare A B [C]` as a command: options checked, files compared, fixes
// written to the --fix-side file, the report handed to the writer.
#include <ostream>
#include <string>
#include <vector>

#include "commands/check.h"
#include "commands/compare.h"

namespace assetlint::commands {

struct CompareCommandOptions {
  std::vector<std::string> map_pairs;  // "a=b"
  double rtol = 1e-6;
  std::string fix_side;  // a compared path (or its file name); empty: none
  bool fix = false;
  // Print the summary of each compared pair before the findings (the text formats).
  bool summary = false;
};

// 0 when the files agree, 1 when they differ, 2 on a usage or read error.
int run_compare(const std::vector<std::string>& paths, const CompareCommandOptions& options, const SettingsFor& settings,
                std::ostream& out, std::ostream& err, const WriteReport& write_report);

}  // namespace assetlint::commands
