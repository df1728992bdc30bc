#pragma once
// Which files a run checks, from the paths named on the command line.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "config/file_selection.h"

namespace assetlint {

// A path that could not be looked at: it is named, never skipped in silence.
struct PathError {
  std::string path;
  std::string message;  // "cannot read directory 'x': Permission denied"
};

struct PathExpansion {
  std::vector<std::string> files;           // to check, each directory's sorted
  std::vector<PathError> errors;            // named paths that do not exist; directories not read
  std::vector<std::string> binary_usd;      // .usdc/.usdz and binary .usd files found (not checked)
  std::vector<std::string> without_assets;  // directories named that hold no asset file
};

// A path as every report spells it, so that baseline keys and fingerprints do not depend
// on how the tool was invoked: lexically normal, '/'-separated, no "./" prefix, relative
// to `cwd` when inside it.
std::string spelled(const std::filesystem::path& path, const std::filesystem::path& cwd);

// Which exclusions apply where: the file selection in effect for a path (its nearest
// asset-lint.toml and the command line). Empty: the defaults (hidden entries excluded,
// .gitignore respected).
using SelectionFor = std::function<const config::FileSelection&(const std::string& path)>;

// Files as given (spelled as above); directories searched recursively for *.urdf, *.usda,
// text .usd files (a `#usda` header), *.mjcf and *.xml whose root is <mujoco>, leaving out what `exclude` names and, inside a
// git work tree, what .gitignore files ignore. A named file (or directory) is left out
// only with force_exclude. A directory or entry that cannot be read is an error naming
// it; the rest of the walk goes on.
PathExpansion expand_paths(const std::vector<std::string>& paths, const SelectionFor& selection_for = {});

}  // namespace assetlint
