#include "physics/mujoco_inertia.h"

#include <algorithm>

#include "physics/inertia.h"

namespace assetlint::physics {

std::optional<std::string> mujoco_inertia_refusal(const Eigen::Matrix3d& inertia, const MujocoInertiaInput& input) {
  Eigen::Vector3d moments = principal_moments(inertia);
  using Form = MujocoInertiaInput::Form;
  if (input.form == Form::Full) {
    if (inertia.isZero(0.0)) return std::nullopt;  // unwritten: the body is a point mass
    if (moments[0] < kMujocoMinEigenvalue) return "inertia must have positive eigenvalues";
  }
  // A negative moment of a full tensor fails the eigenvalue check; a diagonal one is raised to
  // boundinertia (0 by default) first, so whether it is refused is not known without the form.
  if (input.form == Form::Unknown && moments[0] < 0) return std::nullopt;
  moments = moments.cwiseMax(input.boundinertia);
  if (moments.minCoeff() < 0) return "mass and inertia cannot be negative";  // a negative boundinertia
  std::sort(moments.data(), moments.data() + 3);
  const double noise = 1e-9 * moments[2];
  if (moments[0] + moments[1] < moments[2] - noise && !input.balanceinertia)
    return "inertia must satisfy A + B >= C; use 'balanceinertia' to fix";
  return std::nullopt;
}

}  // namespace assetlint::physics
