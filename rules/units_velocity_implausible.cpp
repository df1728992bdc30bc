#include <fmt/format.h>

#include <numbers>
#include <optional>

#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// The unit a velocity literal was probably meant in, when the file's unit makes it
// too fast or too slow to be real.
std::optional<Unit> faster_reading(Unit unit) {
  switch (unit) {
    case Unit::RadianPerSecond: return Unit::DegreePerSecond;
    case Unit::MeterPerSecond: return Unit::MillimeterPerSecond;
    default: return std::nullopt;
  }
}
std::optional<Unit> slower_reading(Unit unit) {
  if (unit == Unit::DegreePerSecond) return Unit::RadianPerSecond;
  return std::nullopt;
}

std::string seconds(double t) {
  return t < 1.0 ? format_number(t * 1000.0, 3) + " ms" : format_number(t, 3) + " s";
}

class UnitsVelocityImplausible final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    if (asset.format == SourceFormat::Mjcf) return;  // MuJoCo has no max joint velocity
    const double min_time = rule_option(info_, settings, "min_traversal_time_s");
    const double max_time = rule_option(info_, settings, "max_traversal_time_s");
    const double max_angular = rule_option(info_, settings, "max_angular_velocity");
    const double max_linear = rule_option(info_, settings, "max_linear_velocity");
    const double placeholder = rule_option(info_, settings, "placeholder_velocity");

    for (const Joint& joint : asset.joints) {
      if (!joint.velocity || !joint.velocity->span.valid() || !is_single_dof(joint.type)) continue;
      const Quantity& velocity = *joint.velocity;
      if (velocity.value <= 0) continue;
      double range = 0;
      std::string range_text;
      if (joint.type == JointType::Continuous) {
        range = 2 * std::numbers::pi;
        range_text = "one turn";
      } else if (joint.lower && joint.upper && joint.upper->value > joint.lower->value) {
        range = joint.upper->value - joint.lower->value;
        range_text = fmt::format("its {} range", describe(range, joint.lower->unit));
      } else {
        continue;
      }
      const double time = range / velocity.value;
      const bool angular = is_angular(joint.type);
      const double speed_bound = angular ? max_angular : max_linear;
      auto plausible = [&](double t) { return t >= min_time && t <= max_time; };

      if (time < min_time && velocity.value > speed_bound) {
        if (velocity.value >= placeholder) {
          out.report(velocity.span,
                     fmt::format("velocity limit {} of {} is a placeholder, not a limit: it would cross {} in {}; "
                                 "set the joint's real maximum speed",
                                 describe(velocity), joint_label(joint), range_text, seconds(time)));
          continue;
        }
        report_reading(out, joint, velocity, faster_reading(velocity.unit), range, range_text, time, "fast",
                       plausible, fmt::format("less than {}", seconds(min_time)));
      } else if (time > max_time) {
        report_reading(out, joint, velocity, slower_reading(velocity.unit), range, range_text, time, "slow",
                       plausible, fmt::format("more than {}", seconds(max_time)));
      }
    }
  }

 private:
  template <typename Plausible>
  void report_reading(Reporter& out, const Joint& joint, const Quantity& velocity, std::optional<Unit> reading,
                      double range, const std::string& range_text, double time, std::string_view direction,
                      Plausible plausible, const std::string& bound) const {
    if (!reading) return;
    const double meant = to_model_units(velocity.authored, *reading);
    const double meant_time = range / meant;
    if (!plausible(meant_time)) return;
    Diagnostic& d = out.report(
        velocity.span,
        fmt::format("velocity limit {} of {} is implausibly {}: it would cross {} in {} ({}); read as {} it is {} "
                    "and takes {}, so it was probably written in {}",
                    describe(velocity), joint_label(joint), direction, range_text, seconds(time), bound,
                    unit_symbol(*reading), describe(meant, velocity.unit), seconds(meant_time), unit_symbol(*reading)));
    d.fix = Fix{fmt::format("convert the velocity limit from {} to {}", unit_symbol(*reading), unit_symbol(velocity.unit)),
                Applicability::Unsafe, {replace_value(velocity, meant, 4)}};
  }

  RuleInfo info_{"units-velocity-implausible",
                 "A joint velocity limit that only makes sense in another unit (or is a placeholder)",
                 Severity::Warning,
                 true,
                 RuleOrigin::Check,
                 {{"min_traversal_time_s", 0.02, "crossing the full range faster than this is implausible (seconds)"},
                  {"max_traversal_time_s", 10.0, "crossing the full range slower than this is implausible (seconds)"},
                  {"max_angular_velocity", 50.0,
                   "angular limits above this (rad/s) and too fast to be real are reported"},
                  {"max_linear_velocity", 5.0, "linear limits above this (m/s) and too fast to be real are reported"},
                  {"placeholder_velocity", 1000.0,
                   "limits at or above this (rad/s or m/s) are placeholders such as 1000 or 1e9"}}};
};

}  // namespace

const Rule& units_velocity_implausible() {
  static const UnitsVelocityImplausible rule;
  return rule;
}

}  // namespace assetlint::rules
