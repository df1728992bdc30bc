#include "rules/compare_rules.h"

namespace assetlint::rules {

const RuleInfo kCompareMismatch{
    "compare-mismatch",
    "`compare`: two files give a joint, link or the scene different physics (a unit slip when the ratio says so)",
    Severity::Error, true, RuleOrigin::Reader, {}};

const RuleInfo kCompareUnmatched{
    "compare-unmatched",
    "`compare`: a joint or link of one file has no counterpart in the other",
    Severity::Info, false, RuleOrigin::Reader, {}};

}  // namespace assetlint::rules
