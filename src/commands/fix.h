#pragma once
// `asset-lint --fix` / `--diff`: fixes every file the paths name, writes (or diffs)
// the results, reports what remains. Called by the command line after option parsing.
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "commands/check.h"
#include "fix/fixer.h"
#include "pipeline/lint.h"

namespace assetlint::commands {

struct FixCommandOptions {
  bool diff = false;    // print a unified diff instead of writing
  bool unsafe = false;  // --unsafe-fixes
  unsigned jobs = 1;
  Severity fail_on = Severity::Warning;
  SelectionFor selection_for;  // exclusions of the directory walks (empty: the defaults)
  // --add-suppressions: makes each file's fixer hook (FixOptions::on_report), which decides
  // the edits instead of the rules' fixes; and the word for what was written.
  std::function<std::function<void(FileReport&)>()> make_hook;
  // The line naming a written file (default: "fixed 2 problems in a.urdf").
  std::function<std::string(const fix::FixedFile& file)> written;
};

// Fixes the files under `paths` (directories searched as for checking). With `diff`,
// prints unified diffs to `out` and writes nothing; returns 1 when there is a diff, 0
// when none, 2 on errors. Otherwise writes the fixed files, prints what remains with
// `write_report`, and returns 0 when nothing remains, 1 when findings remain, 2 on
// read/write errors or fixes that do not converge. Per-file progress and errors go to `err`.
int run_fix_command(const std::vector<std::string>& paths, const SettingsFor& settings,
                    const FixCommandOptions& options, std::ostream& out, std::ostream& err,
                    const WriteReport& write_report);

}  // namespace assetlint::commands
