#include <fmt/format.h>

#include <cmath>

#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// PHYSICS.md §3 and the guide: leave max joint velocity unset on mimic joints; the
// followed joint's limit already bounds them through the gearing, and a lower
// limit on the mimic makes the velocity clamp fight the mimic constraint.
// Relative slack for limits written with fewer digits than the product.
constexpr double kSlack = 1e-6;
// USD's maxJointVelocity default (deg/s): authoring it explicitly changes nothing.
constexpr double kUsdDefaultMaxVelocityDeg = 1e6;

class MimicMaxVelocity final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings&, Reporter& out) const override {
    for (const Joint& joint : asset.joints) {
      if (!joint.mimic || !is_single_dof(joint.type) || !joint.velocity || !joint.velocity->span.valid()) continue;
      const Quantity& velocity = *joint.velocity;
      const Joint* reference = asset.followed_joint(joint);
      const double gearing = std::fabs(joint.mimic->multiplier.value);
      const Quantity* reference_velocity =
          reference && is_single_dof(reference->type) && reference->velocity && reference->velocity->value > 0 ? &*reference->velocity : nullptr;

      if (asset.format == SourceFormat::Usda) {
        if (velocity.authored >= kUsdDefaultMaxVelocityDeg) continue;
        // USD can leave the attribute unauthored, which is what the guide asks for.
        std::string comparison =
            reference_velocity
                ? fmt::format("; '{}' is limited to {}, which bounds this joint at {} through gearing {}",
                              reference->name.text, describe(*reference_velocity),
                              describe(gearing * reference_velocity->value, velocity.unit),
                              format_number(joint.mimic->multiplier.authored))
                : std::string();
        Diagnostic& d = out.report(
            velocity.span, fmt::format("mimic {} sets max joint velocity {}; leave it unset on mimic joints{}",
                                       joint_label(joint), describe(velocity), comparison));
        if (velocity.declaration.valid()) {
          d.fix = Fix{"remove maxJointVelocity from the mimic joint", Applicability::Safe,
                      {Edit{velocity.declaration.file, velocity.declaration.offset, velocity.declaration.length, ""}}};
        }
        continue;
      }

      if (!reference_velocity) continue;
      const double needed = gearing * reference_velocity->value;
      if (velocity.value >= needed * (1 - kSlack)) continue;
      Diagnostic& d = out.report(
          velocity.span,
          fmt::format("mimic {} is limited to {}, below |multiplier {}| × {} of '{}' = {}: the velocity clamp "
                      "fights the mimic constraint",
                      joint_label(joint), describe(velocity), format_number(joint.mimic->multiplier.authored),
                      describe(*reference_velocity), reference->name.text, describe(needed, velocity.unit)));
      d.fix = Fix{fmt::format("raise the limit to {}", describe(needed, velocity.unit)), Applicability::Safe,
                  {Edit{velocity.span.file, velocity.span.offset, velocity.span.length,
                        format_number_at_least(velocity.authored_for(needed))}}};
    }
  }

 private:
  RuleInfo info_{"mimic-max-velocity",
                 "A mimic joint's own velocity limit can clamp it below what the joint it follows demands",
                 Severity::Warning, true, RuleOrigin::Check, {}};
};

}  // namespace

const Rule& mimic_max_velocity() {
  static const MimicMaxVelocity rule;
  return rule;
}

}  // namespace assetlint::rules
