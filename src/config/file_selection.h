#pragma once
// Which files a directory walk leaves out: `exclude` / `extend-exclude` in asset-lint.toml
// (globs relative to its directory) and on the command line (relative to the working
// directory), and whether .gitignore files are respected.
#include <optional>
#include <string>
#include <vector>

#include "engine/settings.h"

namespace assetlint::config {

struct ExcludePattern {
  std::string glob;    // a glob without '/' matches an entry's name at any depth
  std::string base;    // absolute directory the glob is relative to
  std::string origin;  // "asset-lint.toml:3", "--exclude", "default"
};

// As one asset-lint.toml sets it.
struct FileSelectionConfig {
  std::optional<std::vector<ExcludePattern>> exclude;  // replaces the default
  std::vector<ExcludePattern> extend_exclude;
  std::optional<Configured<bool>> respect_gitignore;
  std::optional<std::vector<std::string>> xacro_entry_points;  // [xacro] entry_points, absolute
};

// As the command line sets it; wins over every configuration file.
struct FileSelectionOverrides {
  std::optional<std::vector<std::string>> exclude;
  std::vector<std::string> extend_exclude;
  bool no_respect_gitignore = false;
  bool force_exclude = false;  // exclusions apply to files named on the command line too
};

// Hidden files and directories (.git, .venv, ...), as before there was an `exclude`.
inline const char* const kDefaultExclude[] = {".*"};

struct FileSelection {
  std::vector<ExcludePattern> exclude;  // in effect: exclude (or the default), then extend-exclude
  Configured<bool> respect_gitignore{true, "default"};
  bool force_exclude = false;
  // The .xacro files a directory walk expands ([xacro] entry_points, absolute); empty: the
  // files no other .xacro file includes.
  std::vector<std::string> xacro_entry_points;

  // The pattern that excludes `path` (any spelling); nullptr when none does.
  const ExcludePattern* excluding(const std::string& path) const;
};

// The selection in effect for one configuration (nullopt: no asset-lint.toml), with the
// command line's on top; command-line globs are relative to `working_directory`.
FileSelection effective_file_selection(const std::optional<FileSelectionConfig>& config,
                                       const FileSelectionOverrides& overrides, const std::string& working_directory);

}  // namespace assetlint::config
