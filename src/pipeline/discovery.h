#pragma once
// Which files a run checks, from the paths named on the command line.
#include <string>
#include <vector>

namespace assetlint {

// Files to check for the given paths: files as given, directories searched
// recursively for *.urdf and *.usda (hidden directories skipped), sorted.
struct PathExpansion {
  std::vector<std::string> files;
  std::vector<std::string> errors;  // paths that do not exist
};
PathExpansion expand_paths(const std::vector<std::string>& paths);

}  // namespace assetlint
