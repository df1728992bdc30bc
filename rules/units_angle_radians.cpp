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
    for (const Joint& joint : asset.joints) {
      if (joint.type != JointType::Revolute || !joint.lower || !joint.upper) continue;
      const Quantity& lower = *joint.lower;
      const Quantity& upper = *joint.upper;
      if (lower.unit != Unit::Degree || upper.unit != Unit::Degree) continue;
      const double largest = std::max(std::fabs(lower.authored), std::fabs(upper.authored));
      if (largest == 0 || largest > max_magnitude) continue;
      // Whole degrees (0 1, -2 2) are plausible small ranges; radians rarely are whole.
      if (lower.authored == std::round(lower.authored) && upper.authored == std::round(upper.authored)) continue;
      if (!seen.insert(upper.span.offset + (static_cast<std::size_t>(upper.span.file) << 48)).second) continue;
      Diagnostic& d = out.report(upper.span, fmt::format("range [{}, {}] of {} looks like radians read as degrees",
                                                         format_number(lower.authored), format_number(upper.authored),
                                                         joint_label(joint)));
      d.note(fmt::format("MJCF reads hinge ranges in degrees unless <compiler angle=\"radian\">: this joint moves {} "
                         "degrees in all, {} as radians (option max_magnitude_deg = {}).",
                         format_number(upper.authored - lower.authored, 4),
                         format_number(degrees_from_radians(upper.authored - lower.authored), 4) + " degrees",
                         format_number(max_magnitude)));
      std::vector<Edit> edits;
      for (const Quantity* limit : {&lower, &upper})
        if (limit->span.valid() && limit->authored != 0) edits.push_back(replace_value(*limit, limit->authored, 6));
      d.fix = Fix{fmt::format("read the range as radians and write it in degrees: [{}, {}]",
                              format_number(degrees_from_radians(lower.authored), 6),
                              format_number(degrees_from_radians(upper.authored), 6)),
                  Applicability::Unsafe, std::move(edits)};
    }
  }

 private:
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
