#include <fmt/format.h>

#include <vector>

#include "rules/all_rules.h"
#include "rules/consumer_concern.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// What a URDF says that some of its consumers drop on import: a <mimic> (MuJoCo's URDF
// importer before 3.13, Gazebo with a physics engine that has no mimic constraint), and
// <dynamics damping friction> (Isaac Sim 6.1's URDF importer). Each finding names the
// consumers it concerns; docs/consumers.md gives the source of each fact.
class ConsumerDropsValue final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    if (asset.format != SourceFormat::Urdf) return;  // the facts are about URDF importers
    const ConsumerProfile profile = consumer_profile(asset.format, settings);
    const Concern mimic = concern(profile, [](const Consumer& c) { return !couples_urdf_mimic(c); }, Severity::Warning);
    const Concern dynamics =
        concern(profile, [](const Consumer& c) { return !keeps_urdf_dynamics(c); }, Severity::Warning);
    std::vector<const Joint*> mimics;
    for (const Joint& joint : asset.joints) {
      if (joint.mimic && is_single_dof(joint.type)) mimics.push_back(&joint);
      if (dynamics.any()) dropped_dynamics(joint, dynamics, profile, out);
    }
    if (!mimic.any() || mimics.empty()) return;
    // Named consumers: one warning per mimic. The default list: one info for the file.
    if (mimic.severity == Severity::Info) dropped_mimic(*mimics.front(), mimics.size(), mimic, profile, out);
    else
      for (const Joint* joint : mimics) dropped_mimic(*joint, 1, mimic, profile, out);
  }

 private:
  static void dropped_mimic(const Joint& joint, std::size_t count, const Concern& concern,
                            const ConsumerProfile& profile, Reporter& out) {
    Diagnostic& d = out.report(joint.mimic->span, concern.severity,
                               count == 1 ? fmt::format("the mimic of {} is dropped by {}", joint_label(joint),
                                                        join_labels(concern.affected))
                                          : fmt::format("the mimics of '{}' and {} other joints are dropped by {}",
                                                        joint.name.text, count - 1, join_labels(concern.affected)));
    d.note(fmt::format("There {} does not follow '{}': it is a free joint that nothing drives, and the fingers "
                       "no longer close together.",
                       count == 1 ? "the joint" : "each mimic joint (here '" + joint.name.text + "')",
                       joint.mimic->reference.text));
    for (const Consumer& c : profile.consumers) {
      if (couples_urdf_mimic(c)) continue;
      if (c.is(ConsumerKind::Mujoco))
        d.note("MuJoCo's URDF importer (xml_urdf.cc) reads no <mimic> before 3.13; from 3.13 it writes an <equality> "
               "<joint> with polycoef = [offset, multiplier]. Convert to MJCF with that equality, or load with MuJoCo "
               "3.13 or later.");
      else if (c.is(ConsumerKind::Gazebo))
        d.note(fmt::format("Gazebo passes the mimic to its physics engine, and {} has no mimic constraint (gz-sim logs "
                           "that none is created); bullet-featherstone has one: `gz sim --physics-engine "
                           "gz-physics-bullet-featherstone-plugin`, or couple the joints in the controller "
                           "(gz_ros2_control commands a mimic joint itself).",
                           c.engine_label()));
    }
    name_consumers(d, concern, profile);
  }

  static void dropped_dynamics(const Joint& joint, const Concern& concern, const ConsumerProfile& profile,
                               Reporter& out) {
    const bool damping = joint.joint_damping && joint.joint_damping->span.valid() && joint.joint_damping->value > 0;
    const bool friction = joint.joint_friction && joint.joint_friction->span.valid() && joint.joint_friction->value > 0;
    if (!damping && !friction) return;
    const Span at = damping ? joint.joint_damping->span : joint.joint_friction->span;
    std::string what = damping && friction ? "damping and friction" : damping ? "damping" : "friction";
    Diagnostic& d = out.report(at, concern.severity,
                               fmt::format("<dynamics> {} of {} {} dropped by {}", what, joint_label(joint), damping && friction ? "are" : "is",
                                           join_labels(concern.affected)));
    std::vector<std::string> values;
    if (damping) values.push_back(fmt::format("damping {}", describe(*joint.joint_damping)));
    if (friction) values.push_back(fmt::format("friction {}", describe(*joint.joint_friction)));
    d.note(fmt::format("Written: {}. Isaac Sim 6.1's URDF converter writes them as newton:damping and newton:friction, "
                       "while the step that builds the PhysX drive and joint friction still reads the urdf:dynamics "
                       "attributes of 6.0: the PhysX layer gets neither, so the joint moves undamped and without "
                       "friction there (6.0.1 wrote them as drive damping and physxJoint:jointFriction).",
                       join_labels(values)));
    d.note("Set the damping on the drive and physxJoint:jointFriction in the imported USD, or import with Isaac Sim 6.0.");
    name_consumers(d, concern, profile);
  }

  RuleInfo info_{"consumer-drops-value",
                 "A value of the file that a consumer it is judged for drops on import (a URDF <mimic>, "
                 "<dynamics damping friction>)",
                 Severity::Warning, false, RuleOrigin::Check, {}};
};

}  // namespace

const Rule& consumer_drops_value() {
  static const ConsumerDropsValue rule;
  return rule;
}

}  // namespace assetlint::rules
