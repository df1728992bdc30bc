#pragma once
// Byte-range edits on one text: conflict detection and application. Pure functions,
// no I/O; the fixer and the tests share them.
#include <string>
#include <string_view>
#include <vector>

#include "engine/diagnostic.h"

namespace assetlint::fix {

// Whether two edits of the same file may not both be applied: their ranges overlap,
// they start at the same offset (two insertions, or an insertion where another edit
// starts), or an insertion sits at the end of the other edit. Edits of different
// files never conflict.
bool edits_conflict(const Edit& a, const Edit& b);

// Whether any edit of `a` conflicts with any edit of `b`.
bool edit_lists_conflict(const std::vector<Edit>& a, const std::vector<Edit>& b);

// Whether the edits of one fix are usable on their own: each lies inside `text`
// (edits must all name the same file as the text) and no two of them conflict.
bool edits_fit(const std::vector<Edit>& edits, std::string_view text);

// Applies non-conflicting edits (all on this one text, any order) and returns the
// new text. Bytes outside the edit ranges are copied unchanged. Throws
// std::invalid_argument if an edit is out of range or two edits conflict.
std::string apply_edits(std::string_view text, std::vector<Edit> edits);

}  // namespace assetlint::fix
