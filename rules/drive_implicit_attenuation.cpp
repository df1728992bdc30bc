#include <fmt/format.h>

#include <cmath>

#include "rules/all_rules.h"
#include "rules/drive_support.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// PHYSICS.md §2: PhysX integrates drives implicitly. One step scales the spring/damper
// impulse by 1 / (1 + dt·(dt·k + d)/I): once (dt·nf)² > 1 the drive delivers less
// than half of k·Δ, and stiffer drives push *less*.
class DriveImplicitAttenuation final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    // MuJoCo integrates position actuators' springs explicitly: nothing attenuates them.
    if (asset.format == SourceFormat::Mjcf) return;
    const double threshold = rule_option(info_, settings, "max_dt_nf_squared");
    for (const Joint& joint : asset.joints) {
      auto driven = spring_drive(asset, joint, settings);
      if (!driven || (driven->drive->type == DriveType::Force && !driven->inertia.known)) continue;
      const double inertia = driven->inertia_used;
      const double dt = driven->rate.dt();
      const double nf = physics::natural_frequency(driven->stiffness, inertia);
      const double x = (dt * nf) * (dt * nf);
      if (x <= threshold) continue;
      const double fraction = 1.0 / (1.0 + dt * (dt * driven->stiffness + driven->damping) / inertia);
      const Drive& drive = *driven->drive;
      std::string message = fmt::format(
          "implicit drive of {} delivers {}% of the spring force: (dt·nf)² = ({} s × {} rad/s)² = {} > {} at {} Hz "
          "({}); PhysX scales each step by 1 / (1 + dt·(dt·k + d)/I) = {} with k = {}, d = {}, {}",
          joint_label(joint), format_number(100.0 * fraction, 3), format_number(dt, 4), format_number(nf, 4),
          format_number(x, 4), format_number(threshold), format_number(driven->rate.timesteps_per_second),
          driven->rate.rate_origin, format_number(fraction, 3),
          describe_gain(drive.stiffness, driven->stiffness, stiffness_unit(joint)),
          describe_gain(drive.damping, driven->damping, damping_unit(joint)), driven->inertia_text());
      const Quantity* force = max_force_of(joint);
      const auto delta = target_delta(joint, settings);
      if (delta) {
        const double pushed = driven->stiffness * *delta * fraction;
        message += fmt::format("; at a {}° target delta it pushes {} instead of {}", format_number(settings.gripper.target_delta_deg.value),
                               describe(pushed, Unit::NewtonMeter), describe(driven->stiffness * *delta, Unit::NewtonMeter));
      }
      if (force && force->value > 0 && std::isfinite(force->value)) {
        const double needed = force->value / (driven->stiffness * fraction);
        const bool within = joint.lower && joint.upper ? needed <= joint.upper->value - joint.lower->value : true;
        message += fmt::format("; max force {} needs a position error of {}{}", describe(*force),
                               describe(needed, is_angular(joint.type) ? Unit::Degree : Unit::Meter),
                               within ? "" : ", more than the joint's whole range: it is never reached");
      }
      out.report(drive.stiffness->span.valid() ? drive.stiffness->span : joint.name.span, std::move(message));
    }
  }

 private:
  RuleInfo info_{"drive-implicit-attenuation",
                 "PhysX's implicit drive delivers only a fraction of the spring force at this time step",
                 Severity::Warning,
                 false,
                 RuleOrigin::Check,
                 {{"max_dt_nf_squared", 1.0,
                   "report when (dt·nf)² exceeds this (1: the drive delivers less than half of k·Δ)"}}};
};

}  // namespace

const Rule& drive_implicit_attenuation() {
  static const DriveImplicitAttenuation rule;
  return rule;
}

}  // namespace assetlint::rules
