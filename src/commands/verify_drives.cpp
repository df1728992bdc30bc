#include "commands/verify_drives.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
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

  backends::mujoco::MujocoDriveEngine engine(plan, error);
  if (!error.empty()) return fail(error);
  const std::vector<verify::DriveScene> scenes = verify::drive_scenes(plan);
  const unsigned threads = options.jobs ? options.jobs : std::max(1u, std::thread::hardware_concurrency());

  // Every scene and every joint's loads are independent: one job each, results in fixed slots.
  std::vector<std::optional<verify::DriveTrajectory>> trajectories(scenes.size());
  std::vector<std::string> errors(scenes.size());
  std::vector<verify::JointLoads> loads(plan.joints.size());
  const std::size_t jobs = scenes.size() + plan.joints.size();
  parallel_for(jobs, threads, [&](std::size_t i) {
    if (i < scenes.size()) {
      if (scenes[i].not_run.empty()) trajectories[i] = engine.run(scenes[i], errors[i]);
    } else {
      loads[i - scenes.size()] = verify::joint_loads(plan, engine, i - scenes.size());
    }
  });
  for (const std::string& e : errors)
    if (!e.empty()) return fail(e);

  DriveReport report;
  report.path = options.path;
  report.engine_version = engine.version();
  report.translation = engine.translation();
  report.plan = &plan;
  for (const auto& t : trajectories)
    if (t) report.steps += t->steps;
  for (std::size_t j = 0; j < plan.joints.size(); ++j) {
    const verify::DriveScene* step = nullptr;
    const verify::DriveScene* sweep = nullptr;
    const verify::DriveTrajectory* step_run = nullptr;
    const verify::DriveTrajectory* sweep_run = nullptr;
    for (std::size_t i = 0; i < scenes.size(); ++i) {
      if (scenes[i].joint != j) continue;
      const verify::DriveTrajectory* run = trajectories[i] ? &*trajectories[i] : nullptr;
      if (scenes[i].kind == verify::DriveTestKind::Step) step = &scenes[i], step_run = run;
      else sweep = &scenes[i], sweep_run = run;
    }
    for (auto& r : verify::judge_joint(plan, j, loads[j], step, step_run, sweep, sweep_run))
      report.results.push_back(std::move(r));
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
