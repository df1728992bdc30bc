#include <fmt/format.h>

#include <string>
#include <string_view>
#include <utility>

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
    for (const Joint& joint : asset.joints) check_locked_twin(asset, joint, out);
  }

 private:
  static bool ranged(const Joint& joint) {
    return (joint.type == JointType::Revolute || joint.type == JointType::Prismatic) && joint.lower && joint.upper &&
           joint.lower->span.valid() && joint.upper->span.valid();
  }

  // The name of the other side of a symmetric mechanism: left ↔ right, l_ ↔ r_, _l ↔ _r.
  static const Joint* mirror_twin(const Asset& asset, const Joint& joint) {
    static const std::pair<std::string_view, std::string_view> swaps[] = {
        {"left", "right"}, {"Left", "Right"}, {"LEFT", "RIGHT"}, {"l_", "r_"}, {"L_", "R_"}, {"_l", "_r"}, {"_L", "_R"}};
    const std::string& name = joint.name.text;
    for (const auto& [a, b] : swaps) {
      for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
        for (std::size_t at = name.find(from); at != std::string::npos; at = name.find(from, at + 1)) {
          std::string other = name;
          other.replace(at, from.size(), to);
          if (const Joint* twin = asset.find_joint(other); twin && twin != &joint) return twin;
        }
      }
    }
    return nullptr;
  }

  // A joint whose limits lock it (lower = upper) while its mirror twin moves: one side of a
  // symmetric mechanism is frozen, usually limits copied wrong.
  static void check_locked_twin(const Asset& asset, const Joint& joint, Reporter& out) {
    if (!ranged(joint) || joint.lower->value != joint.upper->value || joint.is_mimic()) return;
    const Joint* twin = mirror_twin(asset, joint);
    if (!twin || !ranged(*twin) || twin->type != joint.type || !(twin->lower->value < twin->upper->value)) return;
    Diagnostic& d = out.report(joint.upper->span, Severity::Warning,
                               fmt::format("{} is locked at {} while its mirror '{}' moves", joint_label(joint),
                                           describe(*joint.upper), twin->name.text));
    d.note(fmt::format("Its limits are [{}, {}]; '{}' moves over [{}, {}].", describe(*joint.lower),
                       describe(*joint.upper), twin->name.text, describe(*twin->lower), describe(*twin->upper)));
    d.note(twin->upper->span, fmt::format("'{}' is the same joint on the other side.", twin->name.text));
    d.note("PhysX, MuJoCo and Gazebo hold a joint with equal limits at that position: one side of the mechanism "
           "cannot move while the other does. If the joint is meant to be fixed, make it a fixed joint; otherwise "
           "give it its twin's range (mirrored if its axis is).");
  }

  RuleInfo info_{"limits-inverted",
                 "A joint's lower limit is above its upper limit, or equal limits lock a joint whose mirror twin moves",
                 Severity::Error, true, RuleOrigin::Check, {}};
};

}  // namespace

const Rule& limits_inverted() {
  static const LimitsInverted rule;
  return rule;
}

}  // namespace assetlint::rules
