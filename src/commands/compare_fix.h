#pragma once
// Writing `compare`'s fixes into the file the user named with --fix-side.
#include <optional>
#include <string>

#include "pipeline/lint.h"

namespace assetlint::commands {

// Applies every fix of `report` (they all edit the fix side), checks that each edited file
// still reads as a model, and writes it atomically. Returns what went wrong, if anything;
// `changed` counts the files written.
std::optional<std::string> apply_compare_fixes(const FileReport& report, const SettingsFor& settings, int& changed);

}  // namespace assetlint::commands
