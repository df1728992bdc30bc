#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "physics/servo_step.h"
#include "physics/tendon_lag.h"
#include "rules/all_rules.h"
#include "rules/drive_support.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// A servo on a fixed tendon of several joints drives the tendon's length, not any one joint: the
// length follows its target with the tendon's time constant, whatever one joint's own ratio.
// Nothing when the joint is not on such a tendon, or a joint of it follows another by mimic (the
// tendon's coordinate is then not the simple sum the formula assumes).
std::optional<double> tendon_lag(const Asset& asset, const Joint& joint, double stiffness, double damping) {
  if (!joint.transmission || joint.transmission->shares.size() < 2) return std::nullopt;
  const double ratio = joint.transmission->ratio;
  if (!(ratio > 0)) return std::nullopt;
  std::vector<physics::TendonJointDamper> joints;
  for (const TendonShare& share : joint.transmission->shares) {
    const Joint* member = asset.find_joint(share.joint);
    if (!member || member->is_mimic()) return std::nullopt;
    joints.push_back({share.coef, member->joint_damping ? member->joint_damping->value : 0.0});
  }
  // The drive's damping holds the servo's kv through ratio² and the joint's own damping.
  const double own = joint.joint_damping ? joint.joint_damping->value : 0.0;
  const double kv = std::max(0.0, damping - own) / (ratio * ratio);
  return physics::tendon_time_constant(stiffness / (ratio * ratio), kv, joints);
}

// PHYSICS.md §2: dr = d / (2·sqrt(k·I)); 1 is critical damping, the guide's starting
// point. Far below it the joint rings; far above it the joint crawls. I is the drive's judged
// inertia (drive_support.h), the same one drive-natural-frequency uses.
class DriveDampingRatio final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const double low = rule_option(info_, settings, "min_ratio");
    const double high = rule_option(info_, settings, "max_ratio");
    const double max_time_constant = rule_option(info_, settings, "max_time_constant");
    const DriveModel model(asset, settings);
    for (const Joint& joint : asset.joints) {
      auto driven = model.spring_drive(joint);
      // Unknown damping (MJCF dampratio the reader does not convert): no ratio to judge; the
      // reader's finding says why. Unknown inertia: drive-natural-frequency says so.
      if (!driven || !driven->damping_known() || !driven->judged.known) continue;
      const double inertia = driven->inertia_used;
      const double ratio = physics::damping_ratio(driven->damping, driven->stiffness, inertia);
      if (ratio >= low && ratio <= high) continue;
      const Drive& drive = *driven->drive;
      const double critical = physics::damping_for_ratio(1.0, driven->stiffness, inertia);
      const bool below = ratio < low;
      // Past MuJoCo's 1/timestep a stiff servo steps steadily only because its damping is high
      // and implicit (drive-natural-frequency): critical damping would undo that.
      const physics::SimulationRate& rate = driven->rate;
      const bool steadies_stiff_spring =
          !below && !driven->acceleration() && rate.solver == physics::Solver::MuJoCo &&
          rate.h() * physics::natural_frequency(driven->stiffness, inertia) > 1 &&
          physics::step_verdict(rate.integrator, rate.h(), mujoco_servo(*driven, inertia)) == physics::StepVerdict::Decays;
      // A load the inertia leaves out lowers the true ratio: "too high" is then unproven. A loop
      // or coupling also brings the damping of the joints it turns, through a geometry the file
      // does not give: then "too low" is unproven as well. A hanging body adds only inertia.
      const bool load_left_out = joint.hidden_load && (!below || !joint.hidden_load->rope);
      // Far above critical the drive is a first-order lag: "sluggish" is a claim about how long
      // the joint takes to follow, and a short time constant refutes it.
      const std::optional<double> tendon_time = below ? std::nullopt : tendon_lag(asset, joint, driven->stiffness, driven->damping);
      // The tendon's verdict is one, given once: on the tendon's first joint.
      if (tendon_time && joint.transmission->shares.front().joint != joint.name.text) continue;
      const double time_constant =
          tendon_time ? *tendon_time
                      : 1.0 / physics::slowest_decay_rate(physics::Servo{inertia, driven->stiffness, 0.0, driven->damping});
      const bool follows_quickly = !below && !steadies_stiff_spring && !load_left_out && time_constant <= max_time_constant;
      // A joint that turns without limits (a wheel) with damping far above critical is driven by
      // velocity: the small stiffness only nudges it, and nobody asks it to reach a position.
      const bool velocity_driven = !below && !steadies_stiff_spring && !load_left_out && !follows_quickly &&
                                   is_angular(joint.type) && turns_without_limits(joint);
      // MuJoCo's frictionloss is dry friction: each swing loses 4·F/k of amplitude, so a swing
      // the size of a target step dies within a cycle however small the viscous damping.
      // The step a swing starts from: the guide's target delta on a hinge; a slide has none, but
      // no step is larger than its range.
      const auto delta = target_delta(joint, settings);
      const std::optional<double> range_width =
          joint.lower && joint.upper && joint.upper->value > joint.lower->value
              ? std::optional<double>(joint.upper->value - joint.lower->value)
              : std::nullopt;
      const std::optional<double> step = delta ? delta : range_width;
      const double friction = asset.format == SourceFormat::Mjcf && joint.joint_friction ? joint.joint_friction->value : 0.0;
      const double amplitude_lost = 4.0 * friction / driven->stiffness;
      const bool friction_stops_ringing = below && step && friction > 0 && amplitude_lost >= *step;
      // The ratio rests on a tensor inertia-invalid already reports: that finding is the fact to
      // act on, and the ratio follows once the tensor is real.
      const bool rests_on_doubt = below && !driven->inertia_doubt.empty();
      const bool info_only = steadies_stiff_spring || load_left_out || follows_quickly || friction_stops_ringing ||
                             rests_on_doubt || velocity_driven;
      const Span at = drive.damping && drive.damping->span.valid() ? drive.damping->span
                      : drive.stiffness->span.valid()              ? drive.stiffness->span
                                                                   : joint.name.span;
      Diagnostic& d = out.report(
          at, info_only ? Severity::Info : info_.default_severity,
          load_left_out && below
              ? fmt::format("drive of {}: damping ratio {} below {} on the joint alone; its load adds inertia and "
                            "damping",
                            short_name(joint), format_number(ratio, 3), format_number(low))
          : load_left_out ? fmt::format("drive of {}: damping ratio {} on the joint alone is above {}; with its load it is lower",
                                      short_name(joint), format_number(ratio, 3), format_number(high))
          : friction_stops_ringing
              ? fmt::format("drive of {}: damping ratio {} is below {}, but its frictionloss stops the ringing",
                            short_name(joint), format_number(ratio, 3), format_number(low))
          : rests_on_doubt
              ? fmt::format("drive of {}: damping ratio {} is below {}, on an inertia that is itself in doubt",
                            short_name(joint), format_number(ratio, 3), format_number(low))
          : velocity_driven
              ? fmt::format("drive of {}: damping ratio {} on a joint without limits: a velocity drive",
                            short_name(joint), format_number(ratio, 3))
          : follows_quickly && tendon_time
              ? fmt::format("drive of {}: damping ratio {} is above {}, but its {} follows its target within {} s",
                            short_name(joint), format_number(ratio, 3), format_number(high), joint.transmission->tendon,
                            format_number(time_constant, 2))
          : follows_quickly
              ? fmt::format("drive of {}: damping ratio {} is above {}, but the joint follows its target within {} s",
                            short_name(joint), format_number(ratio, 3), format_number(high), format_number(time_constant, 2))
          : tendon_time
              ? fmt::format("drive of {}: damping ratio {} is above {}: its {} follows its target sluggishly",
                            short_name(joint), format_number(ratio, 3), format_number(high), joint.transmission->tendon)
              : fmt::format("drive of {}: damping ratio {} is {} {}: the joint {}", short_name(joint),
                                      format_number(ratio, 3), below ? "below" : "above", format_number(below ? low : high),
                                      below ? "oscillates around its target" : "moves sluggishly"));
      d.note(fmt::format("For {}: dr = d / (2·sqrt(k·I)) = {} / (2·sqrt({} × {})) = {} with {}.",
                         joint_label(joint), describe_gain(drive.damping, driven->damping, damping_unit(joint)),
                         describe_gain(drive.stiffness, driven->stiffness, stiffness_unit(joint)),
                         format_number(inertia, 3), format_number(ratio, 3), driven->inertia_text()));
      if (!drive.damping_origin.empty()) d.note(drive.damping_origin + ".");
      if (!drive.damping_other_release.empty()) d.note(drive.damping_other_release + ".");
      if (!driven->acceleration()) d.note(fmt::format("Inertias: {}.", driven->inertias_text()));
      if (tendon_time && !steadies_stiff_spring && !load_left_out && !velocity_driven)
        d.note(joint.transmission->span,
               fmt::format("{} pulls {}, which spans {} joints: the servo drives the tendon's length, and far above "
                           "critical each joint moves at cᵢ·F/dᵢ, so the joints' dampers act on the tendon as one "
                           "damper of 1/Σ(cᵢ²/dᵢ) beside the actuator's kv. The length follows its target with the "
                           "time constant (kv + 1/Σ cᵢ²/dᵢ) / kp = {} s, {} max_time_constant = {} s{}.",
                           joint.transmission->actuator, joint.transmission->tendon, joint.transmission->shares.size(),
                           format_number(time_constant, 3), follows_quickly ? "within" : "above",
                           format_number(max_time_constant),
                           follows_quickly ? ": damped hard but not slow" : ": the tendon lags its target"));
      else if (!below && !steadies_stiff_spring && !load_left_out && !velocity_driven)
        d.note(fmt::format("So far above critical the drive acts as a first-order lag: its slow mode ω·(ζ − √(ζ² − 1)) "
                           "gives a time constant of {} s (≈ d/k), {} max_time_constant = {} s{}.",
                           format_number(time_constant, 3), follows_quickly ? "within" : "above",
                           format_number(max_time_constant),
                           follows_quickly ? ": the joint is damped hard but not slow" : ": the joint lags its target"));
      if (velocity_driven)
        d.note(fmt::format("The joint turns without limits (a wheel, a spindle): with damping this far above its "
                           "stiffness the drive follows a target velocity, which is how such joints are driven; a "
                           "position target would take d/k = {} s to reach. If the joint is meant to hold positions, "
                           "give it limits or raise the stiffness.",
                           format_number(time_constant, 3)));
      if (friction_stops_ringing && delta)
        d.note(joint.joint_friction->span, fmt::format(
                   "MuJoCo's frictionloss {} N·m acts as dry friction: each swing loses 4·F/k = {} rad of amplitude, "
                   "more than a {}° step to the target, so the joint settles within a cycle. Within F/k = {} rad of the target "
                   "the spring no longer beats the friction, but MuJoCo's frictionloss is a soft constraint "
                   "(solreffriction): the joint creeps the rest of the way rather than stopping short.",
                   format_number(friction), format_number(amplitude_lost, 3), format_number(degrees_from_radians(*delta), 3),
                   format_number(friction / driven->stiffness, 3)));
      else if (friction_stops_ringing)
        d.note(joint.joint_friction->span, fmt::format(
                   "MuJoCo's frictionloss {} N acts as dry friction: each swing loses 4·F/k = {} m of amplitude, more "
                   "than the joint's whole range of {} m, so no step can start a second swing; {}.",
                   format_number(friction), format_number(amplitude_lost, 3), format_number(*range_width, 3),
                   friction / driven->stiffness < *range_width
                       ? fmt::format("within F/k = {} m of its target the spring no longer beats the friction, and "
                                     "MuJoCo's soft friction constraint (solreffriction) lets it creep the rest of the way",
                                     format_number(friction / driven->stiffness, 3))
                       : fmt::format("F/k = {} m is more than the range too: the servo's force never exceeds the "
                                     "friction, and the joint moves only as far as MuJoCo's soft friction constraint "
                                     "(solreffriction) lets it creep",
                                     format_number(friction / driven->stiffness, 3))));
      if (load_left_out)
        d.note(joint.hidden_load->span,
               joint.hidden_load->rope
                   ? fmt::format("The drive's inertia is a lower bound: {}, which its M₀ᵢᵢ leaves out. The ratio with "
                                 "the load hanging is lower, "
                                 "by how much the file cannot tell; no fix is offered.",
                                 joint.hidden_load->what)
                   : below
                   ? fmt::format("The drive's inertia is incomplete: {}, which its M₀ᵢᵢ (every other joint held) "
                                 "leaves out. Those joints add inertia, which lowers the ratio, and their own damping, "
                                 "which raises it, each through the loop's geometry: whether the drive rings is not "
                                 "judged, and no fix is offered.",
                                 joint.hidden_load->what)
                   : fmt::format("The drive's inertia is incomplete: {}, which its M₀ᵢᵢ (every other joint held) "
                                 "leaves out. The ratio with the joints it turns is "
                                 "usually lower, by how much the loop's geometry decides; no fix is offered.",
                                 joint.hidden_load->what));
      if (steadies_stiff_spring) {
        const physics::Servo servo = mujoco_servo(*driven, inertia);
        d.note(fmt::format(
            "Past MuJoCo's bound (h·nf = {} at {}), this damping is what lets {} step the spring steadily "
            "(drive-natural-frequency); damping for ratio 1 would leave it ringing faster than the step resolves. "
            "The joint follows its target with time constant {} s; to make it quicker, lower the stiffness first.",
            format_number(rate.h() * physics::natural_frequency(driven->stiffness, inertia), 3), rate.step_text(),
            physics::integrator_name(rate.integrator), format_number(1.0 / physics::slowest_decay_rate(servo), 3)));
      }
      const bool fix_offered = !steadies_stiff_spring && !load_left_out && !velocity_driven;
      if (driven->inertia_doubt.empty() && fix_offered)
        d.note(fmt::format("Damping for ratio 1 (critical, the guide's starting point) is {}.",
                           describe_gain(drive.damping, critical, damping_unit(joint))));
      if (!driven->inertia_doubt.empty()) {
        d.note(fmt::format("No fix is offered: {}, so a damping computed from it would be as wrong{}.", driven->inertia_doubt,
                           rests_on_doubt ? "; the ratio is only as right as that tensor (inertia-invalid), hence an info"
                                          : ""));
      } else if (fix_offered && drive.damping && drive.damping->span.valid()) {
        d.fix = Fix{fmt::format("set damping {} for a damping ratio of 1", describe_gain(drive.damping, critical, damping_unit(joint))),
                    Applicability::Unsafe, {replace_value(*drive.damping, critical, 4)}};
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
                  {"max_ratio", 10.0, "damping ratios above this are reported (the joint crawls)"},
                  {"max_time_constant", 0.2,
                   "seconds: a ratio above max_ratio is a warning only when the drive's time constant exceeds this "
                   "(an info otherwise)"}}};
};

}  // namespace

const Rule& drive_damping_ratio() {
  static const DriveDampingRatio rule;
  return rule;
}

}  // namespace assetlint::rules
