// The order in which OpenUSD's text writer lists properties (dictionary_less,
// formats/usdc/crate_usda_style.h), which the crate layer reader follows.
#include <catch2/catch.hpp>

#include <string_view>

#include "formats/usdc/crate_usda_style.h"

using assetlint::usdc::dictionary_less;

TEST_CASE("properties are ordered as OpenUSD's text writer orders them", "[usdc]") {
  // Letters without regard to case; a shared prefix does not decide.
  CHECK(dictionary_less("physics:damping", "physics:Stiffness"));
  CHECK_FALSE(dictionary_less("physics:Stiffness", "physics:damping"));
  CHECK(dictionary_less("drive:angular:physics:damping", "drive:angular:physics:stiffness"));
  // Digit runs by value, also where they start inside the shared prefix.
  CHECK(dictionary_less("joint9", "joint10"));
  CHECK(dictionary_less("joint19", "joint100"));
  CHECK_FALSE(dictionary_less("joint100", "joint19"));
  CHECK(dictionary_less("link2:mass", "link12:mass"));
  // Leading zeros do not count toward the value; equal values fall back to byte order.
  CHECK(dictionary_less("a001b", "a2b"));
  CHECK(dictionary_less("a01", "a1"));
  CHECK_FALSE(dictionary_less("a1", "a01"));
  // A prefix sorts first; a name is not less than itself.
  CHECK(dictionary_less("physics", "physics:mass"));
  CHECK_FALSE(dictionary_less("physics:mass", "physics:mass"));
  // '_' before letters.
  CHECK(dictionary_less("a_b", "aab"));
}
