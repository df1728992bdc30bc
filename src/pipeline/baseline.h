#pragma once
// A baseline: the findings a repository had when it adopted asset-lint, recorded by keys
// that survive unrelated edits (rule, path relative to the baseline's directory, the
// element or prim and the attribute; never line numbers or message text). A run with a
// baseline reports only findings not in it, and names the entries that no longer occur.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/lint.h"

namespace assetlint {

struct BaselineEntry {
  std::string path;       // '/'-separated, relative to the baseline file's directory
  std::string element;    // "joint 'finger_joint'", "/gripper/driven"; empty outside any
  std::string attribute;  // "limit.velocity", "drive:angular:physics:stiffness"; may be empty
  std::string rule;
  std::size_t count = 1;  // findings with this key

  bool same_key(const BaselineEntry& other) const;
  std::string to_string() const;  // "gripper.urdf: joint 'finger_joint' limit.lower [limits-inverted]"
};

// The entries of `reports`' findings, sorted, one per key with its count; paths relative
// to `directory`.
std::vector<BaselineEntry> baseline_entries(const std::vector<FileReport>& reports,
                                            const std::filesystem::path& directory);

// The baseline file's text: JSON, one entry per key, sorted (diffs stay small).
std::string baseline_text(const std::vector<BaselineEntry>& entries);
// Reads a baseline file; nullopt with `error` set when it cannot be read or is not one.
std::optional<std::vector<BaselineEntry>> read_baseline(const std::string& path, std::string& error);

struct BaselineMatch {
  std::size_t matched = 0;            // findings dropped from the reports
  std::vector<BaselineEntry> stale;   // entries (of files this run checked) that no longer occur
};

// Drops from `reports` the findings the baseline records (up to each entry's count).
BaselineMatch apply_baseline(std::vector<FileReport>& reports, const std::vector<BaselineEntry>& baseline,
                             const std::filesystem::path& directory);

}  // namespace assetlint
