# Adapts tune to physics' drive row (step.h, drive_row.h, articulation.h) once on main.
p='/work/wt-workflow/src/commands/tune_derivation.cpp'; s=open(p).read()
s=s.replace('#include "physics/drive.h"\n','#include "physics/articulation.h"\n#include "physics/drive.h"\n#include "physics/drive_row.h"\n',1)
s=s.replace('''    rate_ = physics::effective_simulation(asset, settings);
    // On the command line, --rate and --position-iterations win over the stage too: tune
    // answers "what if".
    const auto& sim = settings.simulation;
    if (sim.timesteps_per_second && sim.timesteps_per_second->origin.starts_with("--")) {
      rate_.timesteps_per_second = sim.timesteps_per_second->value;
      rate_.rate_origin = sim.timesteps_per_second->origin;
    }
    if (sim.position_iterations && sim.position_iterations->origin.starts_with("--")) {
      rate_.position_iterations = sim.position_iterations->value;
      rate_.iterations_origin = sim.position_iterations->origin;
    }
    d_.simulation = fmt::format("{} solver, {}", rate_.solver, rate_.describe());''','''    rate_ = command_rate(asset, settings);
    d_.simulation = rate_.describe();''')
s=s.replace('#include "commands/tune_derivation.h"\n','#include "commands/tune_derivation.h"\n#include "commands/command_input.h"\n',1)
s=s.replace('''    stiffness_steps();
    armature_steps();''','''    stiffness_steps();
    implicit_step();
    armature_steps();''')
# articulated inertia note in the inertia step
s=s.replace('''    step.result = TuneResult{inertia_.value, symbol(units_.inertia), {}, {}};''','''    step.result = TuneResult{inertia_.value, symbol(units_.inertia), {}, {}};
    step.notes.push_back(articulated_note());''')
s=s.replace('''  TuneInput armature_input() const {''','''  std::string articulated_note() const {
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

  // x = 1/(1 + h·(h·k + d)·r) of PhysX's drive row at the recommended k and d.
  void implicit_step() {
    TuneStep& step = add("implicit_factor", "implicit factor of PhysX's drive row at that drive",
                         "x = 1 / (1 + h·(h·k + d) / I)");
    step.inputs.push_back(TuneInput{"h", "the step the row is built with", rate_.h(), "s", rate_.step_text(), {}});
    bool ok = from_step(step, "stiffness", "k", "stiffness");
    ok = from_step(step, "damping", "d", "damping") && ok;
    const bool articulated = articulated_.known;
    if (articulated)
      step.inputs.push_back(TuneInput{"I", "articulated inertia 1/r", articulated_.value, symbol(units_.inertia),
                                      "the articulation (1/(M⁻¹)ᵢᵢ)", {}});
    else if (auto i = index_of("effective_inertia")) step.inputs.push_back(inertia_input(*i));
    else ok = from_step(step, "effective_inertia", "I", "effective inertia") && ok;
    if (!ok) return;
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

  TuneInput armature_input() const {''')
s=s.replace('''    inertia_ = physics::effective_inertia(asset_, joint_);''','''    inertia_ = physics::effective_inertia(articulation_, asset_, joint_);
    articulated_ = articulation_.inertia(joint_);''')
s=s.replace('''  physics::EffectiveInertia inertia_;
  TuneDerivation d_;''','''  physics::EffectiveInertia inertia_;
  physics::Articulation articulation_{asset_};
  physics::ArticulatedInertia articulated_;
  TuneDerivation d_;''')
s=s.replace('''    s.emplace_back("position_iterations", rate_.position_iterations);''','''    s.emplace_back("position_iterations", rate_.position_iterations);
    s.emplace_back("step_h_s", rate_.h());
    s.emplace_back("articulated_inertia_kgm2",
                   articulated_.known ? std::optional<double>(articulated_.value) : std::nullopt);
    s.emplace_back("implicit_factor", value_of("implicit_factor"));''')
open(p,'w').write(s)

p='/work/wt-workflow/src/commands/command_input.h'; s=open(p).read()
s=s.replace('#include "engine/settings.h"\n','#include "engine/settings.h"\n#include "physics/step.h"\n',1)
s=s.replace('''}  // namespace assetlint::commands''','''// The rate, iterations and solver a command steps at: the asset's (stage, then
// configuration, then PhysX defaults), except that values given on the command line
// (origin "--rate", "--position-iterations", "--solver") win over the stage too.
physics::SimulationRate command_rate(const Asset& asset, const Settings& settings);

}  // namespace assetlint::commands''')
open(p,'w').write(s)
p='/work/wt-workflow/src/commands/command_input.cpp'; s=open(p).read()
s=s.replace('''}  // namespace assetlint::commands''','''physics::SimulationRate command_rate(const Asset& asset, const Settings& settings) {
  physics::SimulationRate rate = physics::effective_simulation(asset, settings);
  const auto& sim = settings.simulation;
  if (sim.timesteps_per_second && sim.timesteps_per_second->origin.starts_with("--")) {
    rate.timesteps_per_second = sim.timesteps_per_second->value;
    rate.rate_origin = sim.timesteps_per_second->origin;
  }
  if (sim.position_iterations && sim.position_iterations->origin.starts_with("--")) {
    rate.position_iterations = sim.position_iterations->value;
    rate.iterations_origin = sim.position_iterations->origin;
  }
  if (sim.solver && sim.solver->origin.starts_with("--")) {
    rate.solver = sim.solver->value == "PGS" ? physics::Solver::PGS : physics::Solver::TGS;
    rate.solver_origin = sim.solver->origin;
  }
  return rate;
}

}  // namespace assetlint::commands''')
open(p,'w').write(s)
