#pragma once
// Findings of `asset-lint compare` (two files that should describe the same robot).
#include "engine/rule.h"

namespace assetlint::rules {

extern const RuleInfo kCompareMismatch;
extern const RuleInfo kCompareUnmatched;

}  // namespace assetlint::rules
