#include "backends/mujoco/mujoco_drive_engine.h"

#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "backends/mujoco/drive_scene.h"
#include "backends/mujoco/mjcf_scene.h"
#include "physics/drive_response.h"
#include "util/numbers.h"

namespace assetlint::backends::mujoco {
namespace {

// libmujoco reports through global handlers: a warning is kept for the thread whose step raised
// it (each test steps on one thread), an error is thrown.
thread_local std::string t_warning;
void keep_warning(const char* message) {
  if (t_warning.empty()) t_warning = message;
}
void throw_error(const char* message) { throw std::runtime_error(message); }

// rad/s (m/s): every joint slower than this is at rest; in the half second the step needs to be
// called steady it moves at most 0.5 µrad.
constexpr double kRestSpeed = 1e-6;

struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using Data = std::unique_ptr<mjData, DataDeleter>;

}  // namespace

struct MujocoDriveEngine::Impl {
  const verify::DrivePlan& plan;
  mjModel* model = nullptr;
  std::vector<std::size_t> actuated;       // actuator k → plan joint
  std::vector<int> actuator_of;            // plan joint → actuator (−1: none)
  std::vector<int> qpos, dof;              // plan joint → its address (−1: welded)
  std::vector<std::vector<std::pair<int, const Joint*>>> followers;  // plan joint → (qpos address, follower)
  double gravity_work = 0;                 // J: the most gravity can release (physics/drive_response.h)
  decltype(mju_user_warning) previous_warning = nullptr;
  decltype(mju_user_error) previous_error = nullptr;

  explicit Impl(const verify::DrivePlan& p) : plan(p) {}

  // Every joint at its start (the tested one at `q`), followers where their mimics put them.
  void pose(mjData* d, std::optional<std::pair<std::size_t, double>> moved) const {
    for (std::size_t i = 0; i < plan.joints.size(); ++i) {
      if (qpos[i] < 0) continue;
      const double q = moved && moved->first == i ? moved->second : plan.joints[i].start;
      d->qpos[qpos[i]] = q;
      for (const auto& [address, follower] : followers[i])
        d->qpos[address] = follower->mimic->multiplier.value * q + follower->mimic->offset.value;
    }
    for (std::size_t k = 0; k < actuated.size(); ++k) d->ctrl[k] = plan.joints[actuated[k]].start;
  }
};

MujocoDriveEngine::MujocoDriveEngine(const verify::DrivePlan& plan, std::string& error) : impl_(std::make_unique<Impl>(plan)) {
  Impl& s = *impl_;
  s.previous_warning = mju_user_warning;
  s.previous_error = mju_user_error;
  mju_user_warning = keep_warning;
  mju_user_error = throw_error;
  const std::string text = drive_scene_mjcf(plan, s.actuated, error);
  if (text.empty()) return;
  try {
    auto vfs = std::make_unique<mjVFS>();
    mj_defaultVFS(vfs.get());
    const char* name = "asset_lint_verify_drives.xml";
    mj_makeEmptyFileVFS(vfs.get(), name, static_cast<int>(text.size()));
    std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), name)], text.data(), text.size());
    char message[1000] = "";
    s.model = mj_loadXML(name, vfs.get(), message, sizeof message);
    mj_deleteVFS(vfs.get());
    if (!s.model) {
      error = fmt::format("MuJoCo could not compile the drive scene: {}", message);
      return;
    }
  } catch (const std::runtime_error& e) {
    error = fmt::format("MuJoCo error compiling the drive scene: {}", e.what());
    return;
  }
  const mjModel* m = s.model;
  const Asset& asset = *plan.asset;
  s.actuator_of.assign(plan.joints.size(), -1);
  for (std::size_t k = 0; k < s.actuated.size(); ++k) s.actuator_of[s.actuated[k]] = static_cast<int>(k);
  const auto address = [&](const Joint& joint, bool velocity) {
    const int id = mj_name2id(m, mjOBJ_JOINT, joint_name(asset, joint).c_str());
    return id < 0 ? -1 : velocity ? m->jnt_dofadr[id] : m->jnt_qposadr[id];
  };
  for (const verify::TestedJoint& j : plan.joints) {
    s.qpos.push_back(address(*j.joint, false));
    s.dof.push_back(address(*j.joint, true));
    std::vector<std::pair<int, const Joint*>> f;
    for (const Joint* follower : j.followers)
      if (const int a = address(*follower, false); a >= 0) f.emplace_back(a, follower);
    s.followers.push_back(std::move(f));
  }
  // Each body's centre of mass lies within the sum of the offsets along its chain (plus the
  // travel of any slide on it) of the root: gravity can release at most m·g·2·that.
  std::vector<double> reach(m->nbody, 0.0);
  for (int b = 1; b < m->nbody; ++b) {
    double r = reach[m->body_parentid[b]] + mju_norm3(m->body_pos + 3 * b);
    for (int j = m->body_jntadr[b]; j >= 0 && j < m->body_jntadr[b] + m->body_jntnum[b]; ++j)
      if (m->jnt_type[j] == mjJNT_SLIDE)
        r += m->jnt_limited[j] ? std::max(std::abs(m->jnt_range[2 * j]), std::abs(m->jnt_range[2 * j + 1])) : 0.0;
    reach[b] = r;
    s.gravity_work += m->body_mass[b] * plan.gravity * 2 * (r + mju_norm3(m->body_ipos + 3 * b));
  }
}

MujocoDriveEngine::~MujocoDriveEngine() {
  if (impl_->model) mj_deleteModel(impl_->model);
  mju_user_warning = impl_->previous_warning;
  mju_user_error = impl_->previous_error;
}

std::string MujocoDriveEngine::version() const { return mj_versionString(); }

std::optional<verify::DriveTrajectory> MujocoDriveEngine::run(const verify::DriveScene& scene, std::string& error) const {
  const Impl& s = *impl_;
  if (!s.model) {
    error = "the drive scene was not compiled";
    return std::nullopt;
  }
  const mjModel* m = s.model;
  const verify::TestedJoint& j = s.plan.joints[scene.joint];
  const int qpos = s.qpos[scene.joint], dof = s.dof[scene.joint], actuator = s.actuator_of[scene.joint];
  if (qpos < 0 || actuator < 0) {
    error = fmt::format("joint '{}' has no actuator in the drive scene", j.joint->name.text);
    return std::nullopt;
  }
  Data data(mj_makeData(m));
  mjData* d = data.get();
  s.pose(d, std::make_pair(scene.joint, verify::scene_target(scene, 0)));
  verify::DriveTrajectory trajectory;
  double travel = 0;
  for (std::size_t i = 1; i < scene.waypoints.size(); ++i)
    travel = std::max(travel, std::abs(scene.waypoints[i].second - scene.waypoints.front().second));
  const double spring = j.drive->stiffness * travel;
  trajectory.energy_budget =
      physics::drive_energy_budget(j.drive->max_force ? std::min(*j.drive->max_force, spring) : spring, travel, s.gravity_work);
  std::vector<mjtNum> momentum(m->nv);
  const auto sample = [&] {
    verify::DriveSample x;
    x.t = d->time;
    x.q = d->qpos[qpos];
    x.velocity = d->qvel[dof];
    x.target = d->ctrl[actuator];
    for (const auto& [address, follower] : s.followers[scene.joint])
      x.mimic_error = std::max(x.mimic_error, std::abs(d->qpos[address] - (follower->mimic->multiplier.value * x.q +
                                                                           follower->mimic->offset.value)));
    mj_mulM(m, d, momentum.data(), d->qvel);
    x.kinetic_energy = 0.5 * mju_dot(momentum.data(), d->qvel, m->nv);
    trajectory.samples.push_back(x);
  };
  t_warning.clear();
  try {
    d->ctrl[actuator] = verify::scene_target(scene, 0);
    mj_forward(m, d);
    sample();
    const int per_sample = std::max(1, static_cast<int>(std::lround(s.plan.sample / m->opt.timestep)));
    const long count = std::lround(scene.duration / (per_sample * m->opt.timestep));
    double rest_since = -1;  // s: since when every joint has been at rest (< 0: it is not)
    for (long n = 0; n < count; ++n) {
      for (int k = 0; k < per_sample; ++k) {
        d->ctrl[actuator] = verify::scene_target(scene, d->time);
        mj_step(m, d);
        ++trajectory.steps;
      }
      bool finite = true;
      for (int i = 0; i < m->nq; ++i) finite = finite && std::isfinite(d->qpos[i]);
      for (int i = 0; i < m->nv; ++i) finite = finite && std::isfinite(d->qvel[i]);
      if (!finite || !t_warning.empty()) {
        trajectory.diverged = true;
        trajectory.divergence = !finite ? fmt::format("non-finite state at {} s", format_number(d->time, 3))
                                        : fmt::format("MuJoCo warning at {} s: {}", format_number(d->time, 3), t_warning);
        break;
      }
      sample();
      if (scene.rest_ends > 0 && d->time > scene.step_at + 1e-9) {
        double fastest = 0;
        for (int i = 0; i < m->nv; ++i) fastest = std::max(fastest, std::abs(d->qvel[i]));
        if (fastest > kRestSpeed) rest_since = -1;
        else if (rest_since < 0) rest_since = d->time;
        if (rest_since >= 0 && d->time - rest_since >= scene.rest_ends - 1e-9) break;
      }
    }
  } catch (const std::runtime_error& e) {
    error = fmt::format("MuJoCo error in scene '{}': {}", scene.name, e.what());
    return std::nullopt;
  }
  return trajectory;
}

double MujocoDriveEngine::gravity_torque(std::size_t joint, double q) const {
  const Impl& s = *impl_;
  const mjModel* m = s.model;
  if (!m || s.dof[joint] < 0) return NAN;
  Data data(mj_makeData(m));
  mjData* d = data.get();
  s.pose(d, std::make_pair(joint, q));
  mj_forward(m, d);
  double torque = d->qfrc_bias[s.dof[joint]];
  for (const auto& [address, follower] : s.followers[joint]) {
    const int id = mj_name2id(m, mjOBJ_JOINT, joint_name(*s.plan.asset, *follower).c_str());
    torque += follower->mimic->multiplier.value * d->qfrc_bias[m->jnt_dofadr[id]];
  }
  return torque;
}

double MujocoDriveEngine::joint_inertia(std::size_t joint) const {
  const Impl& s = *impl_;
  const mjModel* m = s.model;
  if (!m || s.dof[joint] < 0) return NAN;
  Data data(mj_makeData(m));
  mjData* d = data.get();
  s.pose(d, std::nullopt);
  mj_forward(m, d);
  std::vector<mjtNum> full(static_cast<std::size_t>(m->nv) * m->nv);
  mj_fullM(m, full.data(), d->qM);
  // Jᵀ·M·J over the joint and its followers (gearing J: 1, then each follower's multiplier).
  std::vector<std::pair<int, double>> gearing{{s.dof[joint], 1.0}};
  for (const auto& [address, follower] : s.followers[joint]) {
    const int id = mj_name2id(m, mjOBJ_JOINT, joint_name(*s.plan.asset, *follower).c_str());
    gearing.emplace_back(m->jnt_dofadr[id], follower->mimic->multiplier.value);
  }
  double inertia = 0;
  for (const auto& [a, ga] : gearing)
    for (const auto& [b, gb] : gearing) inertia += ga * gb * full[static_cast<std::size_t>(a) * m->nv + b];
  return inertia;
}

std::vector<std::string> MujocoDriveEngine::translation() const {
  const verify::DrivePlan& plan = impl_->plan;
  std::vector<std::string> lines{
      fmt::format("Base: '{}' welded to the world{}; gravity {} m/s² along −z of its frame.", plan.base,
                  plan.base_pinned ? " (the asset's base floats: it is pinned where it stands)" : "",
                  format_number(plan.gravity, 4)),
      fmt::format("Drives: one <general> actuator per tested joint, force = kp·(target − q) − kv·q̇, forcerange ± the max "
                  "force, under integrator=\"{}\" (the kv term solved at the new velocity); the step h = {} s ({}).",
                  kIntegrator, format_number(plan.timestep, 4), plan.timestep_origin),
      "Max joint velocity: MuJoCo has none; the sweep's target is ramped at it, and the joint is not clamped when its "
      "drive pushes it faster (the velocity test reports the peak speed reached).",
      "Held joints: every other tested joint's drive holds its start pose (0 within its limits), a joint without a "
      "drive is held there by an <equality><joint>; mimic followers are <equality><joint> constraints (time constant "
      "two steps); armature and joint friction (frictionloss) carry over; contacts are off.",
  };
  if (!plan.held_rigid.empty()) {
    std::string names;
    for (const auto& name : plan.held_rigid) names += (names.empty() ? "'" : ", '") + name + "'";
    lines.push_back(fmt::format("Welded: {} (not single-DOF joints) are held rigid at their start.", names));
  }
  return lines;
}

}  // namespace assetlint::backends::mujoco
