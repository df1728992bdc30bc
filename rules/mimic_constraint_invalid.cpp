#include <fmt/format.h>
#include <fmt/ranges.h>

#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

constexpr const char* kSimReadyMimic = "SimReady DJ.007";

// A mimic that is written but couples nothing, or couples otherwise than written: a
// multiplier (gearing, newton:mimicCoef1) of 0, a reference relationship with more than one
// target, a joint of the pair excluded from the articulation, a naturalFrequency of 0 beside a
// damping ratio. Undefined, self and chained references are structure-mimic-reference's.
class MimicConstraintInvalid final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings&, Reporter& out) const override {
    for (const Joint& joint : asset.joints) {
      if (!joint.mimic || !is_single_dof(joint.type)) continue;
      const Mimic& mimic = *joint.mimic;
      if (mimic.multiplier.is_authored() && mimic.multiplier.value == 0) zero_multiplier(joint, out);
      if (!mimic.extra_references.empty()) several_references(joint, out);
      const Joint* reference = mimic.reference.text.empty() ? nullptr : asset.find_joint(mimic.reference.text);
      if (!mimic.instance.empty()) {  // PhysxMimicJointAPI: omni.physx's own conditions
        if (joint.excluded_from_articulation) excluded(joint, joint, out);
        else if (reference && reference->excluded_from_articulation) excluded(joint, *reference, out);
      }
      if (mimic.natural_frequency && mimic.natural_frequency->is_authored() && mimic.natural_frequency->value == 0)
        zero_natural_frequency(joint, out);
    }
  }

 private:
  static Diagnostic& tagged(Diagnostic& d) {
    d.related.push_back(kSimReadyMimic);
    return d;
  }

  static void zero_multiplier(const Joint& joint, Reporter& out) {
    const Mimic& mimic = *joint.mimic;
    Diagnostic& d = tagged(out.report(mimic.multiplier.span, Severity::Error,
                                      fmt::format("the mimic of {} has multiplier 0: it follows nothing",
                                                  joint_label(joint))));
    d.note(fmt::format("q = 0 · q('{}') + offset holds the joint at its offset ({}) whatever '{}' does: a lock, not a "
                       "coupling. PhysX solves qA + gearing·qB + offset = 0 with gearing 0 the same way, and Newton "
                       "joint0 = coef0 + coef1·joint1 with coef1 0.",
                       mimic.reference.text, describe(mimic.offset), mimic.reference.text));
    d.note("Write the ratio the linkage has (a parallel finger: 1 or −1; the sign is the file's convention), or make the "
           "joint fixed if a lock is meant.");
  }

  static void several_references(const Joint& joint, Reporter& out) {
    const Mimic& mimic = *joint.mimic;
    std::vector<std::string> names{mimic.reference.text};
    for (const Name& extra : mimic.extra_references) names.push_back(extra.text);
    Diagnostic& d = tagged(out.report(mimic.extra_references.front().span, Severity::Error,
                                      fmt::format("the mimic of {} names {} reference joints: PhysX couples none",
                                                  joint_label(joint), names.size())));
    d.note(fmt::format("The reference relationship targets {}. omni.physx builds a mimic joint only from exactly one "
                       "target (parseMimicJoints in usdLoad/MimicJoint.cpp) and logs an error otherwise: the joint is "
                       "not coupled to any of them.",
                       fmt::format("'{}'", fmt::join(names, "', '"))));
    d.note(mimic.reference.span, fmt::format("Keep one target, the joint it follows ('{}' is the first).", names.front()));
  }

  static void excluded(const Joint& joint, const Joint& culprit, Reporter& out) {
    const bool own = &joint == &culprit;
    Diagnostic& d = tagged(out.report(own ? joint.mimic->span : joint.mimic->reference.span, Severity::Error,
                                      own ? fmt::format("mimic {} is excluded from the articulation: PhysX couples "
                                                        "nothing",
                                                        joint_label(joint))
                                          : fmt::format("mimic {} follows '{}', which is excluded from the "
                                                        "articulation",
                                                        joint_label(joint), short_path(culprit.name.text))));
    d.note(fmt::format("'{}' has physics:excludeFromArticulation = true, so PhysX builds it as a maximal-coordinate "
                       "joint outside the articulation. A mimic joint couples two coordinates of one articulation: "
                       "omni.physx refuses it (parseMimicJoints, usdLoad/MimicJoint.cpp) and the joints move "
                       "independently.",
                       culprit.name.text));
    d.note(culprit.name.span, "Include the joint in the articulation, or close the loop at another joint.");
  }

  static void zero_natural_frequency(const Joint& joint, Reporter& out) {
    const Mimic& mimic = *joint.mimic;
    const bool damped = mimic.damping_ratio && mimic.damping_ratio->is_authored() && mimic.damping_ratio->value > 0;
    Diagnostic& d = tagged(out.report(mimic.natural_frequency->span, damped ? Severity::Warning : Severity::Info,
                                      fmt::format("the mimic of '{}' has naturalFrequency 0: a hard constraint{}",
                                                  short_path(joint.name.text),
                                                  damped ? " that ignores its dampingRatio" : "")));
    d.note("PhysX treats a mimic as compliant only when naturalFrequency and dampingRatio are both above 0 "
           "(computeMimicJointImpulses, DyCpuGpuArticulation.h); otherwise it corrects the whole error with the "
           "solver's bias every position iteration.");
    if (damped)
      d.note(fmt::format("dampingRatio {} asks for a compliant coupling that PhysX does not build. Write the natural "
                         "frequency the coupling should have (rad/s; the followed joint's drive frequency or above), or "
                         "remove dampingRatio if a hard constraint is meant.",
                         format_number(mimic.damping_ratio->authored)));
    else
      d.note("An unauthored naturalFrequency means the same; write it only to make the coupling compliant.");
  }

  RuleInfo info_{"mimic-constraint-invalid",
                 "A mimic that couples nothing or not as written: multiplier 0, several reference joints, a joint "
                 "excluded from the articulation, naturalFrequency 0",
                 Severity::Error, false, RuleOrigin::Check, {}};
};

}  // namespace

const Rule& mimic_constraint_invalid() {
  static const MimicConstraintInvalid rule;
  return rule;
}

}  // namespace assetlint::rules
