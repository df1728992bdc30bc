#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <string>

#include "physics/drive.h"
#include "rules/drive_support.h"
#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// The guide's armature section: armature an order of magnitude above the lighter link's
// inertia needs a motor datasheet behind it, armature = G²·I_rotor. How risky such an
// armature is depends on what the asset says about the motor (docs/rules/armature-excessive.md):
//   - a declared motor that reflects it: justified, silent;
//   - a passive joint (MJCF: no actuator reaches it): no rotor to reflect, a warning;
//   - a declared gear G: the implied rotor armature/G² against the link, info or warning;
//   - otherwise: a warning when the drive would fail drive-natural-frequency without the
//     armature (the tuning lever the guide warns about), else info.
class ArmatureExcessive final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const double factor = rule_option(info_, settings, "max_ratio");
    const DriveModel model(asset, settings);
    for (const Joint& joint : asset.joints) {
      if (!is_single_dof(joint.type) || !joint.armature || joint.armature->value <= 0) continue;
      const physics::EffectiveInertia inertia = physics::effective_inertia(model.articulation(), asset, joint);
      if (!inertia.known || inertia.link_inertia <= 0) continue;
      const double armature = joint.armature->value;
      const double ratio = armature / inertia.link_inertia;
      if (ratio <= factor) continue;
      if (joint.motor && armature <= reflected(*joint.motor) * (1 + 1e-6)) continue;
      Candidate c{joint, inertia, armature, ratio, factor, model.spring_drive(joint)};
      report(c, out);
    }
  }

 private:
  struct Candidate {
    const Joint& joint;
    const physics::EffectiveInertia& inertia;
    double armature;
    double ratio;
    double factor;
    std::optional<DrivenJoint> driven;
    const char* unit() const { return is_angular(joint.type) ? "kg·m²" : "kg"; }
  };

  struct Crutch {
    double natural_frequency;  // rad/s, without the armature
    double inertia;            // what it was computed on
    bool articulated;          // on the articulation's inertia, else the lighter link's
  };

  static double reflected(const Motor& motor) { return motor.gear_ratio * motor.gear_ratio * motor.rotor_inertia.value; }

  void report(const Candidate& c, Reporter& out) const {
    const Joint& joint = c.joint;
    const Span at = joint.armature->span.valid() ? joint.armature->span : joint.name.span;
    const std::string amount = fmt::format("{} {}", format_number(c.armature, 3), c.unit());
    const std::string times = format_number(c.ratio, 3);

    if (joint.motor) {
      Diagnostic& d = out.report(at, Severity::Warning,
                                 fmt::format("armature {} of {} ({}× the lighter link) is more than its declared motor "
                                             "reflects", amount, short_name(joint), times));
      d.note(link_text(c));
      d.note(fmt::format("The declared motor ({}: G = {}, I_rotor = {} kg·m²) reflects only G²·I_rotor = {} kg·m².",
                         joint.motor->origin, format_number(joint.motor->gear_ratio),
                         format_number(joint.motor->rotor_inertia.value, 3), format_number(reflected(*joint.motor), 3)));
      drive_effect(c, d);
      return;
    }
    if (joint.actuation == Actuation::Passive) {
      Diagnostic& d = out.report(at, Severity::Warning,
                                 fmt::format("armature {} of {} ({}× the lighter link) on a joint no actuator moves", amount,
                                             short_name(joint), times));
      d.note(link_text(c));
      d.note("No actuator reaches this joint, directly or through a fixed tendon, so no motor's rotor is reflected onto "
             "it: the armature is inertia the real mechanism does not have, and it slows every motion the linkage "
             "makes. If it only steadies a closed chain, keep it as small as does that.");
      drive_effect(c, d);
      return;
    }
    if (joint.transmission) {
      const double gear = joint.transmission->ratio;
      const double rotor = c.armature / (gear * gear);
      const double rotor_ratio = rotor / c.inertia.link_inertia;
      const bool plausible = rotor_ratio <= c.factor;
      Diagnostic& d = out.report(
          at, plausible ? Severity::Info : Severity::Warning,
          fmt::format("armature {} of {} ({}× the lighter link) is {} its gear {}", amount, short_name(joint), times,
                      plausible ? "consistent with" : "too large even behind", format_number(gear)));
      d.note(joint.transmission->span,
             fmt::format("The actuator's gear G = {} implies a rotor of armature / G² = {} kg·m², {}× the lighter "
                         "link's inertia ({} {}; threshold {}×).",
                         format_number(gear), format_number(rotor, 3), format_number(rotor_ratio, 3),
                         format_number(c.inertia.link_inertia, 3), c.unit(), format_number(c.factor)));
      d.note(plausible ? "The guide's test, armature = G²·I_rotor, holds for a rotor of that size: confirm it against "
                         "the motor datasheet."
                       : fmt::format("A rotor of more than {}× the inertia of the link it turns fails the guide's "
                                     "test: the armature adds inertia the robot does not have.",
                                     format_number(c.factor)));
      drive_effect(c, d);
      return;
    }
    if (const auto without = crutch(c)) {
      Diagnostic& d = out.report(at, Severity::Warning,
                                 fmt::format("armature {} of {} ({}× the lighter link) is what keeps its drive within the "
                                             "{} bound", amount, short_name(joint), times,
                                             physics::solver_name(c.driven->rate.solver)));
      d.note(link_text(c));
      d.note(fmt::format("Without the armature the drive's natural frequency would be sqrt({} {} / {} {}) = {} rad/s "
                         "on {}, above the bound {} rad/s ({}): the armature is the tuning lever the guide describes, "
                         "and it changes the robot unless a motor datasheet backs it.",
                         format_number(c.driven->stiffness, 4), unit_symbol(stiffness_unit(joint)),
                         format_number(without->inertia, 3), c.unit(),
                         format_number(without->natural_frequency, 4),
                         without->articulated ? "the articulation's own inertia" : "the lighter link",
                         format_number(c.driven->rate.frequency_bound(), 4), c.driven->rate.step_text()));
      const physics::SimulationRate& rate = c.driven->rate;
      if (rate.solver == physics::Solver::MuJoCo && rate.integrator != physics::MujocoIntegrator::ImplicitFast &&
          physics::damps_stably(physics::MujocoIntegrator::ImplicitFast, rate.h(),
                                mujoco_servo(*c.driven, without->inertia)))
        d.note("Under <option integrator=\"implicitfast\">, which takes the actuator's kv implicitly, the drive would be "
               "damped stably without the armature.");
      drive_effect(c, d);
      return;
    }
    Diagnostic& d = out.report(at, Severity::Info,
                               fmt::format("armature {} of {} is {}× the lighter link's inertia (threshold {}×)", amount,
                                           short_name(joint), times, format_number(c.factor)));
    d.note(link_text(c));
    d.note(c.driven ? "Its drive would be steady without it (within the natural-frequency bound, or damped stably by "
                      "MuJoCo's integrator), so it models a motor rather than steadying the drive; declare the motor to "
                      "record that."
                    : "No spring drive depends on it, so it models a motor rather than steadying a drive; declare the "
                      "motor to record that.");
    drive_effect(c, d);
  }

  // The natural frequency the drive would have without its armature, when that fails the
  // bound drive-natural-frequency uses: the armature is what keeps the drive stable.
  // On the articulation's own inertia when known (what the solver's drive row sees; the
  // armature adds to it one for one), else on the guide's lighter link.
  static std::optional<Crutch> crutch(const Candidate& c) {
    if (!c.driven || c.driven->acceleration()) return std::nullopt;
    const bool articulated = c.driven->articulated.known && c.driven->articulated.value > c.armature;
    const double inertia = articulated ? c.driven->articulated.value - c.armature : c.inertia.link_inertia;
    const double without = physics::natural_frequency(c.driven->stiffness, inertia);
    if (without <= c.driven->rate.frequency_bound()) return std::nullopt;
    // Past the bound, MuJoCo's integrator may still damp it stably without the armature.
    const physics::SimulationRate& rate = c.driven->rate;
    if (rate.solver == physics::Solver::MuJoCo &&
        physics::damps_stably(rate.integrator, rate.h(), mujoco_servo(*c.driven, inertia)))
      return std::nullopt;
    return Crutch{without, inertia, articulated};
  }

  static std::string link_text(const Candidate& c) {
    const Joint& joint = c.joint;
    const double gearing = c.inertia.gearing;
    return fmt::format("For {}, the lighter link '{}' about '{}' has {} {}{} (threshold {}×); the guide's test is "
                       "armature = G²·I_rotor: this equals a rotor as heavy as that link behind a {}:1 gearbox.",
                       joint_label(joint), c.inertia.link->name.text, c.inertia.via->name.text,
                       format_number(c.inertia.link_inertia, 3), c.unit(),
                       std::abs(gearing) != 1.0 ? fmt::format(" (reflected with gearing² {})", format_number(gearing * gearing, 3))
                                                : std::string(),
                       format_number(c.factor), format_number(std::sqrt(c.ratio), 3));
  }

  static void drive_effect(const Candidate& c, Diagnostic& d) {
    if (!c.driven || c.driven->acceleration()) return;
    const DrivenJoint& driven = *c.driven;
    const double k = driven.stiffness;
    std::string effect = fmt::format("It lowers the drive's natural frequency on the lighter link from {} to {} rad/s",
                                     format_number(physics::natural_frequency(k, c.inertia.link_inertia), 3),
                                     format_number(physics::natural_frequency(k, c.inertia.value), 3));
    if (driven.articulated.known)
      effect += fmt::format("; with it the drive row's x on the articulation is {} ({})",
                            format_number(driven.row(driven.articulated.value).x(), 3), driven.rate.step_text());
    d.note(effect + fmt::format(". Inertias: {}.", driven.inertias_text()));
  }

 private:
  RuleInfo info_{"armature-excessive",
                 "Joint armature an order of magnitude above the lighter link's inertia about the axis",
                 Severity::Warning,
                 false,
                 RuleOrigin::Check,
                 {{"max_ratio", 10.0, "report armature above this multiple of the lighter link's inertia about the axis"}}};
};

}  // namespace

const Rule& armature_excessive() {
  static const ArmatureExcessive rule;
  return rule;
}

}  // namespace assetlint::rules
