#include <fmt/format.h>

#include <cmath>

#include "physics/gripper.h"
#include "rules/all_rules.h"
#include "rules/consumer_concern.h"
#include "rules/limit_placeholders.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// The guide's second step: bound the driven joint's velocity by the spec, ω = joint
// range / (stroke per finger / finger speed). Besides the spec: what a 0, a sentinel or
// a missing value means to PhysX and to the importers (PHYSICS.md §2 item 8).
class JointMaxVelocity final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    if (!max_velocity_read(asset, settings)) return;  // no consumer the asset is judged for bounds speed by it
    const Joint* spec = physics::spec_joint(asset, settings);
    const bool usd = asset.format == SourceFormat::Usda;
    bool placeholder_reported = false;
    const SharedValues velocities(asset, &Joint::velocity);
    const std::size_t movable = movable_joint_count(asset);
    for (const Joint& joint : asset.joints) {
      if (!is_single_dof(joint.type) || joint.is_mimic()) continue;
      const auto wanted = &joint == spec ? physics::required_velocity(settings, joint) : std::nullopt;
      const bool driven = has_active_drive(joint) || (&joint == spec && (settings.gripper.driven_joint || wanted));
      const Context c{{asset, settings, joint, usd, driven, out}, wanted ? &*wanted : nullptr, &velocities, movable};
      const OptQuantity& v = joint.velocity;
      if (v && v->span.valid() && v->value < 0 && usd) negative(c, *v);
      else if (v && v->span.valid() && v->value == 0 && usd) frozen(c, *v);
      else if (v && v->span.valid() && v->value <= 0 && !usd) sentinel(c, *v);
      else if (!v || !v->span.valid()) unset(c);
      else if (wanted) against_spec(c, *v);
      else if (!placeholder_reported) placeholder_reported = placeholder(c, *v);
    }
  }

 private:
  struct Context : LimitCheck {
    const physics::RequiredVelocity* wanted;
    const SharedValues* velocities;
    std::size_t movable_joints;
    // The unit the file writes this joint's velocity in: a prismatic joint's is a distance per second.
    Unit file_unit() const {
      if (!is_angular(joint.type)) return Unit::MeterPerSecond;
      return usd ? Unit::DegreePerSecond : Unit::RadianPerSecond;
    }
  };

  // USD: PhysX clamps |v| to the value every iteration; 0 is not "no limit".
  static void frozen(const Context& c, const Quantity& v) {
    Diagnostic& d = c.out.report(v.span, Severity::Error, fmt::format("max joint velocity 0 freezes {}", c.label()));
    d.related.push_back("SimReady DJ.005");
    d.note("PhysX clamps the joint's speed to maxJointVelocity in every solver iteration: 0 holds it still. USD has no "
           "'unbounded' sentinel; leave the attribute unauthored (or write the spec's value) instead.");
    spec_fix(c, v, d);
  }

  // USD: PhysX clamps the joint speed into [−v, v]; with v < 0 that interval is empty and the
  // clamp returns its upper end, so every iteration sets the speed to v.
  static void negative(const Context& c, const Quantity& v) {
    Diagnostic& d = c.out.report(v.span, Severity::Error,
                                 fmt::format("negative max joint velocity runs {} at {}", c.label(), describe(v)));
    d.related.push_back("SimReady DJ.005");
    d.note(fmt::format("PhysX's articulation solver clamps a joint's speed with PxClamp(v, -max, max) once |v| exceeds "
                       "max (solveInternalJointConstraintRecursive); with max = {} the clamp returns max itself, so "
                       "every solver iteration sets the joint moving at {} towards its lower stop, drive or no drive. "
                       "PhysX's setMaxJointVelocity does not check the sign.",
                       describe(v), describe(v)));
    d.note("Write the motor's no-load speed as a positive number, or leave the attribute unauthored.");
    spec_fix(c, v, d);
  }

  // URDF velocity ≤ 0: what it means depends on who reads the file. 0 and Gazebo's −1 are
  // conventions; any other negative number is a slip.
  static void sentinel(const Context& c, const Quantity& v) {
    Diagnostic& d = report_sentinel(
        c, v, "velocity", c.wanted != nullptr,
        "Isaac Sim's URDF importer reads velocity ≤ 0 as no limit (it writes no max joint velocity); urdfdom-based "
        "tools (ROS controllers, Gazebo through SDFormat) read 0 as a joint that may not move, and Gazebo reads −1 "
        "as no limit.",
        "speed limit");
    if (c.wanted) d.note(fmt::format("The spec gives {}: {}.", describe(c.wanted->velocity, c.file_unit()), c.wanted->derivation));
    spec_fix(c, v, d);
  }

  static void unset(const Context& c) {
    if (!c.driven) return;
    const Joint& joint = c.joint;
    Diagnostic& d = c.out.report(joint.name.span, c.wanted ? Severity::Warning : Severity::Info,
                                 fmt::format("{} has no max joint velocity", c.label()));
    if (c.usd)
      d.note(fmt::format("Unauthored, omni.physx sets no limit (FLT_MAX) when PhysxJointAPI is not applied and the "
                         "schema's fallback 1e6 {} when it is: nothing bounds how fast the drive moves the joint.",
                         is_angular(joint.type) ? "deg/s" : "distance units/s"));
    else
      d.note("Nothing bounds how fast the drive moves the joint.");
    if (c.wanted) {
      d.note(fmt::format("The spec gives {}: {}.", describe(c.wanted->velocity, c.file_unit()), c.wanted->derivation));
      if (c.usd && is_angular(joint.type))
        d.note(fmt::format("Add `float physxJoint:maxJointVelocity = {}` with PhysxJointAPI applied.",
                           format_number(from_model_units(c.wanted->velocity, c.file_unit()), 4)));
    } else {
      d.note("Without a [gripper] spec in asset-lint.toml this is an info (test scenes often mean it).");
    }
  }

  static void against_spec(const Context& c, const Quantity& v) {
    const double tolerance = rule_option(info_static(), c.settings, "tolerance_factor");
    const double ratio = v.value / c.wanted->velocity;
    if (ratio <= tolerance && ratio >= 1.0 / tolerance) return;
    Diagnostic& d = c.out.report(v.span, fmt::format("max joint velocity of {} is {}× what the spec gives",
                                                     joint_label(c.joint), format_number(ratio, 3)));
    d.note(fmt::format("Authored {}; the spec gives {}.", describe(v), describe(c.wanted->velocity, v.unit)));
    d.note(fmt::format("The spec: {}.", c.wanted->derivation));
    d.note(fmt::format("Reported beyond tolerance_factor {}× either way.", format_number(tolerance)));
    const std::size_t sharing = c.velocities->others(c.joint);
    if (!c.usd && is_power_of_ten(v.value, 2) && sharing > 0)
      d.note(fmt::format("The same round {} is on {} other joint{}: a placeholder.", format_number(v.authored),
                         sharing, sharing == 1 ? "" : "s"));
    spec_fix(c, v, d);
  }

  // URDF: velocity="100" on every joint is a value nobody measured. Once per file.
  static bool placeholder(const Context& c, const Quantity& v) {
    if (!velocity_placeholder_on_every_joint(c.asset, c.joint, *c.velocities, c.movable_joints)) return false;
    const std::size_t sharing = c.velocities->others(c.joint);
    Diagnostic& d = c.out.report(v.span, Severity::Info,
                                 fmt::format("velocity {} on every joint ({}) looks like a placeholder", describe(v),
                                             sharing + 1));
    d.note("The same round value on every movable joint is not a motor's rating; this finding is made once per file.");
    d.note("With a [gripper] spec in asset-lint.toml, the spec's joint is judged against the speed the spec gives.");
    return true;
  }

  static void spec_fix(const Context& c, const Quantity& v, Diagnostic& d) {
    if (!c.wanted || !v.span.valid()) return;
    d.fix = Fix{fmt::format("set the max joint velocity to the spec's {}", describe_written(v, c.wanted->velocity)),
                Applicability::Unsafe,
                {replace_value(v, c.wanted->velocity, 4)}};
  }

  static const RuleInfo& info_static();
  const RuleInfo& info_ = info_static();
};

const RuleInfo& JointMaxVelocity::info_static() {
  static const RuleInfo info{"joint-max-velocity",
                             "A max joint velocity that freezes the joint, is a sentinel or placeholder, is unset on a "
                             "driven joint, or is far from the gripper spec",
                             Severity::Warning,
                             true,
                             RuleOrigin::Check,
                             {{"tolerance_factor", 2.0, "report a velocity more than this factor above or below the spec's"}}};
  return info;
}

}  // namespace

const Rule& joint_max_velocity() {
  static const JointMaxVelocity rule;
  return rule;
}

}  // namespace assetlint::rules
