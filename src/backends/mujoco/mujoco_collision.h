#pragma once
// collision::Engine on MuJoCo's own collision pipeline (libmujoco, the C API): the shapes are
// written as an MJCF model, one free body per collision body so that every pair of bodies is
// tested (no parent filter, no weld), compiled from memory, and mj_collision's contacts read
// after mj_kinematics. Meshes collide as their convex hull, as in any MuJoCo model.
#include "engine/collision.h"

namespace assetlint::backends::mujoco {

class MujocoCollision final : public collision::Engine {
 public:
  std::string name() const override;
  std::optional<collision::Overlaps> overlaps(const std::vector<collision::PlacedShape>& shapes,
                                              std::string& error) const override;
};

// The instance the pipeline installs.
const MujocoCollision& collision_engine();

}  // namespace assetlint::backends::mujoco
