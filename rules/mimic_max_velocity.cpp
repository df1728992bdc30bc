#include <fmt/format.h>

#include <cmath>

#include "rules/all_rules.h"
#include "rules/consumer_concern.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// PHYSICS.md §3 and the guide: leave max joint velocity unset on mimic joints; the
// followed joint's limit already bounds them through the gearing, and a lower
// limit on the mimic makes the velocity clamp fight the mimic constraint.
// USD's maxJointVelocity default (deg/s): authoring it explicitly changes nothing.
constexpr double kUsdDefaultMaxVelocityDeg = 1e6;

class MimicMaxVelocity final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    if (!max_velocity_read(asset, settings)) return;  // no consumer the asset is judged for bounds speed by it
    for (const Joint& joint : asset.joints) {
      if (!joint.mimic || !is_single_dof(joint.type) || !joint.velocity || !joint.velocity->span.valid()) continue;
      const Quantity& velocity = *joint.velocity;
      const bool usd = asset.format == SourceFormat::Usda;
      if (usd && velocity.authored >= kUsdDefaultMaxVelocityDeg) continue;
      const auto demand = mimic_demand(asset, joint);
      const Joint* reference = demand ? demand->reference : nullptr;
      const Quantity* reference_velocity = demand ? demand->reference_velocity : nullptr;
      const double needed = demand ? demand->velocity : 0.0;

      if (reference_velocity && velocity.value < needed * (1 - kMimicDemandSlack)) {
        report_too_low(joint, *reference, *reference_velocity, needed, usd, out);
      } else if (usd) {
        // At or above the bound the clamp never acts: harmless, only not what the guide does.
        // URDF has no "unset" (urdfdom requires velocity), so there it passes.
        Diagnostic& d = out.report(velocity.span, Severity::Info,
                                   fmt::format("mimic {} sets a max joint velocity: unnecessary", joint_label(joint)));
        d.note(fmt::format("It sets {}; the guide leaves max joint velocity unset on mimic joints.", describe(velocity)));
        if (reference_velocity)
          d.note(reference->name.span, fmt::format("'{}' is limited to {}, which bounds this joint at {} through "
                                                   "gearing {}: the clamp never acts.",
                                                   reference->name.text, describe(*reference_velocity),
                                                   describe(needed, velocity.unit),
                                                   format_number(joint.mimic->multiplier.authored)));
        else
          d.note("The followed joint authors no velocity limit, so there is no bound to compare with.");
        add_removal(velocity, d);
      }
    }
  }

 private:
  static void report_too_low(const Joint& joint, const Joint& reference, const Quantity& reference_velocity,
                             double needed, bool usd, Reporter& out) {
    const Quantity& velocity = *joint.velocity;
    Diagnostic& d = out.report(velocity.span, fmt::format("mimic {} is limited below the velocity its gearing demands",
                                                          joint_label(joint)));
    d.note(fmt::format("Its own limit is {}; it must reach {}.", describe(velocity), describe(needed, velocity.unit)));
    d.note(reference.name.span,
           fmt::format("'{}' is limited to {}; through |multiplier {}| this joint must reach {}.", reference.name.text,
                       describe(reference_velocity), format_number(joint.mimic->multiplier.authored),
                       describe(needed, velocity.unit)));
    d.note("The velocity clamp then fights the mimic constraint; with a hard mimic the guide warns this can make the "
           "simulation unstable.");
    if (usd) {
      add_removal(velocity, d);
      return;
    }
    // Raising a limit changes the robot: never a safe fix.
    d.fix = Fix{fmt::format("raise the limit to {}", describe(needed, velocity.unit)), Applicability::Unsafe,
                {Edit{velocity.span.file, velocity.span.offset, velocity.span.length,
                      format_number_at_least(velocity.authored_for(needed))}}};
  }

  // USD can leave the attribute unauthored (PhysX's default), which is what the guide asks for.
  // Deleting a vendor's value is still a change to their asset: unsafe.
  static void add_removal(const Quantity& velocity, Diagnostic& d) {
    if (!velocity.declaration.valid()) return;
    d.fix = Fix{"remove maxJointVelocity from the mimic joint (unset: PhysX's default)", Applicability::Unsafe,
                {Edit{velocity.declaration.file, velocity.declaration.offset, velocity.declaration.length, ""}}};
  }

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
