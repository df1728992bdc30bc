#include "commands/verify_drives.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <cmath>
#include <thread>

#include "backends/mujoco/mjcf_scene.h"
#include "backends/mujoco/mujoco_drive_engine.h"
#include "commands/exit_status.h"
#include "commands/verify_drives_report.h"
#include "commands/verify_meshes.h"
#include "verify/drive_metrics.h"

namespace assetlint::commands {
namespace {

constexpr double kMaxSample = 0.001;  // s: samples at most this far apart

// Runs `count` independent jobs on `threads` threads; each job writes only its own slot.
void parallel_for(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& job) {
  std::atomic<std::size_t> next{0};
  const auto worker = [&] {
    for (std::size_t i = next++; i < count; i = next++) job(i);
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < std::min<std::size_t>(threads, count); ++t) pool.emplace_back(worker);
  worker();
  for (auto& thread : pool) thread.join();
}

// One verification: the engine for the plan, every scene stepped and judged.
struct DriveRun {
  std::unique_ptr<backends::mujoco::MujocoDriveEngine> engine;
  std::vector<verify::DriveScene> scenes;
  std::vector<std::optional<verify::DriveTrajectory>> trajectories;
  std::vector<verify::JointLoads> loads;
  std::vector<verify::DriveResult> results;  // point into scenes and trajectories: a DriveRun is not copied
  long steps = 0;
};

DriveRun run_drives(const verify::DrivePlan& plan, unsigned threads, std::string& error) {
  DriveRun run;
  run.engine = std::make_unique<backends::mujoco::MujocoDriveEngine>(plan, error);
  if (!error.empty()) return run;
  run.scenes = verify::drive_scenes(plan);
  // Every scene and every joint's loads are independent: one job each, results in fixed slots.
  run.trajectories.resize(run.scenes.size());
  run.loads.resize(plan.joints.size());
  std::vector<std::string> errors(run.scenes.size());
  parallel_for(run.scenes.size() + plan.joints.size(), threads, [&](std::size_t i) {
    if (i < run.scenes.size()) {
      if (run.scenes[i].not_run.empty()) run.trajectories[i] = run.engine->run(run.scenes[i], errors[i]);
    } else {
      run.loads[i - run.scenes.size()] = verify::joint_loads(plan, *run.engine, i - run.scenes.size());
    }
  });
  for (const std::string& e : errors)
    if (!e.empty() && error.empty()) error = e;
  for (const auto& t : run.trajectories)
    if (t) run.steps += t->steps;
  for (std::size_t j = 0; j < plan.joints.size(); ++j) {
    const verify::DriveScene* step = nullptr;
    const verify::DriveScene* sweep = nullptr;
    const verify::DriveTrajectory* step_run = nullptr;
    const verify::DriveTrajectory* sweep_run = nullptr;
    for (std::size_t i = 0; i < run.scenes.size(); ++i) {
      if (run.scenes[i].joint != j) continue;
      const verify::DriveTrajectory* t = run.trajectories[i] ? &*run.trajectories[i] : nullptr;
      if (run.scenes[i].kind == verify::DriveTestKind::Step) step = &run.scenes[i], step_run = t;
      else sweep = &run.scenes[i], sweep_run = t;
    }
    for (auto& r : verify::judge_joint(plan, j, run.loads[j], step, step_run, sweep, sweep_run))
      run.results.push_back(std::move(r));
  }
  return run;
}

}  // namespace

bool has_gripper_spec(const GripperSpec& g) {
  return g.payload_kg || g.friction || g.lever_arm_m || g.finger_speed_m_s || g.stroke_m || g.torque_margin ||
         g.driven_joint || g.gravity.origin != "default" || g.target_delta_deg.origin != "default";
}

int run_drive_tests(const DriveTestOptions& options, const CommandAsset& input, std::ostream& out, std::ostream& err) {
  const auto fail = [&](const std::string& message) {
    err << "asset-lint verify: error: " << options.path << ": " << message << "\n";
    return kExitError;
  };
  const Settings& settings = input.settings;
  const Asset& asset = input.loaded.read.asset;
  verify::DrivePlan plan = verify::plan_drive_tests(asset, settings);
  if (plan.joints.empty()) return fail("no actuated joint to test (no revolute, continuous or prismatic joint)");
  const physics::SimulationRate rate = command_rate(asset, settings);
  plan.timestep = rate.h();
  plan.timestep_origin = rate.describe();
  plan.sample = plan.timestep * std::max(1.0, std::floor(kMaxSample / plan.timestep));
  plan.gravity = settings.gripper.gravity.value;
  // Mesh files are read only for moving links whose mass comes from their shapes.
  std::vector<std::string> shaped;
  for (const Link& link : asset.links)
    if (!backends::mujoco::has_authored_mass(link) && !plan.static_links.count(link.name.text))
      shaped.push_back(link.name.text);
  std::string error;
  if (!read_collision_meshes(options.path, asset, settings, shaped, plan.meshes, error)) return fail(error);

  const unsigned threads = options.jobs ? options.jobs : std::max(1u, std::thread::hardware_concurrency());
  DriveRun run = run_drives(plan, threads, error);
  if (!error.empty()) return fail(error);
  DriveReport report;
  report.path = options.path;
  report.engine_version = run.engine->version();
  report.translation = run.engine->translation();
  report.plan = &plan;
  report.steps = run.steps;
  report.results = run.results;

  // Fine-tuning: every joint that fails a test or has no drive gets the proposed gains, and the
  // whole robot is tested again with them.
  verify::DrivePlan tuned = plan;
  DriveRun confirm;
  if (options.fine_tune) {
    for (std::size_t j = 0; j < plan.joints.size(); ++j) {
      const bool fails = std::any_of(run.results.begin(), run.results.end(), [&](const verify::DriveResult& r) {
        return r.joint == plan.joints[j].joint->name.text && r.ran && !r.passed;
      });
      if (!fails && plan.joints[j].drive) continue;
      tuned.joints[j].drive = verify::proposed_drive(plan, j, run.loads[j]);
      tuned.joints[j].no_drive.clear();
      report.fine_tuned.push_back(j);
    }
    if (!report.fine_tuned.empty()) {
      confirm = run_drives(tuned, threads, error);
      if (!error.empty()) return fail(error);
      report.tuned_plan = &tuned;
      report.tuned_results = confirm.results;
      report.steps += confirm.steps;
    }
  }
  if (options.format == "json") write_drive_json(out, report);
  else write_drive_text(out, report);
  if (options.plot) {
    if (!write_text_file(*options.plot, drive_svg(report), error)) return fail(error);
    err << fmt::format("asset-lint verify: wrote the plot to {}\n", *options.plot);
  }
  return report.passed() ? kExitClean : kExitFindings;
}

}  // namespace assetlint::commands
