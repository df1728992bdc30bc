#include <fmt/format.h>

#include "rules/all_rules.h"
#include "rules/support.h"

namespace assetlint::rules {
namespace {

class StructureMimicReference final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings&, Reporter& out) const override {
    for (const Joint& joint : asset.joints) {
      if (!joint.mimic) continue;
      const Mimic& mimic = *joint.mimic;
      if (!is_single_dof(joint.type)) {
        out.report(mimic.span, fmt::format("{} has a mimic, but only revolute, continuous and prismatic joints can "
                                           "follow another joint",
                                           joint_label(joint)));
        continue;
      }
      if (mimic.reference.text.empty()) {
        out.report(mimic.span, fmt::format("the mimic of {} names no joint to follow", joint_label(joint)));
        continue;
      }
      if (mimic.reference.text == joint.name.text) {
        out.report(mimic.reference.span, fmt::format("{} mimics itself", joint_label(joint)));
        continue;
      }
      const Joint* reference = asset.find_joint(mimic.reference.text);
      if (!reference) {
        out.report(mimic.reference.span, fmt::format("{} mimics joint '{}', which is not defined",
                                                     joint_label(joint), mimic.reference.text));
      } else if (reference->is_mimic()) {
        out.report(mimic.reference.span,
                   fmt::format("{} mimics '{}', which itself mimics '{}': mimic chains are not supported by "
                               "PhysX or most importers; make both follow '{}'",
                               joint_label(joint), reference->name.text, reference->mimic->reference.text,
                               reference->mimic->reference.text));
      } else if (!is_single_dof(reference->type)) {
        out.report(mimic.reference.span, fmt::format("{} mimics {}, which has no single degree of freedom to follow",
                                                     joint_label(joint), joint_label(*reference)));
      }
    }
  }

 private:
  RuleInfo info_{"structure-mimic-reference",
                 "A mimic joint follows a missing joint, itself, another mimic joint, or sits on a fixed joint",
                 Severity::Error, false, RuleOrigin::Check, {}};
};

}  // namespace

const Rule& structure_mimic_reference() {
  static const StructureMimicReference rule;
  return rule;
}

}  // namespace assetlint::rules
