#pragma once
// The guide's verification scenes (docs/verify.md), engine-neutral: what is in each scene,
// how it is driven and for how long. A backend (src/backends/<engine>/) turns a plan into
// its own scene and steps it; src/verify/metrics.h judges what it sampled.
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/settings.h"
#include "model/asset.h"
#include "verify/gripper_layout.h"

namespace assetlint::verify {

enum class SceneKind { Close, Grasp, Hold, Lift };
std::string_view kind_name(SceneKind kind);

// The box between the pads, in the base frame: its edges along closing, lateral, approach.
struct ObjectSpec {
  std::string shape = "box";
  double width = 0;     // m, along the closing direction
  double depth = 0;     // m, along the lateral direction
  double height = 0;    // m, along the approach direction
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // base frame
  double mass = 0;      // kg: the payload
  double friction = 0;  // the spec's μ
  double opening = 0;   // the driven joint's position where the pads meet it
  std::string sized_for;  // "almost open", "halfway", "nearly closed (…)"
};

struct SceneSpec {
  std::string name;  // "grasp 42.5 mm"
  SceneKind kind = SceneKind::Close;
  std::optional<ObjectSpec> object;
  bool gravity = false;       // whether gravity acts at all in the scene
  double gravity_on_at = 0;   // s: gravity switches on here (0: from the start)
  double lift_start = 0, lift_duration = 0, lift_height = 0;  // the mount's lift (height 0: none)
  double duration = 0;        // s simulated
  double window = 0;          // s: the last `window` seconds give the steady values and the jitter
  double judged_from = 0;     // s: slip is measured from here (gravity on, or the lift's start)
  std::string not_run;        // non-empty: why the scene cannot be judged (it is not stepped)
};

// The driven joint's drive as PhysX has it, in model units.
struct DriveSpec {
  double stiffness = 0, damping = 0;
  std::optional<double> max_force;     // N·m (N); unset: unbounded
  std::optional<double> max_velocity;  // rad/s (m/s); unset: unbounded
  std::string origin;                  // where the gains came from
};

struct VerifyPlan {
  const Asset* asset = nullptr;
  GripperLayout layout;
  MeshPoints meshes;
  std::string asset_dir;  // the asset's directory (meshes resolve against it)
  DriveSpec drive;
  double timestep = 0;    // s: the engine's step (PhysX's h: dt/N under TGS, dt under PGS; MJCF's timestep)
  std::string timestep_origin;
  double frame = 0;       // s: the sampling interval (one PhysX frame, dt)
  double gravity = 9.81;  // m/s²
  std::optional<double> spec_close_time;  // s: (stroke / 2) / finger speed
  std::optional<double> required_grip_force;  // N: m·g/μ
  std::vector<SceneSpec> scenes;
};

// The close, grasp ×3, hold ×3 and lift scenes of `layout` with the spec of `settings`.
// Scenes whose spec inputs are missing carry `not_run`.
std::vector<SceneSpec> build_scenes(const VerifyPlan& plan, const Settings& settings);

// The drive's target at time t: the closed position approached at the max velocity from
// the open one (PhysX's maxJointVelocity, emulated by ramping the target), else a step.
double drive_target(const VerifyPlan& plan, double t);

}  // namespace assetlint::verify
