#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "physics/gripper.h"
#include "rules/all_rules.h"
#include "rules/limit_placeholders.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// The guide's first step: bound every drive's force by the robot's spec. Without a spec
// only what is certainly wrong is a warning; sentinels and placeholders are infos that
// say what they mean to whom (PHYSICS.md §2 item 8).
class DriveMaxForce final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const Joint* spec = physics::spec_joint(asset, settings);
    const SharedValues efforts(asset, &Joint::effort);
    const ZeroEfforts zero_efforts = zero_effort_joints(asset);
    for (const Joint& joint : asset.joints) {
      if (!is_single_dof(joint.type) || joint.is_mimic()) continue;
      const bool usd = asset.format == SourceFormat::Usda;
      if (joint.drive && !has_active_drive(joint)) continue;
      if (usd && !joint.drive) continue;  // no applied drive: not a driven joint in USD
      // URDF carries no drive: a joint is driven when configuration gives it one or the
      // spec names it; otherwise its effort is only a limit.
      const auto required = &joint == spec ? physics::required_force(asset, settings, joint) : std::nullopt;
      const bool driven = joint.drive || (&joint == spec && (settings.gripper.driven_joint || required));
      Context c{{asset, settings, joint, usd, driven, out}, required ? &*required : nullptr, &efforts, &zero_efforts};
      if (usd && (!joint.drive->max_force || std::isinf(joint.drive->max_force->value))) {
        unbounded(c);
        continue;
      }
      const OptQuantity& force = joint.drive && joint.drive->max_force ? joint.drive->max_force : joint.effort;
      if (!force) continue;
      judge(c, *force);
      if (!usd) effort_within_friction(c, *force);
    }
  }

 private:
  // URDF joints whose effort is written as 0: on every movable joint of an arm it is a file-wide
  // choice, reported once, at the first of them.
  struct ZeroEfforts {
    std::size_t count = 0;
    std::size_t movable = 0;
    const Joint* first = nullptr;
    bool everywhere() const { return movable > 1 && count == movable; }
  };

  static ZeroEfforts zero_effort_joints(const Asset& asset) {
    ZeroEfforts z;
    if (asset.format != SourceFormat::Urdf) return z;
    for (const Joint& joint : asset.joints) {
      if (!is_single_dof(joint.type) || joint.is_mimic()) continue;
      ++z.movable;
      if (joint.effort && joint.effort->value == 0) {
        ++z.count;
        if (!z.first) z.first = &joint;
      }
    }
    return z;
  }

  struct Context : LimitCheck {
    const physics::RequiredForce* required;
    const SharedValues* efforts;
    const ZeroEfforts* zero_efforts;
    const char* what() const { return usd ? "maxForce" : "effort"; }
    // The joint a gripper's mimic joints follow: its effort is the grip.
    bool gripper_driver() const { return physics::drives_gripper(asset, joint); }
  };

  void unbounded(const Context& c) const {
    const Drive& drive = *c.joint.drive;
    const Span& span = drive.max_force ? drive.max_force->span : drive.span;
    // A drive that moves mimic followers is a gripper's (or a coupled hand's): it closes on
    // objects, and how hard is the force bound. A test scene's lone drive may mean "unlimited".
    const bool gripper = c.gripper_driver();
    Diagnostic& d = c.out.report(span, c.required || gripper ? Severity::Warning : Severity::Info,
                                 fmt::format("{} has no force bound (maxForce {})", c.label(),
                                             drive.max_force ? "inf" : "unauthored"));
    d.related.push_back("SimReady DJ.001");
    d.note(drive.max_force ? "maxForce = inf: PhysX never clamps the drive force."
                           : "PhysicsDriveAPI's maxForce falls back to inf: PhysX never clamps the drive force.");
    envelope_note(c, d);
    if (c.required) {
      spec_notes(c, d);
    } else if (gripper) {
      const std::size_t followers = c.asset.mimic_followers(c.joint.name.text).size();
      d.note(fmt::format("It drives a gripper ({} mimic joint{} follow{} it), so consumers disagree: PhysX and Newton's "
                         "USD importer leave the force unlimited and the fingers squeeze with whatever the position "
                         "error asks, while NVIDIA's SimReady validation (DJ.001) fails a drive whose maxForce is not "
                         "authored, finite and positive.",
                         followers, followers == 1 ? "" : "s", followers == 1 ? "s" : ""));
      d.note("Author the motor's rated torque (N·m) or force (N) as maxForce; a [gripper] spec in asset-lint.toml "
             "derives the force the payload needs.");
    } else {
      d.note("Without a [gripper] spec in asset-lint.toml this is reported as an info: a test scene may mean it. "
             "With one, the bound is derived from the payload and judged.");
    }
  }

  void judge(const Context& c, const Quantity& q) const {
    const double placeholder = rule_option(info_, c.settings, "placeholder_force");
    if (q.value <= 0 && !c.usd && q.span.valid()) return sentinel(c, q);
    if (q.value == 0) return zero_bound(c, q);
    if (q.value < 0) {
      c.out.report(q.span, fmt::format("{} has negative {} {}", c.label(), c.what(), describe(q)));
      return;
    }
    if (c.required) return against_spec(c, q);
    const std::size_t sharing = c.efforts->others(c.joint);
    const bool round_repeat = !c.usd && is_power_of_ten(q.value, 3) && sharing > 0;
    if (q.value < placeholder && !round_repeat) return;
    // On a gripper's driven joint the placeholder is the grip itself: a simulator that applies
    // it squeezes with 1000 N·m where the real motor gives a few.
    const bool grip = !c.usd && c.gripper_driver();
    Diagnostic& d = c.out.report(q.span, grip ? Severity::Warning : Severity::Info,
                                 fmt::format("{} {} of {} looks like a placeholder", c.what(), describe(q), c.label()));
    if (q.value >= placeholder)
      d.note(fmt::format("At or above placeholder_force {}, the bound is effectively no bound.", format_number(placeholder)));
    if (round_repeat)
      d.note(fmt::format("The same round {} is on {} other joint{} of the file: a value written for every joint, not "
                         "a motor's rating.",
                         format_number(q.value), sharing, sharing == 1 ? "" : "s"));
    if (grip) {
      d.note(fmt::format("{} mimic joint{} {} it: this is the gripper's driven joint, and its effort is the grip. "
                         "Isaac Sim's importer writes it as the drive's maxForce and PhysX applies up to it; Gazebo and "
                         "ros_control clamp commands to it; MuJoCo importers make it the actuator's force range. Each "
                         "lets the simulated gripper hold what the real one drops.",
                         c.asset.mimic_followers(c.joint.name.text).size(),
                         c.asset.mimic_followers(c.joint.name.text).size() == 1 ? "" : "s",
                         c.asset.mimic_followers(c.joint.name.text).size() == 1 ? "follows" : "follow"));
      d.note("Take the motor's rated torque (or force) from the data sheet; asset-lint.toml's [gripper] spec derives the "
             "force the payload needs.");
      return;
    }
    d.note("Without a [gripper] spec in asset-lint.toml this is an info. With one, the bound is judged against the "
           "force the payload needs (a placeholder far above it makes the simulated gripper hold what the real one drops).");
  }

  // A USD drive whose maxForce is 0 exerts nothing: PhysX clamps the drive force to it. Where
  // other drives of the asset author positive bounds, a zero on a joint no spec and no mimic
  // relies on reads as a joint left passive on purpose (a rover's rocker-bogie); where every
  // drive is zero, or the joint drives a gripper, the robot cannot move what it must.
  static void zero_bound(const Context& c, const Quantity& q) {
    const DriveBounds bounds = drive_bounds(c.asset);
    const bool deliberate = bounds.positive > 0 && !c.required && !c.gripper_driver();
    Diagnostic& d = c.out.report(q.span, deliberate ? Severity::Info : Severity::Warning,
                                 fmt::format("{} has maxForce 0: the drive cannot move it", c.label()));
    d.note("PhysX sets up no drive on a joint whose maxForce is 0: the joint is passive, moved only by gravity, contact "
           "and its links, whatever the drive's stiffness and damping.");
    if (deliberate) {
      d.note(fmt::format("{} other drive{} of the asset author{} a positive maxForce, so a zero here reads as a joint "
                         "meant to stay passive (a suspension, a free bogie). If it is, removing the drive says so; if "
                         "not, author the motor's rated torque (N·m) or force (N).",
                         bounds.positive, bounds.positive == 1 ? "" : "s", bounds.positive == 1 ? "s" : ""));
    } else if (bounds.positive == 0 && bounds.zero > 1) {
      d.note(fmt::format("None of the asset's {} drives authors a positive maxForce: the robot cannot move at all.",
                         bounds.zero));
    } else if (c.gripper_driver()) {
      d.note("It is the joint the gripper's mimic joints follow: the gripper cannot close.");
    }
    if (c.required) spec_notes(c, d);
  }

  struct DriveBounds {
    std::size_t zero = 0, positive = 0;
  };

  static DriveBounds drive_bounds(const Asset& asset) {
    DriveBounds b;
    for (const Joint& joint : asset.joints) {
      if (!joint.drive || !has_active_drive(joint) || !joint.drive->max_force || joint.is_mimic()) continue;
      const double f = joint.drive->max_force->value;
      if (f == 0) ++b.zero;
      else if (f > 0) ++b.positive;
    }
    return b;
  }

  // URDF <dynamics friction> is a Coulomb torque (force) opposing motion: an effort no larger
  // than it can never start the joint. Talos's grippers write 1.0 for effort, friction,
  // damping and velocity alike, a value typed into every field.
  static void effort_within_friction(const Context& c, const Quantity& effort) {
    const OptQuantity& friction = c.joint.joint_friction;
    if (!friction || !friction->span.valid() || !(friction->value > 0) || !(effort.value > 0)) return;
    if (effort.value > friction->value * (1 + 1e-9)) return;
    // MuJoCo bounds only actuator forces by actuatorfrcrange: a joint moved by an equality, a
    // loop or contact is not held back by its actuators' bound.
    const bool mjcf = c.asset.format == SourceFormat::Mjcf;
    if (mjcf && c.joint.actuation != Actuation::Actuated) return;
    const bool equal = effort.value >= friction->value * (1 - 1e-9);
    Diagnostic& d = c.out.report(friction->span, Severity::Warning,
                                 fmt::format("friction {} of {} {} its {}: {}", describe(*friction), joint_label(c.joint),
                                             equal ? "equals" : "exceeds", mjcf ? "actuator force bound" : "effort limit",
                                             mjcf ? "its actuators can never move it" : "it can never move"));
    if (mjcf)
      d.note(effort.span, fmt::format("MuJoCo clamps the actuator force on this joint to {}, and its frictionloss is a "
                                      "constraint force of up to {} opposing any motion: the actuators alone cannot "
                                      "start the joint.",
                                      describe(effort), describe(*friction)));
    else
      d.note(effort.span, fmt::format("The effort limit is {}; consumers that apply <dynamics friction> as Coulomb "
                                      "friction (Gazebo, through SDFormat's joint friction) need more than that to start "
                                      "the joint.",
                                      describe(effort)));
    if (equal)
      d.note("The same number in effort and friction is usually one value typed into every field: take both from the "
             "actuator's data sheet.");
  }

  // URDF effort ≤ 0: what it means depends on who reads the file. 0 and Gazebo's −1 are
  // conventions; any other negative number is a slip.
  void sentinel(const Context& c, const Quantity& q) const {
    const ZeroEfforts& zeros = *c.zero_efforts;
    const bool file_wide = q.value == 0 && zeros.everywhere();
    if (file_wide && &c.joint != zeros.first) return;  // one finding for the file, at the first joint
    Diagnostic& d = report_sentinel(
        c, q, "effort", c.required != nullptr || file_wide || (q.value == 0 && c.gripper_driver()),
        "Isaac Sim's URDF importer reads effort ≤ 0 as no limit (it writes maxForce = FLT_MAX); urdfdom-based "
        "tools (ROS controllers, Gazebo through SDFormat) read 0 as a zero force, and Gazebo reads −1 as no limit.",
        "force limit");
    if (file_wide)
      d.note(fmt::format("Every one of the {} movable joints writes effort=\"0\": in Gazebo, MuJoCo and ros_control the "
                         "robot has no torque at all, in Isaac Sim it has unlimited torque. Write each joint's rated "
                         "effort (the others are not reported separately).",
                         zeros.movable));
    else if (q.value == 0 && c.gripper_driver())
      d.note("It is the joint the gripper's mimic joints follow: read as zero the gripper cannot close, read as no "
             "limit it squeezes without bound.");
    if (c.required) {
      spec_notes(c, d);
      fix_to_spec(c, q, d);
    }
  }

  void against_spec(const Context& c, const Quantity& q) const {
    const double need = c.required->required;
    const double excess = rule_option(info_, c.settings, "excess_factor");
    const std::string unit(unit_symbol(c.required->unit));
    if (q.value >= need * (1 - 1e-9) && q.value <= need * excess) return;
    const bool below = q.value < need;
    // The primary line quotes the value in model units; a scaled stage's literal goes in a note.
    const std::string value = fmt::format("{} {}", format_number(q.value, 4), unit);
    Diagnostic& d = c.out.report(
        q.span, below ? fmt::format("{} {} of {} is below the {} {} the payload spec needs", c.what(), value,
                                    joint_label(c.joint), format_number(need, 4), unit)
                      : fmt::format("{} {} of {} is {}× the {} {} the payload spec needs", c.what(), value,
                                    joint_label(c.joint), format_number(q.value / need, 3), format_number(need, 4), unit));
    if (describe(q) != value) d.note(fmt::format("As written: {} {}.", c.what(), describe(q)));
    if (!below) {
      d.note(fmt::format("A bound more than excess_factor {}× the spec's makes the simulated gripper that much stronger "
                         "than the real one: it holds payloads the real one drops.",
                         format_number(excess)));
      if (is_power_of_ten(q.value, 3)) d.note(fmt::format("A round {} is usually a placeholder.", format_number(q.value)));
    }
    envelope_note(c, d);
    spec_notes(c, d);
    fix_to_spec(c, q, d);
  }

  static void spec_notes(const Context& c, Diagnostic& d) {
    if (!c.required) return;
    for (const std::string& step : c.required->steps) d.note(step);
    if (c.joint.drive && c.joint.drive->max_force && !c.joint.drive->origin.empty() && !c.joint.drive->max_force->span.valid())
      d.note(fmt::format("The bound comes from [drives.{}] max_force ({}).", c.joint.name.text, c.joint.drive->origin));
  }

  static void envelope_note(const Context& c, Diagnostic& d) {
    if (!c.joint.drive || !c.joint.drive->envelope) return;
    d.note(c.joint.drive->envelope->span,
           fmt::format("PhysxDrivePerformanceEnvelopeAPI:{} is applied: the effort limit falls with speed "
                       "(maxForce − velocityDependentResistance·|v|, 0 at maxActuatorVelocity); maxForce is the bound "
                       "at rest only.",
                       c.joint.drive->instance));
  }

  static void fix_to_spec(const Context& c, const Quantity& q, Diagnostic& d) {
    if (!q.span.valid()) return;
    const std::string written = format_number_rounded_up(q.authored_for(c.required->required), 3);
    d.fix = Fix{fmt::format("set the {} to the payload spec's {}", c.what(),
                            q.scale == 1.0 ? fmt::format("{} {}", written, unit_symbol(c.required->unit))
                                           : fmt::format("{} (stage units; {} {})", written,
                                                         format_number(c.required->required, 4), unit_symbol(c.required->unit))),
                Applicability::Unsafe, {Edit{q.span.file, q.span.offset, q.span.length, written}}};
  }

  RuleInfo info_{"drive-max-force",
                 "A driven joint's maximum force is zero, unbounded, a placeholder, far from the payload spec, or no "
                 "larger than the joint's friction",
                 Severity::Warning,
                 true,
                 RuleOrigin::Check,
                 {{"placeholder_force", 1e6, "efforts at or above this (N·m or N) are placeholders, not limits"},
                  {"excess_factor", 3.0, "with a [gripper] spec, report a bound more than this factor above the spec's"}}};
};

}  // namespace

const Rule& drive_max_force() {
  static const DriveMaxForce rule;
  return rule;
}

}  // namespace assetlint::rules
