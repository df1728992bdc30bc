#include <fmt/format.h>

#include <cmath>

#include "physics/gripper.h"
#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// The guide's second step: bound the driven joint's velocity by the spec, ω = joint
// range / (stroke per finger / finger speed). Unset (USD default 1e6 deg/s) means a
// gripper that can close in microseconds.
class JointMaxVelocity final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    if (asset.format == SourceFormat::Mjcf) return;  // MuJoCo has no max joint velocity
    const double tolerance = rule_option(info_, settings, "tolerance_factor");
    const Joint* spec = physics::spec_joint(asset, settings);
    for (const Joint& joint : asset.joints) {
      if (!is_single_dof(joint.type) || joint.is_mimic()) continue;
      const bool driven = joint.drive && ((joint.drive->stiffness && joint.drive->stiffness->value > 0) ||
                                          (joint.drive->damping && joint.drive->damping->value > 0));
      const auto wanted = &joint == spec ? physics::required_velocity(settings, joint) : std::nullopt;
      const Unit unit = is_angular(joint.type) ? Unit::RadianPerSecond : Unit::MeterPerSecond;
      const bool missing = !joint.velocity || (joint.velocity->span.valid() && joint.velocity->value == 0);
      if (missing) {
        if (!driven && !wanted) continue;
        const bool usd = asset.format == SourceFormat::Usda;
        std::string message = fmt::format(
            "driven {} has no max joint velocity{}: nothing bounds how fast the drive can move it", joint_label(joint),
            joint.velocity ? " (0: unbounded for most importers)" : usd ? " (USD default 1e6 deg/s)" : "");
        if (wanted) message += fmt::format("; the spec gives {} ({})", describe(wanted->velocity, usd ? Unit::DegreePerSecond : unit), wanted->derivation);
        Diagnostic& d = out.report(joint.velocity ? joint.velocity->span : joint.name.span, std::move(message));
        if (wanted && joint.velocity && joint.velocity->span.valid())
          d.fix = Fix{"set the max joint velocity from the spec", Applicability::Unsafe,
                      {replace_value(*joint.velocity, wanted->velocity, 4)}};
        continue;
      }
      if (!wanted || !joint.velocity->span.valid()) continue;
      const double ratio = joint.velocity->value / wanted->velocity;
      if (ratio <= tolerance && ratio >= 1.0 / tolerance) continue;
      Diagnostic& d = out.report(
          joint.velocity->span,
          fmt::format("max joint velocity {} of {} is {}× the spec's {} ({}; tolerance {}×)", describe(*joint.velocity),
                      joint_label(joint), format_number(ratio, 3), describe(wanted->velocity, joint.velocity->unit),
                      wanted->derivation, format_number(tolerance)));
      d.fix = Fix{"set the max joint velocity from the spec", Applicability::Unsafe,
                  {replace_value(*joint.velocity, wanted->velocity, 4)}};
    }
  }

 private:
  RuleInfo info_{"joint-max-velocity",
                 "The driven joint's max velocity is unset, or far from what the gripper spec gives",
                 Severity::Warning,
                 true,
                 RuleOrigin::Check,
                 {{"tolerance_factor", 2.0, "report a velocity more than this factor above or below the spec's"}}};
};

}  // namespace

const Rule& joint_max_velocity() {
  static const JointMaxVelocity rule;
  return rule;
}

}  // namespace assetlint::rules
