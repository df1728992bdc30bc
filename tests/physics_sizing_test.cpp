#include <catch2/catch.hpp>

#include "physics/sizing.h"

using namespace assetlint;

TEST_CASE("sizing: the guide's stiffness, close time, and rotor inertia", "[physics]") {
  CHECK(physics::stiffness_for_force(24.0, 5.0 * 3.14159265358979 / 180.0) == Approx(275.02).epsilon(1e-4));
  CHECK(physics::close_time(0.085, 0.15) == Approx(0.0425 / 0.15).epsilon(1e-12));
  CHECK(physics::rotor_inertia_for_armature(5e-3, 50.0) == Approx(2e-6).epsilon(1e-12));
}
