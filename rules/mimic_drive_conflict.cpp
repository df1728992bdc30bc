#include <fmt/format.h>

#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// A mimic joint is moved by its constraint; a drive on it pulls towards its own target
// and the two fight. Only applied drives count: stale attributes of a deleted drive
// schema are reported as stale-schema-attribute by the USD reader.
class MimicDriveConflict final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings&, Reporter& out) const override {
    for (const Joint& joint : asset.joints) {
      if (!joint.mimic || !joint.drive) continue;
      const Drive& drive = *joint.drive;
      const bool stiff = drive.stiffness && drive.stiffness->value > 0;
      const bool damped = drive.damping && drive.damping->value > 0;
      if (!stiff && !damped) continue;
      const std::string where = drive.origin.empty() ? (drive.instance.empty() ? std::string("a drive")
                                                                               : "PhysicsDriveAPI:" + drive.instance)
                                                     : "a drive from " + drive.origin;
      Diagnostic& d = out.report(drive.span.valid() ? drive.span : joint.name.span,
                                 fmt::format("mimic {} also has {}", joint_label(joint), where));
      d.note(fmt::format("The drive (stiffness {}, damping {}) pulls towards its own target while the mimic constraint "
                         "makes the joint follow '{}': the two fight.",
                         drive.stiffness ? describe(*drive.stiffness) : "0", drive.damping ? describe(*drive.damping) : "0",
                         joint.mimic->reference.text));
      if (joint.type == JointType::Prismatic)
        d.note("A prismatic mimic is coupled as a revolute one is: omni.physx maps it to the joint's linear axis "
               "(PxArticulationAxis::eX, InternalMimicJoint.cpp) and PhysX's mimic solve works on joint coordinates "
               "whatever their kind, so the follower needs no drive of its own.");
      d.note("Remove the drive from the mimic joint; the followed joint's drive moves both.");
      d.related.insert(d.related.end(), {"SimReady DJ.004", "SimReady DJ.006"});
    }
  }

 private:
  RuleInfo info_{"mimic-drive-conflict", "A mimic joint that also has an applied drive with stiffness or damping",
                 Severity::Warning, false, RuleOrigin::Check, {}};
};

}  // namespace

const Rule& mimic_drive_conflict() {
  static const MimicDriveConflict rule;
  return rule;
}

}  // namespace assetlint::rules
