// Mass properties of the solids MuJoCo derives from geoms, against closed forms worked by hand.
#include <catch2/catch.hpp>

#include <numbers>

#include "physics/solid_inertia.h"

using namespace assetlint::physics;

TEST_CASE("solid volumes and moments match their closed forms", "[physics][solid]") {
  constexpr double pi = std::numbers::pi;
  SECTION("a 0.1 m sphere of 1 kg: 2/5 m r^2") {
    const SolidShape s{Solid::Sphere, {0.1, 0, 0}};
    CHECK(solid_volume(s) == Approx(4.18879e-3).epsilon(1e-5));
    CHECK(solid_principal_moments(s, 1.0)[0] == Approx(0.004));
  }
  SECTION("a box of half extents 0.1, 0.2, 0.3 and 6 kg: m (b^2 + c^2) / 3") {
    const SolidShape s{Solid::Box, {0.1, 0.2, 0.3}};
    CHECK(solid_volume(s) == Approx(0.048));
    const auto m = solid_principal_moments(s, 6.0);
    CHECK(m[0] == Approx(2.0 * (0.04 + 0.09)));
    CHECK(m[1] == Approx(2.0 * (0.01 + 0.09)));
    CHECK(m[2] == Approx(2.0 * (0.01 + 0.04)));
  }
  SECTION("a cylinder of radius 0.05 m, 0.4 m long, 2 kg") {
    const SolidShape s{Solid::Cylinder, {0.05, 0.2, 0}};
    CHECK(solid_volume(s) == Approx(pi * 0.0025 * 0.4));
    const auto m = solid_principal_moments(s, 2.0);
    CHECK(m[0] == Approx(2.0 * (3 * 0.0025 + 0.16) / 12));
    CHECK(m[2] == Approx(0.0025));
  }
  SECTION("a capsule is its cylinder plus a sphere split at the ends") {
    // r = 0.1, cylinder 0.2 long, density 1000: cylinder 6.2832 kg, spheres 4.1888 kg.
    const SolidShape s{Solid::Capsule, {0.1, 0.1, 0}};
    const double volume = solid_volume(s);
    CHECK(volume == Approx(pi * 0.01 * 0.2 + 4.0 * pi * 0.001 / 3.0));
    const double mass = 1000 * volume, cylinder = 1000 * pi * 0.01 * 0.2, spheres = mass - cylinder;
    const auto m = solid_principal_moments(s, mass);
    // Hemisphere centroid at 0.1 + 3/8·0.1 from the middle; about its own centroid a hemisphere
    // has 2/5 m r² − m (3r/8)² across.
    const double d = 0.1 + 0.0375;
    const double hemisphere_across = (spheres / 2) * (0.4 * 0.01 - 0.0375 * 0.0375) + (spheres / 2) * d * d;
    CHECK(m[0] == Approx(cylinder * (3 * 0.01 + 0.04) / 12 + 2 * hemisphere_across));
    CHECK(m[2] == Approx(cylinder * 0.01 / 2 + spheres * 0.4 * 0.01));
  }
  SECTION("an ellipsoid: m (b^2 + c^2) / 5") {
    const auto m = solid_principal_moments({Solid::Ellipsoid, {0.1, 0.2, 0.3}}, 5.0);
    CHECK(m[0] == Approx(0.13));
    CHECK(m[2] == Approx(0.05));
  }
}

TEST_CASE("two point-like parts combine with the parallel-axis theorem", "[physics][solid]") {
  MassPart a, b;
  a.mass = b.mass = 1.0;
  a.com = {0.5, 0, 0};
  b.com = {-0.5, 0, 0};
  a.inertia = b.inertia = Eigen::Matrix3d::Identity() * 0.01;
  const MassPart total = combine_parts({a, b});
  CHECK(total.mass == 2.0);
  CHECK(total.com.norm() == Approx(0.0).margin(1e-15));
  CHECK(total.inertia(0, 0) == Approx(0.02));
  CHECK(total.inertia(1, 1) == Approx(0.02 + 0.5));
  CHECK(total.inertia(2, 2) == Approx(0.02 + 0.5));
}
