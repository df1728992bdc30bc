#pragma once
// The verification scenes stepped headless in MuJoCo (libmujoco, the C API): each scene is
// written as MJCF (mjcf_scene.h), compiled from memory and stepped; positions, contact
// depths and contact forces are sampled once per frame.
#include "verify/engine.h"

namespace assetlint::backends::mujoco {

class MujocoEngine final : public verify::Engine {
 public:
  verify::EngineInfo info(const verify::VerifyPlan& plan) const override;
  std::optional<verify::Trajectory> run(const verify::VerifyPlan& plan, const verify::SceneSpec& scene,
                                        std::string& error) override;
};

}  // namespace assetlint::backends::mujoco
