#include "physics/solid_inertia.h"

#include <numbers>

namespace assetlint::physics {

double solid_volume(const SolidShape& shape) {
  const Eigen::Vector3d& s = shape.size;
  constexpr double pi = std::numbers::pi;
  switch (shape.kind) {
    case Solid::Sphere: return 4.0 * pi * s[0] * s[0] * s[0] / 3.0;
    case Solid::Capsule: return pi * s[0] * s[0] * (2.0 * s[1]) + 4.0 * pi * s[0] * s[0] * s[0] / 3.0;
    case Solid::Cylinder: return pi * s[0] * s[0] * (2.0 * s[1]);
    case Solid::Box: return 8.0 * s[0] * s[1] * s[2];
    case Solid::Ellipsoid: return 4.0 * pi * s[0] * s[1] * s[2] / 3.0;
  }
  return 0.0;
}

Eigen::Vector3d solid_principal_moments(const SolidShape& shape, double mass) {
  const Eigen::Vector3d& s = shape.size;
  switch (shape.kind) {
    case Solid::Sphere: return Eigen::Vector3d::Constant(2.0 * mass * s[0] * s[0] / 5.0);
    case Solid::Capsule: {
      const double r = s[0], height = 2.0 * s[1];
      // The two hemispheres make one sphere's volume: (4/3)πr³ against πr²·height.
      const double spheres = mass * 4.0 * r / (4.0 * r + 3.0 * height);
      const double cylinder = mass - spheres;
      const double across_cylinder = cylinder * (3.0 * r * r + height * height) / 12.0;
      // Each hemisphere about its own centroid, moved to the capsule's: 2r²/5 about the
      // sphere centre, plus the shift of the centroid (height/2 + 3r/8) net of its own offset.
      const double across_spheres = spheres * (2.0 * r * r / 5.0 + height * height / 4.0 + 3.0 * height * r / 8.0);
      const double along = cylinder * r * r / 2.0 + spheres * 2.0 * r * r / 5.0;
      return {across_cylinder + across_spheres, across_cylinder + across_spheres, along};
    }
    case Solid::Cylinder: {
      const double r = s[0], height = 2.0 * s[1];
      const double across = mass * (3.0 * r * r + height * height) / 12.0;
      return {across, across, mass * r * r / 2.0};
    }
    case Solid::Box:
      return {mass * (s[1] * s[1] + s[2] * s[2]) / 3.0, mass * (s[0] * s[0] + s[2] * s[2]) / 3.0,
              mass * (s[0] * s[0] + s[1] * s[1]) / 3.0};
    case Solid::Ellipsoid:
      return {mass * (s[1] * s[1] + s[2] * s[2]) / 5.0, mass * (s[0] * s[0] + s[2] * s[2]) / 5.0,
              mass * (s[0] * s[0] + s[1] * s[1]) / 5.0};
  }
  return Eigen::Vector3d::Zero();
}

MassPart combine_parts(const std::vector<MassPart>& parts) {
  MassPart total;
  for (const MassPart& p : parts) {
    total.mass += p.mass;
    total.com += p.mass * p.com;
  }
  if (!(total.mass > 0)) return total;
  total.com /= total.mass;
  for (const MassPart& p : parts) {
    const Eigen::Vector3d d = p.com - total.com;
    total.inertia += p.inertia + p.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  return total;
}

}  // namespace assetlint::physics
