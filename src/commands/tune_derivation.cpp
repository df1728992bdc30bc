#include "commands/tune_derivation.h"
#include "commands/command_input.h"

#include <fmt/format.h>

#include <cmath>

#include "physics/articulation.h"
#include "physics/drive.h"
#include "physics/drive_row.h"
#include "physics/gripper.h"
#include "physics/inertia.h"
#include "physics/servo_step.h"
#include "physics/sizing.h"
#include "util/numbers.h"

namespace assetlint::commands {
namespace {

std::string origin_of(const Asset& asset, const WrittenAt& written_at, const Span& model_span) {
  if (!model_span.valid()) return "the asset (default)";
  const Span span = written_at ? written_at(model_span) : model_span;
  const SourceFile& source = asset.source(span.file);
  if (source.binary()) return fmt::format("{} <{}>", source.path(), source.object_at(span.offset));
  return fmt::format("{}:{}", source.path(), span.line);
}

std::string step_origin(std::size_t index) { return fmt::format("step {}", index + 1); }

TuneInput configured(std::string symbol, std::string what, const Configured<double>& value, std::string unit) {
  return TuneInput{std::move(symbol), std::move(what), value.value, std::move(unit), value.origin, {}};
}

// The unit a gain of this joint is authored in by USD (per degree) and its PhysX unit.
struct GainUnits {
  Unit stiffness, damping, stiffness_usd, damping_usd, force, velocity, velocity_usd, inertia, position;
};
GainUnits gain_units(const Joint& joint) {
  if (is_angular(joint.type))
    return {Unit::NewtonMeterPerRadian, Unit::NewtonMeterSecondPerRadian, Unit::NewtonMeterPerDegree,
            Unit::NewtonMeterSecondPerDegree, Unit::NewtonMeter, Unit::RadianPerSecond, Unit::DegreePerSecond,
            Unit::KilogramMeter2, Unit::Radian};
  return {Unit::NewtonPerMeter, Unit::NewtonSecondPerMeter, Unit::NewtonPerMeter, Unit::NewtonSecondPerMeter,
          Unit::Newton, Unit::MeterPerSecond, Unit::MeterPerSecond, Unit::Kilogram, Unit::Meter};
}

std::string symbol(Unit unit) { return std::string(unit_symbol(unit)); }

TuneResult result_in(double value, Unit unit, Unit usd_unit) {
  TuneResult r{value, symbol(unit), std::nullopt, {}};
  if (usd_unit != unit) {
    r.usd_value = from_model_units(value, usd_unit);
    r.usd_unit = symbol(usd_unit);
  }
  return r;
}

// An asset quantity as an input, with the literal as written when its unit differs.
TuneInput quantity_input(const Asset& asset, const WrittenAt& written_at, std::string symbol_text, std::string what,
                         const Quantity& q) {
  TuneInput in{std::move(symbol_text), std::move(what), q.value, symbol(model_unit(q.unit)), {}, {}};
  in.origin = q.span.valid() ? origin_of(asset, written_at, q.span) : "the asset's default";
  if (converts(q.unit) && q.unit != Unit::UsdGearing)
    in.as_written = fmt::format("{} {}", format_number(q.authored, 6), unit_symbol(q.unit));
  // Values from [drives.<joint>] carry no span; Drive::origin names the table.
  return in;
}

class Deriver {
 public:
  Deriver(const std::string& path, const Asset& asset, const WrittenAt& written_at, const Settings& settings,
          const Joint& joint)
      : asset_(asset), written_at_(written_at), settings_(settings), joint_(joint), units_(gain_units(joint)) {
    d_.path = path;
    d_.joint = &joint;
    for (const Joint* member : physics::coupled_joints(asset, joint))
      if (member != &joint) d_.mimics.push_back(member);
    rate_ = command_rate(asset, settings);
    d_.simulation = rate_.describe();
  }

  TuneDerivation run() {
    force_steps();
    velocity_steps();
    inertia_step();
    current_frequency_step();
    stiffness_steps();
    implicit_step();
    armature_steps();
    summary();
    // USD's per-degree equivalents help whoever ports a URDF to USD; an MJCF has no use for them.
    if (asset_.format == SourceFormat::Mjcf)
      for (TuneStep& step : d_.steps)
        if (step.result) step.result->usd_value.reset();
    return std::move(d_);
  }

 private:
  TuneStep& add(std::string name, std::string title, std::string formula) {
    d_.steps.push_back(TuneStep{std::move(name), std::move(title), std::move(formula), {}, {}, {}, {}});
    return d_.steps.back();
  }
  std::size_t last() const { return d_.steps.size() - 1; }
  std::optional<std::size_t> index_of(std::string_view name) const {
    for (std::size_t i = 0; i < d_.steps.size(); ++i)
      if (d_.steps[i].name == name && d_.steps[i].result) return i;
    return std::nullopt;
  }
  std::optional<double> value_of(std::string_view name) const {
    if (auto i = index_of(name)) return d_.steps[*i].result->value;
    return std::nullopt;
  }
  // An earlier step's result as an input, or a missing input pointing at that step.
  bool from_step(TuneStep& step, std::string_view name, std::string symbol_text, std::string what) {
    if (auto i = index_of(name)) {
      const TuneResult& r = *d_.steps[*i].result;
      step.inputs.push_back(TuneInput{std::move(symbol_text), std::move(what), r.value, r.unit, step_origin(*i), {}});
      return true;
    }
    step.missing.push_back(TuneMissing{std::move(what), fmt::format("the result of step '{}'", name), ""});
    return false;
  }
  bool spec(TuneStep& step, const std::optional<Configured<double>>& value, std::string symbol_text, std::string what,
            std::string unit, std::string key, std::string flag) {
    if (value) {
      step.inputs.push_back(configured(std::move(symbol_text), std::move(what), *value, std::move(unit)));
      return true;
    }
    step.missing.push_back(TuneMissing{std::move(what), "[gripper] " + key, std::move(flag)});
    return false;
  }

  void force_steps() {
    const GripperSpec& g = settings_.gripper;
    const auto required = physics::required_force(asset_, settings_, joint_);

    TuneStep& grip = add("grip_force", "grip force (both fingers)", "F = m·g / μ");
    bool ok = spec(grip, g.payload_kg, "m", "payload", "kg", "payload_kg", "--payload-kg");
    grip.inputs.push_back(configured("g", "gravity", g.gravity, "m/s²"));
    ok = spec(grip, g.friction, "μ", "friction coefficient", "", "friction", "--friction") && ok;
    if (ok && required) grip.result = TuneResult{required->grip_force, "N", {}, {}};

    TuneStep& finger = add("force_per_finger", "force per finger", "F_finger = F / 2");
    if (from_step(finger, "grip_force", "F", "grip force") && required)
      finger.result = TuneResult{required->per_finger, "N", {}, {}};

    const bool angular = is_angular(joint_.type);
    TuneStep& torque = add("torque_per_joint", angular ? "torque per joint" : "force per joint",
                           angular ? "τ = F_finger · r, rounded up to a multiple of the margin"
                                   : "F_joint = F_finger (a prismatic finger: no lever arm)");
    ok = from_step(torque, "force_per_finger", "F_finger", "force per finger");
    if (angular) ok = spec(torque, g.lever_arm_m, "r", "lever arm", "m", "lever_arm_m", "--lever-arm-m") && ok;
    if (g.torque_margin) torque.inputs.push_back(configured("margin", "torque margin", *g.torque_margin, "N·m"));
    if (ok && required) {
      const double per_joint = angular ? required->rounded_torque : required->per_finger;
      torque.result = TuneResult{per_joint, symbol(units_.force), {}, {}};
      if (angular && required->rounded_torque != required->per_joint_torque)
        torque.notes.push_back(fmt::format("{} N·m rounded up to a multiple of {} N·m: {} N·m.",
                                           format_number(required->per_joint_torque, 3), format_number(g.torque_margin->value),
                                           format_number(required->rounded_torque, 4)));
      else if (!g.torque_margin && angular)
        torque.notes.push_back("Not rounded: [gripper] torque_margin (--torque-margin) is not set.");
    }

    TuneStep& total = add("max_drive_force", "max drive force on the driven joint",
                          "τ_max = Σ|gearing| · τ (the joint, gearing 1, and every mimic it drives)");
    ok = from_step(total, "torque_per_joint", "τ", angular ? "torque per joint" : "force per joint");
    const double gearing_sum = required ? required->gearing_sum : static_cast<double>(d_.mimics.size() + 1);
    total.inputs.push_back(TuneInput{"Σ|gearing|", "joints moved by the drive, each by its gearing", gearing_sum, "",
                                     fmt::format("the asset: '{}' and {} mimic joint{}", joint_.name.text,
                                                 d_.mimics.size(), d_.mimics.size() == 1 ? "" : "s"),
                                     {}});
    if (ok && required) {
      total.result = TuneResult{required->required, symbol(units_.force), {}, {}};
      if (const Quantity* current = current_max_force())
        total.notes.push_back(fmt::format("The asset has {} {} ({}).", format_number(current->value, 4),
                                          unit_symbol(units_.force),
                                          current->span.valid() ? origin_of(asset_, written_at_, current->span)
                                                                : drive_settings_origin("max_force")));
    }
  }

  const Quantity* current_max_force() const {
    if (joint_.drive && joint_.drive->max_force && std::isfinite(joint_.drive->max_force->value))
      return &*joint_.drive->max_force;
    if (joint_.effort) return &*joint_.effort;
    return nullptr;
  }

  void velocity_steps() {
    const GripperSpec& g = settings_.gripper;
    TuneStep& close = add("close_time", "close time", "t = (stroke / 2) / v_finger");
    bool ok = spec(close, g.stroke_m, "stroke", "stroke (both fingers)", "m", "stroke_m", "--stroke-m");
    ok = spec(close, g.finger_speed_m_s, "v_finger", "finger speed", "m/s", "finger_speed_m_s", "--finger-speed-m-s") &&
         ok;
    if (ok) close.result = TuneResult{physics::close_time(g.stroke_m->value, g.finger_speed_m_s->value), "s", {}, {}};

    TuneStep& velocity = add("max_joint_velocity", "max joint velocity", "ω = (upper − lower) / t");
    ok = true;
    if (joint_.lower && joint_.upper && std::isfinite(joint_.lower->value) && std::isfinite(joint_.upper->value)) {
      velocity.inputs.push_back(quantity_input(asset_, written_at_, "lower", "lower limit", *joint_.lower));
      velocity.inputs.push_back(quantity_input(asset_, written_at_, "upper", "upper limit", *joint_.upper));
    } else {
      velocity.missing.push_back(TuneMissing{"the joint's finite range", "the joint's lower and upper limits", ""});
      ok = false;
    }
    ok = from_step(velocity, "close_time", "t", "close time") && ok;
    if (!ok) return;
    const auto required = physics::required_velocity(settings_, joint_);
    if (!required) {
      velocity.missing.push_back(TuneMissing{"a range with upper > lower", "the joint's lower and upper limits", ""});
      return;
    }
    velocity.result = result_in(required->velocity, units_.velocity, units_.velocity_usd);
    if (!d_.mimics.empty())
      velocity.notes.push_back(
          "None on the mimic joints: leave their max joint velocity unset, the gearing bounds them through this one.");
  }

  void inertia_step() {
    TuneStep& step = add("effective_inertia", "effective inertia (the guide's lighter link)",
                         "I = I_com + m·d² of the lightest link over the joint and its mimics, + armature");
    inertia_ = physics::effective_inertia(articulation_, asset_, joint_);
    articulated_ = articulation_.inertia(joint_);
    if (!inertia_.known) {
      std::string links;
      for (const auto& name : inertia_.unknown_links) links += (links.empty() ? "'" : ", '") + name + "'";
      step.missing.push_back(TuneMissing{"mass and inertia of a moving link",
                                         links.empty() ? "the asset's links" : "the asset's links " + links, ""});
      return;
    }
    const Link& link = *inertia_.link;
    const Joint& via = *inertia_.via;
    const Inertial& inertial = *link.inertial;
    const bool angular = is_angular(via.type);
    if (angular) {
      const int side = &link == asset_.find_link(via.parent.text) ? 0 : 1;
      const auto& frame = via.frame_in_link[static_cast<std::size_t>(side)];
      const double distance = physics::axis_distance(inertial, frame, via.axis);
      const double about_axis = physics::inertia_about_axis(inertial, frame, via.axis);
      const double m = inertial.mass.value;
      const std::string where = origin_of(asset_, written_at_, inertial.span.valid() ? inertial.span : link.span);
      step.inputs.push_back(TuneInput{"I_com", fmt::format("inertia of '{}' about its COM along the axis of '{}'",
                                                           link.name.text, via.name.text),
                                      about_axis - m * distance * distance, "kg·m²",
                                      origin_of(asset_, written_at_, inertial.inertia_span.valid() ? inertial.inertia_span : link.span),
                                      {}});
      step.inputs.push_back(TuneInput{"m", fmt::format("mass of '{}'", link.name.text), m, "kg",
                                      origin_of(asset_, written_at_, inertial.mass.span.valid() ? inertial.mass.span : link.span),
                                      {}});
      step.inputs.push_back(TuneInput{"d", "distance of its COM from the axis", distance, "m", where, {}});
    } else {
      step.inputs.push_back(TuneInput{"m", fmt::format("mass of '{}'", link.name.text), inertial.mass.value, "kg",
                                      origin_of(asset_, written_at_, inertial.mass.span), {}});
    }
    if (joint_.armature)
      step.inputs.push_back(armature_input());
    step.result = TuneResult{inertia_.value, symbol(units_.inertia), {}, {}};
    step.notes.push_back(articulated_note());
    step.notes.push_back(fmt::format("Lighter link: '{}' on joint '{}' ({} {}).", link.name.text, via.name.text,
                                     format_number(inertia_.link_inertia, 3), unit_symbol(units_.inertia)));
    if (!inertia_.unknown_links.empty()) {
      std::string links;
      for (const auto& name : inertia_.unknown_links) links += (links.empty() ? "'" : ", '") + name + "'";
      step.notes.push_back(fmt::format("Links without authored mass or inertia were left out: {}.", links));
    }
  }

  std::string articulated_note() const {
    if (articulated_.known)
      return fmt::format("The drive row sees the articulated inertia 1/r = {} {} (the other joints free): the guide's "
                         "lighter link is a conservative stand-in for the natural-frequency check.",
                         format_number(articulated_.value, 3), unit_symbol(units_.inertia));
    std::string links;
    for (const auto& name : articulated_.unknown_links) links += (links.empty() ? "'" : ", '") + name + "'";
    return fmt::format("The articulated inertia is unknown{}.",
                       links.empty() ? (articulated_.reason.empty() ? std::string() : ": " + articulated_.reason)
                                     : " (unauthored mass: " + links + ")");
  }

  // k and d from the earlier steps and the inertia the step is judged on (the articulated
  // one when known, else the lighter link); false when one of them is missing.
  bool drive_inputs(TuneStep& step) {
    bool ok = from_step(step, "stiffness", "k", "stiffness");
    ok = from_step(step, "damping", "d", "damping") && ok;
    if (articulated_.known)
      step.inputs.push_back(TuneInput{"I", "articulated inertia 1/r", articulated_.value, symbol(units_.inertia),
                                      "the articulation (1/(M⁻¹)ᵢᵢ)", {}});
    else if (auto i = index_of("effective_inertia")) step.inputs.push_back(inertia_input(*i));
    else ok = from_step(step, "effective_inertia", "I", "effective inertia") && ok;
    return ok;
  }

  // MJCF: one MuJoCo step of the servo at the recommended k and d, under the file's
  // integrator (physics/servo_step.h); there is no PhysX row to attenuate the spring.
  void mujoco_step() {
    TuneStep& step = add("mujoco_step", "one MuJoCo step of that servo",
                         fmt::format("spectral radius of (q, q̇) → (q′, q̇′) under {}, < 1 is stable",
                                     physics::integrator_name(rate_.integrator)));
    step.inputs.push_back(TuneInput{"h", "timestep", rate_.h(), "s", rate_.step_text(), {}});
    const bool articulated = articulated_.known;
    if (!drive_inputs(step)) return;
    const double k = *value_of("stiffness"), d = *value_of("damping");
    const double inertia = articulated ? articulated_.value : inertia_.value;
    const auto radius = [&](double i) {
      return physics::servo_step(rate_.integrator, rate_.h(), physics::mujoco_servo(joint_, k, d, i)).spectral_radius();
    };
    step.result = TuneResult{radius(inertia), "", {}, {}};
    step.notes.push_back(fmt::format("{} ({}) takes the spring explicitly; on the guide's lighter link ({} {}) the "
                                     "spectral radius is {}, h·nf = {}.",
                                     physics::integrator_name(rate_.integrator), rate_.integrator_origin,
                                     format_number(inertia_.value, 3), unit_symbol(units_.inertia),
                                     format_number(radius(inertia_.value), 3),
                                     format_number(rate_.h() * physics::natural_frequency(k, inertia_.value), 3)));
    if (step.result->value >= 1) {
      const double implicit =
          physics::servo_step(physics::MujocoIntegrator::ImplicitFast, rate_.h(), physics::mujoco_servo(joint_, k, d, inertia))
              .spectral_radius();
      const bool implicit_helps = implicit < 1 && rate_.integrator != physics::MujocoIntegrator::ImplicitFast;
      step.notes.push_back(fmt::format("It grows every step: MuJoCo needs a smaller <option timestep>{} more armature{}.",
                                       implicit_helps ? "," : " or",
                                       implicit_helps ? fmt::format(", or integrator=\"implicitfast\" (spectral radius {})",
                                                                    format_number(implicit, 3))
                                                      : std::string()));
    }
    if (auto delta = target_delta_value()) {
      const double spring = k * *delta;
      const auto force = value_of("max_drive_force");
      const bool capped = force && *force < spring;
      step.notes.push_back(fmt::format("Held Δ before the target by a contact, the servo pushes {} {} (k·Δ{}): "
                                       "MuJoCo applies the actuator force as written, with no row to attenuate it.",
                                       format_number(capped ? *force : spring, 3), unit_symbol(units_.force),
                                       capped ? ", capped at the force range" : ""));
    }
    if (!articulated) step.notes.push_back(articulated_note());
  }

  // x = 1/(1 + h·(h·k + d)·r) of PhysX's drive row at the recommended k and d.
  void implicit_step() {
    if (rate_.solver == physics::Solver::MuJoCo) return mujoco_step();
    TuneStep& step = add("implicit_factor", "implicit factor of PhysX's drive row at that drive",
                         "x = 1 / (1 + h·(h·k + d) / I)");
    step.inputs.push_back(TuneInput{"h", "the step the row is built with", rate_.h(), "s", rate_.step_text(), {}});
    const bool articulated = articulated_.known;
    if (!drive_inputs(step)) return;
    const double k = *value_of("stiffness"), d = *value_of("damping");
    const DriveType type = joint_.drive ? joint_.drive->type : DriveType::Force;
    const auto row = physics::drive_row(rate_, k, d, type, articulated ? articulated_.value : inertia_.value);
    step.result = TuneResult{row.x(), "", {}, {}};
    const auto guide_row = physics::drive_row(rate_, k, d, type, inertia_.value);
    step.notes.push_back(fmt::format("On the guide's lighter link ({} {}): x = {}; h·nf = {}.",
                                     format_number(inertia_.value, 3), unit_symbol(units_.inertia),
                                     format_number(guide_row.x(), 3),
                                     format_number(rate_.h() * physics::natural_frequency(k, inertia_.value), 3)));
    if (auto delta = target_delta_value()) {
      physics::ForceLimit limit;
      if (auto force = value_of("max_drive_force")) limit.max_force = *force;
      const auto hold = physics::static_hold(row, *delta, limit);
      step.notes.push_back(fmt::format(
          "Held {} before the target by a contact, the drive pushes {} {} of k·Δ = {} {} ({}{}).",
          "Δ", format_number(hold.force, 3), unit_symbol(units_.force), format_number(hold.spring, 3),
          unit_symbol(units_.force), physics::solver_name(rate_.solver),
          hold.capped ? ", capped at max force" : ""));
    }
    if (!articulated) step.notes.push_back(articulated_note());
  }

  std::optional<double> target_delta_value() const {
    for (const TuneStep& s : d_.steps)
      if (s.name == "stiffness")
        for (const TuneInput& in : s.inputs)
          if (in.symbol == "Δ") return in.value;
    return std::nullopt;
  }

  TuneInput armature_input() const {
    TuneInput in = quantity_input(asset_, written_at_, "armature", "armature", *joint_.armature);
    if (!joint_.armature->span.valid()) in.origin = drive_settings_origin("armature");
    return in;
  }

  // Where a [drives.<joint>] value came from, for values the asset does not author.
  std::string drive_settings_origin(std::string_view key) const {
    auto it = settings_.drives.find(joint_.name.text);
    if (it == settings_.drives.end()) return "the asset's default";
    const DriveSettings& drive = it->second;
    const auto pick = [&](const std::optional<Configured<double>>& v) { return v ? v->origin : drive.origin; };
    if (key == "stiffness") return pick(drive.stiffness);
    if (key == "damping") return pick(drive.damping);
    if (key == "armature") return pick(drive.armature);
    if (key == "max_force") return pick(drive.max_force);
    if (key == "gear_ratio") return pick(drive.gear_ratio);
    return drive.origin;
  }

  TuneInput inertia_input(std::size_t index) const {
    return TuneInput{"I", "effective inertia", inertia_.value, symbol(units_.inertia), step_origin(index), {}};
  }

  // "9034 rad/s is 36.1× the 250 Hz rate and below 250 × 64 = 16000 rad/s, the guide's bound"
  std::string against_rate(double nf) const {
    const double bound = rate_.frequency_bound();
    std::string what;
    switch (rate_.solver) {
      case physics::Solver::TGS:
        what = fmt::format("{} × {} = {} rad/s, the guide's over-optimistic bound (rate × position iterations)",
                           format_number(rate_.timesteps_per_second), rate_.iterations(), format_number(bound, 4));
        break;
      case physics::Solver::PGS:
        what = fmt::format("{} rad/s, the rate: PGS builds the drive row with the whole frame", format_number(bound, 4));
        break;
      case physics::Solver::MuJoCo:
        what = fmt::format("1/timestep = {} rad/s: MuJoCo steps the spring once per timestep", format_number(bound, 4));
        break;
    }
    const std::string verdict =
        nf <= bound ? ""
        : rate_.solver == physics::Solver::MuJoCo
            ? "; unless the integrator damps it stably (drive-natural-frequency judges that), prone to fail"
            : ": prone to fail";
    return fmt::format("{} rad/s is {}× the {} Hz rate and {} {}{}", format_number(nf, 4),
                       format_number(nf / rate_.timesteps_per_second, 3), format_number(rate_.timesteps_per_second),
                       nf > bound ? "above" : "within", what, verdict);
  }

  void current_frequency_step() {
    TuneStep& step = add("current_natural_frequency", "natural frequency of the current drive", "nf = sqrt(k / I)");
    bool ok = true;
    const Drive* drive = joint_.drive ? &*joint_.drive : nullptr;
    if (drive && drive->stiffness && drive->stiffness->value > 0 && std::isfinite(drive->stiffness->value)) {
      TuneInput k = quantity_input(asset_, written_at_, "k", "current stiffness", *drive->stiffness);
      if (!drive->stiffness->span.valid()) k.origin = drive_settings_origin("stiffness");
      k.unit = symbol(units_.stiffness);
      step.inputs.push_back(std::move(k));
    } else {
      step.missing.push_back(TuneMissing{"the current drive stiffness",
                                         fmt::format("the asset's drive stiffness, or [drives.{}] stiffness",
                                                     joint_.name.text),
                                         ""});
      ok = false;
    }
    if (auto i = index_of("effective_inertia")) step.inputs.push_back(inertia_input(*i));
    else {
      step.missing.push_back(TuneMissing{"effective inertia", "the result of step 'effective_inertia'", ""});
      ok = false;
    }
    if (!ok) return;
    const double nf = physics::natural_frequency(drive->stiffness->value, inertia_.value);
    step.result = TuneResult{nf, "rad/s", {}, {}};
    step.notes.push_back(against_rate(nf) + ".");
  }

  void stiffness_steps() {
    const bool angular = is_angular(joint_.type);
    TuneStep& k = add("stiffness", "stiffness from max force and target delta", "k = τ_max / Δ");
    bool ok = true;
    if (auto i = index_of("max_drive_force")) {
      const TuneResult& r = *d_.steps[*i].result;
      k.inputs.push_back(TuneInput{"τ_max", "max drive force", r.value, r.unit, step_origin(*i), {}});
    } else if (const Quantity* current = current_max_force(); current && current->value > 0) {
      TuneInput in = quantity_input(asset_, written_at_, "τ_max", "max drive force (the asset's; no payload spec)", *current);
      if (!current->span.valid()) in.origin = drive_settings_origin("max_force");
      in.unit = symbol(units_.force);
      k.inputs.push_back(std::move(in));
    } else {
      k.missing.push_back(TuneMissing{"max drive force", "the payload spec of step 'max_drive_force'", ""});
      ok = false;
    }
    if (angular) {
      const auto& delta = settings_.gripper.target_delta_deg;
      k.inputs.push_back(TuneInput{"Δ", "target delta", radians_from_degrees(delta.value), "rad", delta.origin,
                                   fmt::format("{} deg", format_number(delta.value))});
    } else {
      k.missing.push_back(TuneMissing{"a target delta in metres", "[gripper] target_delta_deg is an angle", ""});
      ok = false;
    }
    if (ok) {
      const double stiffness = physics::stiffness_for_force(k.inputs[0].value, k.inputs[1].value);
      k.result = result_in(stiffness, units_.stiffness, units_.stiffness_usd);
      k.notes.push_back("The spring alone still delivers the max force this far before the target.");
    }

    TuneStep& nf = add("natural_frequency", "natural frequency at that stiffness", "nf = sqrt(k / I)");
    ok = from_step(nf, "stiffness", "k", "stiffness");
    if (auto i = index_of("effective_inertia")) nf.inputs.push_back(inertia_input(*i));
    else ok = from_step(nf, "effective_inertia", "I", "effective inertia") && ok;
    if (ok) {
      const double value = physics::natural_frequency(*value_of("stiffness"), inertia_.value);
      nf.result = TuneResult{value, "rad/s", {}, {}};
      nf.notes.push_back(against_rate(value) + ".");
    }

    TuneStep& damping = add("damping", "damping for damping ratio 1", "d = 2·ζ·sqrt(k·I), ζ = 1");
    ok = from_step(damping, "stiffness", "k", "stiffness");
    if (auto i = index_of("effective_inertia")) damping.inputs.push_back(inertia_input(*i));
    else ok = from_step(damping, "effective_inertia", "I", "effective inertia") && ok;
    if (ok) {
      const double value = physics::damping_for_ratio(1.0, *value_of("stiffness"), inertia_.value);
      damping.result = result_in(value, units_.damping, units_.damping_usd);
      damping.notes.push_back("Critical damping: the target is reached without overshoot; recompute it whenever k changes.");
    }
  }

  void armature_steps() {
    if (!joint_.armature || joint_.armature->value <= 0 || !inertia_.known) return;
    const double armature = joint_.armature->value;
    TuneStep& step = add("armature_natural_frequency", "natural frequency with the armature",
                         "nf = sqrt(k / (I_link + armature))");
    bool ok = from_step(step, "stiffness", "k", "stiffness");
    step.inputs.push_back(TuneInput{"I_link", "lighter link", inertia_.link_inertia, symbol(units_.inertia),
                                    step_origin(*index_of("effective_inertia")), {}});
    step.inputs.push_back(armature_input());
    if (ok) {
      const double k = *value_of("stiffness");
      const double with = physics::natural_frequency(k, inertia_.link_inertia + armature);
      step.result = TuneResult{with, "rad/s", {}, {}};
      step.notes.push_back(fmt::format("Without the armature: {} rad/s; {}.",
                                       format_number(physics::natural_frequency(k, inertia_.link_inertia), 4),
                                       against_rate(with)));
      step.notes.push_back(fmt::format("The armature is {}× the lighter link: a motor datasheet should justify it.",
                                       format_number(armature / inertia_.link_inertia, 3)));
    }

    TuneStep& rotor = add("rotor_inertia", "rotor inertia the armature implies", "I_rotor = armature / G²");
    rotor.inputs.push_back(armature_input());
    auto it = settings_.drives.find(joint_.name.text);
    if (it == settings_.drives.end() || !it->second.gear_ratio) {
      rotor.missing.push_back(TuneMissing{"gear ratio", fmt::format("[drives.{}] gear_ratio", joint_.name.text), ""});
      return;
    }
    rotor.inputs.push_back(TuneInput{"G", "gear ratio", it->second.gear_ratio->value, "", it->second.gear_ratio->origin, {}});
    rotor.result = TuneResult{physics::rotor_inertia_for_armature(armature, it->second.gear_ratio->value),
                              symbol(units_.inertia), {}, {}};
    rotor.notes.push_back("Compare it with the motor datasheet's rotor inertia.");
  }

  void summary() {
    auto& s = d_.summary;
    s.emplace_back("grip_force_n", value_of("grip_force"));
    s.emplace_back("force_per_finger_n", value_of("force_per_finger"));
    s.emplace_back("torque_per_joint_nm", value_of("torque_per_joint"));
    s.emplace_back("max_drive_force_nm", value_of("max_drive_force"));
    s.emplace_back("close_time_s", value_of("close_time"));
    s.emplace_back("max_joint_velocity_rad_s", value_of("max_joint_velocity"));
    s.emplace_back("effective_inertia_kgm2", value_of("effective_inertia"));
    s.emplace_back("current_natural_frequency_rad_s", value_of("current_natural_frequency"));
    s.emplace_back("stiffness_nm_per_rad", value_of("stiffness"));
    s.emplace_back("natural_frequency_rad_s", value_of("natural_frequency"));
    s.emplace_back("damping_nms_per_rad", value_of("damping"));
    s.emplace_back("sim_rate_hz", rate_.timesteps_per_second);
    s.emplace_back("position_iterations", rate_.position_iterations);
    s.emplace_back("step_h_s", rate_.h());
    s.emplace_back("articulated_inertia_kgm2",
                   articulated_.known ? std::optional<double>(articulated_.value) : std::nullopt);
    s.emplace_back("implicit_factor", value_of("implicit_factor"));
    if (index_of("armature_natural_frequency") || joint_.armature) {
      s.emplace_back("armature_natural_frequency_rad_s", value_of("armature_natural_frequency"));
      s.emplace_back("rotor_inertia_kgm2", value_of("rotor_inertia"));
    }
    TuneRecommendation& r = d_.recommended;
    r.max_force = value_of("max_drive_force");
    r.max_velocity = value_of("max_joint_velocity");
    r.stiffness = value_of("stiffness");
    r.damping = value_of("damping");
  }

  const Asset& asset_;
  const WrittenAt& written_at_;
  const Settings& settings_;
  const Joint& joint_;
  GainUnits units_;
  physics::SimulationRate rate_;
  physics::EffectiveInertia inertia_;
  physics::Articulation articulation_{asset_};
  physics::ArticulatedInertia articulated_;
  TuneDerivation d_;
};

}  // namespace

Settings with_spec_flags(Settings settings, const SpecFlags& flags) {
  GripperSpec& g = settings.gripper;
  const auto set = [](std::optional<Configured<double>>& field, const std::optional<double>& value, const char* flag) {
    if (value) field = Configured<double>{*value, flag};
  };
  set(g.payload_kg, flags.payload_kg, "--payload-kg");
  set(g.friction, flags.friction, "--friction");
  set(g.lever_arm_m, flags.lever_arm_m, "--lever-arm-m");
  set(g.finger_speed_m_s, flags.finger_speed_m_s, "--finger-speed-m-s");
  set(g.stroke_m, flags.stroke_m, "--stroke-m");
  set(g.torque_margin, flags.torque_margin, "--torque-margin");
  if (flags.gravity) g.gravity = Configured<double>{*flags.gravity, "--gravity"};
  if (flags.target_delta_deg) g.target_delta_deg = Configured<double>{*flags.target_delta_deg, "--target-delta-deg"};
  set(settings.simulation.timesteps_per_second, flags.rate, "--rate");
  set(settings.simulation.position_iterations, flags.position_iterations, "--position-iterations");
  return settings;
}

const Joint* tune_joint(const Asset& asset, const Settings& settings, const std::optional<std::string>& requested,
                        std::string& error, const char* joint_flag) {
  std::string name;
  std::string source;
  if (requested) {
    name = *requested;
    source = "--joint";
  } else if (settings.gripper.driven_joint) {
    name = settings.gripper.driven_joint->value;
    source = fmt::format("[gripper] driven_joint ({})", settings.gripper.driven_joint->origin);
  }
  if (!name.empty()) {
    const Joint* joint = asset.find_joint(name);
    if (!joint) {
      error = fmt::format("{} names joint '{}', which the asset does not have", source, name);
      return nullptr;
    }
    if (joint->is_mimic()) {
      error = fmt::format("{} names '{}', a mimic of '{}': name the joint it follows", source, name,
                          joint->mimic->reference.text);
      return nullptr;
    }
    if (!is_single_dof(joint->type)) {
      error = fmt::format("{} names '{}', a {} joint: tune a revolute or prismatic joint", source, name,
                          joint_type_name(joint->type));
      return nullptr;
    }
    return joint;
  }
  std::vector<const Joint*> driven, movable;
  for (const Joint& joint : asset.joints) {
    if (!is_single_dof(joint.type) || joint.is_mimic()) continue;
    movable.push_back(&joint);
    if (joint.drive) driven.push_back(&joint);
  }
  const auto& candidates = driven.empty() ? movable : driven;
  if (candidates.size() == 1) return candidates.front();
  if (candidates.empty()) {
    error = "the asset has no driven joint (no revolute or prismatic joint that is not a mimic)";
    return nullptr;
  }
  std::string list;
  for (const Joint* joint : candidates) list += (list.empty() ? "'" : ", '") + joint->name.text + "'";
  error = fmt::format("{} joints could be the driven one ({}); name it with {}[gripper] driven_joint in asset-lint.toml",
                      candidates.size(), list, joint_flag ? fmt::format("{} or ", joint_flag) : std::string());
  return nullptr;
}

TuneDerivation derive(const std::string& path, const ReadResult& read, const Settings& settings, const Joint& joint) {
  return Deriver(path, read.asset, read.written_at, settings, joint).run();
}

}  // namespace assetlint::commands
