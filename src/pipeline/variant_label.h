#pragma once
// How a finding names the variant selections it was found with. Its primary message starts
// "in variant PhysX=Enabled: " (one selection) or "in variants PhysX=Enabled; MuJoCo=Enabled: "
// (several); a selection that takes a nested set too names each set it selects
// ("Newton=Enabled, NewtonSolver=Featherstone"). The JSON and SARIF reports read the selections
// back from that prefix, so the message and their `variants` field always agree.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace assetlint {

using VariantChoice = std::pair<std::string, std::string>;  // set, variant
using VariantSelection = std::vector<VariantChoice>;

// "Newton=Enabled, NewtonSolver=Featherstone"
std::string selection_label(const VariantSelection& selection);
// "in variant A=B: ", "in variants A=B; C=D, E=F: "
std::string variant_prefix(const std::vector<VariantSelection>& selections);
// The selections a message's prefix names; empty when it has none.
std::vector<VariantSelection> variant_selections(std::string_view message);

}  // namespace assetlint
