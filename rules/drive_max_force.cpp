#include <fmt/format.h>

#include <cmath>

#include "physics/gripper.h"
#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// The guide's first step: bound every drive's force by the robot's spec. A zero bound
// makes the joint limp; a placeholder (1e6, 1e9, inf) means the drive is unbounded.
class DriveMaxForce final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const double placeholder = rule_option(info_, settings, "placeholder_force");
    const Joint* spec = physics::spec_joint(asset, settings);
    for (const Joint& joint : asset.joints) {
      if (!is_single_dof(joint.type) || joint.is_mimic()) continue;
      const bool usd = asset.format == SourceFormat::Usda;
      const char* what = usd ? "drive maxForce" : "effort limit";
      const OptQuantity* force = &joint.effort;
      if (joint.drive) {
        const bool active = (joint.drive->stiffness && joint.drive->stiffness->value > 0) ||
                            (joint.drive->damping && joint.drive->damping->value > 0);
        if (!active) continue;
        if (joint.drive->max_force) force = &joint.drive->max_force;
        if (usd && (!joint.drive->max_force || std::isinf(joint.drive->max_force->value))) {
          out.report(joint.drive->max_force ? joint.drive->max_force->span : joint.drive->span,
                     fmt::format("driven {} has no {} ({}): the drive can push with unbounded force; set it from "
                                 "the robot's spec (payload, friction and lever arm)",
                                 joint_label(joint), what, joint.drive->max_force ? "inf" : "unauthored, default inf"));
          continue;
        }
      } else if (usd) {
        continue;  // no drive: not a driven joint in USD
      }
      if (!*force) continue;
      const Quantity& q = **force;
      if (q.value == 0) {
        out.report(q.span, fmt::format("driven {} has {} {}: the drive cannot move it", joint_label(joint), what,
                                       describe(q)));
      } else if (q.value >= placeholder) {
        out.report(q.span,
                   fmt::format("driven {} has {} {}, a placeholder (≥ {}): the drive is effectively unbounded; set "
                               "it from the robot's spec",
                               joint_label(joint), what, describe(q), format_number(placeholder)));
      } else if (q.value < 0) {
        out.report(q.span, fmt::format("driven {} has negative {} {}", joint_label(joint), what, describe(q)));
      } else if (&joint == spec) {
        check_spec(asset, settings, joint, q, what, out);
      }
    }
  }

 private:
  // The guide's derivation from the payload spec (PHYSICS.md §3): the drive must hold
  // the payload through every joint it moves.
  static void check_spec(const Asset& asset, const Settings& settings, const Joint& joint, const Quantity& q,
                         const char* what, Reporter& out) {
    const auto required = physics::required_force(asset, settings, joint);
    if (!required || q.value >= required->required * (1 - 1e-9)) return;
    Diagnostic& d = out.report(q.span, fmt::format("{} {} of {} is below the {} the payload spec needs: {}", what,
                                                   describe(q), joint_label(joint),
                                                   describe(required->required, q.unit), required->derivation));
    if (q.span.valid())
      d.fix = Fix{"raise the max force to the payload spec's", Applicability::Unsafe,
                  {Edit{q.span.file, q.span.offset, q.span.length, format_number_rounded_up(q.authored_for(required->required), 3)}}};
  }

  RuleInfo info_{"drive-max-force",
                 "A driven joint's maximum force is zero, unbounded, a placeholder, or below the payload spec",
                 Severity::Warning,
                 true,
                 RuleOrigin::Check,
                 {{"placeholder_force", 1e6, "efforts at or above this (N·m or N) are placeholders, not limits"}}};
};

}  // namespace

const Rule& drive_max_force() {
  static const DriveMaxForce rule;
  return rule;
}

}  // namespace assetlint::rules
