#include "backends/mujoco/mujoco_engine.h"

#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "backends/mujoco/mjcf_scene.h"
#include "util/numbers.h"

namespace assetlint::backends::mujoco {
namespace {

using verify::SceneSpec;
using verify::VerifyPlan;

// libmujoco reports through global handlers: warnings would go to stdout, errors exit the
// process. Both are caught here, for the one scene being stepped.
thread_local std::string g_warning;
void on_warning(const char* message) {
  if (g_warning.empty()) g_warning = message;
}
void on_error(const char* message) { throw std::runtime_error(message); }

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

mjModel* compile(const std::string& text, std::string& error) {
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const char* name = "asset_lint_verify_scene.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), name, static_cast<int>(text.size())) != 0) {
    error = "MuJoCo's virtual file system refused the scene";
    return nullptr;
  }
  const int index = mj_findFileVFS(vfs.get(), name);
  std::memcpy(vfs->filedata[index], text.data(), text.size());
  char message[1000] = "";
  mjModel* model = mj_loadXML(name, vfs.get(), message, sizeof message);
  mj_deleteVFS(vfs.get());
  if (!model) error = fmt::format("MuJoCo could not compile the scene: {}", message);
  return model;
}

// The lift's height at t: a smooth step (3s² − 2s³) from 0 to the scene's height.
double lift_height(const SceneSpec& scene, double t) {
  if (scene.lift_height <= 0 || scene.lift_duration <= 0) return 0;
  const double s = std::clamp((t - scene.lift_start) / scene.lift_duration, 0.0, 1.0);
  return scene.lift_height * s * s * (3 - 2 * s);
}

Eigen::Isometry3d body_pose(const mjData* d, int body) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    pose.translation()(r) = d->xpos[3 * body + r];
    for (int c = 0; c < 3; ++c) pose.linear()(r, c) = d->xmat[9 * body + 3 * r + c];
  }
  return pose;
}

std::string shape_mass_note(const VerifyPlan& plan) {
  std::string links;
  for (const Link& link : plan.asset->links)
    if (!has_authored_mass(link) && !link.collisions.empty()) links += (links.empty() ? "'" : ", '") + link.name.text + "'";
  if (links.empty()) return "Mass: every link's own.";
  return fmt::format("Mass: links without an authored mass ({}) take it from their collision shapes at {} kg/m³, as "
                     "PhysX does for a body whose mass is not authored.",
                     links, format_number(kShapeDensity));
}

// Mimic joints whose own limits cannot hold the driven range mapped through the mimic: MuJoCo
// enforces both, so the limit pulls against the mimic constraint and takes torque from the drive.
std::vector<std::string> mimic_limit_notes(const VerifyPlan& plan) {
  std::vector<std::string> notes;
  const Joint& driven = *plan.layout.driven;
  const double from = std::min(plan.layout.open, plan.layout.closed), to = std::max(plan.layout.open, plan.layout.closed);
  for (const Joint* mimic : plan.layout.mimics) {
    if (!mimic->lower || !mimic->upper || mimic->type == JointType::Continuous) continue;
    const double m = mimic->mimic->multiplier.value, offset = mimic->mimic->offset.value;
    const double low = std::min(m * from, m * to) + offset, high = std::max(m * from, m * to) + offset;
    const double lower = mimic->lower->value, upper = mimic->upper->value;
    constexpr double kTolerance = 1e-6;
    if (low >= lower - kTolerance && high <= upper + kTolerance) continue;
    const std::string unit = is_angular(mimic->type) ? "rad" : "m";
    notes.push_back(fmt::format(
        "Limits: mimic '{}' maps '{}' from [{}, {}] {} to [{}, {}] {}, outside its own limits [{}, {}] {}; MuJoCo "
        "enforces both (the limit with its default solref of 0.02 s), so the limit pulls against the mimic and takes "
        "torque from the drive (asset-lint check: mimic-limit-conflict).",
        mimic->name.text, driven.name.text, format_number(from, 4), format_number(to, 4),
        is_angular(driven.type) ? "rad" : "m", format_number(low, 4),
        format_number(high, 4), unit, format_number(lower, 4), format_number(upper, 4), unit));
  }
  return notes;
}

}  // namespace

verify::EngineInfo MujocoEngine::info(const VerifyPlan& plan) const {
  verify::EngineInfo info;
  info.name = "mujoco";
  info.version = mj_versionString();
  info.timestep_s = plan.timestep;
  info.integrator = kIntegrator;
  info.cone = kCone;
  info.impratio = kImpratio;
  const verify::DriveSpec& d = plan.drive;
  info.translation = {
      fmt::format("Drive: PhysX's spring-damper becomes a <general> actuator with an affine bias, force = kp·(target − "
                  "q) − kv·q̇ with kp = {} and kv = {}, {}; integrator=\"implicit\" solves kv at the new velocity so a "
                  "stiff damped drive stays stable.",
                  format_number(d.stiffness, 4), format_number(d.damping, 4),
                  d.max_force ? fmt::format("forcerange ±{} (the max force)", format_number(*d.max_force, 4))
                              : std::string("no force range (no max force)")),
      d.max_velocity
          ? fmt::format("Max joint velocity: MuJoCo has none; the drive's target is ramped from open to closed at {} "
                        "(PhysX's maxJointVelocity), so the joint is not clamped if a force pushes it faster.",
                        format_number(*d.max_velocity, 4))
          : std::string("Max joint velocity: none set; the target steps from open to closed at once."),
      "Armature carries over as MuJoCo's joint armature.",
      plan.layout.mimics.empty()
          ? std::string("Mimic joints: none.")
          : fmt::format("Mimic joints: {} <equality><joint> constraints (q = offset + multiplier·q_driven), solref "
                        "time constant {} s (two steps); the peak tracking error is reported.",
                        plan.layout.mimics.size(), format_number(2 * plan.timestep, 3)),
      fmt::format("Contact: elliptic friction cone and impratio {} (MuJoCo's pyramidal cone and impratio 1 let a "
                  "squeezed box creep out); solref time constant {} s (two steps) and solimp 0.95 0.99 for "
                  "sub-millimetre penetration; multiccd, so a flat mesh face rests on the box in several points; the "
                  "spec's μ on the object and on every gripper geom, because MuJoCo takes the larger of the two and "
                  "defaults to 1.",
                  format_number(kImpratio), format_number(2 * plan.timestep, 3)),
      fmt::format("Mount: the base link rides a {} kg free body welded to a kinematic (mocap) mount that lifts it; the "
                  "gripper's own links do not collide with each other.",
                  format_number(kMountMass)),
  };
  // After the mimic joints' line: their limit conflicts; before the mount's: the mass.
  const auto limits = mimic_limit_notes(plan);
  info.translation.insert(info.translation.begin() + 4, limits.begin(), limits.end());
  info.translation.insert(info.translation.end() - 1, shape_mass_note(plan));
  return info;
}

std::optional<verify::Trajectory> MujocoEngine::run(const VerifyPlan& plan, const SceneSpec& scene, std::string& error) {
  const std::string text = scene_mjcf(plan, scene, error);
  if (text.empty()) return std::nullopt;
  const auto previous_warning = mju_user_warning;
  const auto previous_error = mju_user_error;
  mju_user_warning = on_warning;
  mju_user_error = on_error;
  g_warning.clear();
  struct Restore {
    decltype(mju_user_warning) warning;
    decltype(mju_user_error) error;
    ~Restore() {
      mju_user_warning = warning;
      mju_user_error = error;
    }
  } restore{previous_warning, previous_error};

  std::unique_ptr<mjModel, ModelDeleter> model(compile(text, error));
  if (!model) return std::nullopt;
  mjModel* m = model.get();
  std::unique_ptr<mjData, DataDeleter> data(mj_makeData(m));
  mjData* d = data.get();
  const Asset& asset = *plan.asset;
  const verify::GripperLayout& layout = plan.layout;

  const auto joint_address = [&](const Joint& joint) {
    const int id = mj_name2id(m, mjOBJ_JOINT, joint_name(asset, joint).c_str());
    return m->jnt_qposadr[id];
  };
  const int driven = joint_address(*layout.driven);
  std::vector<std::pair<int, const Joint*>> mimics;
  for (const Joint* mimic : layout.mimics) mimics.emplace_back(joint_address(*mimic), mimic);
  std::array<int, 2> pads{};
  for (int side = 0; side < 2; ++side)
    pads[side] = mj_name2id(m, mjOBJ_BODY, body_name(asset, *asset.find_link(layout.pads[side])).c_str());
  const int object_body = scene.object ? mj_name2id(m, mjOBJ_BODY, "object") : -1;
  const int object_geom = scene.object ? mj_name2id(m, mjOBJ_GEOM, "object") : -1;
  const int mocap = m->body_mocapid[mj_name2id(m, mjOBJ_BODY, "mount")];

  // Start open, the mimics where their constraints put them.
  d->qpos[driven] = layout.open;
  for (const auto& [address, joint] : mimics)
    d->qpos[address] = joint->mimic->multiplier.value * layout.open + joint->mimic->offset.value;
  const Eigen::Vector3d up = -layout.approach;
  const auto set_inputs = [&](double t) {
    d->ctrl[0] = verify::drive_target(plan, t);
    const bool gravity = scene.gravity && t >= scene.gravity_on_at - 1e-12;
    for (int i = 0; i < 3; ++i) {
      m->opt.gravity[i] = gravity ? plan.gravity * layout.approach(i) : 0.0;
      d->mocap_pos[3 * mocap + i] = lift_height(scene, t) * up(i);
    }
  };
  verify::Trajectory trajectory;
  std::vector<mjtNum> momentum(m->nv);
  const auto sample = [&](double penetration) {
    verify::Sample s;
    s.t = d->time;
    s.q = d->qpos[driven];
    for (const auto& [address, joint] : mimics)
      s.mimic_error = std::max(s.mimic_error, std::abs(d->qpos[address] - (joint->mimic->multiplier.value * s.q +
                                                                           joint->mimic->offset.value)));
    for (int side = 0; side < 2; ++side) s.pads[side] = body_pose(d, pads[side]);
    for (int i = 0; i < 3; ++i) s.mount(i) = d->mocap_pos[3 * mocap + i];
    if (object_body >= 0) {
      s.object = body_pose(d, object_body).translation();
      for (int c = 0; c < d->ncon; ++c) {
        const mjContact& contact = d->contact[c];
        if (contact.geom1 != object_geom && contact.geom2 != object_geom) continue;
        mjtNum force[6];
        mj_contactForce(m, d, c, force);
        const Eigen::Vector3d normal(contact.frame[0], contact.frame[1], contact.frame[2]);
        // The normal points from geom1 to geom2: the object is pushed along it when it is geom2.
        const Eigen::Vector3d on_object = (contact.geom2 == object_geom ? 1.0 : -1.0) * force[0] * normal;
        s.normal_force[on_object.dot(layout.closing) > 0 ? 0 : 1] += force[0];
      }
    }
    s.penetration = penetration;
    // ½·q̇ᵀ·M·q̇ with the step's mass matrix (mj_energyVel left d->energy[1] at 0 in MuJoCo 2.2.2 here).
    mj_mulM(m, d, momentum.data(), d->qvel);
    s.kinetic_energy = 0.5 * mju_dot(momentum.data(), d->qvel, m->nv);
    trajectory.samples.push_back(s);
  };

  try {
    set_inputs(0);
    mj_forward(m, d);
    sample(0);
    const int per_frame = std::max(1, static_cast<int>(std::lround(plan.frame / plan.timestep)));
    const long frames = std::lround(scene.duration / (per_frame * plan.timestep));
    for (long frame = 0; frame < frames; ++frame) {
      double penetration = 0;
      for (int step = 0; step < per_frame; ++step) {
        set_inputs(d->time);
        mj_step(m, d);
        ++trajectory.steps;
        for (int c = 0; c < d->ncon; ++c)
          if (d->contact[c].geom1 == object_geom || d->contact[c].geom2 == object_geom)
            penetration = std::max(penetration, -d->contact[c].dist);
      }
      bool finite = true;
      for (int i = 0; i < m->nq; ++i) finite = finite && std::isfinite(d->qpos[i]);
      for (int i = 0; i < m->nv; ++i) finite = finite && std::isfinite(d->qvel[i]);
      if (!finite || !g_warning.empty()) {
        trajectory.diverged = true;
        trajectory.divergence = !finite ? fmt::format("non-finite state at {} s", format_number(d->time, 3))
                                        : fmt::format("MuJoCo warning at {} s: {}", format_number(d->time, 3), g_warning);
        break;
      }
      sample(penetration);
    }
  } catch (const std::runtime_error& e) {
    error = fmt::format("MuJoCo error in scene '{}': {}", scene.name, e.what());
    return std::nullopt;
  }
  return trajectory;
}

}  // namespace assetlint::backends::mujoco
