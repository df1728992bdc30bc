#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "physics/drive.h"
#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

bool same(double a, double b) {
  return a == b || std::fabs(a - b) <= 1e-6 * std::max(std::fabs(a), std::fabs(b));
}

// A drive gain somewhere in the asset whose number a mimic value repeats.
struct CopiedFrom {
  const Joint* joint = nullptr;
  std::string what;  // "stiffness" / "damping"
  bool inactive = false;
  std::string text;  // the gain as written
};

// Every drive gain of the asset, sorted by value, so that each mimic value is looked up
// in O(log n) instead of a walk over all joints.
class GainTable {
 public:
  explicit GainTable(const Asset& asset) {
    std::size_t order = 0;
    for (const Joint& joint : asset.joints) {
      for (const auto& [drive, inactive] : {std::pair{&joint.drive, false}, std::pair{&joint.inactive_drive, true}}) {
        if (!*drive) continue;
        for (const auto& [gain, what] : {std::pair{&(*drive)->stiffness, "stiffness"}, std::pair{&(*drive)->damping, "damping"}}) {
          if (!*gain) continue;
          const Quantity& q = **gain;
          // Either as written or in the other unit (per degree ↔ per radian).
          const double candidates[] = {q.authored, q.value, from_model_units(q.value, Unit::NewtonMeterPerDegree)};
          for (double candidate : candidates)
            if (candidate != 0 && !std::isnan(candidate)) entries_.push_back({candidate, order++, CopiedFrom{&joint, what, inactive, describe(q)}});
        }
      }
    }
    std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) { return a.value < b.value; });
  }

  // The first gain in document order that `value` repeats.
  std::optional<CopiedFrom> find(double value) const {
    const double reach = std::isfinite(value) ? 2e-6 * std::fabs(value) : 0.0;
    auto it = std::lower_bound(entries_.begin(), entries_.end(), value - reach,
                               [](const Entry& e, double v) { return e.value < v; });
    const Entry* best = nullptr;
    for (; it != entries_.end() && it->value <= value + reach; ++it)
      if (same(value, it->value) && (!best || it->order < best->order)) best = &*it;
    if (!best) return std::nullopt;
    return best->from;
  }

 private:
  struct Entry {
    double value;
    std::size_t order;
    CopiedFrom from;
  };
  std::vector<Entry> entries_;
};

// The guide: "natural frequency is not stiffness, and damping ratio is not damping".
// A mimic's compliance copied from a drive's gains, or physically implausible.
class MimicCopiedDriveGains final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const double max_ratio = rule_option(info_, settings, "max_damping_ratio");
    const double bound = physics::effective_simulation(asset, settings).optimistic_bound();
    std::optional<GainTable> gains;
    for (const Joint& joint : asset.joints) {
      if (!joint.mimic || !joint.mimic->natural_frequency || !joint.mimic->damping_ratio) continue;
      const Quantity& nf = *joint.mimic->natural_frequency;
      const Quantity& dr = *joint.mimic->damping_ratio;
      if (nf.value <= 0 || dr.value <= 0) continue;  // a hard constraint, as the guide recommends to start

      std::vector<std::string> problems;
      if (!gains) gains.emplace(asset);
      const auto nf_copy = gains->find(nf.value);
      const auto dr_copy = gains->find(dr.value);
      auto copied = [&](const char* name, const Quantity& q, const CopiedFrom& from) {
        return fmt::format("{} {} equals the {}{} {} of '{}'", name, format_number(q.value, 6),
                           from.inactive ? "stale (unapplied) drive " : "drive ", from.what, from.text,
                           from.joint->name.text);
      };
      if (nf_copy) problems.push_back(copied("naturalFrequency", nf, *nf_copy));
      else if (nf.value > bound)
        problems.push_back(fmt::format("naturalFrequency {} rad/s exceeds the solver bound {} (rate × position iterations)",
                                       format_number(nf.value, 4), format_number(bound, 4)));
      if (dr_copy) problems.push_back(copied("dampingRatio", dr, *dr_copy));
      else if (dr.value > max_ratio)
        problems.push_back(fmt::format("dampingRatio {} is far above critical (1; threshold {})", format_number(dr.value, 4),
                                       format_number(max_ratio)));
      if (problems.empty()) continue;

      std::string message = fmt::format("mimic {}: ", joint_label(joint));
      for (std::size_t i = 0; i < problems.size(); ++i) message += (i ? "; " : "") + problems[i];
      message += "; natural frequency is not stiffness and damping ratio is not damping";

      // Converted from the followed joint's drive over the coupled set's inertia.
      const Joint* driver = asset.followed_joint(joint);
      const physics::EffectiveInertia inertia = physics::effective_inertia(asset, joint);
      std::optional<Fix> fix;
      if (driver && driver->drive && driver->drive->stiffness && driver->drive->stiffness->value > 0 && inertia.known) {
        const double k = driver->drive->stiffness->value;
        const double d = driver->drive->damping ? driver->drive->damping->value : 0.0;
        const double new_nf = physics::natural_frequency(k, inertia.value);
        const double new_dr = physics::damping_ratio(d, k, inertia.value);
        std::vector<Edit> edits;
        if (new_nf > bound) {
          // Too stiff to resolve as a compliant constraint: the guide's starting point.
          message += fmt::format("; converted from the drive of '{}' the natural frequency would be {} rad/s, above the "
                                 "solver bound {}: make it a hard constraint (0 / 0), as the guide recommends to start",
                                 driver->name.text, format_number(new_nf, 4), format_number(bound, 4));
          if (nf.span.valid()) edits.push_back(replace_value(nf, 0.0));
          if (dr.span.valid()) edits.push_back(replace_value(dr, 0.0));
          if (!edits.empty()) fix = Fix{"make the mimic a hard constraint", Applicability::Unsafe, std::move(edits)};
        } else {
          message += fmt::format("; converted from the drive of '{}' (k = {} N·m/rad, d = {} N·m·s/rad, I = {}): "
                                 "naturalFrequency {} rad/s, dampingRatio {}",
                                 driver->name.text, format_number(k, 4), format_number(d, 4), inertia.describe(),
                                 format_number(new_nf, 4), format_number(new_dr, 3));
          if (nf.span.valid()) edits.push_back(replace_value(nf, new_nf, 4));
          if (dr.span.valid() && new_dr > 0) edits.push_back(replace_value(dr, new_dr, 3));
          if (!edits.empty())
            fix = Fix{"convert the drive gains to natural frequency and damping ratio", Applicability::Unsafe, std::move(edits)};
        }
      } else {
        message += "; start with a hard constraint (0 / 0), as the guide recommends";
      }
      Diagnostic& diagnostic = out.report(nf_copy || nf.value > bound ? nf.span : dr.span, std::move(message));
      diagnostic.fix = std::move(fix);
    }
  }

 private:
  RuleInfo info_{"mimic-copied-drive-gains",
                 "A mimic joint's natural frequency / damping ratio copied from drive stiffness / damping, or implausible",
                 Severity::Warning,
                 true,
                 RuleOrigin::Check,
                 {{"max_damping_ratio", 10.0, "mimic damping ratios above this are implausible"}}};
};

}  // namespace

const Rule& mimic_copied_drive_gains() {
  static const MimicCopiedDriveGains rule;
  return rule;
}

}  // namespace assetlint::rules
