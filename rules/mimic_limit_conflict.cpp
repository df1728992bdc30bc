#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

class MimicLimitConflict final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const double tolerance = rule_option(info_, settings, "tolerance");
    for (const Joint& joint : asset.joints) {
      if (!joint.mimic || joint.type == JointType::Continuous || !is_single_dof(joint.type) || !joint.lower || !joint.upper)
        continue;
      const Joint* reference = asset.followed_joint(joint);
      if (!reference || reference->type == JointType::Continuous || !is_single_dof(reference->type) || !reference->lower ||
          !reference->upper)
        continue;
      if (reference->lower->value > reference->upper->value || joint.lower->value > joint.upper->value) continue;
      const double m = joint.mimic->multiplier.value;
      const double offset = joint.mimic->offset.value;
      const double a = m * reference->lower->value + offset;
      const double b = m * reference->upper->value + offset;
      const double mapped_low = std::min(a, b), mapped_high = std::max(a, b);
      const bool below = mapped_low < joint.lower->value - tolerance;
      const bool above = mapped_high > joint.upper->value + tolerance;
      if (!below && !above) continue;

      const Unit unit = joint.lower->unit;
      const auto range = [&](double low, double high) {
        return fmt::format("[{}, {}]", format_number(from_model_units(low, unit)), format_number(from_model_units(high, unit)));
      };
      const std::string convention = asset.format == SourceFormat::Usda
                                         ? fmt::format("q + {}·q_ref + {} = 0",
                                                       format_number(joint.mimic->multiplier.authored),
                                                       format_number(joint.mimic->offset.authored))
                                         : fmt::format("multiplier {}, offset {}", format_number(m),
                                                       format_number(from_model_units(offset, unit)));
      Diagnostic& d = out.report(
          (below ? joint.lower : joint.upper)->span.valid() ? (below ? joint.lower : joint.upper)->span : joint.limit_span,
          fmt::format("range {} {} of '{}' maps through the mimic ({}) to {} {}, outside the limits {} of {}: "
                      "the joint limit fights the mimic constraint",
                      range(reference->lower->value, reference->upper->value), unit_symbol(unit), reference->name.text,
                      convention, range(mapped_low, mapped_high), unit_symbol(unit),
                      range(joint.lower->value, joint.upper->value), joint_label(joint)));
      std::vector<Edit> edits;
      if (below && joint.lower->span.valid()) edits.push_back(replace_value(*joint.lower, mapped_low, 8));
      if (above && joint.upper->span.valid()) edits.push_back(replace_value(*joint.upper, mapped_high, 8));
      if (!edits.empty()) {
        d.fix = Fix{fmt::format("widen the limits to {} {}", range(std::min(mapped_low, joint.lower->value),
                                                                   std::max(mapped_high, joint.upper->value)),
                                unit_symbol(unit)),
                    Applicability::Unsafe, std::move(edits)};
      }
    }
  }

 private:
  RuleInfo info_{"mimic-limit-conflict",
                 "The followed joint's range, mapped through the mimic gearing, leaves the mimic joint's limits",
                 Severity::Error,
                 true,
                 RuleOrigin::Check,
                 {{"tolerance", 1e-4, "how far (rad or m) the mapped range may stick out before it is reported"}}};
};

}  // namespace

const Rule& mimic_limit_conflict() {
  static const MimicLimitConflict rule;
  return rule;
}

}  // namespace assetlint::rules
