#pragma once
#include <string_view>
#include <vector>

#include "engine/rule.h"

namespace assetlint::rules {

// Every rule that runs on the model, in the order they run.
const std::vector<const Rule*>& checks();
// Every rule id the tool can report, reader-reported ones included, sorted by id.
const std::vector<const RuleInfo*>& catalog();
const RuleInfo* find_rule(std::string_view id);

}  // namespace assetlint::rules
