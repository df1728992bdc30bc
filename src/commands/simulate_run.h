#pragma once
// The time series `asset-lint simulate` steps (docs/simulate.md): PhysX's implicit drive
// row on one degree of freedom (src/physics/drive_row.h) beside the explicit spring at
// the same step h, frame by frame.
#include <optional>
#include <string>
#include <vector>

#include "commands/simulate_metrics.h"
#include "physics/drive_row.h"
#include "physics/servo_step.h"

namespace assetlint::commands {

// An MJCF asset is stepped as MuJoCo steps it, not by PhysX's row.
struct MujocoSetup {
  physics::MujocoIntegrator integrator = physics::MujocoIntegrator::Euler;
  physics::Servo servo;
};

struct SimulationSetup {
  physics::DriveRow row;  // the step, rate and gains; PhysX's row unless `mujoco` is set
  std::optional<MujocoSetup> mujoco;
  physics::FrameLimits limits;
  double from = 0;    // rad (m)
  double target = 0;  // rad (m)
  double load = 0;    // N·m (N): a constant torque on the joint, against the drive when it opposes the motion
  int frames = 0;
};

struct SimulationRun {
  std::string engine = "implicit (PhysX)";  // what stepped `implicit`: "MuJoCo (implicitfast)" for MJCF
  std::vector<Sample> implicit;  // the engine's drive: one sample per frame, the first at t = 0
  std::vector<Sample> explicit_spring;  // stops at divergence
  Metrics implicit_metrics;
  Metrics explicit_metrics;
  bool explicit_stable = true;  // physics::explicit_stable: false when only the clamps bound it
};

// Solver steps (frames × sub-steps) a run may take: `simulate` refuses longer requests.
inline constexpr double kMaxSolverSteps = 2e7;

SimulationRun run_simulation(const SimulationSetup& setup);

}  // namespace assetlint::commands
