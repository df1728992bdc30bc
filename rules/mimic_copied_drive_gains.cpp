#include <fmt/format.h>

#include <cmath>

#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

bool same(double a, double b) {
  return a == b || std::fabs(a - b) <= 1e-6 * std::max(std::fabs(a), std::fabs(b));
}

// A drive gain whose number a mimic value repeats.
struct CopiedFrom {
  const Joint* joint = nullptr;
  const Quantity* gain = nullptr;
  std::string what;  // "drive stiffness", "stale drive damping", ...
};

// Only the drives someone could have copied from: the followed joint's, and the mimic's
// own (a stale drive left under `delete apiSchemas`, or an applied one). An unrelated
// wrist stiffness of 1000 says nothing about a compliant nf = 1000.
std::optional<CopiedFrom> find_copy(const Joint& mimic, const Joint* followed, double value) {
  for (const Joint* joint : {followed, &mimic}) {
    if (!joint) continue;
    for (const auto& [drive, stale] : {std::pair{&joint->drive, false}, std::pair{&joint->inactive_drive, true}}) {
      if (!*drive) continue;
      for (const auto& [gain, what] : {std::pair{&(*drive)->stiffness, "stiffness"}, std::pair{&(*drive)->damping, "damping"}}) {
        if (!*gain) continue;
        const Quantity& q = **gain;
        // Either as written or in the other unit (per degree ↔ per radian).
        const double candidates[] = {q.authored, q.value, from_model_units(q.value, Unit::NewtonMeterPerDegree)};
        for (double candidate : candidates)
          if (candidate != 0 && same(value, candidate))
            return CopiedFrom{joint, &q, fmt::format("{}drive {}", stale ? "stale " : "", what)};
      }
    }
  }
  return std::nullopt;
}

// The guide: "natural frequency is not stiffness, and damping ratio is not damping". A
// compliant mimic's nf / dr repeating a drive gain next to it, a compliance PhysX ignores,
// and a damping ratio so large that the mimic barely corrects drift (PHYSICS.md §2 item 7).
class MimicCopiedDriveGains final : public Rule {
  static constexpr double kFarFactor = 10.0;

 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const double max_ratio = rule_option(info_, settings, "max_damping_ratio");
    for (const Joint& joint : asset.joints) {
      if (!joint.mimic || !joint.mimic->natural_frequency) continue;
      const Quantity& nf = *joint.mimic->natural_frequency;
      if (nf.value <= 0) continue;  // a hard constraint, as the guide recommends to start
      const OptQuantity& dr = joint.mimic->damping_ratio;
      const Joint* followed = asset.find_joint(joint.mimic->reference.text);

      const auto nf_copy = find_copy(joint, followed, nf.value);
      const auto dr_copy = dr && dr->value > 0 ? find_copy(joint, followed, dr->value) : std::nullopt;
      if (nf_copy || dr_copy) {
        copied(joint, nf, dr, nf_copy, dr_copy, out);
        continue;
      }
      if (!dr || dr->value <= 0) {
        Diagnostic& d = out.report(dr && dr->span.valid() ? dr->span : nf.span, Severity::Info,
                                   fmt::format("mimic '{}': naturalFrequency {} with dampingRatio {}: hard, compliance "
                                               "ignored",
                                               joint.name.text, format_number(nf.value, 6),
                                               dr ? format_number(dr->value, 6) : "unauthored"));
        d.note("PhysX makes a mimic compliant only when both naturalFrequency and dampingRatio are > 0; otherwise the "
               "constraint is hard and the natural frequency does nothing.");
        d.note("Author a dampingRatio > 0 for compliance, or naturalFrequency 0 to say the constraint is hard.");
        continue;
      }
      if (dr->value > max_ratio) {
        // Past the bound by an order of magnitude the drift outlasts any grasp: the followers
        // drift apart under load (fingers out of parallel), whatever the value's origin.
        const bool far = dr->value >= kFarFactor * max_ratio;
        Diagnostic& d = out.report(dr->span, far ? Severity::Warning : Severity::Info,
                                   fmt::format("mimic '{}': dampingRatio {} {} position drift", joint.name.text,
                                               format_number(dr->value, 4), far ? "all but stops correcting" : "barely corrects"));
        d.note(fmt::format("PhysX turns the mimic into an implicit spring with kp = nf²/r and kd = 2·nf·dr/r: at "
                           "dampingRatio {} (above max_damping_ratio {}) the damping term dominates and the drift between "
                           "'{}' and '{}' decays with time constant kd/kp = 2·dr/nf = 2 × {} / {} rad/s = {} s.",
                           format_number(dr->value, 4), format_number(max_ratio), joint.name.text,
                           joint.mimic->reference.text, format_number(dr->value, 4), format_number(nf.value, 4),
                           format_number(2 * dr->value / nf.value, 3)));
        if (far)
          d.note(fmt::format("That is {}× or more the bound: under a load the followers drift apart (fingers out of "
                             "parallel) and stay apart for seconds.",
                             format_number(kFarFactor)));
        d.note("A hard mimic (naturalFrequency 0) keeps the joints together; the guide starts there.");
      }
    }
  }

 private:
  static void copied(const Joint& joint, const Quantity& nf, const OptQuantity& dr, const std::optional<CopiedFrom>& nf_copy,
                     const std::optional<CopiedFrom>& dr_copy, Reporter& out) {
    const bool on_nf = nf_copy.has_value();
    const CopiedFrom& from = on_nf ? *nf_copy : *dr_copy;
    const Quantity& value = on_nf ? nf : *dr;
    const bool own = from.joint == &joint;
    Diagnostic& d = out.report(
        value.span, fmt::format("mimic '{}': {} {} repeats {} {}", joint.name.text,
                                on_nf ? "naturalFrequency" : "dampingRatio", format_number(value.value, 6),
                                own ? "its own" : "the followed joint's", from.what));
    auto describe_copy = [&](const char* name, const Quantity& q, const CopiedFrom& c) {
      d.note(c.gain->span, fmt::format("{} {} repeats the {} {} of '{}'{}.", name, format_number(q.value, 6), c.what,
                                       describe(*c.gain), c.joint->name.text,
                                       c.joint == &joint ? " (the mimic's own drive values)" : " (the joint it follows)"));
    };
    describe_copy(on_nf ? "naturalFrequency" : "dampingRatio", value, from);
    if (on_nf && dr_copy) describe_copy("dampingRatio", *dr, *dr_copy);
    d.note("Natural frequency (rad/s) is not stiffness and damping ratio is not damping: PhysX derives the mimic's "
           "spring from them (kp = nf²/r, kd = 2·nf·dr/r), with no relation to any drive's gains.");
    d.note("The guide starts mimic joints hard (naturalFrequency 0) and adds compliance only when hard constraints "
           "visibly fight.");
    std::vector<Edit> edits;
    if (nf.span.valid()) edits.push_back(replace_value(nf, 0.0));
    if (dr && dr->span.valid() && dr->value != 0) edits.push_back(replace_value(*dr, 0.0));
    if (!edits.empty())
      d.fix = Fix{"make the mimic a hard constraint: naturalFrequency = 0, dampingRatio = 0", Applicability::Unsafe,
                  std::move(edits)};
  }

  RuleInfo info_{"mimic-copied-drive-gains",
                 "A mimic joint's natural frequency / damping ratio copied from a drive's stiffness / damping, a "
                 "compliance PhysX ignores, or an overdamped mimic",
                 Severity::Warning,
                 true,
                 RuleOrigin::Check,
                 {{"max_damping_ratio", 10.0,
                   "mimic damping ratios above this get an info (drift is barely corrected), 10× above it a warning"}}};
};

}  // namespace

const Rule& mimic_copied_drive_gains() {
  static const MimicCopiedDriveGains rule;
  return rule;
}

}  // namespace assetlint::rules
