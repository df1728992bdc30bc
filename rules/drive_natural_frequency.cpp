#include <fmt/format.h>

#include <cmath>

#include "rules/all_rules.h"
#include "rules/drive_support.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// PHYSICS.md §2–3: nf = sqrt(k / I) compared with the simulation rate, as the guide
// does (rad/s against steps per second, no 2π). Above rate × position iterations (the
// guide's over-optimistic bound) a drive is prone to fail; far above the rate it is
// suspicious. The fix follows the guide: k = max force / target delta, lower where
// that still exceeds the bound, and damping for a damping ratio of 1.
class DriveNaturalFrequency final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const double factor = rule_option(info_, settings, "far_above_rate_factor");
    for (const Joint& joint : asset.joints) {
      auto driven = spring_drive(asset, joint, settings);
      if (!driven) continue;
      const Drive& drive = *driven->drive;
      const Span at = drive.stiffness->span.valid() ? drive.stiffness->span : joint.name.span;
      if (drive.type == DriveType::Force && !driven->inertia.known) {
        out.report(at, Severity::Info,
                   fmt::format("natural frequency of the drive of {} not checked: no link of it or its mimics "
                               "authors both mass and inertia{}; PhysX derives them from colliders",
                               joint_label(joint), unknown_list(driven->inertia)));
        continue;
      }
      const double inertia = driven->inertia_used;
      const double nf = physics::natural_frequency(driven->stiffness, inertia);
      const physics::SimulationRate& rate = driven->rate;
      const double bound = rate.optimistic_bound();
      const double warn = factor * rate.timesteps_per_second;
      if (nf <= warn) continue;

      const Unit k_unit = stiffness_unit(joint), d_unit = damping_unit(joint);
      std::string message = fmt::format(
          "natural frequency {} rad/s of the drive of {} (stiffness {}, {}) ", format_number(nf, 4), joint_label(joint),
          describe_gain(drive.stiffness, driven->stiffness, k_unit), driven->inertia_text());
      const bool error = nf > bound;
      if (error) {
        message += fmt::format("exceeds {} = {}, the guide's over-optimistic bound", rate.describe(), format_number(bound, 4));
      } else {
        message += fmt::format("is {}× the {} Hz simulation rate ({}; warning above {}×, error above {} × {} = {})",
                               format_number(nf / rate.timesteps_per_second, 3), format_number(rate.timesteps_per_second),
                               rate.rate_origin, format_number(factor), format_number(rate.timesteps_per_second),
                               format_number(rate.position_iterations), format_number(bound, 4));
      }

      // The guide's stiffness: full max force still reached `target delta` before the target.
      std::optional<double> proposed;
      std::string reason;
      const Quantity* force = max_force_of(joint);
      const auto delta = target_delta(joint, settings);
      const bool force_known = force && force->value > 0 && std::isfinite(force->value);
      if (force_known && delta && drive.type == DriveType::Force) {
        const double k_force = force->value / *delta;
        const double nf_force = physics::natural_frequency(k_force, inertia);
        if (nf_force > bound) {
          // Lowering k further would lose the max force at the target delta: the guide's
          // other levers are armature and the simulation rate.
          const double armature = k_force / (warn * warn) - inertia;
          message += fmt::format(
              "; even the guide's stiffness (max force {} / {}° target delta = {}) gives {} rad/s: add armature ≥ {} "
              "kg·m² (natural frequency {}× the rate) or simulate at ≥ {} Hz",
              describe(*force), format_number(settings.gripper.target_delta_deg.value),
              describe_gain(drive.stiffness, k_force, k_unit), format_number(nf_force, 4), format_number(armature, 3),
              format_number(factor), format_number(std::ceil(nf_force / factor), 4));
          out.report(at, error ? Severity::Error : Severity::Warning, std::move(message));
          continue;
        }
        proposed = k_force;
        reason = fmt::format("max force {} reached {}° before the target", describe(*force),
                             format_number(settings.gripper.target_delta_deg.value));
      }
      if (!proposed) {
        // No force bound to keep: the stiffness for a natural frequency at the warning threshold.
        proposed = physics::stiffness_for_frequency(warn, inertia);
        reason = fmt::format("natural frequency {}× the rate{}", format_number(factor),
                             force_known ? "" : "; no max force to keep");
      }
      if (*proposed >= driven->stiffness * (1 - 1e-6)) {
        // The guide's stiffness is not lower than what the file has: stiffness is not the
        // lever here (and a fix must never stiffen a drive).
        const double armature = driven->stiffness / (warn * warn) - inertia;
        message += fmt::format("; the guide's stiffness ({}) is not lower: add armature ≥ {} kg·m² (natural frequency "
                               "{}× the rate) or simulate at ≥ {} Hz",
                               describe_gain(drive.stiffness, *proposed, k_unit), format_number(armature, 3),
                               format_number(factor), format_number(std::ceil(nf / factor), 4));
        out.report(at, error ? Severity::Error : Severity::Warning, std::move(message));
        continue;
      }
      const double damping = physics::damping_for_ratio(1.0, *proposed, inertia);
      message += fmt::format("; stiffness {} → {} ({}), damping → {} for damping ratio 1 (natural frequency {} rad/s)",
                             describe_gain(drive.stiffness, driven->stiffness, k_unit),
                             describe_gain(drive.stiffness, *proposed, k_unit), reason,
                             describe_gain(drive.damping, damping, d_unit),
                             format_number(physics::natural_frequency(*proposed, inertia), 3));
      Diagnostic& d = out.report(at, error ? Severity::Error : Severity::Warning, std::move(message));
      std::vector<Edit> edits;
      // Rounded down, so the written stiffness does not land back above the threshold.
      if (drive.stiffness->span.valid())
        edits.push_back(Edit{drive.stiffness->span.file, drive.stiffness->span.offset, drive.stiffness->span.length,
                             format_number_at_most(drive.stiffness->authored_for(*proposed), 4)});
      if (drive.damping && drive.damping->span.valid()) edits.push_back(replace_value(*drive.damping, damping, 4));
      if (!edits.empty())
        d.fix = Fix{"set stiffness and damping per the guide", Applicability::Unsafe, std::move(edits)};
    }
  }

 private:
  static std::string unknown_list(const physics::EffectiveInertia& inertia) {
    if (inertia.unknown_links.empty()) return "";
    std::string list;
    for (const auto& name : inertia.unknown_links) list += (list.empty() ? "" : ", ") + ("'" + name + "'");
    return " (" + list + ")";
  }

  RuleInfo info_{"drive-natural-frequency",
                 "A drive's natural frequency sqrt(k/I) is far above what the simulation rate can resolve",
                 Severity::Warning,
                 true,
                 RuleOrigin::Check,
                 {{"far_above_rate_factor", 20.0,
                   "warn when the natural frequency (rad/s) exceeds this multiple of the simulation rate (steps/s)"}}};
};

}  // namespace

const Rule& drive_natural_frequency() {
  static const DriveNaturalFrequency rule;
  return rule;
}

}  // namespace assetlint::rules
