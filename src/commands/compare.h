#pragma once
// `asset-lint compare A B [C]`: do two files (URDF, USDA, MJCF) describe the same physics?
// Links and joints are paired by name (compare_names.h); every quantity both files give
// is compared in model units (radians, N·m/rad, kg, metres, in the frame of the roots).
// One `compare-mismatch` finding per difference, at the first file's span with a note at
// the other's, naming unit slips (180/π, π/180, −1 for gearing, 1000); `compare-unmatched`
// for names only one file has. With three files, the first is compared with each other.
#include <cstddef>
#include <map>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "engine/diagnostic.h"
#include "pipeline/lint.h"
#include "model/asset.h"

namespace assetlint::commands {

struct CompareOptions {
  double rtol = 1e-6;
  std::vector<std::pair<std::string, std::string>> map;  // --map a=b: first file's name = other file's name
  // Index (into the compared files) of the file a fix rewrites; -1: no fixes.
  int fix_side = -1;
};

// What a comparison of two files found, in a few numbers: the head of the text report.
struct ComparisonSummary {
  std::string file_a, file_b;      // paths as named
  std::string format_a, format_b;  // "URDF", "USD", "MJCF"
  std::size_t joints_paired = 0, joints_only_a = 0, joints_only_b = 0;
  std::size_t links_paired = 0, links_only_a = 0, links_only_b = 0;
  std::size_t values_compared = 0;  // quantities both files give, over the paired joints and links
  struct Difference {
    std::size_t count = 0;
    std::map<std::string, std::size_t> slips;  // "a sign flip" → how many of `count`
  };
  std::map<std::string, Difference> differences;  // by quantity ("upper limit", "mass")
  std::size_t differing() const;
};

// "robot.urdf (URDF) and robot.usda (USD): 5 joints and 10 links paired; …" as a few lines.
std::vector<std::string> summary_lines(const ComparisonSummary& summary);

struct Comparison {
  std::vector<Diagnostic> diagnostics;
  ComparisonSummary summary;
};

// The differences between `a` and `b`. Spans of b are shifted by `b_offset` FileIds
// (the report lists a's sources first). `fix_b`: fixes rewrite b, else a.
Comparison compare_assets(const Asset& a, const Asset& b, FileId b_offset, const CompareOptions& options, bool fix_b,
                          bool fix_enabled);

// Reads each file, compares the first with each other one, and returns one report holding
// every file's sources; `error` set when a file cannot be read or parsed. `summaries`, when
// given, receives one summary per compared pair.
FileReport compare_files(const std::vector<std::string>& paths, const SettingsFor& settings,
                         const CompareOptions& options, std::string& error,
                         std::vector<ComparisonSummary>* summaries = nullptr);

}  // namespace assetlint::commands
