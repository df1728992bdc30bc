#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

bool has_limits(const Joint& j) {
  return j.type != JointType::Continuous && is_single_dof(j.type) && j.lower && j.upper &&
         j.lower->value <= j.upper->value;
}

// The leader positions a follower can hold: lower ≤ m·q + offset ≤ upper.
std::pair<double, double> leader_range_held(const Joint& follower) {
  const double m = follower.mimic->multiplier.value, o = follower.mimic->offset.value;
  if (m == 0) return {-INFINITY, INFINITY};
  const double a = (follower.lower->value - o) / m, b = (follower.upper->value - o) / m;
  return {std::min(a, b), std::max(a, b)};
}

class MimicLimitConflict final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const double absolute_tolerance = rule_option(info_, settings, "tolerance");
    const double rounding_fraction = rule_option(info_, settings, "rounding_fraction");
    std::vector<const Joint*> leaders_narrowed;  // one narrowing fix per leader
    for (const Joint& joint : asset.joints) {
      if (!joint.mimic || !has_limits(joint)) continue;
      const Joint* reference = asset.followed_joint(joint);
      if (!reference || !has_limits(*reference)) continue;
      const double m = joint.mimic->multiplier.value;
      const double offset = joint.mimic->offset.value;
      const double a = m * reference->lower->value + offset;
      const double b = m * reference->upper->value + offset;
      const double mapped_low = std::min(a, b), mapped_high = std::max(a, b);
      // Multipliers and limits are written to three or four digits: an overshoot within a
      // thousandth of the follower's range is their rounding, not a conflict.
      const double tolerance =
          std::max(absolute_tolerance, rounding_fraction * std::abs(joint.upper->value - joint.lower->value));
      const bool below = mapped_low < joint.lower->value - tolerance;
      const bool above = mapped_high > joint.upper->value + tolerance;
      if (!below && !above) continue;

      const Unit unit = joint.lower->unit;
      const auto range = [&](double low, double high) {
        return fmt::format("[{}, {}] {}", format_number(from_model_units(low, unit)),
                           format_number(from_model_units(high, unit)), unit_symbol(unit));
      };
      // The leader may move in another unit than its follower (a slide driving a hinge).
      const Unit leader_unit = reference->lower->unit;
      const auto leader_range = [&](double low, double high) {
        return fmt::format("[{}, {}] {}", format_number(from_model_units(low, leader_unit)),
                           format_number(from_model_units(high, leader_unit)), unit_symbol(leader_unit));
      };
      const std::string convention = asset.format == SourceFormat::Usda
                                         ? fmt::format("q + {}·q_ref + {} = 0",
                                                       format_number(joint.mimic->multiplier.authored),
                                                       format_number(joint.mimic->offset.authored))
                                         : fmt::format("multiplier {}, offset {}", format_number(m),
                                                       format_number(from_model_units(offset, unit)));
      Diagnostic& d = out.report(
          (below ? joint.lower : joint.upper)->span.valid() ? (below ? joint.lower : joint.upper)->span : joint.limit_span,
          fmt::format("'{}' must reach {} to follow '{}', outside its limits {}", joint.name.text,
                      range(mapped_low, mapped_high), reference->name.text,
                      range(joint.lower->value, joint.upper->value)));
      d.note(reference->name.span,
             fmt::format("'{}' moves over {}; the mimic ({}) maps that to {}.", reference->name.text,
                         leader_range(reference->lower->value, reference->upper->value), convention,
                         range(mapped_low, mapped_high)));
      d.note("The joint limit then fights the mimic constraint: one of them is violated whenever the leader is near "
             "that end.");
      // Fixes an engineer would accept, in order: a sign error mirrored, the leader narrowed
      // to what every follower holds, and only then the follower widened. All change limits.
      if (!joint.lower->span.valid() || !joint.upper->span.valid()) continue;
      const double mirrored_low = -joint.upper->value, mirrored_high = -joint.lower->value;
      if (mapped_low >= mirrored_low - tolerance && mapped_high <= mirrored_high + tolerance) {
        d.note(fmt::format("The mirrored limits {} hold the mapped range: most likely a sign error.",
                           range(mirrored_low, mirrored_high)));
        d.fix = Fix{fmt::format("mirror the limits of '{}' to {}", joint.name.text, range(mirrored_low, mirrored_high)),
                    Applicability::Unsafe,
                    {replace_value(*joint.lower, mirrored_low, 8), replace_value(*joint.upper, mirrored_high, 8)}};
        continue;
      }
      if (auto narrowed = narrowed_leader(asset, *reference, tolerance)) {
        d.note(reference->name.span,
               fmt::format("Every joint that follows '{}' can hold it over {}.", reference->name.text,
                           leader_range(narrowed->first, narrowed->second)));
        if (std::find(leaders_narrowed.begin(), leaders_narrowed.end(), reference) == leaders_narrowed.end()) {
          leaders_narrowed.push_back(reference);
          std::vector<Edit> edits;
          if (narrowed->first > reference->lower->value) edits.push_back(replace_value(*reference->lower, narrowed->first, 8));
          if (narrowed->second < reference->upper->value) edits.push_back(replace_value(*reference->upper, narrowed->second, 8));
          d.fix = Fix{fmt::format("narrow the limits of '{}' to {}", reference->name.text,
                                  leader_range(narrowed->first, narrowed->second)),
                      Applicability::Unsafe, std::move(edits)};
        } else {
          d.note("The fix on the first finding for this leader narrows it, which resolves this one too.");
        }
        continue;
      }
      std::vector<Edit> edits;
      if (below) edits.push_back(replace_value(*joint.lower, mapped_low, 8));
      if (above) edits.push_back(replace_value(*joint.upper, mapped_high, 8));
      d.fix = Fix{fmt::format("widen the limits of '{}' to {}", joint.name.text,
                              range(std::min(mapped_low, joint.lower->value), std::max(mapped_high, joint.upper->value))),
                  Applicability::Unsafe, std::move(edits)};
    }
  }

 private:
  // The leader's range cut down to what every follower with limits can hold, when that is a
  // real narrowing (not empty, not the whole range) and the leader's limits can be edited.
  static std::optional<std::pair<double, double>> narrowed_leader(const Asset& asset, const Joint& leader,
                                                                 double tolerance) {
    if (!leader.lower->span.valid() || !leader.upper->span.valid()) return std::nullopt;
    double low = leader.lower->value, high = leader.upper->value;
    for (const Joint& f : asset.joints) {
      if (!f.mimic || f.mimic->reference.text != leader.name.text || !has_limits(f)) continue;
      const auto [held_low, held_high] = leader_range_held(f);
      low = std::max(low, held_low);
      high = std::min(high, held_high);
    }
    if (high - low <= tolerance) return std::nullopt;
    if (low <= leader.lower->value + tolerance && high >= leader.upper->value - tolerance) return std::nullopt;
    return std::pair{low, high};
  }

  RuleInfo info_{"mimic-limit-conflict",
                 "The followed joint's range, mapped through the mimic gearing, leaves the mimic joint's limits",
                 Severity::Error,
                 true,
                 RuleOrigin::Check,
                 {{"tolerance", 1e-4, "how far (rad or m) the mapped range may stick out before it is reported"},
                  {"rounding_fraction", 1e-3,
                   "an overshoot within this fraction of the follower's range is rounding (0 turns it off)"}}};
};

}  // namespace

const Rule& mimic_limit_conflict() {
  static const MimicLimitConflict rule;
  return rule;
}

}  // namespace assetlint::rules
