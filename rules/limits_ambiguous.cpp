#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// URDF joint limits that its consumers read differently (issue 15): lower/upper on a
// continuous joint (Drake's Robotiq 3F four-bar joints) and a revolute or prismatic <limit>
// without them (Minitaur's knees). One warning per case per file, the rest as notes.
class LimitsAmbiguous final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings&, Reporter& out) const override {
    if (asset.format != SourceFormat::Urdf) return;
    std::vector<const Joint*> bounded_continuous;
    std::vector<const Joint*> missing_bounds;
    for (const Joint& joint : asset.joints) {
      if (joint.type == JointType::Continuous && binding_limits(joint)) bounded_continuous.push_back(&joint);
      const bool limited_type = joint.type == JointType::Revolute || joint.type == JointType::Prismatic;
      if (limited_type && has_limit_element(joint) && !joint.bounds_unreadable && (!joint.lower || !joint.upper)) missing_bounds.push_back(&joint);
    }
    if (!bounded_continuous.empty()) report_continuous(bounded_continuous, out);
    if (!missing_bounds.empty()) report_missing(missing_bounds, out);
  }

 private:
  // Without a <limit> element the reader points limit_span at the joint itself; urdfdom then
  // rejects a revolute or prismatic joint outright (urdf-invalid says so).
  static bool has_limit_element(const Joint& joint) {
    return joint.limit_span.offset != joint.span.offset || joint.limit_span.length != joint.span.length;
  }

  // A range of a full turn or more (±π, ±1e16) restricts nothing a continuous joint does.
  static bool binding_limits(const Joint& joint) {
    if (!joint.lower && !joint.upper) return false;
    if (!joint.lower || !joint.upper) return true;
    return joint.upper->value - joint.lower->value < 2 * std::numbers::pi * (1 - 1e-3);
  }

  static std::string range_text(const Joint& joint) {
    const auto end = [](const OptQuantity& q) { return q ? format_number(q->value, 4) : std::string("unset"); };
    return fmt::format("[{}, {}] rad", end(joint.lower), end(joint.upper));
  }

  static Span limit_at(const Joint& joint) {
    if (joint.lower && joint.lower->span.valid()) return joint.lower->span;
    if (joint.upper && joint.upper->span.valid()) return joint.upper->span;
    return joint.limit_span;
  }

  static void others(Diagnostic& d, const std::vector<const Joint*>& joints, bool with_range) {
    for (std::size_t i = 1; i < joints.size() && i <= 5; ++i)
      d.note(limit_at(*joints[i]), fmt::format("Also '{}'{}.", joints[i]->name.text,
                                                with_range ? " " + range_text(*joints[i]) : std::string()));
    if (joints.size() > 6) d.note(fmt::format("And {} more joints like these.", joints.size() - 6));
  }

  static void report_continuous(const std::vector<const Joint*>& joints, Reporter& out) {
    const Joint& first = *joints.front();
    Diagnostic& d = out.report(
        limit_at(first), Severity::Warning,
        joints.size() == 1
            ? fmt::format("continuous joint '{}' has limits {}: Isaac Sim applies them, ROS tools ignore them",
                          first.name.text, range_text(first))
            : fmt::format("{} continuous joints have lower/upper limits: Isaac Sim applies them, ROS tools ignore them",
                          joints.size()));
    if (joints.size() > 1) d.note(fmt::format("The first, '{}', has {}.", first.name.text, range_text(first)));
    d.note("urdfdom parses the values, but ROS consumers (joint limits, MoveIt, robot_state_publisher) treat a "
           "continuous joint as unbounded; Isaac Sim's URDF importer writes them as the joint's limits. The simulated "
           "joint then stops where the ROS model of the same file does not.");
    d.note("If the joint is bounded, make it revolute; if it turns freely, delete lower and upper. A range of a full "
           "turn or more is not reported: it restricts nothing.");
    others(d, joints, true);
  }

  static void report_missing(const std::vector<const Joint*>& joints, Reporter& out) {
    const Joint& first = *joints.front();
    const bool neither = !first.lower && !first.upper;
    Diagnostic& d = out.report(
        first.limit_span, Severity::Warning,
        joints.size() == 1
            ? fmt::format("{} has <limit> without {}: urdfdom reads 0, Isaac Sim leaves it free", joint_label(first),
                          neither ? "lower and upper" : (!first.lower ? "lower" : "upper"))
            : fmt::format("{} joints have <limit> without lower/upper: urdfdom reads 0, Isaac Sim leaves them free",
                          joints.size()));
    d.note("urdfdom defaults a missing lower or upper to 0, so ROS tools (check_urdf, MoveIt, controllers) see a joint "
           "that cannot leave 0 (or one side of it); Isaac Sim's URDF importer writes no limit for the missing side.");
    d.note("Write the joint's real range; if a revolute joint turns freely, make it continuous.");
    others(d, joints, false);
  }

  RuleInfo info_{"limits-ambiguous",
                 "URDF limits that consumers read differently: lower/upper on a continuous joint, or a <limit> without "
                 "them on a revolute or prismatic joint",
                 Severity::Warning,
                 false,
                 RuleOrigin::Check,
                 {}};
};

}  // namespace

const Rule& limits_ambiguous() {
  static const LimitsAmbiguous rule;
  return rule;
}

}  // namespace assetlint::rules
