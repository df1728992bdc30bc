#pragma once
// Units that values are written in, and the one place where they are converted
// to the SI/PhysX units the rules reason in.
#include <string_view>

namespace assetlint {

enum class Unit {
  None,           // dimensionless (ratios, counts)
  Meter,
  Kilogram,
  KilogramMeter2,
  Radian,
  Degree,
  RadianPerSecond,
  DegreePerSecond,
  MeterPerSecond,
  MillimeterPerSecond,
  Newton,
  NewtonMeter,
  NewtonMeterPerRadian,         // angular stiffness, PhysX
  NewtonMeterPerDegree,         // angular stiffness, USD
  NewtonMeterSecondPerRadian,   // angular damping, PhysX
  NewtonMeterSecondPerDegree,   // angular damping, USD
  NewtonPerMeter,               // linear stiffness
  NewtonSecondPerMeter,         // linear damping
  PerSecond,                    // rates: steps per second, natural frequency in rad/s
  UsdGearing,                   // USD mimic gearing: q + g·q_ref + offset = 0, so multiplier = −g
  UsdOffsetDegree,              // USD angular mimic offset (degrees, sign flipped like gearing)
  UsdOffsetMeter,               // USD linear mimic offset (sign flipped)
  SecondsPerStep,               // MJCF <option timestep>: the model value is the rate, 1 / timestep
  // Mixed mimic gearing (omni.physx InternalMimicJoint.cpp): an angular mimic of a linear
  // joint writes deg per distance, a linear mimic of an angular joint distance per deg;
  // sign flipped like UsdGearing. The stage's metersPerUnit goes into Quantity::scale.
  UsdGearingDegreePerDistance,
  UsdGearingDistancePerDegree,
  RadianPerMeter,
  MeterPerRadian,
};

// Value in the model's unit = authored value × factor (+ sign for the USD mimic convention;
// a step length becomes its rate).
double to_model_units(double authored, Unit unit);
// Inverse of to_model_units: what to write in a file whose literal is in `unit`.
double from_model_units(double model_value, Unit unit);
// The SI/PhysX unit a quantity written in `unit` is converted to.
Unit model_unit(Unit unit);
// Short symbol for messages, e.g. "N·m/rad", "deg/s".
std::string_view unit_symbol(Unit unit);
// Whether a file writes this quantity in a different unit from PhysX.
inline bool converts(Unit unit) { return model_unit(unit) != unit; }

// Angle conversions, for thresholds and messages that are about degrees as such.
double radians_from_degrees(double degrees);
double degrees_from_radians(double radians);

}  // namespace assetlint
