#pragma once
// A physics engine that steps the verification scenes: one folder per engine under
// src/backends/, each implementing this.
#include <optional>
#include <string>
#include <vector>

#include "verify/scene.h"
#include "verify/trajectory.h"

namespace assetlint::verify {

struct EngineInfo {
  std::string name;        // "mujoco"
  std::string version;     // the library's own version string
  double timestep_s = 0;
  std::string integrator;  // "implicit"
  std::string cone;        // "elliptic"
  double impratio = 0;
  // What a user must know about the translation, one sentence each: drives, mimics, contact, mount.
  std::vector<std::string> translation;
};

class Engine {
 public:
  virtual ~Engine() = default;
  virtual EngineInfo info(const VerifyPlan& plan) const = 0;
  // Steps one scene; nullopt with `error` set when the engine cannot build it (an error, not a verdict).
  virtual std::optional<Trajectory> run(const VerifyPlan& plan, const SceneSpec& scene, std::string& error) = 0;
};

}  // namespace assetlint::verify
