#include "pipeline/xacro_includers.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <tuple>

#include "config/project_root.h"
#include "formats/file_kind.h"
#include "formats/xacro/entry_points.h"
#include "pipeline/discovery.h"

namespace assetlint {
namespace {

namespace fs = std::filesystem;

std::string canonical(const std::string& path) {
  std::error_code ec;
  const fs::path c = fs::weakly_canonical(path, ec);
  return ec ? fs::path(path).lexically_normal().string() : c.string();
}

// Where the includers are looked for: the ROS package that holds the file (the nearest
// directory with a package.xml, inside the checked tree), else the file's own directory.
fs::path package_of(const std::string& path, const Settings& settings) {
  std::error_code ec;
  const fs::path file = fs::absolute(path, ec).lexically_normal();
  const fs::path root = config::checked_root(path, settings);
  for (fs::path dir = file.parent_path(); !dir.empty(); dir = dir.parent_path()) {
    if (fs::exists(dir / "package.xml", ec)) return dir;
    if (dir == root || dir == dir.root_path()) break;
  }
  return file.parent_path();
}

// The top-level xacro files a check of the package's directory would expand, that include `path`.
std::vector<std::string> includers(const std::string& path, const fs::path& package) {
  std::vector<std::string> found;
  const std::string cwd = fs::current_path().string();
  for (const std::string& file : expand_paths({spelled(package, cwd)}).files)
    if (file_kind(file) == FileKind::Xacro && canonical(file) != canonical(path) && xacro::includes_file(file, path))
      found.push_back(file);
  return found;
}

}  // namespace

std::optional<FileReport> lint_through_includers(const std::string& path, const std::string& text,
                                                 const Settings& settings, const FileSystem& files) {
  if (file_kind(path) != FileKind::Xacro || !xacro::is_xacro_library(text)) return std::nullopt;
  FileReport report;
  report.path = path;
  const fs::path package = package_of(path, settings);
  const std::vector<std::string> tops = includers(path, package);
  if (tops.empty()) {
    report.error = fmt::format(
        "'{}' only defines macros and properties, and no top-level .xacro file in '{}' includes it: check the file "
        "that includes it (or name that one in [xacro] entry_points)",
        path, spelled(package, fs::current_path()));
    return report;
  }
  // The includers read this file as it is being checked (an editor's unsaved buffer, the
  // fixer's pending edits), under the name the xacro reader asks for.
  OverlayFileSystem edited(files);
  edited.set(path, text);
  edited.set(spelled(fs::absolute(path), fs::current_path()), text);
  const std::string self = canonical(path);
  std::set<std::tuple<std::size_t, std::string, std::string>> seen;
  for (const std::string& top : tops) {
    std::string error;
    const std::optional<std::string> top_text = edited.read(top, error);
    if (!top_text) continue;
    FileReport through = lint_text(top, *top_text, settings, edited);
    if (through.error) {
      report.error = fmt::format("'{}' is checked through '{}', which includes it: {}", path, top, *through.error);
      return report;
    }
    // Each includer numbers its files itself: its numbers become this report's.
    std::vector<FileId> number(through.sources.size());
    for (std::size_t i = 0; i < through.sources.size(); ++i) {
      const auto same = std::find_if(report.sources.begin(), report.sources.end(), [&](const auto& source) {
        return source->path() == through.sources[i]->path();
      });
      number[i] = static_cast<FileId>(same - report.sources.begin());
      if (same == report.sources.end()) report.sources.push_back(through.sources[i]);
    }
    const auto renumber = [&](FileId& file) {
      if (file != kNoFile && file < number.size()) file = number[file];
    };
    for (Diagnostic& d : through.diagnostics) {
      if (d.span.file >= through.sources.size() || canonical(through.source(d.span.file).path()) != self) continue;
      if (!seen.emplace(d.span.offset, d.rule, d.message).second) continue;  // the same finding through another top
      renumber(d.span.file);
      for (Note& note : d.notes) renumber(note.span.file);
      if (d.fix)
        for (Edit& edit : d.fix->edits) renumber(edit.file);
      report.diagnostics.push_back(std::move(d));
    }
  }
  return report;
}

}  // namespace assetlint
