#pragma once
// The fixer: lints a file, applies the fixes it may, re-lints the result in memory
// and repeats until no fix applies. Nothing here writes to disk (see writer.h).
//
//   FixResult r = fix::fix_file("robot.urdf", settings, {.unsafe = true});
//   if (!r.error) for (const auto& f : r.files) fix::write_fixed_file(f);
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "engine/diagnostic.h"
#include "engine/file_system.h"
#include "pipeline/lint.h"
#include "engine/settings.h"

namespace assetlint::fix {

// Which source files a fix may edit, by the path the reader gave the source
// (FileReport::sources[id]->path()). A fix with an edit elsewhere is not applied.
using EditScope = std::function<bool(const std::string& path)>;

// The checked file itself and any file under its directory (the default).
EditScope default_scope(const std::string& checked_path);
// Any file under the directory `root`; for a file, default_scope(root).
EditScope tree_scope(const std::string& root);
// Whether `path` is `root` or lies under it (both made absolute; symbolic links
// resolved, so a link that leads out of the tree is outside it).
bool path_within(const std::string& path, const std::string& root);

// Whether --fix (and --unsafe-fixes when `unsafe`) applies this fix. Display fixes never.
bool fix_applies(const Fix& fix, bool unsafe);

struct FixOptions {
  bool unsafe = false;    // also apply Applicability::Unsafe fixes
  int max_rounds = 10;    // lint-and-apply rounds before giving up (no convergence)
  EditScope scope;        // empty: default_scope(path)
  // Called with each round's lint before its fixes are collected. For tests and
  // tools: it may add or change diagnostics and fixes (edits on the report's texts).
  std::function<void(FileReport&)> on_report;
};

// One fix the fixer applied, with its edits resolved to paths.
struct AppliedFix {
  std::string rule;
  std::string title;
  Applicability applicability = Applicability::Safe;
  struct PathEdit {
    std::string path;
    std::size_t offset = 0;  // in the text the round started from
    std::size_t length = 0;
    std::string replacement;
  };
  std::vector<PathEdit> edits;
};

// One lint-and-apply round: the texts it started from (every source of the report)
// and the fixes it applied to them.
struct FixRound {
  std::vector<std::pair<std::string, std::string>> texts;  // path, bytes
  std::vector<AppliedFix> applied;
};

// A file whose bytes the fixes change.
struct FixedFile {
  std::string path;      // as the reader named it (report.sources[id]->path())
  std::string original;  // the bytes that were linted first
  std::string fixed;     // the bytes after every round
  std::size_t fixes = 0; // applied fixes that edited this file
};

struct FixResult {
  std::string path;                  // the checked path
  FileReport initial;                // the first lint, of the bytes on disk
  FileReport remaining;              // the lint of the fixed text (== initial when nothing changed)
  std::vector<FixedFile> files;      // only files whose bytes change; empty on error
  std::vector<FixRound> rounds;      // rounds that applied at least one fix
  std::size_t applied = 0;           // fixes applied over all rounds
  // Fixes dropped because they are broken (would make the file unparsable, or edit
  // outside their file): full messages, "fix '<title>' [rule] would make ...".
  std::vector<std::string> internal_errors;
  // Fixes not applied for a reason the user may want to know (outside the edit scope).
  std::vector<std::string> notes;
  // The file could not be read, or the fixes did not converge: nothing to write.
  std::optional<std::string> error;

  bool changed() const { return !files.empty(); }
};

// Lints `path` (read through `files`) and computes its fixed text, in memory.
FixResult fix_file(const std::string& path, const Settings& settings, const FixOptions& options,
                   const FileSystem& files = disk());

}  // namespace assetlint::fix
