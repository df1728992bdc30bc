#pragma once
// A fix that rewrites a number would leave a comment at the end of its line restating the old
// number, in the file's unit or another (`stiffness = 99.48   # 5700 N*m/rad`), telling a
// story the file no longer holds. The comment's number is rewritten with the fix.
#include <memory>
#include <vector>

#include "engine/diagnostic.h"
#include "model/source.h"

namespace assetlint::fix {

// Adds to `fix` an edit for each number in a trailing comment on the line of one of its edits
// that restates the replaced number: the same value, or the value times 180/π, π/180, 1000 or
// 1/1000, within the digits the comment writes. The new number is written in the comment's
// unit with four significant digits.
void restate_trailing_comments(const std::vector<std::shared_ptr<const SourceFile>>& sources, Fix& fix);

}  // namespace assetlint::fix
