#pragma once
// What MuJoCo's compiler refuses in a body's inertia (MuJoCo 3.3 and later, mjCBody::Compile in
// src/user/user_objects.cc and mjuu_fullInertia in src/user/user_util.cc). It checks every body
// of the model as written, before fusestatic merges the bodies welded by fixed joints, so a
// welded link's tensor can refuse a file whose fused model would be fine.
#include <Eigen/Core>
#include <optional>
#include <string>

namespace assetlint::physics {

// mjEPS: the smallest eigenvalue mjuu_fullInertia accepts in a full tensor (kg·m²).
inline constexpr double kMujocoMinEigenvalue = 1e-14;

// How the tensor reaches MuJoCo's compiler.
struct MujocoInertiaInput {
  // A full tensor (URDF <inertia>, MJCF fullinertia) is diagonalised by MuJoCo and refused
  // when an eigenvalue is under kMujocoMinEigenvalue; a URDF tensor of six zeros counts as
  // unwritten. A diagonal one (MJCF diaginertia) is first raised to boundinertia (0 by default,
  // which lifts a negative moment to 0) and refused only when A + B < C. When the form is
  // unknown only what refuses both is named.
  enum class Form { Full, Diagonal, Unknown };
  Form form = Form::Full;
  double boundinertia = 0;      // <compiler boundinertia>: every principal moment raised to it
  bool balanceinertia = false;  // <compiler balanceinertia>: A + B < C balanced, not refused
};

// The compiler's error message for this tensor (about the COM, any frame), or nullopt when it
// compiles it. A + B ≥ C is checked exactly on the principal moments; an excess within the
// noise of diagonalising (1e-9 of the largest moment) is taken as equality.
std::optional<std::string> mujoco_inertia_refusal(const Eigen::Matrix3d& inertia, const MujocoInertiaInput& input);

}  // namespace assetlint::physics
