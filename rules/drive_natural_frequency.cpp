#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "physics/servo_step.h"
#include "rules/all_rules.h"
#include "rules/drive_support.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// The guide's check (docs/physics.md "The step h"): nf = sqrt(k / I) against rate × position
// iterations, which under TGS is exactly h·nf ≤ 1 (PhysX solves the drive at the sub-step
// h = dt/N); under PGS the row is built with the whole frame, so the bound is the rate. I is
// the drive's judged inertia (drive_support.h): the guide's lighter link for a mimic-coupled
// gripper, the articulation for any other PhysX drive, M₀ᵢᵢ for MuJoCo. Above the bound: an
// error. Above the rate but within it: the guide's "worth trying", an info with the numbers.
// MuJoCo has no such bound: its integrator's step map decides (physics/servo_step.h), and
// only a growing or undamped mode is an error.
class DriveNaturalFrequency final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const DriveModel model(asset, settings);
    // Built only when an arm's drive falls back to the lighter link: the same tree with the
    // links that author no mass taken as massless, whose 1/r bounds the true one from below.
    std::optional<physics::Articulation> massless_missing;
    const auto lower_bound = [&]() -> const physics::Articulation& {
      if (!massless_missing)
        massless_missing.emplace(asset, physics::default_free_root(asset), physics::Articulation::MissingMass::Massless);
      return *massless_missing;
    };
    for (const Joint& joint : asset.joints) {
      auto driven = model.spring_drive(joint);
      if (!driven) continue;
      const Drive& drive = *driven->drive;
      const Span at = drive.stiffness->span.valid() ? drive.stiffness->span : joint.name.span;
      if (!driven->judged.known) {
        Diagnostic& d = out.report(at, Severity::Info,
                                   fmt::format("drive of {}: natural frequency not checked, no link mass", short_name(joint)));
        if (driven->judged.basis == InertiaBasis::JointSpace)
          d.note(fmt::format("M₀ᵢᵢ, the inertia MuJoCo's step divides by, needs every body the joint moves: {}; MuJoCo "
                             "derives it from geoms asset-lint cannot measure (a mesh, a height field, a shell).",
                             driven->judged.why_unknown()));
        else
          d.note(fmt::format("No moving link of it or its mimics authors mass, inertia and centre of mass ({}); PhysX "
                             "derives them from colliders, which a text linter cannot read.",
                             name_list(driven->inertia.unknown_links)));
        continue;
      }
      const physics::Articulation* lower = driven->judged.fallback.empty() ? nullptr : &lower_bound();
      check_drive(*driven, settings, at, out, lower);
    }
  }

 private:
  // Above the bound on the least inertia the drive can see, the verdict rests on the masses
  // PhysX gives the links that author none (from their colliders): a hand at the end of an arm
  // can bring the drive within, a flange cannot. What they must add is what an engineer can judge.
  static void report_unjudged(const DrivenJoint& driven, double least, const physics::Articulation& lower,
                              const Span& at, Reporter& out) {
    const Joint& joint = *driven.joint;
    const physics::SimulationRate& rate = driven.rate;
    const double bound = rate.frequency_bound();
    const double nf = physics::natural_frequency(driven.stiffness, least);
    const double needed = physics::inertia_for_frequency(driven.stiffness, bound);
    const std::vector<std::string>& massless = lower.assumed_massless();
    Diagnostic& d = out.report(at, Severity::Info,
                               fmt::format("drive of {}: natural frequency not judged, {} link{} without mass", short_name(joint),
                                           massless.size(), massless.size() == 1 ? "" : "s"));
    d.note(fmt::format("For {}: on the authored masses, with {} taken as massless, nf = sqrt(k / I) = sqrt({} / {} {}) = "
                       "{} rad/s, above the {} bound {} rad/s ({}). Mass anywhere only raises I, so that is the most nf "
                       "can be.",
                       joint_label(joint), name_list(massless),
                       describe_gain(driven.drive->stiffness, driven.stiffness, stiffness_unit(joint)), format_number(least, 3),
                       driven.inertia_unit(), format_number(nf, 4), physics::solver_name(rate.solver),
                       format_number(bound, 4), rate.step_text()));
    d.note(fmt::format("The drive is within the bound if those links add at least {} {} to what it sees (I ≥ k / bound² = "
                       "{} {}). PhysX computes their mass from their colliders, which a text linter cannot read: author "
                       "their mass to have the drive judged. Inertias: {}.",
                       format_number(needed - least, 3), driven.inertia_unit(), format_number(needed, 3),
                       driven.inertia_unit(), driven.inertias_text()));
  }

  static void report_stand_in(const DrivenJoint& driven, const Span& at, Reporter& out) {
    const Joint& joint = *driven.joint;
    const physics::SimulationRate& rate = driven.rate;
    const double bound = rate.frequency_bound();
    const double needed = physics::inertia_for_frequency(driven.stiffness, bound);
    Diagnostic& d = out.report(at, Severity::Info,
                               fmt::format("drive of {}: natural frequency not judged, the articulation's mass is unknown",
                                           short_name(joint)));
    d.note(derivation(driven, physics::natural_frequency(driven.stiffness, driven.inertia_used)));
    d.note(fmt::format("That is above the {} bound {} rad/s ({}) on the lighter link, but the joint moves more than "
                       "that link; it is within the bound if it moves at least {} {} about its axis (k / bound²). "
                       "Author the missing masses to have the drive judged.",
                       physics::solver_name(rate.solver), format_number(bound, 4), rate.step_text(),
                       format_number(needed, 3), driven.inertia_unit()));
  }

  static void check_drive(const DrivenJoint& driven, const Settings& settings, const Span& at, Reporter& out,
                          const physics::Articulation* lower) {
    const Joint& joint = *driven.joint;
    const Drive& drive = *driven.drive;
    const physics::SimulationRate& rate = driven.rate;
    const double bound = rate.frequency_bound();
    // An arm's drive that falls back to the lighter link because some links author no mass:
    // the articulation with them massless is the least the drive can see. Within the bound
    // there, it is within whatever PhysX gives those links.
    if (lower && rate.solver != physics::Solver::MuJoCo) {
      const physics::ArticulatedInertia at_least = lower->inertia(joint);
      if (at_least.known) {
        if (physics::natural_frequency(driven.stiffness, at_least.value) <= bound) return;
        return report_unjudged(driven, at_least.value, *lower, at, out);
      }
      // Not even that is known (the root authors no mass): the lighter link alone stands in,
      // and an arm's joint moves more than its lighter link, so past the bound is unproven.
      if (physics::natural_frequency(driven.stiffness, driven.inertia_used) > bound)
        return report_stand_in(driven, at, out);
      return;
    }
    const double inertia = driven.inertia_used;
    const double nf = physics::natural_frequency(driven.stiffness, inertia);
    const double h_nf = rate.h() * nf;
    if (nf <= rate.timesteps_per_second) return;
    const Unit k_unit = stiffness_unit(joint), d_unit = damping_unit(joint);

    if (nf <= bound) {
      Diagnostic& d = out.report(
          at, Severity::Info,
          fmt::format("drive of {}: natural frequency {} rad/s is {}× the rate, within the {} bound {} rad/s",
                      short_name(joint), format_number(nf, 3), format_number(nf / rate.timesteps_per_second, 3),
                      physics::solver_name(rate.solver), format_number(bound, 4)));
      d.note(derivation(driven, nf));
      d.note(bound_text(rate, h_nf));
      d.note("The guide calls a drive above the rate but within rate × iterations worth trying: watch it for "
             "artifacts in a simple test scene, and lower the stiffness if they appear.");
      return;
    }

    const std::optional<MujocoStep> mujoco = mujoco_step(driven);
    // An info past the bound: the derivation and the bound, then why it is not an error.
    const auto info = [&](std::string message) -> Diagnostic& {
      Diagnostic& d = out.report(at, Severity::Info, std::move(message));
      d.note(derivation(driven, nf));
      d.note(bound_text(rate, h_nf));
      return d;
    };
    if (mujoco && !driven.damping_known()) {
      // Whether the step decays depends on the damping: no verdict without it.
      Diagnostic& d = info(
          fmt::format("drive of {}: natural frequency {} rad/s > MuJoCo bound {} rad/s, not judged: damping unknown",
                      short_name(joint), format_number(nf, 4), format_number(bound, 4)));
      d.note(fmt::format("Whether {} damps the spring's unresolved mode depends on the damping, which is unknown: {}.",
                         physics::integrator_name(rate.integrator), driven.drive->damping_unknown));
      return;
    }
    if (mujoco && mujoco->verdict() == physics::StepVerdict::Decays) {
      Diagnostic& d = info(fmt::format("drive of {}: natural frequency {} rad/s > MuJoCo bound {} rad/s, damped stably by {}",
                                       short_name(joint), format_number(nf, 4), format_number(bound, 4),
                                       physics::integrator_name(rate.integrator)));
      for (const std::string& note : mujoco->notes()) d.note(note);
      return;
    }

    // Part of what the drive moves is left out of I (a loop, a coupling, a hanging body): the
    // true nf is lower by an amount the file does not give, so past the bound is not established.
    const HiddenLoad* hidden = joint.hidden_load ? &*joint.hidden_load : nullptr;
    if (hidden) {
      Diagnostic& d = info(fmt::format("drive of {}: natural frequency {} rad/s > bound {} rad/s on the joint alone; its "
                                       "load lowers it",
                                       short_name(joint), format_number(nf, 4), format_number(bound, 4)));
      d.note(hidden->span, fmt::format("I leaves out part of what the drive moves: {}. With it the natural frequency "
                                       "is lower, by how much the file cannot tell, so whether the drive is past the "
                                       "bound is not judged.",
                                       hidden->what));
      return;
    }
    Diagnostic& d = out.report(
        at, Severity::Error,
        mujoco ? fmt::format("drive of {}: natural frequency {} rad/s > MuJoCo bound {} rad/s, {} under {}",
                             short_name(joint), format_number(nf, 4), format_number(bound, 4),
                             mujoco->verdict() == physics::StepVerdict::Grows ? "diverges" : "undamped",
                             physics::integrator_name(rate.integrator))
           : fmt::format("drive of {}: natural frequency {} rad/s > {} bound {} rad/s (h·nf = {})", short_name(joint),
                             format_number(nf, 4), physics::solver_name(rate.solver), format_number(bound, 4),
                             format_number(h_nf, 3)));
    d.related.push_back("SimReady DJ.006");
    d.note(derivation(driven, nf));
    d.note(bound_text(rate, h_nf));
    if (mujoco)
      for (const std::string& note : mujoco->notes()) d.note(note);
    if (rate.solver == physics::Solver::PGS)
      d.note("Under TGS the same drive would be judged against rate × position iterations: PGS builds the drive "
             "row with the whole frame.");

    if (!driven.inertia_doubt.empty()) {
      d.note(fmt::format("No stiffness is proposed: {}, so a value computed from it would be as wrong.",
                         driven.inertia_doubt));
      return;
    }
    // The fix: the guide's stiffness k = max force / target delta when a force spec
    // exists, else the stiffness whose natural frequency is 1/h. Never a stiffer drive.
    const Quantity* force = max_force_of(joint);
    const auto delta = target_delta(joint, settings);
    // FLT_MAX is how PhysX and Isaac write "no limit": a force bound only below it.
    const bool force_known = force && force->value > 0 && std::isfinite(force->value) &&
                             force->value < 0.5 * static_cast<double>(std::numeric_limits<float>::max());
    double proposed = physics::stiffness_for_frequency(bound, inertia);
    std::string reason = fmt::format("natural frequency 1/h = {} rad/s{}", format_number(bound, 4),
                                     force_known ? "" : "; no max force to keep");
    if (force_known && delta && !driven.acceleration()) {
      const double k_force = force->value / *delta;
      const double nf_force = physics::natural_frequency(k_force, inertia);
      if (nf_force > bound) {
        // A softer spring would lose the max force at the target delta: the guide's other
        // levers are armature and the step.
        const double armature = physics::inertia_for_frequency(k_force, bound) - inertia;
        d.note(fmt::format("Even the guide's stiffness, max force {} / {}° target delta = {}, gives {} rad/s: add "
                           "armature ≥ {} {} or shorten h ({}) to ≤ {} s.",
                           describe(*force), format_number(settings.gripper.target_delta_deg.value),
                           describe_gain(drive.stiffness, k_force, k_unit), format_number(nf_force, 4),
                           format_number(armature, 3), driven.inertia_unit(),
                           rate.solver == physics::Solver::MuJoCo ? "a smaller <option timestep>"
                                                                  : "more position iterations or a higher rate",
                           format_number(1.0 / nf_force, 3)));
        return;
      }
      proposed = k_force;
      reason = fmt::format("max force {} reached {}° before the target", describe(*force),
                           format_number(settings.gripper.target_delta_deg.value));
    }
    if (proposed >= driven.stiffness * (1 - 1e-6)) return;  // never a stiffer drive
    const double damping = physics::damping_for_ratio(1.0, proposed, inertia);
    d.note(fmt::format("The guide's stiffness is {} ({}), with damping {} for damping ratio 1 (natural frequency {} "
                       "rad/s).",
                       describe_gain(drive.stiffness, proposed, k_unit), reason,
                       describe_gain(drive.damping, damping, d_unit),
                       format_number(physics::natural_frequency(proposed, inertia), 3)));
    std::vector<Edit> edits;
    // Rounded down, so the written stiffness does not land back above the bound.
    if (drive.stiffness->span.valid())
      edits.push_back(Edit{drive.stiffness->span.file, drive.stiffness->span.offset, drive.stiffness->span.length,
                           format_number_at_most(drive.stiffness->authored_for(proposed), 4)});
    if (drive.damping && drive.damping->span.valid()) edits.push_back(replace_value(*drive.damping, damping, 4));
    if (!edits.empty())
      d.fix = Fix{fmt::format("set stiffness {} and damping {}", describe_gain(drive.stiffness, proposed, k_unit),
                              describe_gain(drive.damping, damping, d_unit)),
                  Applicability::Unsafe, std::move(edits)};
  }

  // The drive as MuJoCo's integrator steps it (physics/servo_step.h), on M₀ᵢᵢ: a spring past
  // h·nf = 1 whose step map decays is not unstable, whatever h·nf; one that grows, or that
  // nothing damps, is.
  struct MujocoStep {
    const DrivenJoint* driven;
    physics::Servo servo;

    physics::StepMap map(physics::MujocoIntegrator integrator) const {
      return physics::servo_step(integrator, driven->rate.h(), servo);
    }
    physics::StepVerdict verdict(physics::MujocoIntegrator integrator) const {
      return physics::step_verdict(integrator, driven->rate.h(), servo);
    }
    physics::StepVerdict verdict() const { return verdict(driven->rate.integrator); }

    std::string damping_text(physics::MujocoIntegrator integrator) const {
      const Unit unit = damping_unit(*driven->joint);
      const double implicit = physics::implicit_damping(integrator, servo);
      const double explicit_part = physics::explicit_damping(integrator, servo);
      if (implicit > 0 && explicit_part > 0)
        return fmt::format("{} of the damping implicitly and {} explicitly", describe(implicit, unit, 3),
                           describe(explicit_part, unit, 3));
      if (implicit > 0) return fmt::format("the damping ({}) implicitly", describe(implicit, unit, 3));
      if (explicit_part > 0) return fmt::format("the damping ({}) explicitly", describe(explicit_part, unit, 3));
      return "no damping";
    }

    static std::string outcome(physics::StepVerdict verdict) {
      switch (verdict) {
        case physics::StepVerdict::Decays: return "decays instead of growing";
        case physics::StepVerdict::Grows: return "grows every step";
        case physics::StepVerdict::Undamped: return "is never damped: nothing dissipates the oscillation";
      }
      return "";
    }

    std::vector<std::string> notes() const {
      const physics::SimulationRate& rate = driven->rate;
      const physics::StepMap step = map(rate.integrator);
      const physics::StepVerdict now = verdict();
      std::vector<std::string> out;
      out.push_back(fmt::format(
          "{} ({}) takes the spring explicitly and {}: one step maps (q, q̇) with spectral radius {} on {} = {} {}, "
          "so the spring's unresolved mode {}.",
          physics::integrator_name(rate.integrator), rate.integrator_origin, damping_text(rate.integrator),
          format_number(step.spectral_radius(), 3), driven->judged.label(), format_number(servo.inertia, 3),
          driven->inertia_unit(), outcome(now)));
      const double damping_ratio = servo.damping_ratio(), slow_rate = physics::slowest_decay_rate(servo);
      if (now == physics::StepVerdict::Decays)
        out.push_back(fmt::format("Damping ratio ζ = {} on {}: {}; the slowest mode decays at {} rad/s, h × that rate = {}.",
                                  format_number(damping_ratio, 3), driven->judged.label(),
                                  damping_ratio >= 1 ? "overdamped, the response is that slow mode"
                                                     : "underdamped, it rings at a frequency the step does not resolve "
                                                       "but dies out",
                                  format_number(slow_rate, 3), format_number(rate.h() * slow_rate, 3)));
      // The other choice of integrator, when it flips the verdict.
      const bool implicit_now = rate.integrator == physics::MujocoIntegrator::Implicit ||
                                rate.integrator == physics::MujocoIntegrator::ImplicitFast;
      const auto other = implicit_now ? physics::MujocoIntegrator::Euler : physics::MujocoIntegrator::ImplicitFast;
      const physics::StepMap alternative = map(other);
      const bool decays_now = now == physics::StepVerdict::Decays;
      const bool decays_other = verdict(other) == physics::StepVerdict::Decays;
      if (decays_other != decays_now)
        out.push_back(fmt::format("Under {}, which takes {}, the same drive would {} (spectral radius {}){}.",
                                  implicit_now ? "MuJoCo's default Euler integrator" : "<option integrator=\"implicitfast\">",
                                  damping_text(other), alternative.stable() ? "decay" : "diverge",
                                  format_number(alternative.spectral_radius(), 3),
                                  alternative.stable() ? "" : ": keep the implicit integrator"));
      return out;
    }
  };

  static std::optional<MujocoStep> mujoco_step(const DrivenJoint& driven) {
    if (driven.rate.solver != physics::Solver::MuJoCo || driven.acceleration() || !(driven.inertia_used > 0))
      return std::nullopt;
    return MujocoStep{&driven, mujoco_servo(driven, driven.inertia_used)};
  }

  static std::string derivation(const DrivenJoint& driven, double nf) {
    if (driven.acceleration())
      return fmt::format("For {}: nf = sqrt(k) = sqrt({}) = {} rad/s: an acceleration drive acts as if I = 1.",
                         joint_label(*driven.joint), describe_gain(driven.drive->stiffness, driven.stiffness, stiffness_unit(*driven.joint)),
                         format_number(nf, 4));
    std::string text = fmt::format(
        "For {}: nf = sqrt(k / I) = sqrt({} / {} {}) = {} rad/s on {}; inertias: {}.",
        joint_label(*driven.joint), describe_gain(driven.drive->stiffness, driven.stiffness, stiffness_unit(*driven.joint)),
        format_number(driven.inertia_used, 3), driven.inertia_unit(), format_number(nf, 4), driven.judged.label(),
        driven.inertias_text());
    if (driven.judged.basis == InertiaBasis::LighterLink && driven.articulated.known)
      text += fmt::format(" On the articulation nf = {} rad/s.",
                          format_number(physics::natural_frequency(driven.stiffness, driven.articulated.value), 4));
    if (!driven.judged.fallback.empty())
      text += " The articulation is unknown, so the guide's lighter link stands in for it: it can sit far below what "
              "an arm's joint moves.";
    if (driven.judged.basis == InertiaBasis::Articulation)
      text += " The drive moves its whole distal subtree: PhysX's drive row sees 1/r, not the neighbouring link.";
    return text;
  }

  static std::string bound_text(const physics::SimulationRate& rate, double h_nf) {
    if (rate.solver == physics::Solver::TGS)
      return fmt::format("The guide's bound is nf ≤ rate × position iterations = {} rad/s, i.e. h·nf ≤ 1 at {}; here "
                         "h·nf = {}.",
                         format_number(rate.frequency_bound(), 4), rate.describe(), format_number(h_nf, 3));
    if (rate.solver == physics::Solver::MuJoCo)
      return fmt::format("MuJoCo integrates a position actuator's spring explicitly once per timestep: past nf = "
                         "1/timestep = {} rad/s ({}; here h·nf = {}) the step does not resolve the spring's own "
                         "oscillation, and whether it dies out is the integrator's step map's to say, not PhysX's bound.",
                         format_number(rate.frequency_bound(), 4), rate.describe(), format_number(h_nf, 3));
    return fmt::format("The bound is nf ≤ rate = {} rad/s, i.e. h·nf ≤ 1 at {}; here h·nf = {}.",
                       format_number(rate.frequency_bound(), 4), rate.describe(), format_number(h_nf, 3));
  }

  RuleInfo info_{"drive-natural-frequency",
                 "A drive's natural frequency sqrt(k/I) exceeds what the solver's step resolves (h·nf > 1)",
                 Severity::Error,
                 true,
                 RuleOrigin::Check,
                 {}};
};

}  // namespace

const Rule& drive_natural_frequency() {
  static const DriveNaturalFrequency rule;
  return rule;
}

}  // namespace assetlint::rules
