#pragma once
// Identical findings in one file, for the text format: the same rule, severity and words,
// differing only in the names they quote ('J1', 'J2', …) and the place. Text prints the
// first in full and one line for the rest; the machine formats keep every location.
#include <cstddef>
#include <vector>

#include "engine/diagnostic.h"

namespace assetlint {

struct FindingGroup {
  std::size_t first = 0;            // index of the finding printed in full
  std::vector<std::size_t> others;  // indices of the findings it stands for, in order
};

// Groups `diagnostics` (one file's findings), in the order of each group's first member.
std::vector<FindingGroup> group_identical(const std::vector<Diagnostic>& diagnostics);

// The first quoted name of a message ("link 'palm' moves …" → "palm"), or "".
std::string first_quoted(const std::string& message);

}  // namespace assetlint
