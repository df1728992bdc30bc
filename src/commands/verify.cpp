#include "commands/verify.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "backends/mujoco/mujoco_engine.h"
#include "commands/command_input.h"
#include "commands/exit_status.h"
#include "commands/tune_apply.h"
#include "commands/tune_derivation.h"
#include "commands/verify_drives.h"
#include "commands/verify_meshes.h"
#include "commands/verify_report.h"
#include "physics/gripper.h"
#include "physics/sizing.h"
#include "util/numbers.h"
#include "verify/fine_tune.h"
#include "verify/metrics.h"

namespace assetlint::commands {
namespace {

std::string origin_of(const ReadResult& read, const Quantity& q, const std::optional<Configured<double>>& configured) {
  if (configured && !q.span.valid()) return configured->origin;
  if (!q.span.valid()) return "the asset's default";
  const Span span = read.written_at ? read.written_at(q.span) : q.span;
  return fmt::format("{}:{}", read.asset.source(span.file).path(), span.line);
}

std::string spec_line(const char* what, const std::optional<Configured<double>>& value, const char* unit) {
  return value ? fmt::format("{} {} {} ({})", what, format_number(value->value, 4), unit, value->origin)
               : fmt::format("{}: not set", what);
}

// Lines on standard error once a run has taken more than a second: which scene of how many
// starts, and the engine steps so far, so that a long verification is seen to move.
class Progress {
 public:
  explicit Progress(std::ostream& err) : err_(err), start_(std::chrono::steady_clock::now()) {}
  void scene_starts(std::size_t index, std::size_t count, const verify::SceneSpec& scene, long steps) {
    if (elapsed() < 1.0) return;
    err_ << fmt::format("asset-lint verify: {}scene {} of {} ({}), {} engine steps so far, {} s\n", run_, index + 1,
                        count, scene.name, steps, format_number(elapsed(), 2));
    err_.flush();
  }
  // Names the fine-tuning's runs from here on.
  void fine_tuning_run(std::size_t run) { run_ = fmt::format("fine-tuning run {}: ", run); }

 private:
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  std::ostream& err_;
  std::chrono::steady_clock::time_point start_;
  std::string run_;
};

// Every scene of `plan` that can be judged, stepped and judged; the rest reported as not run.
std::optional<std::vector<verify::SceneResult>> run_scenes(verify::Engine& engine, const verify::VerifyPlan& plan,
                                                           const Settings& settings, long& steps, std::string& error,
                                                           Progress& progress) {
  std::vector<verify::SceneResult> results;
  for (const verify::SceneSpec& scene : plan.scenes) {
    if (!scene.not_run.empty()) {
      results.push_back(verify::not_run(scene));
      continue;
    }
    progress.scene_starts(results.size(), plan.scenes.size(), scene, steps);
    auto trajectory = engine.run(plan, scene, error);
    if (!trajectory) return std::nullopt;
    steps += trajectory->steps;
    results.push_back(verify::judge(plan, scene, std::move(*trajectory), settings.verify));
  }
  return results;
}

}  // namespace

int run_verify(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"asset-lint verify: the guide's verification scenes (close, grasp, hold, lift) run headless in a physics "
               "engine",
               "asset-lint verify"};
  std::string path, format = "text", engine_name = "mujoco";
  std::optional<std::string> config, plot;
  bool fine_tune = false, apply = false;
  app.add_option("asset", path, "The gripper: a URDF, xacro, USD (.usda, .usd, .usdc) or MJCF file")->required();
  app.add_option("--engine", engine_name, "The engine that steps the scenes: mujoco (MuJoCo 2.2.2)")
      ->check(CLI::IsMember({"mujoco"}));
  app.add_option("--output-format", format, "text or json")->check(CLI::IsMember({"text", "json"}));
  app.add_option("--plot", plot, "Write an SVG of finger opening, object height and penetration over time");
  auto* fine = app.add_flag("--fine-tune", fine_tune,
                            "Bisect the lowest max force, then the lowest stiffness (damping re-derived for the same "
                            "damping ratio), for which every scene still passes");
  app.add_flag("--apply", apply, "With --fine-tune: write those values as `tune --apply` does")->needs(fine);
  bool drives = false;
  unsigned jobs = 0;
  app.add_flag("--drives", drives,
               "Test every actuated joint's drive (step, sweep, hold, velocity, mimic), base fixed, gravity on; the "
               "default when asset-lint.toml has no [gripper] spec");
  app.add_option("-j,--jobs", jobs, "With the drive tests: scenes stepped in parallel (default: one per core)")
      ->check(CLI::Range(1u, 256u));
  app.add_option("--config", config, "Use this asset-lint.toml (default: the nearest one above the asset)");
  CompositionScope scope;
  add_scope_options(app, scope);
  if (auto status = parse_command(app, args, "verify", out, err)) return *status;
  const auto fail = [&](const std::string& message) {
    err << "asset-lint verify: error: " << message << "\n";
    return kExitError;
  };

  CommandAsset input = load_command_asset(path, config, scope);
  if (input.error) return fail(*input.error);
  const Settings& settings = input.settings;
  const Asset& asset = input.loaded.read.asset;
  if (drives || !has_gripper_spec(settings.gripper)) {
    if (apply)
      return fail("--apply writes a gripper's fine-tuning; the drive tests print the gains each joint needs (the "
                  "fine-tuning's proposals, confirmed by a second run), to be written where the format keeps them");
    DriveTestOptions options{path, format, plot, jobs, fine_tune};
    return run_drive_tests(options, input, out, err);
  }
  std::string error;
  const Joint* joint = tune_joint(asset, settings, std::nullopt, error, nullptr);  // verify has no --joint
  if (!joint) return fail(fmt::format("{}: {}", path, error));
  const Drive* drive = joint->drive ? &*joint->drive : nullptr;
  if (!drive || !drive->stiffness || !(drive->stiffness->value > 0))
    return fail(fmt::format("{}: joint '{}' has no drive stiffness: set [drives.{}] stiffness and damping in "
                            "asset-lint.toml (`asset-lint tune --apply` derives them)",
                            path, joint->name.text, joint->name.text));
  verify::VerifyPlan plan;
  plan.asset = &asset;
  plan.asset_dir = std::filesystem::path(path).parent_path().string();
  // Collision meshes, each read once; visual meshes are not in the model and never read.
  std::vector<std::string> link_names;
  for (const Link& link : asset.links) link_names.push_back(link.name.text);
  if (!read_collision_meshes(path, asset, settings, link_names, plan.meshes, error))
    return fail(fmt::format("{}: {}", path, error));
  auto layout = verify::gripper_layout(asset, *joint, error);
  if (!layout) return fail(fmt::format("{}: {}", path, error));
  plan.layout = std::move(*layout);

  const auto configured_drive = settings.drives.find(joint->name.text);
  const DriveSettings* table = configured_drive == settings.drives.end() ? nullptr : &configured_drive->second;
  plan.drive.stiffness = drive->stiffness->value;
  plan.drive.damping = drive->damping ? drive->damping->value : 0.0;
  const Quantity* force = drive->max_force ? &*drive->max_force : joint->effort ? &*joint->effort : nullptr;
  if (force && force->value > 0) plan.drive.max_force = force->value;
  if (joint->velocity && joint->velocity->value > 0) plan.drive.max_velocity = joint->velocity->value;

  const physics::SimulationRate rate = command_rate(asset, settings);
  plan.timestep = rate.h();
  plan.frame = rate.dt();
  plan.timestep_origin = rate.describe();
  const GripperSpec& g = settings.gripper;
  plan.gravity = g.gravity.value;
  if (g.stroke_m && g.finger_speed_m_s) plan.spec_close_time = physics::close_time(g.stroke_m->value, g.finger_speed_m_s->value);
  if (g.payload_kg && g.friction)
    plan.required_grip_force = physics::grip_force(g.payload_kg->value, g.gravity.value, g.friction->value);
  plan.scenes = verify::build_scenes(plan, settings);

  const bool angular = is_angular(joint->type);
  const char* force_unit = angular ? "N·m" : "N";
  VerifyReport report;
  report.path = path;
  report.joint = joint->name.text;
  report.angular = angular;
  report.inputs = {
      spec_line("payload", g.payload_kg, "kg"),
      spec_line("friction μ", g.friction, ""),
      fmt::format("gravity {} m/s² ({})", format_number(g.gravity.value, 4), g.gravity.origin),
      spec_line("stroke", g.stroke_m, "m"),
      spec_line("finger speed", g.finger_speed_m_s, "m/s"),
      fmt::format("target delta {}° ({})", format_number(g.target_delta_deg.value, 4), g.target_delta_deg.origin),
      fmt::format("drive of '{}': stiffness {} {}/{} ({}), damping {} {}·s/{} ({}), max force {}, max velocity {}",
                  joint->name.text, format_number(plan.drive.stiffness, 4), force_unit, angular ? "rad" : "m",
                  origin_of(input.loaded.read, *drive->stiffness, table ? table->stiffness : std::nullopt),
                  format_number(plan.drive.damping, 4), force_unit, angular ? "rad" : "m",
                  drive->damping ? origin_of(input.loaded.read, *drive->damping, table ? table->damping : std::nullopt)
                                 : std::string("none"),
                  plan.drive.max_force ? fmt::format("{} {} ({})", format_number(*plan.drive.max_force, 4), force_unit,
                                                     origin_of(input.loaded.read, *force, table ? table->max_force : std::nullopt))
                                       : std::string("unbounded"),
                  plan.drive.max_velocity
                      ? fmt::format("{} {}/s ({})", format_number(*plan.drive.max_velocity, 4), angular ? "rad" : "m",
                                    origin_of(input.loaded.read, *joint->velocity, table ? table->max_velocity : std::nullopt))
                      : std::string("unbounded")),
      fmt::format("step: {}; the engine steps h = {} s and samples every frame ({} s)", plan.timestep_origin,
                  format_number(plan.timestep, 4), format_number(plan.frame, 4)),
      fmt::format("fingers: pads '{}' and '{}' close along ({}) in the frame of '{}', approach ({}); gap {} mm open "
                  "({} {}), {} mm closed ({} {}); {} mimic joint{}",
                  plan.layout.pads[0], plan.layout.pads[1],
                  fmt::format("{}, {}, {}", format_number(plan.layout.closing.x(), 3),
                              format_number(plan.layout.closing.y(), 3), format_number(plan.layout.closing.z(), 3)),
                  plan.layout.root,
                  fmt::format("{}, {}, {}", format_number(plan.layout.approach.x(), 3),
                              format_number(plan.layout.approach.y(), 3), format_number(plan.layout.approach.z(), 3)),
                  format_number(plan.layout.gap_at(asset, plan.layout.open, plan.meshes) * 1000, 4),
                  format_number(angular ? degrees_from_radians(plan.layout.open) : plan.layout.open, 4),
                  angular ? "deg" : "m", format_number(plan.layout.gap_at(asset, plan.layout.closed, plan.meshes) * 1000, 4),
                  format_number(angular ? degrees_from_radians(plan.layout.closed) : plan.layout.closed, 4),
                  angular ? "deg" : "m", plan.layout.mimics.size(), plan.layout.mimics.size() == 1 ? "" : "s"),
  };

  backends::mujoco::MujocoEngine engine;
  report.engine = engine.info(plan);
  Progress progress(err);
  auto results = run_scenes(engine, plan, settings, report.steps, error, progress);
  if (!results) return fail(fmt::format("{}: {}", path, error));
  report.scenes = std::move(*results);
  if (fine_tune) {
    // A drive passes when every scene that can be judged passes (scenes not run are not judged).
    // Today's drive is the run above: when it fails, the fine-tuning stops there and says what
    // to change first.
    bool failed = false;
    const bool baseline_passed =
        std::none_of(report.scenes.begin(), report.scenes.end(), [](const auto& s) { return s.ran && !s.passed; });
    std::size_t run = 1;
    const auto passes = [&](const verify::DriveSpec& drive) {
      verify::VerifyPlan trial = plan;
      trial.drive = drive;
      progress.fine_tuning_run(++run);
      auto scenes = run_scenes(engine, trial, settings, report.steps, error, progress);
      if (!scenes) {
        failed = true;
        return false;
      }
      for (const auto& s : *scenes)
        if (s.ran && !s.passed) return false;
      return true;
    };
    report.fine_tune = baseline_passed ? verify::fine_tune(plan.drive, passes)
                                       : verify::failing_baseline(plan.drive, report.scenes);
    if (failed) return fail(fmt::format("{}: {}", path, error));
    if (std::any_of(report.scenes.begin(), report.scenes.end(), [](const auto& s) { return !s.ran; }))
      report.fine_tune->notes.push_back("scenes not run are not judged by the fine-tuning");
  }
  if (format == "json") write_verify_json(out, report);
  else write_verify_text(out, report, settings.verify);
  if (plot) {
    if (!write_text_file(*plot, verify_svg(report, plan, settings.verify), error)) return fail(error);
    err << fmt::format("asset-lint verify: wrote the plot to {}\n", *plot);
  }
  if (apply && report.fine_tune && report.fine_tune->baseline_passed) {
    TuneDerivation lowered;
    lowered.path = path;
    lowered.joint = joint;
    lowered.mimics = plan.layout.mimics;
    lowered.recommended.max_force = report.fine_tune->lowest.max_force;
    lowered.recommended.stiffness = report.fine_tune->lowest.stiffness;
    lowered.recommended.damping = report.fine_tune->lowest.damping;
    if (format == "text") out << "\n";
    if (carry_out(plan_tune_apply(lowered, input.loaded.read, settings, config), false, format == "text" ? out : err, err) ==
        kExitError)
      return kExitError;
  }
  return report.passed() ? kExitClean : kExitFindings;
}

}  // namespace assetlint::commands
