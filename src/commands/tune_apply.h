#pragma once
// `asset-lint tune --apply/--diff`: writes a derivation's recommended drive into the
// asset (and, for URDF, its asset-lint.toml) through the fix machinery's edits, diff and
// atomic writer (docs/tune.md "Applying").
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "commands/tune_derivation.h"

namespace assetlint::commands {

struct PlannedFile {
  std::string path;
  std::string original;
  std::string updated;
  bool create = false;               // a new asset-lint.toml
  std::vector<std::string> changes;  // one line per value written
};

struct ApplyPlan {
  std::vector<PlannedFile> files;    // only files whose bytes change
  std::vector<std::string> notes;    // values that could not be written, and why
  std::optional<std::string> error;  // nothing may be written
};

// What --apply would write. `config_path`: the asset-lint.toml named with --config, if any.
// A xacro file's expansion (read.relocate set) is written through its xacro source as --fix
// writes it: only literals written there byte for byte, each note saying why not otherwise.
ApplyPlan plan_tune_apply(const TuneDerivation& derivation, const ReadResult& read, const Settings& settings,
                          const std::optional<std::string>& config_path);

// Prints the plan as a unified diff (`diff`) or writes it atomically. Returns 0 when
// nothing changes or everything was written, 1 when --diff printed a change, 2 on error.
int carry_out(const ApplyPlan& plan, bool diff, std::ostream& out, std::ostream& err);

}  // namespace assetlint::commands
