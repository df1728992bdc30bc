#pragma once
// Which .xacro files of a directory a check expands: the top-level ones. A file another
// .xacro file of the directory includes is checked through its includer, and a file that
// only defines macros and properties (a library) produces no robot of its own.
#include <string>
#include <vector>

namespace assetlint::xacro {

std::vector<std::string> top_level_xacro_files(const std::vector<std::string>& paths);

}  // namespace assetlint::xacro
