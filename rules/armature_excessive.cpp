#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "physics/drive.h"
#include "physics/servo_step.h"
#include "rules/drive_support.h"
#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// Armature on an actuated joint is the motor's rotor reflected through its gearbox, G²·I_rotor
// (docs/rules/armature-excessive.md). The guide asks for a datasheet when it is an order of
// magnitude above the lighter link; on anything but a mimic-coupled gripper the joint moves
// its whole distal subtree, so the comparison is with that (Mᵢᵢ without the armature). It is
// reported when above `max_ratio` of what the joint moves, and escalated to a warning only when
//   - the drive would be unstable without it (PhysX's bound h·nf ≤ 1, MuJoCo's step map: the
//     shared judged inertia of drive_support.h less the armature): the tuning lever the guide
//     warns about;
//   - it dwarfs everything the joint moves (above `flywheel_ratio`): a flywheel, not a rotor;
//   - a declared motor reflects less, or no actuator reaches the joint (no rotor to reflect).
// Otherwise it is an info: an ordinary gearmotor's reflected inertia.
class ArmatureExcessive final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const double factor = rule_option(info_, settings, "max_ratio");
    const double flywheel = rule_option(info_, settings, "flywheel_ratio");
    const double max_time_constant = rule_option(info_, settings, "max_time_constant");
    const double servo_armature = rule_option(info_, settings, "servo_armature");
    const DriveModel model(asset, settings);
    std::vector<const Joint*> unjudged;  // an armature whose load has no mass to compare with
    for (const Joint& joint : asset.joints) {
      if (!is_single_dof(joint.type) || !joint.armature || joint.armature->value <= 0) continue;
      const double armature = joint.armature->value;
      const physics::EffectiveInertia lighter = physics::effective_inertia(model.articulation(), asset, joint);
      const Moved moved = what_it_moves(model, asset, settings, joint, lighter, armature);
      // A stand-in mass (MuJoCo refuses a massless body on a joint; a model meant to carry a
      // tool there puts 1e-9 kg): the armature is then the joint's only inertia, by design.
      if (!moved.known) {
        unjudged.push_back(&joint);
        continue;
      }
      if (moved.value < kStandInLoad) continue;
      const double ratio = armature / moved.value;
      if (ratio <= factor) continue;
      if (joint.motor && armature <= reflected(*joint.motor) * (1 + 1e-6)) continue;
      Candidate c{joint, lighter, moved, armature, ratio, factor, flywheel, servo_armature, model.spring_drive(joint)};
      c.damping = damping_on(asset, joint, c.driven);
      c.max_time_constant = max_time_constant;
      c.harmless_effect = rule_option(info_, settings, "harmless_follower_effect");
      if (crutch(c)) c.shared = shared_by_a_steady_drive(model, asset, joint);
      // Only on the robot's own parts: an object hung from the world (a puck, a leaf) is what
      // the task moves, and a flywheel there changes the task whatever set the value.
      const physics::Body* parent = model.articulation().side(joint, 0);
      if (joint.actuation == Actuation::Passive && parent && !parent->world)
        c.motor_literal = actuated_sharing_literal(asset, joint);
      if (joint.actuation == Actuation::Passive || joint.actuation == Actuation::Linkage)
        c.effect = follower_effect(model, asset, joint, armature, c.effect_unknown);
      if (joint.actuation == Actuation::Passive && touches_nothing(model.articulation(), asset, joint)) {
        report_isolated(c, out);
        continue;
      }
      report(c, out);
    }
    report_unjudged(model, unjudged, out);
  }

 private:
  // kg·m² (kg on a slide): less than a gram at a millimetre from the axis.
  static constexpr double kStandInLoad = 1e-9;

  // What the armature is compared with.
  // Armatures the rule cannot compare with anything: one info for the file, so the silence on
  // them is not read as a verdict.
  static void report_unjudged(const DriveModel& model, const std::vector<const Joint*>& joints, Reporter& out) {
    if (joints.empty()) return;
    const Joint& first = *joints.front();
    const std::string amount = fmt::format("{} {}", format_number(first.armature->value, 3),
                                           is_angular(first.type) ? "kg·m²" : "kg");
    Diagnostic& d = out.report(
        first.armature->span.valid() ? first.armature->span : first.name.span, Severity::Info,
        joints.size() == 1
            ? fmt::format("armature {} of {} not judged: what the joint moves has no known inertia", amount, short_name(first))
            : fmt::format("armature of {} joints not judged ({} of {} first): what they move has no known inertia",
                          joints.size(), amount, short_name(first)));
    constexpr std::size_t kListed = 5;
    for (std::size_t i = 0; i < joints.size() && i < kListed; ++i) {
      const physics::ArticulatedInertia inertia = model.articulation().joint_space_inertia(*joints[i]);
      std::string why = inertia.reason;
      if (!inertia.unknown_links.empty()) {
        why = "unknown mass properties of ";
        for (std::size_t k = 0; k < inertia.unknown_links.size() && k < 3; ++k)
          why += (k ? ", '" : "'") + inertia.unknown_links[k] + "'";
        if (inertia.unknown_links.size() > 3) why += fmt::format(" and {} more", inertia.unknown_links.size() - 3);
      }
      d.note(fmt::format("{}: {}{}.", joint_label(*joints[i]), format_number(joints[i]->armature->value, 3),
                         why.empty() ? "" : fmt::format(" ({})", why)));
    }
    if (joints.size() > kListed) d.note(fmt::format("… and {} more.", joints.size() - kListed));
    d.note("The armature is compared with everything the joint moves; where a body's mass or inertia is unknown (an "
           "MJCF body whose inertia MuJoCo derives from mesh geoms, a link without <inertial>) there is nothing to "
           "compare it with, so no ratio is given. Give the bodies explicit mass and inertia to have it judged.");
  }

  struct Moved {
    bool known = false;
    double value = 0;     // kg·m² (kg), without the armature
    bool lighter = true;  // the guide's lighter link; else everything the joint moves (Mᵢᵢ − armature)
    bool stand_in = false;  // the lighter link standing in for an unknown Mᵢᵢ: a lower bound
    bool with_followers = false;  // Jᵀ·M·J over the joint and the mimics that follow it
    bool mechanism = false;       // MJCF: along the mechanism mimics and loop closures make (physics/linkage.h)
    bool partial = false;  // what a loop, coupling tendon or rope adds is left out (Joint::hidden_load)
    std::string name() const { return lighter ? "the lighter link" : "what it moves"; }
  };

  static Moved what_it_moves(const DriveModel& model, const Asset& asset, const Settings& settings, const Joint& joint,
                             const physics::EffectiveInertia& lighter, double armature) {
    Moved moved;
    const bool guide = asset.format != SourceFormat::Mjcf && guide_applies(asset, settings, joint);
    // MJCF: a joint that mimics or loop closures tie to others moves their mechanism (a mimic
    // follower is compared with its own Mᵢᵢ: its leader's drive is what moves it).
    // The bodies alone: another joint's armature is no more a load than this one's.
    if (const physics::Mechanism tied =
            joint.is_mimic() ? physics::Mechanism{} : model.mechanism(joint, physics::Armatures{nullptr, true});
        tied.tied() && tied.inertia.known && tied.inertia.value > 0) {
      moved.known = true;
      moved.value = tied.inertia.value;
      moved.lighter = false;
      moved.mechanism = true;
      moved.partial = static_cast<bool>(joint.hidden_load);
      return moved;
    }
    if (!guide) {
      // A joint whose mimics follow it turns them too (a motor-side gear and the joint a gear
      // ratio ties to it): what it moves is the mechanism's Jᵀ·M·J, not its own subtree.
      const bool leads = physics::coupled_joints(asset, joint).size() > 1 && !joint.is_mimic();
      const physics::ArticulatedInertia diagonal = leads ? physics::mechanism_inertia(model.articulation(), asset, joint)
                                                         : model.articulation().joint_space_inertia(joint);
      if (diagonal.known && diagonal.value - armature > 0) {
        moved.known = true;
        moved.value = diagonal.value - armature;
        moved.lighter = false;
        moved.with_followers = leads;
        moved.partial = static_cast<bool>(joint.hidden_load);
        return moved;
      }
      moved.stand_in = true;
    }
    if (lighter.known && lighter.link_inertia > 0) {
      moved.known = true;
      moved.value = lighter.link_inertia;
    }
    return moved;
  }

  // What a mimic follower's armature does to the drive of the joint it follows: the leader's
  // servo on the mechanism's Jᵀ·M·J with it and without it (armature × multiplier² less).
  struct FollowerEffect {
    const Joint* leader = nullptr;
    double with = 0, without = 0;  // the mechanism's inertia along the leader, model units
    double settle_with = 0, settle_without = 0;  // s: 1 / the servo's slowest decay rate
    bool stable_with = false, stable_without = false;
    std::string stability{};  // how stability was judged ("implicitfast's step", "the TGS bound")
    double change() const { return std::abs(settle_with - settle_without) / settle_without; }
  };

  static std::optional<FollowerEffect> follower_effect(const DriveModel& model, const Asset& asset, const Joint& joint,
                                                       double armature, std::string& why) {
    const Joint* leader = joint.is_mimic() ? asset.followed_joint(joint) : nullptr;
    // MJCF: the driven joint of the mechanism mimics and loop closures tie this one into.
    if (asset.format == SourceFormat::Mjcf)
      for (const Joint* tied : physics::tied_joints(asset, {&joint}))
        if (tied != &joint && model.spring_drive(*tied)) {
          leader = tied;
          break;
        }
    if (!leader) {
      why = "no spring drive moves the mechanism";
      return std::nullopt;
    }
    if (leader->hidden_load) {
      why = fmt::format("the drive of '{}' is judged on its own M₀ᵢᵢ: {}, with damping or a load the mechanism "
                        "does not fold in",
                        leader->name.text, leader->hidden_load->what);
      return std::nullopt;
    }
    const std::optional<DrivenJoint> driven = model.spring_drive(*leader);
    if (!driven || driven->acceleration() || !driven->damping_known() || !(driven->damping > 0)) {
      why = fmt::format("the drive of '{}' has no known damping", leader->name.text);
      return std::nullopt;
    }
    FollowerEffect e{leader, 0, 0};
    if (const physics::Mechanism with = model.mechanism(*leader); with.tied()) {
      const physics::Mechanism without = model.mechanism(*leader, physics::Armatures{&joint, false});
      if (!with.inertia.known || !without.inertia.known) {
        why = with.inertia.unknown_links.empty()
                  ? with.inertia.reason
                  : fmt::format("the mass of {} comes from geoms asset-lint cannot measure (a mesh, a height field, a shell)",
                                name_list(with.inertia.unknown_links));
        return std::nullopt;
      }
      e.with = with.inertia.value;
      e.without = without.inertia.value;
    } else {
      const physics::ArticulatedInertia mechanism = physics::mechanism_inertia(model.articulation(), asset, *leader);
      const double gearing = joint.mimic->multiplier.value;
      if (!mechanism.known) return std::nullopt;
      e.with = mechanism.value;
      e.without = mechanism.value - armature * gearing * gearing;
    }
    if (!(e.without > 0)) return std::nullopt;
    const physics::SimulationRate& rate = driven->rate;
    const auto judge = [&](double inertia, double& settle, bool& stable) {
      const physics::Servo servo = rate.solver == physics::Solver::MuJoCo
                                       ? mujoco_servo(*driven, inertia)
                                       : physics::Servo{inertia, driven->stiffness, 0, driven->damping};
      settle = 1 / physics::slowest_decay_rate(servo);
      stable = rate.solver == physics::Solver::MuJoCo
                   ? physics::step_verdict(rate.integrator, rate.h(), servo) == physics::StepVerdict::Decays
                   : physics::natural_frequency(driven->stiffness, inertia) <= rate.frequency_bound();
    };
    judge(e.with, e.settle_with, e.stable_with);
    judge(e.without, e.settle_without, e.stable_without);
    if (!std::isfinite(e.settle_with) || !std::isfinite(e.settle_without)) return std::nullopt;
    e.stability = rate.solver == physics::Solver::MuJoCo
                      ? fmt::format("{}'s step", physics::integrator_name(rate.integrator))
                      : fmt::format("the {} bound", physics::solver_name(rate.solver));
    return e;
  }

  struct Candidate {
    const Joint& joint;
    const physics::EffectiveInertia& lighter;
    Moved moved;
    double armature;
    double ratio;
    double factor;
    double flywheel;
    double servo_armature;  // kg·m²: what a small smart servo reflects; a hinge's armature up to it is no flywheel
    std::optional<DrivenJoint> driven;
    const Joint* shared = nullptr;  // a steady drive with the same armature literal
    const Joint* motor_literal = nullptr;  // passive: an actuated joint whose armature is the same literal
    double damping = 0;            // what damps the joint's speed, model units (0: none known)
    double max_time_constant = 0;  // s
    std::optional<FollowerEffect> effect{};  // a mimic follower's: what its armature does to the leader's drive
    std::string effect_unknown{};            // why `effect` could not be computed
    double harmless_effect = 0;            // the settling change under which an unchanged stability is harmless
    // How soon the joint's speed settles under its damping, armature included (0: no damping).
    double lag() const { return damping > 0 ? physics::inertial_time_constant(armature + moved.value, damping) : 0; }
    // The damper, not the armature, sets how the joint moves on anything slower than the lag.
    bool settled_by_damping() const { return damping > 0 && lag() <= max_time_constant; }
    const char* unit() const { return is_angular(joint.type) ? "kg·m²" : "kg"; }
    // Far above everything the joint moves: the drive turns a flywheel.
    // Not when part of the load is left out: the ratio then overstates the armature's share.
    bool dwarfs() const { return !moved.lighter && !moved.partial && ratio > flywheel && !servo_sized(); }
    // A hinge armature a real servo at the joint reflects: a light load makes the ratio large, not the rotor.
    bool servo_sized() const { return is_angular(joint.type) && armature <= servo_armature; }
  };

  // The damping that acts on the joint's speed: its drive's (MuJoCo: kv·G² plus the joint's own
  // damping), or on an MJCF joint no servo drives (a tendon's, a passive one), its own damping.
  static double damping_on(const Asset& asset, const Joint& joint, const std::optional<DrivenJoint>& driven) {
    if (driven) return driven->damping_known() ? driven->damping : 0;
    if (asset.format == SourceFormat::Mjcf && joint.joint_damping) return joint.joint_damping->value;
    return 0;
  }

  struct Crutch {
    double natural_frequency;  // rad/s, without the armature
    double inertia;            // the judged inertia less the armature
  };

  // A passive joint that hangs from the world and moves nothing that collides (a goal marker a
  // task script places): no contact, no joint and no actuator carries its motion to another
  // body, so its inertia, armature included, changes how that body alone moves.
  static bool touches_nothing(const physics::Articulation& articulation, const Asset& asset, const Joint& joint) {
    const physics::Body* parent = articulation.side(joint, 0);
    if (parent && !parent->world) return false;
    if (joint.is_mimic() || !asset.mimic_followers(joint.name.text).empty()) return false;  // a joint equality
    const Link* child = asset.side_link(joint, 1);
    if (!child) return false;
    std::vector<const Link*> pending{child};
    std::vector<const Link*> seen;
    while (!pending.empty()) {
      const Link* link = pending.back();
      pending.pop_back();
      if (std::find(seen.begin(), seen.end(), link) != seen.end()) continue;
      seen.push_back(link);
      if (!link->collisions.empty()) return false;
      for (const Joint* next : asset.joints_at(link->name.text)) {
        if (next->parent.text != link->name.text) continue;
        if (next->actuation != Actuation::Passive && next->actuation != Actuation::Unknown) return false;
        if (const Link* below = asset.side_link(*next, 1)) pending.push_back(below);
      }
    }
    return true;
  }

  void report_isolated(const Candidate& c, Reporter& out) const {
    const Joint& joint = c.joint;
    Diagnostic& d = out.report(joint.armature->span.valid() ? joint.armature->span : joint.name.span, Severity::Info,
                               fmt::format("armature {} {} of {} ({}× {}) on a body nothing touches",
                                           format_number(c.armature, 3), c.unit(), short_name(joint),
                                           format_number(c.ratio, 3), c.moved.name()));
    d.note(moved_text(c));
    d.note("The joint hangs from the world, no actuator reaches it, and nothing it moves has a collision shape: no "
           "contact, joint or drive passes its motion to another body, so the armature only slows this body (a "
           "marker or target a script places). Remove it if the body should move freely.");
  }

  static bool asset_follows(const Joint& joint, const Joint& leader) {
    return joint.mimic && joint.mimic->reference.text == leader.name.text;
  }

  static double reflected(const Motor& motor) { return motor.gear_ratio * motor.gear_ratio * motor.rotor_inertia.value; }

  void report(const Candidate& c, Reporter& out) const {
    const Joint& joint = c.joint;
    const Span at = joint.armature->span.valid() ? joint.armature->span : joint.name.span;
    const std::string amount = fmt::format("{} {}", format_number(c.armature, 3), c.unit());
    const std::string times = format_number(c.ratio, 3);
    const std::string against = c.moved.name();

    if (joint.motor) {
      Diagnostic& d = out.report(at, Severity::Warning,
                                 fmt::format("armature {} of {} ({}× {}) is more than its declared motor reflects",
                                             amount, short_name(joint), times, against));
      d.note(moved_text(c));
      d.note(fmt::format("The declared motor ({}: G = {}, I_rotor = {} kg·m²) reflects only G²·I_rotor = {} kg·m².",
                         joint.motor->origin, format_number(joint.motor->gear_ratio),
                         format_number(joint.motor->rotor_inertia.value, 3), format_number(reflected(*joint.motor), 3)));
      drive_effect(c, d);
      return;
    }
    // A passive joint that takes its armature from a literal set for the motors (a default class
    // on every joint): a side effect of that literal on a part that only swings, not modelling.
    if (joint.actuation == Actuation::Passive && (!c.dwarfs() || c.motor_literal)) {
      Diagnostic& d = out.report(at, Severity::Info,
                                 fmt::format("armature {} of {} ({}× {}) on a free joint no actuator moves", amount,
                                             short_name(joint), times, against));
      d.note(moved_text(c));
      d.note("No actuator reaches this joint and no loop or coupling ties it to one that does: it moves only under "
             "gravity, contact and the reaction of its links, so the armature damps how it swings and loads no drive. "
             "No real mechanism has that inertia; remove it if the joint should swing freely.");
      if (c.motor_literal)
        d.note(joint.armature->span,
               fmt::format("The value is one literal shared with actuated joints ({} first), set for their motors; "
                           "it reaches this joint as a side effect. Give the passive joints armature 0 (their own "
                           "class) if they should swing freely.",
                           joint_label(*c.motor_literal)));
      return;
    }
    if (c.effect && c.effect->change() < c.harmless_effect && c.effect->stable_with == c.effect->stable_without) {
      report_harmless_follower(c, at, amount, times, against, out);
      return;
    }
    if (joint.actuation == Actuation::Linkage && c.effect) {
      const FollowerEffect& e = *c.effect;
      Diagnostic& d = out.report(at, Severity::Warning,
                                 fmt::format("armature {} of linkage joint {} ({}× {}) changes the drive of {} by {} %",
                                             amount, short_name(joint), times, against, short_name(*e.leader),
                                             format_number(e.change() * 100, 2)));
      d.note(moved_text(c));
      d.note(e.leader->name.span,
             fmt::format("Moving with the linkage {} drives, the armature adds {} {} to its inertia along the drive (M₀ "
                         "along the mechanism: {} with it, {} without): the drive settles with a time constant of {} s "
                         "with it and {} s without, {}. No motor's rotor sits at this joint, so the armature is inertia "
                         "the real mechanism does not have; if it only steadies the closed chain, keep it as small as "
                         "does that.",
                         joint_label(*e.leader), format_number(e.with - e.without, 3), c.unit(), format_number(e.with, 3),
                         format_number(e.without, 3), format_number(e.settle_with, 3), format_number(e.settle_without, 3),
                         e.stable_with == e.stable_without ? fmt::format("equally {} under {}", e.stable_with ? "stable" : "unstable", e.stability)
                                                           : fmt::format("{} under {} only with it", e.stable_with ? "stable" : "unstable", e.stability)));
      return;
    }
    if (joint.actuation == Actuation::Linkage) {
      Diagnostic& d = out.report(at, Severity::Warning,
                                 fmt::format("armature {} of linkage joint {} ({}× {}) with no motor of its own", amount,
                                             short_name(joint), times, against));
      d.note(moved_text(c));
      d.note(fmt::format("A loop or coupling ties this joint to the driven mechanism, so the drive moves it, but no "
                         "actuator names it: no motor's rotor is reflected onto it, and the armature is inertia the real "
                         "mechanism does not have, which every drive of the linkage drags. What it does to that drive "
                         "was not computed{}. If it only steadies a closed chain, keep it as small as does that.",
                         c.effect_unknown.empty() ? std::string() : fmt::format(" ({})", c.effect_unknown)));
      drive_effect(c, d);
      return;
    }
    if (joint.actuation == Actuation::Passive) {
      Diagnostic& d = out.report(at, Severity::Warning,
                                 fmt::format("armature {} of {} ({}× {}) on a joint no actuator moves", amount,
                                             short_name(joint), times, against));
      d.note(moved_text(c));
      d.note("No actuator reaches this joint, directly or through a fixed tendon, so no motor's rotor is reflected "
             "onto it: the armature is inertia the real mechanism does not have.");
      drive_effect(c, d);
      return;
    }
    const std::optional<Crutch> without = c.moved.partial ? std::nullopt : crutch(c);
    if (without) {
      const physics::SimulationRate& rate = c.driven->rate;
      Diagnostic& d = out.report(at, c.shared ? Severity::Info : Severity::Warning,
                                 fmt::format("armature {} of {} ({}× {}) is what keeps its drive {}", amount,
                                             short_name(joint), times, against,
                                             rate.solver == physics::Solver::MuJoCo
                                                 ? fmt::format("stable under {}", physics::integrator_name(rate.integrator))
                                                 : fmt::format("within the {} bound", physics::solver_name(rate.solver))));
      d.note(moved_text(c));
      d.note(fmt::format("Without the armature the drive's natural frequency would be sqrt({} {} / {} {}) = {} rad/s "
                         "on {} less the armature, above the bound {} rad/s ({}){}: the armature is the tuning lever "
                         "the guide describes, and it changes the robot unless a motor datasheet backs it.",
                         format_number(c.driven->stiffness, 4), unit_symbol(stiffness_unit(joint)),
                         format_number(without->inertia, 3), c.unit(), format_number(without->natural_frequency, 4),
                         c.driven->judged.basis == InertiaBasis::LighterLink && c.driven->articulated.known
                             ? std::string("the articulation's I")
                             : c.driven->judged.label(), format_number(rate.frequency_bound(), 4), rate.step_text(),
                         rate.solver == physics::Solver::MuJoCo
                             ? fmt::format(", and {}'s step would not damp it", physics::integrator_name(rate.integrator))
                             : std::string()));
      if (rate.solver == physics::Solver::MuJoCo && rate.integrator != physics::MujocoIntegrator::ImplicitFast &&
          rate.integrator != physics::MujocoIntegrator::Implicit &&
          physics::step_verdict(physics::MujocoIntegrator::ImplicitFast, rate.h(),
                                mujoco_servo(*c.driven, without->inertia)) == physics::StepVerdict::Decays)
        d.note("Under <option integrator=\"implicitfast\">, which takes the actuator's kv implicitly, the drive would be "
               "damped stably without the armature.");
      if (c.shared)
        d.note(c.joint.armature->span,
               fmt::format("This armature is {} {}, whose drive is steady without it: a value set for a motor type, "
                           "its reflected rotor inertia, rather than a lever tuned for this joint. Declare the motor "
                           "to record that; the drive then depends on it only as the real joint does.",
                           same_literal(c.joint, *c.shared) ? "one literal shared with" : "the same value as",
                           joint_label(*c.shared)));
      drive_effect(c, d);
      return;
    }
    if (c.dwarfs() && c.settled_by_damping()) {
      Diagnostic& d = out.report(at, Severity::Info,
                                 fmt::format("armature {} of {} is {}× everything the joint moves, but its damping "
                                             "settles it within {} s",
                                             amount, short_name(joint), times, format_number(c.lag(), 2)));
      d.note(moved_text(c));
      d.note(fmt::format("With damping d = {} {}, the joint's speed settles in (armature + load) / d = {} s, within "
                         "max_time_constant = {} s: on any slower motion the joint moves as its damper lets it, and "
                         "the armature adds only that lag (without it, {} s). It is still far above a rotor reflected "
                         "onto this load: confirm it against the motor datasheet, or keep it as the steadier it is.",
                         format_number(c.damping, 4), unit_symbol(damping_unit(joint)), format_number(c.lag(), 3),
                         format_number(c.max_time_constant),
                         format_number(physics::inertial_time_constant(c.moved.value, c.damping), 3)));
      drive_effect(c, d);
      return;
    }
    if (c.dwarfs()) {
      Diagnostic& d = out.report(at, Severity::Warning,
                                 fmt::format("armature {} of {} is {}× everything the joint moves: a flywheel, not a rotor",
                                             amount, short_name(joint), times));
      d.note(moved_text(c));
      d.note(fmt::format("A geared motor's rotor reflects as G²·I_rotor, typically comparable to the load it drives; "
                         "above {}× the joint moves as if the flywheel were the robot, and every motion it makes is "
                         "that much slower to start and stop.",
                         format_number(c.flywheel)));
      drive_effect(c, d);
      return;
    }
    if (joint.transmission) {
      const double gear = joint.transmission->ratio;
      const double rotor = c.armature / (gear * gear);
      const double rotor_ratio = rotor / c.moved.value;
      const bool plausible = rotor_ratio <= c.factor;
      Diagnostic& d = out.report(
          at, Severity::Info,
          fmt::format("armature {} of {} ({}× {}) is {} its gear {}", amount, short_name(joint), times, against,
                      plausible ? "consistent with" : "large even behind", format_number(gear)));
      d.note(joint.transmission->span,
             fmt::format("The actuator's gear G = {} implies a rotor of armature / G² = {} kg·m², {}× {} ({} {}; "
                         "threshold {}×).",
                         format_number(gear), format_number(rotor, 3), format_number(rotor_ratio, 3), against,
                         format_number(c.moved.value, 3), c.unit(), format_number(c.factor)));
      d.note(plausible ? "The guide's test, armature = G²·I_rotor, holds for a rotor of that size: confirm it against "
                         "the motor datasheet."
                       : "A rotor heavier than what it turns is unusual: confirm it against the motor datasheet. The "
                         "drive does not depend on it for stability, so it only changes how quickly the joint moves.");
      drive_effect(c, d);
      return;
    }
    Diagnostic& d = out.report(at, Severity::Info,
                               fmt::format("armature {} of {} is {}× {} (threshold {}×)", amount, short_name(joint),
                                           times, c.moved.lighter ? "the lighter link's inertia" : "what the joint moves",
                                           format_number(c.factor)));
    d.note(moved_text(c));
    if (!c.moved.lighter && !c.moved.partial && c.ratio > c.flywheel && c.servo_sized())
      d.note(fmt::format("Above flywheel_ratio, but within servo_armature = {} kg·m², what a small smart servo at the "
                         "joint reflects (a Dynamixel XL330's 1.7e-8 kg·m² rotor behind its 288:1 gear): a load this "
                         "light makes the ratio large, not the rotor.",
                         format_number(c.servo_armature)));
    if (c.moved.partial && crutch(c))
      d.note("On Mᵢᵢ alone its drive would be past the step's bound without it, but what the joint also turns adds "
             "inertia the file does not give: whether the drive needs the armature is not judged. Declare the motor to "
             "record what the armature models.");
    else
      d.note(c.driven ? "Its drive would be steady without it (within the natural-frequency bound, or damped by MuJoCo's "
                        "integrator), so it models a motor rather than steadying the drive; declare the motor to record "
                        "that."
                      : "No spring drive depends on it, so it models a motor rather than steadying a drive; declare the "
                        "motor to record that.");
    if (c.driven && c.driven->rate.solver == physics::Solver::MuJoCo && !c.driven->damping_known())
      d.note(fmt::format("Whether the drive needs it to stay stable was not judged: {}.", c.driven->drive->damping_unknown));
    drive_effect(c, d);
  }

  // A follower's armature judged by its effect: the leader's servo settles as fast without it,
  // and its step is as stable. A heavily damped servo closes at the pace kv/kp sets, whatever
  // the inertia, so a large ratio to the follower's own link can change nothing.
  void report_harmless_follower(const Candidate& c, const Span& at, const std::string& amount, const std::string& times,
                                const std::string& against, Reporter& out) const {
    const FollowerEffect& e = *c.effect;
    const bool mimic = c.joint.is_mimic() && asset_follows(c.joint, *e.leader);
    Diagnostic& d = out.report(at, Severity::Info,
                               fmt::format("armature {} of {} {} ({}× {}) changes its leader's drive by {} %",
                                           amount, mimic ? "mimic follower" : "linkage joint", short_name(c.joint), times,
                                           against, format_number(e.change() * 100, 2)));
    d.note(moved_text(c));
    d.note(e.leader->name.span,
           fmt::format("{} the armature adds {} {} to the mechanism that {} drives ({}: {} with it, {} without). The drive "
                       "settles with a time constant of {} s with it and {} s without (1 / the servo's slowest decay "
                       "rate), and its stability under {} is the same ({}).",
                       mimic ? fmt::format("Through its multiplier {}", format_number(c.joint.mimic->multiplier.value))
                             : std::string("Moving with the linkage the drive closes through its loop"),
                       format_number(e.with - e.without, 3), c.unit(), joint_label(*e.leader),
                       mimic ? "Jᵀ·M·J" : "M₀ along the mechanism", format_number(e.with, 3),
                       format_number(e.without, 3), format_number(e.settle_with, 3), format_number(e.settle_without, 3),
                       e.stability, e.stable_with ? "stable both ways" : "unstable both ways"));
    d.note(fmt::format("Under harmless_follower_effect ({} %): the {}'s armature is inertia the real mechanism "
                       "does not have, but it changes nothing the drive does; remove it if the model should match the "
                       "mechanism.",
                       format_number(c.harmless_effect * 100), mimic ? "follower" : "linkage joint"));
  }

  // The natural frequency the drive would have without its armature, when the drive would then
  // fail: past PhysX's bound, or (MuJoCo) with a step map that does not decay. On what the
  // solver divides by (DrivenJoint::solver_inertia) less the armature, which adds to Mᵢᵢ and to
  // 1/r one for one: whether the drive is stable is the solver's question, not the guide's figure's.
  static std::optional<Crutch> crutch(const Candidate& c) { return crutch(c.driven, c.armature); }
  static std::optional<Crutch> crutch(const std::optional<DrivenJoint>& driven, double armature) {
    if (!driven || driven->acceleration() || !driven->judged.known) return std::nullopt;
    const double inertia = driven->solver_inertia() - armature;
    if (!(inertia > 0)) return std::nullopt;
    const double without = physics::natural_frequency(driven->stiffness, inertia);
    const physics::SimulationRate& rate = driven->rate;
    if (without <= rate.frequency_bound()) return std::nullopt;
    if (rate.solver == physics::Solver::MuJoCo) {
      if (!driven->damping_known()) return std::nullopt;  // the step's verdict needs the damping
      if (physics::step_verdict(rate.integrator, rate.h(), mujoco_servo(*driven, inertia)) == physics::StepVerdict::Decays)
        return std::nullopt;
    }
    return Crutch{without, inertia};
  }

  // The first other joint in the same file whose armature has the same value as this one's and
  // that `accept` takes (which may ask for the same literal: one default class, one servo type).
  template <class Accept>
  static const Joint* sharing_armature_value(const Asset& asset, const Joint& joint, Accept accept) {
    const Span& literal = joint.armature->span;
    if (!literal.valid()) return nullptr;
    for (const Joint& other : asset.joints) {
      if (&other == &joint || !other.armature) continue;
      if (other.armature->span.file == literal.file && other.armature->value == joint.armature->value && accept(other))
        return &other;
    }
    return nullptr;
  }

  static bool same_literal(const Joint& a, const Joint& b) {
    return a.armature->span.file == b.armature->span.file && a.armature->span.offset == b.armature->span.offset;
  }

  static const Joint* actuated_sharing_literal(const Asset& asset, const Joint& joint) {
    return sharing_armature_value(asset, joint, [&](const Joint& other) {
      return same_literal(joint, other) && other.actuation == Actuation::Actuated;
    });
  }

  // Another actuated joint whose drive is steady without the armature and that takes it from
  // the same literal, or writes the same value again behind the same drive gains: the value is
  // the motor's, set for every joint that servo turns, not a lever tuned for this joint's
  // stability. Whether a model says so once in a class or on every joint is a matter of style;
  // an equal value behind other gains (another class, another motor) says nothing.
  static const Joint* shared_by_a_steady_drive(const DriveModel& model, const Asset& asset, const Joint& joint) {
    const std::optional<DrivenJoint> own = model.spring_drive(joint);
    return sharing_armature_value(asset, joint, [&](const Joint& other) {
      if (other.actuation == Actuation::Passive || other.actuation == Actuation::Linkage) return false;
      const std::optional<DrivenJoint> driven = model.spring_drive(other);
      if (!driven || driven->acceleration() || !driven->judged.known ||
          (driven->rate.solver == physics::Solver::MuJoCo && !driven->damping_known()) ||
          crutch(driven, other.armature->value))
        return false;
      return same_literal(joint, other) || (own && same_gains(*own, *driven));
    });
  }

  // Same stiffness, and the same damping or (MuJoCo) the same servo damping ratio: `dampratio`
  // gives each joint the kv its own M₀ᵢᵢ needs, so one servo's gains written on every joint
  // compile to different kv. The joint's own damping must then match too.
  static bool same_gains(const DrivenJoint& a, const DrivenJoint& b) {
    const auto equal = [](double x, double y) { return std::abs(x - y) <= 1e-9 * std::max(std::abs(x), std::abs(y)); };
    if (!equal(a.stiffness, b.stiffness)) return false;
    if (equal(a.damping, b.damping)) return true;
    if (a.rate.solver != physics::Solver::MuJoCo || b.rate.solver != physics::Solver::MuJoCo) return false;
    const auto joint_damping = [](const DrivenJoint& d) { return d.joint->joint_damping ? d.joint->joint_damping->value : 0.0; };
    const auto servo_ratio = [&](const DrivenJoint& d) {
      return (d.damping - joint_damping(d)) / (2 * std::sqrt(d.stiffness * d.solver_inertia()));
    };
    return a.stiffness > 0 && equal(joint_damping(a), joint_damping(b)) &&
           std::abs(servo_ratio(a) - servo_ratio(b)) <= 1e-6 * std::max(servo_ratio(a), servo_ratio(b));
  }

  static std::string moved_text(const Candidate& c) {
    const Joint& joint = c.joint;
    if (c.moved.lighter) {
      const double gearing = c.lighter.gearing;
      return fmt::format("For {}, the lighter link '{}' about '{}' has {} {}{} (threshold {}×{}); the guide's test is "
                         "armature = G²·I_rotor: this equals a rotor as heavy as that link behind a {}:1 gearbox.",
                         joint_label(joint), c.lighter.link->name.text, c.lighter.via->name.text,
                         format_number(c.lighter.link_inertia, 3), c.unit(),
                         std::abs(gearing) != 1.0
                             ? fmt::format(" (reflected with gearing² {})", format_number(gearing * gearing, 3))
                             : std::string(),
                         format_number(c.factor),
                         c.moved.stand_in ? "; what the whole joint moves is unknown, so the lighter link stands in: "
                                            "the ratio is an upper bound"
                                          : "",
                         format_number(std::sqrt(c.ratio), 3));
    }
    std::string text = fmt::format(
        "For {}, everything the joint moves has {} {} about its axis ({}, without the armature; threshold {}×); "
        "armature = G²·I_rotor: this equals a rotor as heavy as that load behind a {}:1 gearbox.",
        joint_label(joint), format_number(c.moved.value, 3), c.unit(),
        c.moved.mechanism        ? "M₀ along the mechanism that mimics and loop closures tie it into (its bodies alone, no joint's armature), every other joint held"
        : c.moved.with_followers ? "Jᵀ·M·J with the joints that mimic it moving at their multipliers and every other joint held"
                                 : "Mᵢᵢ with every other joint held",
        format_number(c.factor), format_number(std::sqrt(c.ratio), 3));
    if (c.moved.partial)
      text += fmt::format(" That leaves out part of its load ({}), so the ratio overstates the armature's share{}.",
                          joint.hidden_load->what, c.ratio > c.flywheel ? " and is not judged as a flywheel" : "");
    return text;
  }

  static void drive_effect(const Candidate& c, Diagnostic& d) {
    if (!c.driven || c.driven->acceleration() || !c.driven->judged.known) return;
    const DrivenJoint& driven = *c.driven;
    const double k = driven.stiffness, with = driven.judged.value, without = with - c.armature;
    std::string effect =
        without > 0 ? fmt::format("It lowers the drive's natural frequency on {} from {} to {} rad/s",
                                  driven.judged.label(), format_number(physics::natural_frequency(k, without), 3),
                                  format_number(physics::natural_frequency(k, with), 3))
                    : fmt::format("The drive's natural frequency on {} is {} rad/s", driven.judged.label(),
                                  format_number(physics::natural_frequency(k, with), 3));
    if (driven.articulated.known && driven.rate.solver != physics::Solver::MuJoCo)
      effect += fmt::format("; with it the drive row's x on the articulation is {} ({})",
                            format_number(driven.row(driven.articulated.value).x(), 3), driven.rate.step_text());
    d.note(effect + fmt::format(". Inertias: {}.", driven.inertias_text()));
  }

 private:
  RuleInfo info_{"armature-excessive",
                 "Joint armature an order of magnitude above what the joint moves (the lighter link, for a mimic-coupled "
                 "gripper)",
                 Severity::Warning,
                 false,
                 RuleOrigin::Check,
                 {{"max_ratio", 10.0,
                   "report armature above this multiple of what the joint moves about its axis (the lighter link for a "
                   "mimic-coupled gripper drive)"},
                  {"flywheel_ratio", 10000.0,
                   "warn when the armature is above this multiple of everything the joint moves (a flywheel)"},
                  {"servo_armature", 0.0014,
                   "a hinge armature up to this (kg·m²) is what a small smart servo reflects (Dynamixel XL330: "
                   "1.7e-8 kg·m² × 288²) and is never judged a flywheel, however light the load"},
                  {"harmless_follower_effect", 0.01,
                   "a mimic follower's armature that changes its leader's drive settling time by less than this "
                   "fraction, and not its stability, is an info"},
                  {"max_time_constant", 0.2,
                   "no flywheel when the joint's damping settles its speed, armature included, within this many "
                   "seconds"}}};
};

}  // namespace

const Rule& armature_excessive() {
  static const ArmatureExcessive rule;
  return rule;
}

}  // namespace assetlint::rules
