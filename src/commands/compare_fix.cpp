#include "commands/compare_fix.h"

#include <fmt/format.h>

#include <map>

#include "fix/edits.h"
#include "fix/writer.h"

namespace assetlint::commands {

std::optional<std::string> apply_compare_fixes(const FileReport& report, const SettingsFor& settings, int& changed) {
  changed = 0;
  std::map<FileId, std::vector<Edit>> by_file;
  for (const Diagnostic& d : report.diagnostics) {
    if (!d.fix) continue;
    std::vector<Edit>& list = by_file[d.fix->edits.empty() ? 0 : d.fix->edits.front().file];
    // One literal fixed by two findings (a range's bound compared twice): keep the first edit.
    for (const Edit& e : d.fix->edits)
      if (!fix::edit_lists_conflict(list, {e})) list.push_back(e);
  }
  for (auto& [file, edits] : by_file) {
    const SourceFile& source = report.source(file);
    std::string fixed;
    try {
      fixed = fix::apply_edits(source.text(), edits);
    } catch (const std::invalid_argument& e) {
      return fmt::format("cannot apply the fixes to '{}': {}", source.path(), e.what());
    }
    if (fixed == source.text()) continue;
    // The fixed text must still read as a model before it replaces the file.
    OverlayFileSystem overlay(disk());
    overlay.set(source.path(), fixed);
    std::string error;
    auto read = read_asset(source.path(), settings(source.path()), error, overlay);
    if (!read || !read->usable)
      return fmt::format("the fixed '{}' would not read as a model ({}); nothing written", source.path(),
                         error.empty() ? "parse error" : error);
    if (auto failure = fix::write_atomically(source.path(), source.text(), fixed)) return failure;
    ++changed;
  }
  return std::nullopt;
}

}  // namespace assetlint::commands
