#pragma once
// The checked tree of a file: the project it belongs to. Composed USD layers (and
// included files) are read only inside it, unless --allow-outside-root.
//
// In order: the directory given with --root; the root of the git work tree holding the
// file (a directory with a `.git` entry); the directory of the nearest asset-lint.toml;
// the deepest directory named on the command line (or the working directory) that holds
// the file. Empty when none applies: the file's own directory.
#include <string>

#include "engine/read_policy.h"

#include "engine/settings.h"

namespace assetlint::config {

std::string checked_root(const std::string& file, const Settings& settings);

// What a check of `file` may read: the checked tree (the directory of `file` when no tree holds
// it) and the package directories ROS_PACKAGE_PATH names; anything with --allow-outside-root.
ReadPolicy read_policy(const std::string& file, const Settings& settings);

}  // namespace assetlint::config
