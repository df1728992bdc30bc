#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>

#include "physics/gripper.h"
#include "rules/all_rules.h"
#include "rules/consumer_concern.h"
#include "rules/limit_placeholders.h"
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

// A value typed without measuring: at least 100 with one significant digit (100, 200, 3000),
// or above the placeholder bound. It is explained by "nobody measured it" before any unit.
bool round_value(double authored, double placeholder) {
  if (authored >= placeholder) return true;
  if (authored < 100 || authored != std::floor(authored)) return false;
  double leading = authored;
  while (leading >= 10 && std::fmod(leading, 10.0) == 0) leading /= 10;
  return leading < 10;
}

// `value` rounded to `digits` significant digits, when it is that number to a relative 1e-4
// (a float written back by a converter keeps about seven); nullopt otherwise.
std::optional<double> short_number(double value, int digits) {
  if (!(value > 0) || !std::isfinite(value)) return std::nullopt;
  const double scale = std::pow(10.0, digits - 1 - std::floor(std::log10(value)));
  const double rounded = std::round(value * scale) / scale;
  if (std::abs(rounded - value) > 1e-4 * value) return std::nullopt;
  return rounded;
}

// A linear speed that is a short number times 180/π: a limit in rad/s that a converter
// turned into deg/s as if the joint turned (859.4367 = 15 × 180/π).
std::optional<double> degrees_of_radians(const Joint& joint, double authored) {
  if (is_angular(joint.type)) return std::nullopt;
  if (authored == std::round(authored)) return std::nullopt;
  return short_number(authored * std::numbers::pi / 180.0, 3);
}

// What one joint's velocity limit looks like on its own.
struct Verdict {
  const Joint* joint = nullptr;
  std::string range_text;
  double time = 0;                 // seconds to cross the range at the authored limit
  bool fast = false;               // too fast (else too slow)
  bool gripper = false;            // a gripper finger fast by its closing time alone
  std::optional<Unit> reading;     // the unit that makes the crossing time plausible
  double meant = 0;                // the value read in that unit, model units
  double meant_time = 0;
  std::optional<double> from_radians;  // the rad/s value a converter turned into deg/s
};

class UnitsVelocityImplausible final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    if (!max_velocity_read(asset, settings)) return;  // no consumer the asset is judged for bounds speed by it
    const double min_time = rule_option(info_, settings, "min_traversal_time_s");
    const double max_time = rule_option(info_, settings, "max_traversal_time_s");
    const double placeholder = rule_option(info_, settings, "placeholder_velocity");

    // One verdict per value: identical limits in one file were typed once and copied.
    const SharedValues velocities(asset, &Joint::velocity);
    const std::size_t movable_joints = movable_joint_count(asset);
    std::map<std::pair<double, Unit>, std::vector<Verdict>> by_value;
    std::vector<std::pair<double, Unit>> order;
    for (const Joint& joint : asset.joints) {
      auto verdict = judge(asset, joint, settings);
      if (!verdict) continue;
      const auto key = std::pair{joint.velocity->authored, joint.velocity->unit};
      auto& list = by_value[key];
      if (list.empty()) order.push_back(key);
      list.push_back(std::move(*verdict));
    }
    for (const auto& key : order) {
      const auto& verdicts = by_value[key];
      const Verdict& first = verdicts.front();
      const Quantity& velocity = *first.joint->velocity;
      const std::string also = others_note(verdicts);
      const bool exporter_default = first.fast && on_every_kind_of_joint(asset, *first.joint, velocities, movable_joints);
      const std::optional<double> turns = first.fast ? whole_turns_per_second(*first.joint, velocity) : std::nullopt;
      if (first.fast && (round_value(velocity.authored, placeholder) || exporter_default || turns)) {
        // A mimic's own limit is mimic-max-velocity's verdict (Robotiq's 10000 deg/s): one per line.
        if (std::all_of(verdicts.begin(), verdicts.end(), [](const Verdict& v) { return v.joint->is_mimic(); }))
          continue;
        // The same round value on every joint is joint-max-velocity's one placeholder finding per file.
        if (velocity_placeholder_on_every_joint(asset, *first.joint, velocities, movable_joints)) continue;
        Diagnostic& d = out.report(velocity.span, Severity::Info,
                                   fmt::format("velocity limit {} of {} is a placeholder, not a measured limit",
                                               describe(velocity), joint_label(*first.joint)));
        if (turns)
          d.note(fmt::format("At that speed the joint would cross {} in {} (less than {}), but {} is {} turns per "
                             "second, {} × 2π: a round number of turns written for \"no limit\", not a unit mistake.",
                             first.range_text, seconds(first.time), seconds(min_time), describe(velocity),
                             format_number(*turns), format_number(*turns)));
        else if (exporter_default)
          d.note(fmt::format("At that speed the joint would cross {} in {} (less than {}), but every movable joint, "
                             "turning and sliding alike, carries the same {}: a default written without a unit in "
                             "mind, not a unit mistake.",
                             first.range_text, seconds(first.time), seconds(min_time),
                             format_number(velocity.authored)));
        else
          d.note(fmt::format("At that speed the joint would cross {} in {} (less than {}); a round value that fast "
                             "is a default nobody replaced, not a unit mistake.",
                             first.range_text, seconds(first.time), seconds(min_time)));
        if (!also.empty()) d.note(also);
        d.note("Set the joint's real maximum speed from the data sheet; no value is proposed.");
        continue;
      }
      if (first.gripper) {
        report_fast_gripper(verdicts, min_time, settings, out);
        continue;
      }
      if (first.from_radians) {
        report_converted_from_radians(verdicts, also, min_time, out);
        continue;
      }
      const bool any_reading = std::any_of(verdicts.begin(), verdicts.end(), [](const Verdict& v) { return v.reading.has_value(); });
      if (!any_reading) continue;  // fast but explained by no unit: not a unit mistake
      if (report_transmission(asset, verdicts, settings, out)) continue;
      const bool one_reading = std::all_of(verdicts.begin(), verdicts.end(), [&](const Verdict& v) {
        return v.reading && v.reading == first.reading && v.fast == first.fast;
      });
      Diagnostic& d = out.report(velocity.span, fmt::format("velocity limit {} of {} is implausibly {}",
                                                            describe(velocity), joint_label(*first.joint),
                                                            first.fast ? "fast" : "slow"));
      d.note(fmt::format("It would cross {} in {} ({} {}).", first.range_text, seconds(first.time),
                         first.fast ? "less than" : "more than", seconds(first.fast ? min_time : max_time)));
      if (!also.empty()) d.note(also);
      if (!one_reading) {
        d.note("No other unit makes it plausible on every joint that carries it, so no conversion is proposed.");
        continue;
      }
      d.note(fmt::format("Read as {} it is {} and takes {}: it was probably written in {}.",
                         unit_symbol(*first.reading), describe(first.meant, velocity.unit), seconds(first.meant_time),
                         unit_symbol(*first.reading)));
      Fix fix{fmt::format("convert the velocity limit from {} to {}: write {}", unit_symbol(*first.reading),
                          unit_symbol(velocity.unit), describe(first.meant, velocity.unit)),
              Applicability::Unsafe, {}};
      for (const Verdict& v : verdicts) fix.edits.push_back(replace_value(*v.joint->velocity, v.meant, 4));
      d.fix = std::move(fix);
    }
  }

 private:
  std::optional<Verdict> judge(const Asset& asset, const Joint& joint, const Settings& settings) const {
    if (!joint.velocity || !joint.velocity->span.valid() || !is_single_dof(joint.type)) return std::nullopt;
    const Quantity& velocity = *joint.velocity;
    if (velocity.value <= 0) return std::nullopt;
    Verdict v;
    v.joint = &joint;
    double range = 0;
    if (joint.type == JointType::Continuous) {
      range = 2 * std::numbers::pi;
      v.range_text = "one turn";
    } else if (joint.lower && joint.upper && joint.upper->value > joint.lower->value) {
      range = joint.upper->value - joint.lower->value;
      v.range_text = fmt::format("its {} range", describe(range, joint.lower->unit));
    } else {
      return std::nullopt;
    }
    const double min_time = rule_option(info_, settings, "min_traversal_time_s");
    const double max_time = rule_option(info_, settings, "max_traversal_time_s");
    const double speed_bound = rule_option(info_, settings, is_angular(joint.type) ? "max_angular_velocity" : "max_linear_velocity");
    v.time = range / velocity.value;
    if (v.time < min_time && velocity.value > speed_bound) {
      v.fast = true;
    } else if (v.time < min_time && gripper_finger(asset, joint, settings)) {
      // A finger's stroke is short, so a modest-looking speed still slams it shut: no unit is blamed.
      v.fast = v.gripper = true;
      return v;
    } else if (joint.type == JointType::Revolute && range > 2 * std::numbers::pi) {
      // More than a turn of travel on a revolute joint is a stand-in for "free", not a stroke
      // to cross: it is judged slow only if one turn takes too long.
      range = 2 * std::numbers::pi;
      v.range_text = fmt::format("one turn (its {} range is more than a turn)",
                                 describe(joint.upper->value - joint.lower->value, joint.lower->unit));
      v.time = range / velocity.value;
      if (v.time <= max_time) return std::nullopt;
    } else if (v.time <= max_time) {
      return std::nullopt;
    }
    if (v.fast && (v.from_radians = degrees_of_radians(joint, velocity.authored))) return v;
    const std::optional<Unit> reading = v.fast ? faster_reading(velocity.unit) : slower_reading(velocity.unit);
    if (reading) {
      const double meant = to_model_units(velocity.authored, *reading);
      const double meant_time = range / meant;
      if (meant_time >= min_time && meant_time <= max_time) v.reading = reading, v.meant = meant, v.meant_time = meant_time;
    }
    // A mimic's limit that the other reading would put below what its gearing demands is
    // mimic-max-velocity's value: converting it would make that rule raise it back, forever.
    if (v.fast && v.reading) {
      const auto demand = mimic_demand(asset, joint);
      if (demand && v.meant < demand->velocity * (1 - kMimicDemandSlack)) return std::nullopt;
    }
    // Too slow with no unit that explains it is not this rule's business (joint-max-velocity).
    if (!v.fast && !v.reading) return std::nullopt;
    return v;
  }

  // A prismatic finger coupled to another by a mimic (the two fingers of a parallel gripper),
  // unless the [gripper] spec judges its speed (joint-max-velocity).
  static bool gripper_finger(const Asset& asset, const Joint& joint, const Settings& settings) {
    if (joint.type != JointType::Prismatic) return false;
    const Joint* spec = physics::spec_joint(asset, settings);
    const Joint* leader = joint.is_mimic() ? asset.find_joint(joint.mimic->reference.text) : &joint;
    if (leader && leader == spec && physics::required_velocity(settings, *leader)) return false;
    if (joint.is_mimic()) return leader != nullptr;
    for (const Joint& other : asset.joints)
      if (other.is_mimic() && other.mimic->reference.text == joint.name.text) return true;
    return false;
  }

  // Rethink's electric gripper: 5 m/s over 20.8 mm closes in 4 ms; YuMi's 2 m/s over 25 mm
  // in 12.5 ms. Real grippers take a few hundred milliseconds or more.
  void report_fast_gripper(const std::vector<Verdict>& verdicts, double min_time, const Settings& settings,
                           Reporter& out) const {
    const Verdict& first = verdicts.front();
    const Quantity& velocity = *first.joint->velocity;
    Diagnostic& d = out.report(velocity.span, Severity::Warning,
                               fmt::format("gripper finger '{}' closes its stroke in {} at {}", first.joint->name.text,
                                           seconds(first.time), describe(velocity)));
    d.note(fmt::format("At {} the finger crosses {} in {}, under min_traversal_time_s {}; real grippers take hundreds "
                       "of milliseconds (the guide's 2F-85 moves its fingers at 0.15 m/s).",
                       describe(velocity), first.range_text, seconds(first.time), seconds(min_time)));
    d.note(fmt::format("For a gripper finger (a prismatic joint coupled by a mimic) the closing time alone is the test, "
                       "because its stroke is short; other joints must also exceed max_linear_velocity {} m/s.",
                       format_number(rule_option(info_, settings, "max_linear_velocity"))));
    const std::string also = others_note(verdicts);
    if (!also.empty()) d.note(also);
    d.note("The simulated fingers strike the object far harder than the real ones. Take the finger speed from the data "
           "sheet, or give a [gripper] spec (stroke_m, finger_speed_m_s) for joint-max-velocity to judge it; no value is "
           "proposed.");
  }

  // An angular limit that is a round number of turns per second, at least 10 (628.3 rad/s =
  // 100 × 2π; 36000 deg/s): a stand-in for "no limit" written in turns.
  static std::optional<double> whole_turns_per_second(const Joint& joint, const Quantity& velocity) {
    if (!is_angular(joint.type)) return std::nullopt;
    const double turns = velocity.value / (2 * std::numbers::pi);
    if (turns < 10) return std::nullopt;
    return short_number(turns, 1);
  }

  // The same value on every movable joint (at least three), turning and sliding ones among them:
  // one number typed for all of them, read as rad/s on some and m/s on others.
  static bool on_every_kind_of_joint(const Asset& asset, const Joint& joint, const SharedValues& velocities,
                                     std::size_t movable_joints) {
    if (movable_joints < 3 || velocities.others(joint) + 1 < movable_joints) return false;
    bool angular = false, linear = false;
    for (const Joint& other : asset.joints) {
      if (!is_single_dof(other.type) || !other.velocity) continue;
      (is_angular(other.type) ? angular : linear) = true;
    }
    return angular && linear;
  }

  // The linear limit is a rad/s value multiplied by 180/π: the unit is not wrong by a factor
  // that a reading fixes, so no value is proposed.
  static void report_converted_from_radians(const std::vector<Verdict>& verdicts, const std::string& also,
                                            double min_time, Reporter& out) {
    const Verdict& first = verdicts.front();
    const Quantity& velocity = *first.joint->velocity;
    Diagnostic& d = out.report(velocity.span, fmt::format("velocity limit {} of {} is implausibly fast",
                                                          describe(velocity), joint_label(*first.joint)));
    d.note(fmt::format("It would cross {} in {} (less than {}).", first.range_text, seconds(first.time),
                       seconds(min_time)));
    if (!also.empty()) d.note(also);
    d.note(fmt::format("It is {} × 180/π: a limit of {} converted from radians to degrees as if the joint turned. A "
                       "sliding joint's limit is a distance per second, so the conversion only made it {}× larger.",
                       format_number(*first.from_radians, 4), format_number(*first.from_radians, 4),
                       format_number(180.0 / std::numbers::pi, 4)));
    d.note("Write the joint's real maximum speed from the data sheet; no value is proposed.");
  }

  // Another joint whose limits give the same mechanical power, effort × velocity, within
  // power_match_tolerance, at a velocity of its own that is plausible: the same motor behind
  // another transmission (a linkage, a belt, a different gear), not a unit slip.
  struct PowerMatch {
    const Joint* joint = nullptr;
    double power = 0;        // W, this joint's effort × velocity
    double other_power = 0;  // W, the matching joint's
  };
  std::optional<PowerMatch> same_power(const Asset& asset, const Joint& joint, const Settings& settings) const {
    if (!joint.effort || !(joint.effort->value > 0)) return std::nullopt;
    const double tolerance = rule_option(info_, settings, "power_match_tolerance");
    const double power = joint.effort->value * joint.velocity->value;
    std::optional<PowerMatch> best;
    for (const Joint& other : asset.joints) {
      if (&other == &joint || !is_single_dof(other.type) || !other.effort || !other.velocity) continue;
      const double effort = other.effort->value, velocity = other.velocity->value;
      if (!(effort > 0) || !(velocity > 0)) continue;
      // The same limits again is the same joint copied, not a transmission.
      if (std::abs(velocity - joint.velocity->value) <= 0.05 * std::max(velocity, joint.velocity->value)) continue;
      const double other_power = effort * velocity;
      const double mismatch = std::abs(other_power - power) / std::max(other_power, power);
      if (mismatch > tolerance || judge(asset, other, settings)) continue;
      if (!best || mismatch < std::abs(best->other_power - power) / std::max(best->other_power, power))
        best = PowerMatch{&other, power, other_power};
    }
    return best;
  }

  // When every joint carrying the value matches another joint's power, the value is a gear ratio
  // away from that joint's, not a unit away from plausible: an info that names the match, no fix.
  bool report_transmission(const Asset& asset, const std::vector<Verdict>& verdicts, const Settings& settings,
                           Reporter& out) const {
    std::vector<PowerMatch> matches;
    for (const Verdict& v : verdicts) {
      auto match = same_power(asset, *v.joint, settings);
      if (!match) return false;
      matches.push_back(*match);
    }
    const Verdict& first = verdicts.front();
    const PowerMatch& match = matches.front();
    const Joint& joint = *first.joint;
    const Quantity& velocity = *joint.velocity;
    const Joint& other = *match.joint;
    const double ratio = velocity.value / other.velocity->value;
    Diagnostic& d = out.report(velocity.span, Severity::Info,
                               fmt::format("velocity limit {} of {} has the power of '{}': a gear ratio, not a "
                                           "unit",
                                           describe(velocity), joint_label(joint), other.name.text));
    d.note(fmt::format("It would cross {} in {} ({} {}), and read as {} it would take {}; but effort × velocity is "
                       "{} × {} = {} W, and {}'s is {} × {} = {} W: the same motor behind a gear ratio of {}, which "
                       "trades torque for speed.",
                       first.range_text, seconds(first.time), first.fast ? "less than" : "more than",
                       seconds(rule_option(info_, settings, first.fast ? "min_traversal_time_s" : "max_traversal_time_s")),
                       first.reading ? unit_symbol(*first.reading) : "another unit", seconds(first.meant_time),
                       describe(*joint.effort), describe(velocity), format_number(match.power, 4), other.name.text,
                       describe(*other.effort), describe(*other.velocity), format_number(match.other_power, 4),
                       format_number(ratio, 4)));
    d.note(other.velocity->span, fmt::format("'{}': the same power at {}.", other.name.text, describe(*other.velocity)));
    const std::string also = others_note(verdicts);
    if (!also.empty()) d.note(also);
    d.note(first.reading && first.meant > 0
               ? fmt::format("Converting the unit would make it {} ({}× {}) and cripple the joint; no fix is offered. "
                             "Check the speed against the actuator's data sheet.",
                             describe(first.meant, velocity.unit), format_number(std::max(first.meant, velocity.value) / std::min(first.meant, velocity.value), 3),
                             first.fast ? "slower" : "faster")
               : std::string("No unit makes it plausible and no fix is offered. Check the speed against the actuator's "
                             "data sheet."));
    return true;
  }

  static std::string others_note(const std::vector<Verdict>& verdicts) {
    if (verdicts.size() < 2) return {};
    std::string names;
    for (std::size_t i = 1; i < verdicts.size() && i <= 5; ++i)
      names += fmt::format("{}'{}'", i > 1 ? ", " : "", verdicts[i].joint->name.text);
    return fmt::format("The same value is on {} more joint{}: {}{}; this verdict covers them all.", verdicts.size() - 1,
                       verdicts.size() == 2 ? "" : "s", names, verdicts.size() > 6 ? ", …" : "");
  }

  RuleInfo info_{"units-velocity-implausible",
                 "A joint velocity limit that only makes sense in another unit, is a placeholder, or closes a gripper "
                 "implausibly fast",
                 Severity::Warning,
                 true,
                 RuleOrigin::Check,
                 {{"min_traversal_time_s", 0.02, "crossing the full range faster than this is implausible (seconds)"},
                  {"max_traversal_time_s", 10.0, "crossing the full range slower than this is implausible (seconds)"},
                  {"max_angular_velocity", 50.0,
                   "angular limits above this (rad/s) and too fast to be real are reported"},
                  {"max_linear_velocity", 5.0, "linear limits above this (m/s) and too fast to be real are reported"},
                  {"placeholder_velocity", 1000.0,
                   "limits at or above this (rad/s or m/s) are placeholders such as 1000 or 1e9"},
                  {"power_match_tolerance", 0.03,
                   "a limit whose effort × velocity is within this fraction of another joint's (at a plausible velocity "
                   "of its own) is a transmission, not a unit slip"}}};
};

}  // namespace

const Rule& units_velocity_implausible() {
  static const UnitsVelocityImplausible rule;
  return rule;
}

}  // namespace assetlint::rules
