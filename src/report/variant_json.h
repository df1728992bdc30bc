#pragma once
// The variant selections a finding was found with, as the JSON and SARIF reports give them:
// [[{"set": "Newton", "variant": "Enabled"}, {"set": "NewtonSolver", "variant": "Featherstone"}], ...],
// one list per selection; nullopt for a finding of the stage's own selection.
#include <optional>
#include <string_view>

#include <nlohmann/json.hpp>

namespace assetlint {

std::optional<nlohmann::ordered_json> variants_json(std::string_view message);

}  // namespace assetlint
