#include "report/variant_json.h"

#include "pipeline/variant_label.h"

namespace assetlint {

std::optional<nlohmann::ordered_json> variants_json(std::string_view message) {
  const auto selections = variant_selections(message);
  if (selections.empty()) return std::nullopt;
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const auto& selection : selections) {
    nlohmann::ordered_json choices = nlohmann::ordered_json::array();
    for (const auto& [set, variant] : selection) choices.push_back({{"set", set}, {"variant", variant}});
    out.push_back(std::move(choices));
  }
  return out;
}

}  // namespace assetlint
