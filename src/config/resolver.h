#pragma once
// Which settings apply to which file: the nearest asset-lint.toml (or the one named
// with --config) with the command line's options on top.
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "config/config.h"
#include "config/file_selection.h"
#include "engine/settings.h"

namespace assetlint::config {

// Options given on the command line; they win over every configuration file.
struct CommandLineOverrides {
  std::optional<std::vector<std::string>> select;
  std::optional<std::vector<std::string>> ignore;
  std::vector<std::string> extend_select, extend_ignore;  // added to the lists above (or the configuration's)
  std::optional<double> timesteps_per_second;
  std::optional<double> position_iterations;
  std::vector<std::string> trees;  // directories named on the command line, and the working directory
  std::string root;                // --root: the checked tree for every file
  bool allow_outside_root = false;
  std::vector<std::pair<std::string, std::string>> xacro_args;  // --xacro-arg name:=value
  std::vector<std::pair<std::string, std::string>> variants;    // --variant SET=NAME
  std::vector<std::string> targets;                             // --target NAME: replaces [targets] consumers
  FileSelectionOverrides files;     // --exclude, --extend-exclude, --no-respect-gitignore, --force-exclude
  std::string working_directory;    // what command-line exclude globs are relative to
};

class SettingsResolver {
 public:
  SettingsResolver(CommandLineOverrides overrides, std::optional<std::string> explicit_config);

  // Loads the configuration of every file up front, so that an invalid one stops the
  // run before anything is checked. Returns the first error.
  std::optional<ConfigError> prepare(const std::vector<std::string>& files);
  // The settings of a file (prepare() must have seen it, or it is loaded now). Thread-safe.
  const Settings& for_file(const std::string& path);
  std::function<const Settings&(const std::string&)> as_function();
  // Which files a walk through `path` leaves out (the nearest asset-lint.toml above it, or
  // --config, and the command line). Thread-safe.
  const FileSelection& file_selection_for(const std::string& path);

 private:
  const Settings& load(const std::string& config_path, std::optional<ConfigError>& error);

  CommandLineOverrides overrides_;
  std::optional<std::string> explicit_config_;
  std::mutex mutex_;
  std::map<std::string, std::unique_ptr<Settings>> by_config_;  // "" = no configuration file
  std::map<std::string, const Settings*> by_file_;  // found by prepare(): no second directory walk
  std::map<std::string, FileSelection> selections_;  // by configuration path ("" = none)
};

}  // namespace assetlint::config
