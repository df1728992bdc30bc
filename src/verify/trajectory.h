#pragma once
// What a backend samples while it steps a scene, once per frame, in the scene's world frame
// (the base frame at t = 0; the mount lifts along −approach).
#include <Eigen/Geometry>
#include <array>
#include <string>
#include <vector>

namespace assetlint::verify {

struct Sample {
  double t = 0;
  double q = 0;                 // the driven joint's position
  double mimic_error = 0;       // max |q_mimic − (multiplier·q + offset)| over the mimics
  std::array<Eigen::Isometry3d, 2> pads{Eigen::Isometry3d::Identity(), Eigen::Isometry3d::Identity()};
  Eigen::Vector3d mount = Eigen::Vector3d::Zero();
  Eigen::Vector3d object = Eigen::Vector3d::Zero();  // the object's centre (scenes with one)
  double penetration = 0;       // m: the deepest gripper–object contact over the frame's steps (0: none)
  std::array<double, 2> normal_force{0, 0};  // N: each side's contact normal force on the object at the frame's end
  double kinetic_energy = 0;    // J: of every body in the scene at the frame's end
};

struct Trajectory {
  std::vector<Sample> samples;  // the first at t = 0
  bool diverged = false;
  std::string divergence;       // what: "non-finite state at 0.31 s", "MuJoCo warning: …"
  long steps = 0;               // engine steps taken
};

}  // namespace assetlint::verify
