#pragma once
// The drive tests of every actuated joint (docs/verify.md "Drive tests"), engine-neutral: which
// joints are tested with which gains, the pose the rest of the robot holds, and the target
// each scene gives the tested joint. A backend steps the whole robot, base fixed, gravity on,
// every drive at its gains; src/verify/drive_metrics.h judges what it sampled.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "engine/settings.h"
#include "model/asset.h"
#include "verify/gripper_layout.h"
#include "verify/scene.h"

namespace assetlint::verify {

enum class DriveTestKind { Step, Sweep, Hold, Velocity, Mimic };
std::string_view drive_test_name(DriveTestKind kind);

// One joint under test: a single-DOF joint that no other joint drives through a mimic.
struct TestedJoint {
  const Joint* joint = nullptr;
  bool angular = true;
  std::optional<double> lower, upper;  // finite limits (rad or m); unset for a continuous joint
  double start = 0;                    // where it stands while another joint is tested
  std::optional<DriveSpec> drive;      // unset: no position drive
  std::string no_drive;                // why there is none
  std::vector<const Joint*> followers;  // mimic joints that follow it
  const char* unit() const { return angular ? "rad" : "m"; }
  const char* force_unit() const { return angular ? "N·m" : "N"; }
};

struct DrivePlan {
  const Asset* asset = nullptr;
  MeshPoints meshes;                 // collision meshes of links whose mass comes from their shapes
  std::vector<TestedJoint> joints;   // in the asset's joint order
  std::vector<std::string> held_rigid;  // joints the scene welds: the multi-DOF ones
  bool base_pinned = false;          // the asset's base floats (a free joint or none to the world); the scene fixes it
  std::string base;                  // the root link
  // Links that do not move in the scene: welded to a root through fixed, floating (pinned) or
  // multi-DOF (welded) joints. Their mass does not matter; the others' must be known.
  std::set<std::string, std::less<>> static_links;
  double timestep = 0;               // s: the engine's step
  std::string timestep_origin;
  double sample = 0;                 // s: the sampling interval (the step, at most 1 ms apart)
  double gravity = 9.81;             // m/s², along −z of the root's frame
  VerifySettings::Drives limits;
  // Index into `joints` of a tested joint by name; nullopt when it is not tested.
  std::optional<std::size_t> index_of(std::string_view joint) const;
};

// A scene of one joint: its target over time (piecewise linear through `waypoints`; two at the
// same time make a step), every other tested joint at its start, gravity on.
struct DriveScene {
  std::string name;  // "step 'joint1'"
  DriveTestKind kind = DriveTestKind::Step;
  std::size_t joint = 0;  // into DrivePlan::joints
  double duration = 0;
  std::vector<std::pair<double, double>> waypoints;  // (t, target)
  double step_at = 0;    // step: when the target steps
  // The scene may end early once the robot has been at rest this long after `step_at` (a robot at
  // rest under constant targets stays at rest): 0 never.
  double rest_ends = 0;
  std::vector<double> marks;  // sweep: when the target reaches the upper limit's hold end, the lower's, and the end
  double speed = 0;      // sweep: how fast its target moves (rad/s or m/s)
  double rest = 0;       // sweep: how long it rests at each limit (s)
  std::string ramp;      // how fast the sweep's target moves, and why (1 rad/s or 0.1 m/s without a max velocity)
  std::string not_run;   // non-empty: not stepped, and why
};

double scene_target(const DriveScene& scene, double t);

// Every joint that would be tested, with its gains and start pose; `timestep`, `sample` and
// `gravity` are left for the caller.
DrivePlan plan_drive_tests(const Asset& asset, const Settings& settings);

// The scenes that are stepped: one step and one sweep per tested joint with a drive (a
// continuous joint's sweep not run: it has no limits to reach).
std::vector<DriveScene> drive_scenes(const DrivePlan& plan);

}  // namespace assetlint::verify
