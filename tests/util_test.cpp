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
