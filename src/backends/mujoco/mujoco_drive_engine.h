#pragma once
// The drive tests stepped headless in MuJoCo (libmujoco, the C API): the scene of
// drive_scene.h is compiled once and each test steps its own mjData, so tests run in parallel.
// Gravity's pull on a joint comes from MuJoCo's recursive Newton–Euler inverse dynamics
// (mj_rne, inside mj_forward: qfrc_bias at rest).
#include <memory>
#include <string>
#include <vector>

#include "verify/drive_engine.h"


namespace assetlint::backends::mujoco {

class MujocoDriveEngine final : public verify::DriveEngine {
 public:
  // Compiles the plan's scene; `error` is set (and every call fails) when it cannot be built.
  MujocoDriveEngine(const verify::DrivePlan& plan, std::string& error);
  ~MujocoDriveEngine() override;

  std::optional<verify::DriveTrajectory> run(const verify::DriveScene& scene, std::string& error) const override;
  double gravity_torque(std::size_t joint, double q) const override;
  double joint_inertia(std::size_t joint) const override;
  // What the report says about the translation, one sentence each.
  std::vector<std::string> translation() const;
  std::string version() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace assetlint::backends::mujoco
