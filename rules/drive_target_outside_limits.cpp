#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// A drive whose authored target lies beyond the joint's limits: the joint can never reach it,
// so at rest the drive's spring keeps pressing the joint into its stop with stiffness ×
// overshoot (capped by maxForce), and the limit constraint holds that load for good.
class DriveTargetOutsideLimits final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings&, Reporter& out) const override {
    for (const Joint& joint : asset.joints) {
      if (!is_single_dof(joint.type) || joint.is_mimic() || !joint.drive) continue;
      const Drive& drive = *joint.drive;
      if (!drive.target_position || !drive.target_position->is_authored()) continue;
      if (!drive.stiffness || drive.stiffness->value <= 0) continue;
      const double target = drive.target_position->value;
      const bool below = joint.lower && target < joint.lower->value;
      const bool above = joint.upper && target > joint.upper->value;
      if (!below && !above) continue;
      const Quantity& stop = below ? *joint.lower : *joint.upper;
      report(joint, drive, stop, below, out);
    }
  }

 private:
  static void report(const Joint& joint, const Drive& drive, const Quantity& stop, bool below, Reporter& out) {
    const Quantity& target = *drive.target_position;
    const double overshoot = std::abs(target.value - stop.value);
    const double spring = drive.stiffness->value * overshoot;
    const bool angular = is_angular(joint.type);
    const Unit force_unit = angular ? Unit::NewtonMeter : Unit::Newton;
    const bool capped = drive.max_force && drive.max_force->value < spring;
    const double pressing = capped ? drive.max_force->value : spring;
    Diagnostic& d = out.report(target.span,
                               fmt::format("drive target of '{}' is {} past its {} limit: {} into the stop",
                                           short_path(joint.name.text), describe(overshoot, stop.unit),
                                           below ? "lower" : "upper", describe(pressing, force_unit)));
    d.note(stop.span, fmt::format("The {} limit is {}; the target {} lies beyond it, so the joint never reaches it.",
                                  below ? "lower" : "upper", describe(stop), describe(target)));
    d.note(fmt::format("At rest the drive's spring pulls with stiffness × overshoot = {} × {} = {}{}, and the limit "
                       "holds it there: the link is loaded against its stop for as long as the target stays, and it "
                       "slams into the stop when released towards it.",
                       describe(*drive.stiffness), describe(overshoot, stop.unit), describe(spring, force_unit),
                       capped ? fmt::format(", capped by maxForce {}", describe(*drive.max_force)) : ""));
    d.note(fmt::format("Set the target inside [{}, {}] (a gripper's open or closed stop is the limit itself), or widen the "
                       "limit if the mechanism travels further.",
                       joint.lower ? describe(*joint.lower) : "-inf", joint.upper ? describe(*joint.upper) : "inf"));
  }

  RuleInfo info_{"drive-target-outside-limits",
                 "A drive target beyond the joint's limits: at rest the drive presses the joint into its stop",
                 Severity::Warning, false, RuleOrigin::Check, {}};
};

}  // namespace

const Rule& drive_target_outside_limits() {
  static const DriveTargetOutsideLimits rule;
  return rule;
}

}  // namespace assetlint::rules
