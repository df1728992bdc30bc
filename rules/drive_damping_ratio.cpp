#include <fmt/format.h>

#include "rules/all_rules.h"
#include "rules/drive_support.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// PHYSICS.md §2: dr = d / (2·sqrt(k·I)); 1 is critical damping, the guide's starting
// point. Far below it the joint rings; far above it the joint crawls.
class DriveDampingRatio final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const double low = rule_option(info_, settings, "min_ratio");
    const double high = rule_option(info_, settings, "max_ratio");
    for (const Joint& joint : asset.joints) {
      auto driven = spring_drive(asset, joint, settings);
      if (!driven || (driven->drive->type == DriveType::Force && !driven->inertia.known)) continue;
      const double inertia = driven->inertia_used;
      const double ratio = physics::damping_ratio(driven->damping, driven->stiffness, inertia);
      if (ratio >= low && ratio <= high) continue;
      const Drive& drive = *driven->drive;
      const double critical = physics::damping_for_ratio(1.0, driven->stiffness, inertia);
      const bool below = ratio < low;
      Diagnostic& d = out.report(
          drive.damping && drive.damping->span.valid() ? drive.damping->span : drive.stiffness->span.valid() ? drive.stiffness->span : joint.name.span,
          fmt::format("damping ratio {} of the drive of {} is {} {} (damping {}, stiffness {}, {}): the joint {}; "
                      "damping for ratio 1 is {}",
                      format_number(ratio, 3), joint_label(joint), below ? "below" : "above",
                      format_number(below ? low : high), describe_gain(drive.damping, driven->damping, damping_unit(joint)),
                      describe_gain(drive.stiffness, driven->stiffness, stiffness_unit(joint)), driven->inertia_text(),
                      below ? "oscillates around its target" : "moves sluggishly",
                      describe_gain(drive.damping, critical, damping_unit(joint))));
      if (drive.damping && drive.damping->span.valid()) {
        d.fix = Fix{"set damping for a damping ratio of 1", Applicability::Unsafe,
                    {replace_value(*drive.damping, critical, 4)}};
      }
    }
  }

 private:
  RuleInfo info_{"drive-damping-ratio",
                 "A drive's damping ratio d / (2·sqrt(k·I)) is far from critical damping",
                 Severity::Warning,
                 true,
                 RuleOrigin::Check,
                 {{"min_ratio", 0.1, "damping ratios below this are reported (the joint rings)"},
                  {"max_ratio", 10.0, "damping ratios above this are reported (the joint crawls)"}}};
};

}  // namespace

const Rule& drive_damping_ratio() {
  static const DriveDampingRatio rule;
  return rule;
}

}  // namespace assetlint::rules
