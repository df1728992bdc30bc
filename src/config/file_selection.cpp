#include "config/file_selection.h"

#include <filesystem>

#include "util/path_glob.h"

namespace assetlint::config {

const ExcludePattern* FileSelection::excluding(const std::string& path) const {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec).lexically_normal();
  const std::string name = absolute.filename().string();
  for (const auto& pattern : exclude) {
    if (pattern.glob.find('/') == std::string::npos) {
      if (path_glob_match(pattern.glob, name)) return &pattern;
      continue;
    }
    const fs::path relative = absolute.lexically_relative(pattern.base);
    if (relative.empty() || *relative.begin() == "..") continue;
    if (path_glob_match(pattern.glob, relative.generic_string())) return &pattern;
  }
  return nullptr;
}

FileSelection effective_file_selection(const std::optional<FileSelectionConfig>& config,
                                       const FileSelectionOverrides& overrides, const std::string& working_directory) {
  FileSelection selection;
  auto from_command_line = [&](const std::vector<std::string>& globs, const char* flag) {
    std::vector<ExcludePattern> patterns;
    for (const auto& glob : globs) patterns.push_back({glob, working_directory, flag});
    return patterns;
  };
  if (overrides.exclude) {
    selection.exclude = from_command_line(*overrides.exclude, "--exclude");
  } else if (config && config->exclude) {
    selection.exclude = *config->exclude;
  } else {
    for (const char* glob : kDefaultExclude) selection.exclude.push_back({glob, working_directory, "default"});
  }
  if (config) selection.exclude.insert(selection.exclude.end(), config->extend_exclude.begin(), config->extend_exclude.end());
  for (auto& pattern : from_command_line(overrides.extend_exclude, "--extend-exclude"))
    selection.exclude.push_back(std::move(pattern));
  if (config && config->respect_gitignore) selection.respect_gitignore = *config->respect_gitignore;
  if (config && config->xacro_entry_points) selection.xacro_entry_points = *config->xacro_entry_points;
  if (overrides.no_respect_gitignore) selection.respect_gitignore = {false, "--no-respect-gitignore"};
  selection.force_exclude = overrides.force_exclude;
  return selection;
}

}  // namespace assetlint::config
