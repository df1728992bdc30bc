#pragma once
// Which .xacro files of a directory a check expands: the top-level ones. A file another
// .xacro file of the directory includes is checked through its includer, and a file that
// only defines macros and properties (a library) produces no robot of its own.
#include <string>
#include <string_view>
#include <vector>

namespace assetlint::xacro {

std::vector<std::string> top_level_xacro_files(const std::vector<std::string>& paths);

// Whether a xacro file's top level holds only definitions (macros, properties, arguments,
// includes) and its root names no robot: a library that expands to no robot of its own.
bool is_xacro_library(std::string_view text);

// Whether `top` includes `file`, directly or through the files it includes (as far as the
// includes can be told without expanding, as for top_level_xacro_files).
bool includes_file(const std::string& top, const std::string& file);

}  // namespace assetlint::xacro
