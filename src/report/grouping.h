#pragma once
// Identical findings in one file, for the text and GitHub formats: the same rule, severity
// and words, differing only in the names they quote ('J1', 'J2', …), the place, and the
// places named in notes (a xacro macro's call chain). Text prints the first in full and one
// line for the rest, GitHub one annotation per group; the other machine formats keep every
// location.
#include <cstddef>
#include <vector>

#include "engine/diagnostic.h"
#include "pipeline/lint.h"

namespace assetlint {

struct FindingGroup {
  std::size_t first = 0;            // index of the finding printed in full
  std::vector<std::size_t> others;  // indices of the findings it stands for, in order
};

// Groups `diagnostics` (one file's findings), in the order of each group's first member.
std::vector<FindingGroup> group_identical(const std::vector<Diagnostic>& diagnostics);

// "and the same on 23 more: 'palm' (31:17), 'thumb_base' (64:17), …": the places of the
// findings a group's first stands for (with the file's name when it is not the first's).
std::string same_on_more(const FileReport& report, const FindingGroup& group);

// The first quoted name of a message ("link 'palm' moves …" → "palm"), or "".
std::string first_quoted(const std::string& message);

}  // namespace assetlint
