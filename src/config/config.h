#pragma once
// asset-lint.toml: found by walking up from each checked file (to the git work tree's root), or
// named with --config.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "config/file_selection.h"
#include "engine/settings.h"

namespace assetlint::config {

struct ConfigError {
  std::string path;
  std::uint32_t line = 0;
  std::uint32_t column = 0;
  std::string message;
  std::string to_string() const;  // "path:line:col: message"
};

// Reads a configuration file into `settings` (on top of what it holds).
// Unknown keys and bad values are errors; nothing is applied when there is one.
// Origins in messages name the file as `display_path` (default: `path`).
// `files`, when given, receives the file-selection keys (exclude, extend-exclude, respect-gitignore).
std::optional<ConfigError> load(const std::string& path, Settings& settings, const std::string& display_path = "",
                                FileSelectionConfig* files = nullptr);

// Rule patterns with where each was given.
using RulePatterns = std::vector<Configured<std::string>>;
// Replaces the select (is_select) or ignore list of `selection` with `patterns`.
void set_patterns(RuleSelection& selection, bool is_select, const RulePatterns& patterns);
// Adds `more` to a select or ignore list. Extending an empty select list (every rule)
// keeps every rule: it becomes `*` plus `more`.
void extend(RuleSelection& selection, bool is_select, const RulePatterns& more);
// `patterns` all given at `origin` (a command-line flag).
RulePatterns patterns_from(const std::vector<std::string>& patterns, const std::string& origin);

// The same for configuration text already in memory; `path` names it in errors.
std::optional<ConfigError> load_text(std::string_view text, const std::string& path, Settings& settings,
                                     const std::string& display_path = "");

// The nearest asset-lint.toml in the file's directory or an ancestor, up to the root of the git
// work tree holding the file (a configuration above the repository belongs to something else);
// empty if none.
std::filesystem::path discover(const std::filesystem::path& file);

// Where discover() looked: from the file's directory up to `last`, the work tree's root
// (`git_root`) or the file system's.
struct ConfigSearch {
  std::filesystem::path found;  // as discover() returns it
  std::filesystem::path first, last;
  bool git_root = false;
};
ConfigSearch search_config(const std::filesystem::path& file);

inline constexpr const char* kFileName = "asset-lint.toml";

}  // namespace assetlint::config
