#pragma once
// The measurements of the drive tests and their verdicts against [verify.drives]
// (docs/verify.md "Drive tests"), with the physics of each failure and the change that
// fixes it: engine-neutral, from what a DriveEngine sampled and computed.
#include <optional>
#include <string>
#include <vector>

#include "verify/drive_engine.h"
#include "verify/drive_plan.h"

namespace assetlint::verify {

// Set only where it applies to the test.
struct DriveMetrics {
  std::optional<double> step_size, overshoot, settle_time_s, settle_time_2pct_s, steady_error;
  std::optional<int> sign_changes;
  std::optional<double> end_error, end_error_upper, end_error_lower, return_error;
  std::optional<double> peak_velocity, velocity_limit;
  std::optional<double> gravity_torque_max, gravity_torque_at, effort_limit, effort_margin, droop;
  std::optional<double> mimic_error_max;
  std::optional<bool> diverged;
};

// What the joint's drive meets, from the engine: its inertia and gravity's pull.
struct JointLoads {
  double inertia = 0;             // Mᵢᵢ at the start pose, every other joint held
  double gravity_at_start = 0;    // the torque (force) to hold the joint at its start
  double gravity_max = 0;         // the largest over its range, |·|
  double gravity_max_at = 0;      // where
  double gravity_at_step = 0;     // at the step's target
};
JointLoads joint_loads(const DrivePlan& plan, const DriveEngine& engine, std::size_t joint);

// Gains that pass where today's fail: damping for a damping ratio of 1 on the inertia the
// joint sees; stiffness the largest of today's, what keeps the droop under [verify.drives] droop
// over the whole range, what keeps gravity's pull at the step's target within half the settle band,
// and what settles within a fifth of the settle limit; a max force raised to the largest
// gravity torque when it is below it.
DriveSpec proposed_drive(const DrivePlan& plan, std::size_t joint, const JointLoads& loads);

struct DriveResult {
  std::string name;  // "step 'joint1'"
  DriveTestKind kind = DriveTestKind::Step;
  std::string joint;
  bool angular = true;
  bool ran = false, passed = false;
  DriveMetrics metrics;
  std::vector<std::string> failures;  // one sentence per threshold missed ("not run: …" when not run)
  std::vector<std::string> causes;    // the physics behind the failures
  std::string fix;                    // the change that fixes them, in the joint's units
  const DriveTrajectory* trajectory = nullptr;  // the scene it was measured on (step, sweep, velocity, mimic)
  const DriveScene* scene = nullptr;
};

// Every test of one joint, in the order step, sweep, hold, velocity, mimic (mimic only with
// followers); a joint without a drive gives one result, not run. `step` and `sweep` are null
// when the scene was not run (its not_run says why).
std::vector<DriveResult> judge_joint(const DrivePlan& plan, std::size_t joint, const JointLoads& loads,
                                     const DriveScene* step_scene, const DriveTrajectory* step,
                                     const DriveScene* sweep_scene, const DriveTrajectory* sweep);

}  // namespace assetlint::verify
