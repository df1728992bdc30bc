#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

class UnitsAngleDegrees final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const double min_magnitude = rule_option(info_, settings, "min_magnitude_rad");
    const double pi_tolerance = rule_option(info_, settings, "pi_multiple_tolerance");
    const double max_magnitude = rule_option(info_, settings, "max_magnitude_deg");
    std::vector<const Joint*> degree_like;
    for (const Joint& joint : asset.joints) {
      if (joint.type != JointType::Revolute || !joint.lower || !joint.upper) continue;
      const Quantity& lower = *joint.lower;
      const Quantity& upper = *joint.upper;
      if (lower.unit != Unit::Radian || upper.unit != Unit::Radian) continue;
      const double largest = std::max(std::fabs(lower.value), std::fabs(upper.value));
      if (largest <= min_magnitude || largest > max_magnitude) continue;
      // Multiples of π written as decimals (±31.4, ±9.42478) are deliberate radian values:
      // multi-turn ranges or "no limit" placeholders. Whole numbers (44, 90) are degrees.
      if (radian_like(lower.value, pi_tolerance) && radian_like(upper.value, pi_tolerance)) continue;
      if (unlimited_stand_in(asset, joint)) continue;
      // A full turn or more read as degrees ([-180, 180]) restricts nothing within a turn, and
      // neither does the same number of radians: the reading changes no motion the joint makes.
      if (upper.authored - lower.authored >= 360) continue;
      degree_like.push_back(&joint);
    }
    const std::vector<const Joint*> shared = shared_symmetric_bound(degree_like);
    if (!shared.empty()) report_shared(asset, shared, min_magnitude, out);
    for (const Joint* each : degree_like) {
      if (std::find(shared.begin(), shared.end(), each) != shared.end()) continue;
      const Joint& joint = *each;
      const Quantity& lower = *joint.lower;
      const Quantity& upper = *joint.upper;
      const double largest = std::max(std::fabs(lower.value), std::fabs(upper.value));
      const double lower_rad = radians_from_degrees(lower.authored);
      const double upper_rad = radians_from_degrees(upper.authored);
      Diagnostic& d = out.report(largest == std::fabs(upper.value) ? upper.span : lower.span,
                                 fmt::format("limits [{}, {}] of {} look like degrees", format_number(lower.authored),
                                             format_number(upper.authored), joint_label(joint)));
      d.note(fmt::format("{}: {} rad is {} turns, beyond the {} rad threshold (option min_magnitude_rad)",
                         radians_text(asset),
                         format_number(largest, 4), format_number(largest / (2 * std::numbers::pi), 3),
                         format_number(min_magnitude, 4)));
      // Convert only the limits that look like degrees themselves: whole numbers or
      // beyond the threshold. `upper="0.8757"` next to `lower="-46"` is already radians, and
      // 0 is 0 in both units.
      std::vector<Edit> edits;
      for (const Quantity* limit : {&lower, &upper}) {
        const bool degree_like = limit->value != 0 &&
                                 (limit->value == std::round(limit->value) || std::fabs(limit->value) > min_magnitude);
        if (limit->span.valid() && degree_like) edits.push_back(replace_value(*limit, radians_from_degrees(limit->authored)));
      }
      d.fix = Fix{fmt::format("read the limits as degrees and write them in radians: [{}, {}]", format_number(lower_rad),
                              format_number(upper_rad)),
                  Applicability::Unsafe, std::move(edits)};
    }
  }

 private:
  // One symmetric bound written on many joints (±100 on every body joint of an exported
  // humanoid): a value typed for "no limit" or "not set", not each joint's range in degrees.
  // The largest group of at least kSharedJoints joints with the same [−b, b].
  static constexpr std::size_t kSharedJoints = 3;
  static std::vector<const Joint*> shared_symmetric_bound(const std::vector<const Joint*>& joints) {
    std::map<double, std::vector<const Joint*>> by_bound;
    for (const Joint* joint : joints)
      if (joint->lower->authored == -joint->upper->authored) by_bound[std::fabs(joint->upper->authored)].push_back(joint);
    std::vector<const Joint*> largest;
    for (auto& [bound, group] : by_bound)
      if (group.size() >= kSharedJoints && group.size() > largest.size()) largest = group;
    return largest;
  }

  static std::string radians_text(const Asset& asset) {
    return asset.format == SourceFormat::Mjcf ? "This file reads angles in radians (<compiler angle=\"radian\">)"
                                              : "URDF limits are radians";
  }

  void report_shared(const Asset& asset, const std::vector<const Joint*>& joints, double min_magnitude,
                     Reporter& out) const {
    const Joint& first = *joints.front();
    const double bound = std::fabs(first.upper->authored);
    Diagnostic& d = out.report(first.upper->span, Severity::Warning,
                               fmt::format("{} revolute joints share the limits [{}, {}]: a placeholder, not their ranges",
                                           joints.size(), format_number(-bound), format_number(bound)));
    d.note(fmt::format("{}: {} rad is {} turns, beyond the {} rad threshold (option min_magnitude_rad), so every "
                       "consumer lets these joints turn freely.",
                       radians_text(asset), format_number(bound, 4), format_number(bound / (2 * std::numbers::pi), 3),
                       format_number(min_magnitude, 4)));
    d.note(fmt::format("One symmetric value on {} joints ({} first, {} last) is what an author types for \"no limit\" "
                       "or \"not set\"; read as degrees it would give every one of them the same ±{}°, which no "
                       "robot's joints have. No value is proposed.",
                       joints.size(), joint_label(first), joint_label(*joints.back()), format_number(bound)));
    d.note("Write each joint's range from the data sheet in radians; a joint that turns freely is continuous.");
  }

  // A symmetric bound on a joint of a virtual base (a massless child link, or the same ±value
  // on a prismatic sibling: ±20 rad beside ±20 m) stands for "unlimited"; read as degrees it
  // would clamp a floating base to ±20°.
  static bool unlimited_stand_in(const Asset& asset, const Joint& joint) {
    if (joint.lower->authored != -joint.upper->authored) return false;
    const double bound = std::fabs(joint.upper->authored);
    const Link* child = asset.side_link(joint, 1);
    const bool massless_child = child && (!child->inertial || (child->inertial->mass_authored && child->inertial->mass.value == 0));
    if (massless_child) return true;
    return std::any_of(asset.joints.begin(), asset.joints.end(), [&](const Joint& other) {
      return other.type == JointType::Prismatic && other.lower && other.upper &&
             other.lower->authored == -other.upper->authored && std::fabs(other.upper->authored) == bound;
    });
  }

  static bool radian_like(double value, double tolerance) {
    if (value == 0) return true;
    if (value == std::round(value)) return false;
    const double halfturns = value / std::numbers::pi;
    return std::fabs(halfturns - std::round(halfturns)) <= tolerance;
  }

  RuleInfo info_{"units-angle-degrees",
                 "Revolute limits written in degrees where URDF expects radians",
                 Severity::Error,
                 true,
                 RuleOrigin::Check,
                 {{"min_magnitude_rad", 4 * std::numbers::pi,
                   "a limit must exceed this magnitude (radians; default 4π, two turns) to be read as degrees"},
                  {"max_magnitude_deg", 360.0, "limits larger than this are not read as degrees either"},
                  {"pi_multiple_tolerance", 0.01,
                   "a non-integer limit whose multiple of π is within this (in units of π) of a whole number is "
                   "taken as deliberate radians"}}};
};

}  // namespace

const Rule& units_angle_degrees() {
  static const UnitsAngleDegrees rule;
  return rule;
}

}  // namespace assetlint::rules
