#pragma once
// A physics engine that steps the drive tests (verify/drive_plan.h): the whole robot, base
// fixed, gravity on. One instance per plan; `run` and `gravity_torque` may be called from
// several threads at once.
#include <optional>
#include <string>
#include <vector>

#include "verify/drive_plan.h"

namespace assetlint::verify {

struct DriveSample {
  double t = 0;
  double q = 0, velocity = 0, target = 0;  // the tested joint
  double mimic_error = 0;                  // max |q_follower − (multiplier·q + offset)| over its followers
  double kinetic_energy = 0;               // J: of the whole robot
};

struct DriveTrajectory {
  std::vector<DriveSample> samples;  // the first at t = 0
  bool diverged = false;
  std::string divergence;
  double energy_budget = 0;  // J: physics/drive_response.h, for this scene
  long steps = 0;
};

class DriveEngine {
 public:
  virtual ~DriveEngine() = default;
  virtual std::optional<DriveTrajectory> run(const DriveScene& scene, std::string& error) const = 0;
  // The torque (force) the joint's drive must supply to hold still against gravity with the
  // joint at q and every other joint at its start, its followers where their mimics put them.
  virtual double gravity_torque(std::size_t joint, double q) const = 0;
  // The inertia the joint sees at its start pose with every other joint held (Mᵢᵢ, armature
  // and followers reflected included), kg·m² or kg.
  virtual double joint_inertia(std::size_t joint) const = 0;
};

}  // namespace assetlint::verify
