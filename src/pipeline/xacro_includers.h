#pragma once
// An include-only xacro file (macros and properties, as ROS packages split a robot into a
// `…_macro.xacro` and the file that calls it) expands to no robot: checked on its own it is
// checked through the top-level xacro files of its package that include it, and keeps the
// findings that lie in it. A person edits the macro file; the editor and the hooks name it.
#include <optional>
#include <string>

#include "engine/file_system.h"
#include "engine/settings.h"
#include "pipeline/lint.h"

namespace assetlint {

// nullopt when `text` (the file `path`) is not an include-only xacro file. Otherwise the
// report of `path`: the findings in it of every top-level file that includes it (read through
// `files`, with `path` read as `text`), or an error saying that none does.
std::optional<FileReport> lint_through_includers(const std::string& path, const std::string& text,
                                                 const Settings& settings, const FileSystem& files);

}  // namespace assetlint
