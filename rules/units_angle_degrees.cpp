#include <fmt/format.h>

#include <algorithm>
#include <cmath>
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
      const double lower_rad = radians_from_degrees(lower.authored);
      const double upper_rad = radians_from_degrees(upper.authored);
      Diagnostic& d = out.report(largest == std::fabs(upper.value) ? upper.span : lower.span,
                                 fmt::format("limits [{}, {}] of {} look like degrees", format_number(lower.authored),
                                             format_number(upper.authored), joint_label(joint)));
      d.note(fmt::format("URDF limits are radians: {} rad is {} turns, beyond the {} rad threshold (option "
                         "min_magnitude_rad)",
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
