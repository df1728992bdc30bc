#include <fmt/format.h>

#include <cmath>

#include "rules/all_rules.h"
#include "rules/drive_support.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// docs/physics.md "The drive row": PhysX solves a drive implicitly with
// x = 1/(1 + h·(h·k + d)·r) at the solver's step h. Against a hard stop TGS holds x·k·Δ
// and PGS (1 − (1 − x)^M)·k·Δ; against a compliant load the drive keeps its full k. The
// verdict rests on x with the articulated inertia 1/r when known: a warning when x is below
// `min_factor` (the drive holds less than that share of k·Δ at a contact). With the
// articulated inertia unknown, the guide's lighter-link x is reported as an info.
class DriveImplicitAttenuation final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    // MuJoCo integrates position actuators' springs explicitly: nothing attenuates them.
    if (asset.format == SourceFormat::Mjcf) return;
    const double threshold = rule_option(info_, settings, "min_factor");
    const DriveModel model(asset, settings);
    for (const Joint& joint : asset.joints) {
      auto driven = model.spring_drive(joint);
      if (!driven) continue;
      if (!driven->acceleration() && !driven->articulated.known && !driven->inertia.known) continue;
      const physics::DriveRow row = driven->verdict_row();
      const double x = row.x();
      const double share = static_hold_share(row);
      if (share >= threshold) continue;
      const physics::SimulationRate& rate = driven->rate;
      const bool capped_anyway = held_at_max_force(*driven, row, settings);
      const bool wheel = velocity_drive(*driven);
      const Severity severity = !capped_anyway && !wheel && (driven->verdict_on_articulation() || driven->acceleration())
                                    ? Severity::Warning
                                    : Severity::Info;
      Diagnostic& d = out.report(
          driven->drive->stiffness->span.valid() ? driven->drive->stiffness->span : joint.name.span, severity,
          fmt::format("drive of {} holds {}% of k·Δ at a hard stop (x = {}, {}{}){}", short_name(joint),
                      format_number(100.0 * share, 2), format_number(x, 2), rate.step_text(),
                      driven->verdict_on_articulation() || driven->acceleration() ? "" : ", lighter link",
                      capped_anyway ? ", still above its max force" : wheel ? ", a velocity drive" : ""));
      d.note(factor_text(*driven, row));
      if (wheel)
        d.note(fmt::format("The joint turns without limits and its damping is {}× critical or more: the drive makes it "
                           "follow a target velocity (a wheel), and its stiffness only nudges it. No position target "
                           "is held at a stop, so the attenuation of k·Δ costs nothing the joint is asked for.",
                           format_number(kVelocityDriveRatio)));
      if (!driven->verdict_on_articulation() && !driven->acceleration())
        d.note("The articulated inertia is unknown, so this rests on the guide's lighter-link estimate, which can sit "
               "far below what the drive row sees (and x with it); author the missing masses to judge it.");
      d.note(fmt::format("Step: {}.", rate.describe()));
      d.note(hold_text(*driven, row, settings));
      if (capped_anyway)
        d.note("The attenuated hold is still above the max force, which PhysX clamps the drive to: the joint holds its "
               "max force at the stop either way, so the attenuation costs nothing there.");
      d.note("Against a compliant load (gravity, an external force) the drive acts with its full k; at a stop a stiffer "
             "drive does not push harder: x·k·Δ saturates toward Δ/(h²·r).");
    }
  }

 private:
  // The share of k·Δ held at a stop (before any force cap): x under TGS, 1 − (1 − x)^M under PGS.
  static double static_hold_share(const physics::DriveRow& row) {
    const physics::Hold hold = physics::static_hold(row, 1.0);
    return hold.uncapped / hold.spring;
  }

  // Whether the attenuated hold at the guide's target step still reaches the max force: the
  // clamp, not x, then sets what the drive holds at a stop.
  static bool held_at_max_force(const DrivenJoint& driven, const physics::DriveRow& row, const Settings& settings) {
    const auto delta = target_delta(*driven.joint, settings);
    if (!delta) return false;
    const physics::ForceLimit limit = force_limit_of(*driven.joint);
    return std::isfinite(limit.max_force) && physics::static_hold(row, *delta, limit).capped;
  }

  static std::string factor_text(const DrivenJoint& driven, const physics::DriveRow& row) {
    const Joint& joint = *driven.joint;
    const std::string k = describe_gain(driven.drive->stiffness, driven.stiffness, stiffness_unit(joint));
    const std::string d = describe_gain(driven.drive->damping, driven.damping, damping_unit(joint));
    if (driven.acceleration())
      return fmt::format("For {}: x = 1/(1 + h·(h·k + d)) = {} with k = {}, d = {}: an acceleration drive ignores the "
                         "inertia.",
                         joint_label(joint), format_number(row.x(), 3), k, d);
    std::string text = fmt::format("For {}: x = 1/(1 + h·(h·k + d)·r) = {} with k = {}, d = {}, 1/r = {} {}",
                                   joint_label(joint), format_number(row.x(), 3), k, d,
                                   format_number(1.0 / row.response, 3), driven.inertia_unit());
    text += driven.verdict_on_articulation() ? " (the articulation)" : " (the lighter link)";
    if (driven.verdict_on_articulation() && driven.inertia.known)
      text += fmt::format("; on the lighter link x = {}", format_number(driven.row(driven.inertia.value).x(), 3));
    return text + fmt::format(". Inertias: {}.", driven.inertias_text());
  }

  static std::string hold_text(const DrivenJoint& driven, const physics::DriveRow& row, const Settings& settings) {
    const auto delta = target_delta(*driven.joint, settings);
    if (!delta)
      return row.solver == physics::Solver::TGS
                 ? "At a hard stop TGS holds x·k·Δ on average over the frame."
                 : fmt::format("At a hard stop PGS restarts the drive impulse every frame and holds (1 − (1 − x)^{})·k·Δ.",
                               row.iterations);
    const physics::ForceLimit limit = force_limit_of(*driven.joint);
    const Unit unit = is_angular(driven.joint->type) ? Unit::NewtonMeter : Unit::Newton;
    const physics::Hold hold = physics::static_hold(row, *delta, limit);
    const std::string formula = row.solver == physics::Solver::TGS
                                    ? std::string("x·k·Δ")
                                    : fmt::format("(1 − (1 − x)^{})·k·Δ (PGS restarts the drive impulse every frame; "
                                                  "{} position + velocity iterations)",
                                                  row.iterations, row.iterations);
    std::string text = fmt::format("At a hard stop {}° before the target it holds {} = {} instead of k·Δ = {}",
                                   format_number(settings.gripper.target_delta_deg.value), formula,
                                   describe(hold.uncapped, unit), describe(hold.spring, unit));
    if (std::isfinite(limit.max_force))
      text += fmt::format("{} max force {} (the frame's impulse is clamped to maxForce·dt)",
                          hold.capped ? ", capped at" : "; bounded by", describe(limit.max_force, unit));
    return text + ".";
  }

  RuleInfo info_{"drive-implicit-attenuation",
                 "PhysX's implicit drive row holds only a fraction x of k·Δ at a contact at the solver's step",
                 Severity::Warning,
                 false,
                 RuleOrigin::Check,
                 {{"min_factor", 0.5,
                   "report when the drive holds less than this share of k·Δ at a hard stop: x = 1/(1 + h·(h·k + d)·r) "
                   "under TGS, 1 − (1 − x)^M under PGS"}}};
};

}  // namespace

const Rule& drive_implicit_attenuation() {
  static const DriveImplicitAttenuation rule;
  return rule;
}

}  // namespace assetlint::rules
