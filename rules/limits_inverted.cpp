#include <fmt/format.h>

#include "rules/all_rules.h"
#include "rules/support.h"

namespace assetlint::rules {
namespace {

class LimitsInverted final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings&, Reporter& out) const override {
    for (const Joint& joint : asset.joints) {
      if (joint.type != JointType::Revolute && joint.type != JointType::Prismatic) continue;
      if (!joint.lower || !joint.upper || joint.lower->value <= joint.upper->value) continue;
      Diagnostic& d = out.report(
          joint.lower->span.valid() ? joint.lower->span : joint.limit_span,
          fmt::format("{} has lower limit {} above upper limit {}", joint_label(joint), describe(*joint.lower),
                      describe(*joint.upper)));
      d.note("The joint has no valid position: every pose violates one of its limits.");
      if (joint.lower->span.valid() && joint.upper->span.valid()) {
        const auto text = [&](const Quantity& q) { return std::string(asset.source(q.span.file).view().substr(q.span.offset, q.span.length)); };
        d.fix = Fix{"swap lower and upper", Applicability::Unsafe,
                    {Edit{joint.lower->span.file, joint.lower->span.offset, joint.lower->span.length, text(*joint.upper)},
                     Edit{joint.upper->span.file, joint.upper->span.offset, joint.upper->span.length, text(*joint.lower)}}};
      }
    }
  }

 private:
  RuleInfo info_{"limits-inverted", "A joint's lower limit is above its upper limit", Severity::Error, true,
                 RuleOrigin::Check, {}};
};

}  // namespace

const Rule& limits_inverted() {
  static const LimitsInverted rule;
  return rule;
}

}  // namespace assetlint::rules
