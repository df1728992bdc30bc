// Unit tests of the model layer: sources and positions, units, quantities, topology.
#include <catch2/catch.hpp>

#include <numbers>

#include "model/asset.h"
#include "model/source.h"
#include "model/topology.h"
#include "model/units.h"

using namespace assetlint;

TEST_CASE("source positions count lines for LF, CRLF and CR, and columns in code points", "[model]") {
  SourceFile lf("a", "ab\ncd\n");
  CHECK(lf.position(0).line == 1);
  CHECK(lf.position(3).line == 2);
  CHECK(lf.position(4).column == 2);
  SourceFile crlf("b", "ab\r\ncd\r\nef");
  CHECK(crlf.position(4).line == 2);
  CHECK(crlf.position(4).column == 1);
  CHECK(crlf.position(9).line == 3);
  CHECK(crlf.line_count() == 3);
  SourceFile utf8("c", "\xC2\xB0x = 47");  // "°x = 47": ° is two bytes, one column
  CHECK(utf8.position(2).column == 2);
  SourceFile bom("d", "\xEF\xBB\xBF<robot/>");
  CHECK(bom.position(3).column == 1);  // the BOM is invisible
  const Span span = lf.span(0, 4, 1);
  CHECK(span.line == 2);
  CHECK(span.column == 2);
  CHECK(span.valid());
  CHECK(lf.position(1000).line == 3);  // clamped to the end
}

TEST_CASE("units convert once, both ways, with the USD conventions", "[model]") {
  CHECK(to_model_units(180.0, Unit::Degree) == Approx(std::numbers::pi));
  CHECK(to_model_units(166.0, Unit::DegreePerSecond) == Approx(2.8972).epsilon(1e-4));
  // USD stiffness per degree: 4.8 /deg is 275 N·m/rad (PHYSICS.md §3).
  CHECK(to_model_units(4.8, Unit::NewtonMeterPerDegree) == Approx(275.02).epsilon(1e-4));
  CHECK(from_model_units(275.0, Unit::NewtonMeterPerDegree) == Approx(4.7997).epsilon(1e-4));
  CHECK(to_model_units(3.0, Unit::NewtonMeterPerDegree) == Approx(171.887).epsilon(1e-5));
  // USD gearing g is the negated URDF multiplier: q + g·q_ref + offset = 0.
  CHECK(to_model_units(-1.0, Unit::UsdGearing) == 1.0);
  CHECK(to_model_units(10.0, Unit::UsdOffsetDegree) == Approx(-0.174533).epsilon(1e-5));
  CHECK(to_model_units(2.5, Unit::KilogramMeter2) == 2.5);
  CHECK(model_unit(Unit::NewtonMeterSecondPerDegree) == Unit::NewtonMeterSecondPerRadian);
  CHECK(unit_symbol(Unit::NewtonMeterPerRadian) == "N·m/rad");
  CHECK(converts(Unit::Degree));
  CHECK_FALSE(converts(Unit::Radian));
  const Quantity q = Quantity::from_authored(47.0, Unit::Degree, Span{});
  CHECK(q.value == Approx(0.820305).epsilon(1e-6));
  CHECK(q.authored_for(0.5) == Approx(28.6479).epsilon(1e-5));
}

TEST_CASE("moving bodies group links welded by fixed joints", "[model]") {
  Asset asset;
  for (const char* name : {"base", "arm", "sensor", "tool"}) asset.links.push_back(Link{Name{name, {}}, {}, {}});
  auto joint = [&](const char* name, JointType type, const char* parent, const char* child) {
    Joint j;
    j.name.text = name;
    j.type = type;
    j.parent.text = parent;
    j.child.text = child;
    asset.joints.push_back(j);
  };
  joint("shoulder", JointType::Revolute, "base", "arm");
  joint("mount", JointType::Fixed, "arm", "sensor");
  joint("flange", JointType::Fixed, "sensor", "tool");
  const auto bodies = moving_bodies(asset);
  REQUIRE(bodies.size() == 1);
  CHECK(bodies[0].joint->name.text == "shoulder");
  REQUIRE(bodies[0].links.size() == 3);
  CHECK(bodies[0].links[0]->name.text == "arm");
}
