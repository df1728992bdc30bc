#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <set>

#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// The mirror image of units-angle-degrees, for formats that read hinge limits in degrees
// (MJCF without <compiler angle="radian">): radians copied from a URDF make a range of
// under a degree, and the joint barely moves.
class UnitsAngleRadians final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    if (asset.format != SourceFormat::Mjcf) return;
    const double max_magnitude = rule_option(info_, settings, "max_magnitude_deg");
    std::set<std::size_t> seen;  // a range written once in a default class is reported once
    std::vector<const Joint*> radian_like;
    std::size_t hinges_in_degrees = 0;
    for (const Joint& joint : asset.joints) {
      if (joint.type != JointType::Revolute || !joint.lower || !joint.upper) continue;
      const Quantity& lower = *joint.lower;
      const Quantity& upper = *joint.upper;
      if (lower.unit != Unit::Degree || upper.unit != Unit::Degree) continue;
      ++hinges_in_degrees;
      const double largest = std::max(std::fabs(lower.authored), std::fabs(upper.authored));
      if (largest == 0 || largest > max_magnitude) continue;
      // Whole degrees (0 1, -2 2) are plausible small ranges; radians rarely are whole.
      if (lower.authored == std::round(lower.authored) && upper.authored == std::round(upper.authored)) continue;
      // Degrees a converter computed from round radians (4.58 = 0.08 rad, as a motion-capture
      // humanoid writes every range): already converted, not radians left unconverted.
      if (converted_from_round_radians(lower.authored) && converted_from_round_radians(upper.authored)) continue;
      if (!seen.insert(upper.span.offset + (static_cast<std::size_t>(upper.span.file) << 48)).second) continue;
      radian_like.push_back(&joint);
    }
    if (radian_like.size() >= 2 && radian_like.size() == hinges_in_degrees) {
      report_whole_file(radian_like, max_magnitude, out);
      return;
    }
    for (const Joint* joint : radian_like) report_joint(*joint, max_magnitude, out);
  }

 private:
  // Whether degrees written with d decimals are a radian value of two decimals converted and
  // rounded: |x·π/180 − round₂(x·π/180)| within the rounding of the last written digit. A
  // radian value left unconverted (1.57, 0.785) is that only by chance (about 1 in 60 per bound).
  static bool converted_from_round_radians(double degrees) {
    if (degrees == 0) return true;
    const double radians = radians_from_degrees(degrees);
    return std::fabs(radians - std::round(radians * 100) / 100) <=
           radians_from_degrees(half_unit_in_last_digit(degrees)) * (1 + 1e-9);
  }


  static std::string derivation(const Joint& joint, double max_magnitude) {
    const Quantity& lower = *joint.lower;
    const Quantity& upper = *joint.upper;
    return fmt::format("MJCF reads hinge ranges in degrees unless <compiler angle=\"radian\">: {} moves {} "
                       "degrees in all, {} as radians (option max_magnitude_deg = {}).",
                       joint_label(joint), format_number(upper.authored - lower.authored, 4),
                       format_number(degrees_from_radians(upper.authored - lower.authored), 4) + " degrees",
                       format_number(max_magnitude));
  }

  // One hinge among others in degrees: a value copied from a URDF.
  void report_joint(const Joint& joint, double max_magnitude, Reporter& out) const {
    const Quantity& lower = *joint.lower;
    const Quantity& upper = *joint.upper;
    Diagnostic& d = out.report(upper.span, fmt::format("range [{}, {}] of {} looks like radians read as degrees",
                                                       format_number(lower.authored), format_number(upper.authored),
                                                       joint_label(joint)));
    d.note(derivation(joint, max_magnitude));
    std::vector<Edit> edits;
    for (const Quantity* limit : {&lower, &upper})
      if (limit->span.valid() && limit->authored != 0) edits.push_back(replace_value(*limit, limit->authored, 6));
    d.fix = Fix{fmt::format("read the range as radians and write it in degrees: [{}, {}]",
                            format_number(degrees_from_radians(lower.authored), 6),
                            format_number(degrees_from_radians(upper.authored), 6)),
                Applicability::Unsafe, std::move(edits)};
  }

  // Every hinge written in radians: the file means radians throughout. Loaded by itself MuJoCo
  // reads degrees and every joint barely moves; merged into a model that sets the compiler's
  // angle (robosuite's fragments are), it is right. The file cannot tell which: one warning.
  void report_whole_file(const std::vector<const Joint*>& joints, double max_magnitude, Reporter& out) const {
    const Joint& first = *joints.front();
    Diagnostic& d = out.report(first.upper->span, Severity::Warning,
                               fmt::format("all {} hinge ranges look like radians, but this file reads angles in degrees",
                                           joints.size()));
    d.note(derivation(first, max_magnitude));
    d.note("Loaded by itself, MuJoCo reads every one of them in degrees (its <compiler angle> defaults to degree), and "
           "each joint moves a few degrees at most. A file that a framework merges into a model setting "
           "<compiler angle=\"radian\"> (robosuite's robot and gripper files are merged into its base.xml) is read "
           "as radians there.");
    d.note("Say which the file means: add <compiler angle=\"radian\"/> to it (merged models keep reading radians; "
           "check its euler and axisangle values, which the setting also turns to radians).");
  }

  RuleInfo info_{"units-angle-radians",
                 "MJCF hinge ranges read in degrees that look like radians (a URDF's values copied unchanged)",
                 Severity::Error,
                 true,
                 RuleOrigin::Check,
                 {{"max_magnitude_deg", 2 * std::numbers::pi + 0.01,
                   "a range whose bounds are all within this many degrees (default 2π + 0.01) and not whole "
                   "numbers is read as radians"}}};
};

}  // namespace

const Rule& units_angle_radians() {
  static const UnitsAngleRadians rule;
  return rule;
}

}  // namespace assetlint::rules
