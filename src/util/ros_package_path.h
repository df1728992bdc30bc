#pragma once
// Where ROS packages are looked up besides the checked tree: the entries of ROS_PACKAGE_PATH,
// then the directories given with --package-path. Both are chosen by whoever runs asset-lint
// (the CI job, the user), never by the files being checked, so reads under them are allowed.
#include <string>
#include <vector>

namespace assetlint {

std::vector<std::string> ros_package_search_path();

// --package-path: set by the CLI before any file is read.
void add_package_paths(const std::vector<std::string>& directories);

}  // namespace assetlint
