#include "rules/support.h"

#include <fmt/format.h>

#include <cmath>

#include "util/numbers.h"

namespace assetlint::rules {

std::string describe(double model_value, Unit file_unit, int significant) {
  const auto with_symbol = [](const std::string& number, Unit unit) {
    const auto symbol = unit_symbol(unit);
    return symbol.empty() ? number : number + " " + std::string(symbol);
  };
  const std::string in_file = with_symbol(format_number(from_model_units(model_value, file_unit), significant), file_unit);
  if (!converts(file_unit) || file_unit == Unit::UsdGearing) return in_file;
  return fmt::format("{} ({})", in_file, with_symbol(format_number(model_value, significant), model_unit(file_unit)));
}

std::string describe(const Quantity& q, int significant) { return describe_written(q, q.value, significant); }

std::string describe_written(const Quantity& q, double model_value, int significant) {
  if (q.scale == 1.0 || !q.span.valid()) return describe(model_value, q.unit, significant);
  const auto symbol = unit_symbol(model_unit(q.unit));
  // The literal is scaled on its way to the model: a USD stage's units, an MJCF actuator's gear.
  return fmt::format("{} in file units ({}{}{})", format_number(q.authored_for(model_value), significant),
                     format_number(model_value, significant), symbol.empty() ? "" : " ", symbol);
}

std::optional<MimicDemand> mimic_demand(const Asset& asset, const Joint& joint) {
  if (!joint.mimic || !is_single_dof(joint.type)) return std::nullopt;
  const Joint* reference = asset.followed_joint(joint);
  if (!reference || !is_single_dof(reference->type) || !reference->velocity || reference->velocity->value <= 0)
    return std::nullopt;
  return MimicDemand{reference, &*reference->velocity,
                     std::fabs(joint.mimic->multiplier.value) * reference->velocity->value};
}

Edit replace_value(const Quantity& q, double model_value, int significant) {
  return Edit{q.span.file, q.span.offset, q.span.length, format_number(q.authored_for(model_value), significant)};
}

std::string short_path(const std::string& name) {
  const auto slash = name.find_last_of('/');
  return slash == std::string::npos ? name : name.substr(slash + 1);
}

std::string joint_label(const Joint& joint) {
  return fmt::format("{} joint '{}'", joint_type_name(joint.type), joint.name.text);
}

}  // namespace assetlint::rules
