#include <catch2/catch.hpp>

#include "physics/sizing.h"

using namespace assetlint;

TEST_CASE("sizing: the guide's stiffness, close time, rotor inertia and torque rounding", "[physics]") {
  CHECK(physics::stiffness_for_force(24.0, 5.0 * 3.14159265358979 / 180.0) == Approx(275.02).epsilon(1e-4));
  CHECK(physics::close_time(0.085, 0.15) == Approx(0.0425 / 0.15).epsilon(1e-12));
  CHECK(physics::rotor_inertia_for_armature(5e-3, 50.0) == Approx(2e-6).epsilon(1e-12));
  CHECK(physics::round_up_to_multiple(3.3333, 1.0) == 4.0);
  CHECK(physics::round_up_to_multiple(4.0, 1.0) == 4.0);
  CHECK(physics::round_up_to_multiple(0.3 * 3, 0.3) == Approx(0.9));  // 0.8999999… stays 0.9
  CHECK(physics::round_up_to_multiple(3.3333, 0.5) == 3.5);
  CHECK(physics::round_up_to_multiple(3.3333, 0.0) == 3.3333);  // no margin: unchanged
}
