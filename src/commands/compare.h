#pragma once
// `asset-lint compare A B [C]`: do two files (URDF, USDA, MJCF) describe the same physics?
// Links and joints are paired by name (compare_names.h); every quantity both files give
// is compared in model units (radians, N·m/rad, kg, metres, in the frame of the roots).
// One `compare-mismatch` finding per difference, at the first file's span with a note at
// the other's, naming unit slips (180/π, π/180, −1 for gearing, 1000); `compare-unmatched`
// for names only one file has. With three files, the first is compared with each other.
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

// The differences between `a` and `b`. Spans of b are shifted by `b_offset` FileIds
// (the report lists a's sources first). `fix_b`: fixes rewrite b, else a.
std::vector<Diagnostic> compare_assets(const Asset& a, const Asset& b, FileId b_offset, const CompareOptions& options,
                                       bool fix_b, bool fix_enabled);

// Reads each file, compares the first with each other one, and returns one report holding
// every file's sources; `error` set when a file cannot be read or parsed.
FileReport compare_files(const std::vector<std::string>& paths, const SettingsFor& settings,
                         const CompareOptions& options, std::string& error);

}  // namespace assetlint::commands
