#pragma once
// `asset-lint check - --stdin-filename PATH`: lints the text on standard input as if it
// were the file PATH (its configuration, per-file-ignores and relative USD layers), for
// editors and format-on-save. With --fix the fixed text goes to standard output.
#include <istream>
#include <ostream>
#include <string>

#include "commands/check.h"
#include "engine/settings.h"

namespace assetlint::commands {

struct StdinOptions {
  std::string filename;  // the path the text stands for
  bool fix = false;
  bool unsafe = false;
  Severity fail_on = Severity::Warning;
};

// Without fix: writes the report with `write_report`. With fix: writes the fixed text (the
// input unchanged when no fix applies) to `out`, and remaining findings nowhere but the
// exit status. Returns the check's exit status.
int run_stdin(std::istream& in, const Settings& settings, const StdinOptions& options, std::ostream& out,
              std::ostream& err, const WriteReport& write_report);

}  // namespace assetlint::commands
