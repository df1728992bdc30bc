#include "commands/simulate.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>
#include <fstream>

#include "commands/command_input.h"
#include "commands/exit_status.h"
#include "commands/simulate_report.h"
#include "commands/simulate_run.h"
#include "commands/tune_derivation.h"
#include "physics/articulation.h"
#include "physics/drive.h"
#include "physics/sizing.h"
#include "util/numbers.h"

namespace assetlint::commands {
namespace {

// A flag's number, any sign but finite.
std::optional<double> finite_flag(const std::string& flag, const std::string& text, std::string& error) {
  const auto value = parse_double(text);
  if (!value || !std::isfinite(*value)) {
    error = fmt::format("{} must be a finite number, got '{}'", flag, text);
    return std::nullopt;
  }
  return value;
}

}  // namespace

int run_simulate(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"asset-lint simulate: steps the driven joint as PhysX's articulation drive (or, for MJCF, MuJoCo) does, beside "
               "the explicit spring at the same step",
               "asset-lint simulate"};
  std::string path, format = "text", solver, inertia_choice;
  std::optional<std::string> joint_name, config, from_text, to_text, load_text, duration_text = std::string("1"), plot,
      csv, rate_text, iterations_text;
  bool from_open = false, to_closed = false;
  app.add_option("asset", path, "The .urdf, .xacro, .usda or MJCF .xml file")->required();
  app.add_option("--joint", joint_name, "The driven joint (default: [gripper] driven_joint, else the only driven joint)");
  auto* from = app.add_option("--from", from_text, "Start position: degrees (revolute) or metres (prismatic)");
  auto* open = app.add_flag("--from-open", from_open, "Start at the lower limit (the default)");
  auto* to = app.add_option("--to", to_text, "Target: degrees (revolute) or metres (prismatic)");
  auto* closed = app.add_flag("--to-closed", to_closed, "Target the upper limit (the default)");
  from->excludes(open);
  to->excludes(closed);
  app.add_option("--load-torque", load_text, "A constant load against the motion, N·m (N for prismatic joints)");
  app.add_option("--duration", duration_text, "Simulated time, s (default 1)");
  app.add_option("--plot", plot, "Write an SVG plot of position and force over time");
  app.add_option("--csv", csv, "Write the time series as CSV");
  app.add_option("--rate", rate_text, "Simulation rate, steps per second (wins over the stage and [simulation])");
  app.add_option("--position-iterations", iterations_text, "Solver position iterations, 1 to 255");
  app.add_option("--solver", solver, "TGS or PGS (wins over the stage and [simulation])")
      ->check(CLI::IsMember({"TGS", "PGS"}));
  app.add_option("--inertia", inertia_choice,
                 "The inertia to step: mechanism (Jᵀ·M·J over the joint and its mimics; the default when it has "
                 "mimics), articulation (1/r, what PhysX's row sees for the joint alone; the default otherwise) or "
                 "lighter-link (the guide's estimate)")
      ->check(CLI::IsMember({"mechanism", "articulation", "lighter-link"}));
  app.add_option("--config", config, "Use this asset-lint.toml (default: the nearest one above the asset)");
  app.add_option("--output-format", format, "text or json")->check(CLI::IsMember({"text", "json"}));
  CompositionScope scope;
  add_scope_options(app, scope);
  if (auto status = parse_command(app, args, "simulate", out, err)) return *status;
  const auto fail = [&](const std::string& message) {
    err << "asset-lint simulate: error: " << message << "\n";
    return kExitError;
  };
  std::string error;
  SpecFlags flags;
  if (rate_text && !(flags.rate = positive_flag("--rate", *rate_text, error))) return fail(error);
  if (iterations_text) {
    flags.position_iterations = positive_flag("--position-iterations", *iterations_text, error);
    if (!flags.position_iterations) return fail(error);
    if (*flags.position_iterations != std::floor(*flags.position_iterations) || *flags.position_iterations > 255)
      return fail(fmt::format("--position-iterations must be a whole number from 1 to 255, got '{}'", *iterations_text));
  }
  const auto duration = positive_flag("--duration", *duration_text, error);
  if (!duration) return fail(error);
  std::optional<double> load;
  if (load_text && !(load = positive_flag("--load-torque", *load_text, error, true))) return fail(error);
  std::optional<double> from_value, to_value;
  if (from_text && !(from_value = finite_flag("--from", *from_text, error))) return fail(error);
  if (to_text && !(to_value = finite_flag("--to", *to_text, error))) return fail(error);

  CommandAsset input = load_command_asset(path, config, scope);
  if (input.error) return fail(*input.error);
  Settings settings = with_spec_flags(input.settings, flags);
  if (!solver.empty()) settings.simulation.solver = Configured<std::string>{solver, "--solver"};
  const Asset& asset = input.loaded.read.asset;
  const Joint* joint = tune_joint(asset, settings, joint_name, error);
  if (!joint) return fail(fmt::format("{}: {}", path, error));
  const bool angular = is_angular(joint->type);
  const Drive* drive = joint->drive ? &*joint->drive : nullptr;
  if (!drive || !drive->stiffness || !(drive->stiffness->value > 0) || !std::isfinite(drive->stiffness->value))
    return fail(fmt::format("{}: joint '{}' has no drive stiffness: author one in the asset or set [drives.{}] "
                            "stiffness (`asset-lint tune --apply` derives it)",
                            path, joint->name.text, joint->name.text));

  // Positions: the joint's range unless given.
  const auto position = [&](const std::optional<double>& given, const OptQuantity& limit, const char* flag)
      -> std::optional<double> {
    if (given) return angular ? radians_from_degrees(*given) : *given;
    if (limit && std::isfinite(limit->value)) return limit->value;
    error = fmt::format("{}: joint '{}' has no finite {} limit: pass {}", path, joint->name.text,
                        flag == std::string("--from") ? "lower" : "upper", flag);
    return std::nullopt;
  };
  const auto start = position(from_value, joint->lower, "--from");
  if (!start) return fail(error);
  const auto target = position(to_value, joint->upper, "--to");
  if (!target) return fail(error);

  const physics::SimulationRate rate = command_rate(asset, settings);
  // The inertia the row sees.
  SimulationContext context;
  context.path = path;
  context.joint = joint->name.text;
  context.angular = angular;
  context.force_unit = angular ? "N·m" : "N";
  const char* inertia_unit = angular ? "kg·m²" : "kg";
  const physics::Articulation articulation(asset);
  const physics::ArticulatedInertia articulated = articulation.inertia(*joint);
  const physics::EffectiveInertia lighter = physics::effective_inertia(articulation, asset, *joint);
  const std::size_t mimics = physics::coupled_joints(asset, *joint).size() - 1;
  const bool chosen = !inertia_choice.empty();
  if (!chosen) inertia_choice = mimics > 0 ? "mechanism" : "articulation";
  const auto unknown = [&](const physics::ArticulatedInertia& i) {
    std::string links;
    for (const auto& name : i.unknown_links) links += (links.empty() ? "'" : ", '") + name + "'";
    return links.empty() ? i.reason : "unauthored mass: " + links;
  };
  double inertia = 0;
  const physics::ArticulatedInertia mechanism = physics::mechanism_inertia(articulation, asset, *joint);
  const physics::ArticulatedInertia& wanted = inertia_choice == "mechanism" ? mechanism : articulated;
  if (!chosen && !wanted.known && lighter.known) {
    // By default, an unknown articulation falls back to the guide's estimate, and says so.
    inertia = lighter.value;
    context.inertia_origin = fmt::format("the guide's lighter link: the {} inertia is unknown ({})", inertia_choice,
                                         unknown(wanted));
  } else if (inertia_choice == "lighter-link") {
    if (!lighter.known)
      return fail(fmt::format("{}: --inertia lighter-link: no link of joint '{}' or its mimics authors mass and inertia",
                              path, joint->name.text));
    inertia = lighter.value;
    context.inertia_origin = "the guide's lighter link (--inertia lighter-link)";
  } else if (inertia_choice == "mechanism") {
    if (!mechanism.known)
      return fail(fmt::format("{}: the mechanism inertia of joint '{}' is unknown ({}): pass --inertia lighter-link",
                              path, joint->name.text, unknown(mechanism)));
    inertia = mechanism.value;
    context.inertia_origin = fmt::format("mechanism: Jᵀ·M·J over '{}' and its {} mimic{}, the mimics rigid",
                                         joint->name.text, mimics, mimics == 1 ? "" : "s");
  } else {
    if (!articulated.known)
      return fail(fmt::format("{}: the articulated inertia of joint '{}' is unknown ({}): pass --inertia lighter-link",
                              path, joint->name.text, unknown(articulated)));
    inertia = articulated.value;
    context.inertia_origin = "articulation: 1/(M⁻¹)ᵢᵢ with the other joints free";
  }
  context.inertia = inertia;

  SimulationSetup setup;
  setup.row = physics::drive_row(rate, drive->stiffness->value, drive->damping ? drive->damping->value : 0.0,
                                 drive->type, inertia);
  if (rate.solver == physics::Solver::MuJoCo && drive->type == DriveType::Force)
    setup.mujoco = MujocoSetup{rate.integrator, physics::mujoco_servo(*joint, setup.row.stiffness, setup.row.damping,
                                                                      inertia)};
  const Quantity* force = drive->max_force ? &*drive->max_force : joint->effort ? &*joint->effort : nullptr;
  if (force && force->value > 0) setup.limits.force.max_force = force->value;
  if (joint->velocity && joint->velocity->value > 0) setup.limits.max_velocity = joint->velocity->value;
  setup.from = *start;
  setup.target = *target;
  // The load pushes against the motion toward the target.
  setup.load = load ? (*target >= *start ? -*load : *load) : 0.0;
  // A load that wins pushes the joint back into its range limit behind the start: a hard stop.
  const bool closing = *target >= *start;
  const OptQuantity& behind = closing ? joint->lower : joint->upper;
  if (setup.load != 0 && behind && std::isfinite(behind->value) &&
      (closing ? behind->value <= *start : behind->value >= *start)) {
    setup.limits.stop = behind->value;
    setup.limits.stop_direction = closing ? -1 : 1;
  }
  const double frames = std::ceil(*duration / rate.dt() - 1e-9);
  const double work = frames * setup.row.substeps * 2;
  if (work > kMaxSolverSteps)
    return fail(fmt::format("--duration {} s at {} Hz with {} sub-steps is {} solver steps, above the limit of {}: "
                            "shorten the duration",
                            *duration_text, format_number(rate.timesteps_per_second), setup.row.substeps,
                            format_number(work, 3), format_number(kMaxSolverSteps, 3)));
  setup.frames = static_cast<int>(frames);

  const Unit k_unit = angular ? Unit::NewtonMeterPerRadian : Unit::NewtonPerMeter;
  const Unit d_unit = angular ? Unit::NewtonMeterSecondPerRadian : Unit::NewtonSecondPerMeter;
  const double nf = physics::natural_frequency(setup.row.stiffness, inertia);
  context.setup = {
      fmt::format("Drive: k = {} {}, d = {} {}, max force {}, max velocity {}", format_number(setup.row.stiffness, 4),
                  unit_symbol(k_unit), format_number(setup.row.damping, 4), unit_symbol(d_unit),
                  std::isfinite(setup.limits.force.max_force)
                      ? fmt::format("{} {} (per frame: max force × dt)", format_number(setup.limits.force.max_force, 4),
                                    context.force_unit)
                      : std::string("unbounded"),
                  std::isfinite(setup.limits.max_velocity)
                      ? fmt::format("{} {}/s", format_number(setup.limits.max_velocity, 4), angular ? "rad" : "m")
                      : std::string("unbounded")),
      fmt::format("Step: {}", rate.describe()),
      fmt::format("Inertia: {} {} ({}); 1/r of the joint alone: {}; the guide's lighter link: {}",
                  format_number(inertia, 3), inertia_unit, context.inertia_origin,
                  articulated.known ? fmt::format("{} {}", format_number(articulated.value, 3), inertia_unit)
                                    : "unknown (" + unknown(articulated) + ")",
                  lighter.known ? lighter.describe() : std::string("unknown")),
      setup.mujoco
          ? fmt::format("Integrator: {} ({}): one step's spectral radius {} within the force range; h·nf = {} s × {} "
                        "rad/s = {}",
                        physics::integrator_name(rate.integrator), rate.integrator_origin,
                        format_number(physics::servo_step(rate.integrator, setup.row.h, setup.mujoco->servo)
                                          .spectral_radius(),
                                      3),
                        format_number(setup.row.h, 3), format_number(nf, 4), format_number(setup.row.h * nf, 3))
          : fmt::format("Row: x = 1/(1 + h·(h·k + d)/I) = {}; h·nf = {} s × {} rad/s = {}",
                        format_number(setup.row.x(), 3), format_number(setup.row.h, 3), format_number(nf, 4),
                        format_number(setup.row.h * nf, 3)),
  };
  if (load) context.setup.push_back(fmt::format("Load: {} {} against the motion", format_number(*load, 4), context.force_unit));
  const GripperSpec& g = settings.gripper;
  if (g.stroke_m && g.finger_speed_m_s) {
    context.spec_close_time = physics::close_time(g.stroke_m->value, g.finger_speed_m_s->value);
    context.spec_origin = fmt::format("{} m stroke ({}) at {} m/s ({})", format_number(g.stroke_m->value),
                                      g.stroke_m->origin, format_number(g.finger_speed_m_s->value),
                                      g.finger_speed_m_s->origin);
  }

  const SimulationRun run = run_simulation(setup);
  if (format == "json") write_simulation_json(out, context, setup, run);
  else write_simulation_text(out, context, setup, run);
  if (csv) {
    std::ostringstream text;
    write_simulation_csv(text, context, run);
    if (!write_text_file(*csv, text.str(), error)) return fail(error);
  }
  if (plot && !write_text_file(*plot, simulation_svg(context, setup, run), error)) return fail(error);
  return kExitClean;
}

}  // namespace assetlint::commands
