#pragma once
// What a run could not look at, for every report: a gate never says "clean" about
// files it did not read.
#include <cstddef>
#include <vector>

#include "pipeline/discovery.h"

namespace assetlint {

struct RunProblems {
  std::vector<PathError> errors;  // paths and files not read: the run exits 2
  std::size_t binary_usd = 0;     // binary USD files found in directories, not checked
};

}  // namespace assetlint
