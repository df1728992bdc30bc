#include <catch2/catch.hpp>

#include <limits>

#include "engine/settings.h"
#include "util/numbers.h"

using namespace assetlint;

TEST_CASE("format_number writes the shortest text at the requested precision", "[util]") {
  CHECK(format_number(275.86206896551727, 3) == "276");
  CHECK(format_number(275.86206896551727) == "275.862");
  CHECK(format_number(0.8203047484373349) == "0.820305");
  CHECK(format_number(2.9) == "2.9");
  CHECK(format_number(2.0) == "2");
  CHECK(format_number(-0.8757) == "-0.8757");
  CHECK(format_number(166.15776058) == "166.158");
  CHECK(format_number(0.0612) == "0.0612");
  CHECK(format_number(3.37e-6) == "3.37e-6");
  CHECK(format_number(2.1e-6, 4) == "2.1e-6");
  CHECK(format_number(1e9) == "1e9");
  CHECK(format_number(12345678.0) == "1.23457e7");
  CHECK(format_number(1234567.0) == "1234570");
  CHECK(format_number(999999.0) == "999999");
  CHECK(format_number(0.0) == "0");
  CHECK(format_number(-0.0000001, 2) == "-1e-7");
  CHECK(format_number(std::numeric_limits<double>::infinity()) == "inf");
  CHECK(format_number(41127.3, 3) == "41100");
}

TEST_CASE("rounded-up and bounded formatting", "[util]") {
  CHECK(format_number_rounded_up(13.333333, 3) == "13.4");
  CHECK(format_number_rounded_up(20.000000000000004, 3) == "20");
  CHECK(format_number_rounded_up(6.6667, 3) == "6.67");
  CHECK(format_number_rounded_up(0.08333, 2) == "0.084");
  CHECK(format_number_at_least(3.57689069, 6) == "3.576891");
  CHECK(format_number_at_most(4.8530, 4) == "4.853");
  CHECK(format_number_at_most(0.08470001, 3) == "0.0847");
}

TEST_CASE("parse_double accepts whole numbers only", "[util]") {
  CHECK(parse_double("47") == 47.0);
  CHECK(parse_double("+1.5e-3") == 0.0015);
  CHECK(parse_double("-0.8757") == -0.8757);
  CHECK_FALSE(parse_double("abc"));
  CHECK_FALSE(parse_double("1.0abc"));
  CHECK_FALSE(parse_double(""));
  CHECK_FALSE(parse_double(" 1"));
  auto xyz = parse_doubles(" 0  0.1\t-1 ");
  REQUIRE(xyz);
  CHECK(*xyz == std::vector<double>{0, 0.1, -1});
  CHECK_FALSE(parse_doubles("0 x 1"));
  CHECK(trim("  a b \r\n") == "a b");
}

TEST_CASE("rule selection globs", "[util]") {
  CHECK(glob_match("mimic-*", "mimic-max-velocity"));
  CHECK(glob_match("*", "anything"));
  CHECK(glob_match("*-velocity*", "units-velocity-implausible"));
  CHECK(glob_match("drive-?ax-force", "drive-max-force"));
  CHECK_FALSE(glob_match("mimic-*", "drive-max-force"));
  CHECK_FALSE(glob_match("mimic", "mimic-max-velocity"));
  RuleSelection selection;
  CHECK(selection.enabled("x"));
  selection.select = {"mimic-*", "units-*"};
  selection.ignore = {"units-velocity-*"};
  CHECK(selection.enabled("mimic-limit-conflict"));
  CHECK(selection.enabled("units-angle-degrees"));
  CHECK_FALSE(selection.enabled("units-velocity-implausible"));
  CHECK_FALSE(selection.enabled("inertia-invalid"));
}

TEST_CASE("half a unit in the last written digit, from the shortest text of the value", "[util]") {
  CHECK(assetlint::half_unit_in_last_digit(0.001437) == Approx(5e-7));
  CHECK(assetlint::half_unit_in_last_digit(-4.58) == Approx(0.005));
  CHECK(assetlint::half_unit_in_last_digit(3.781e-7) == Approx(5e-11));
  CHECK(assetlint::half_unit_in_last_digit(44) == Approx(0.5));
  CHECK(assetlint::half_unit_in_last_digit(0) == 0);
}
