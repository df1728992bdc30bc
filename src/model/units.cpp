#include "model/units.h"

#include <numbers>

namespace assetlint {
namespace {
constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

// Multiplying an authored value by this gives the model (PhysX) value.
double factor(Unit unit) {
  switch (unit) {
    case Unit::Degree:
    case Unit::DegreePerSecond:
      return 1.0 / kDegreesPerRadian;
    case Unit::NewtonMeterPerDegree:
    case Unit::NewtonMeterSecondPerDegree:
      // A torque per degree of error is 180/π times that torque per radian.
      return kDegreesPerRadian;
    case Unit::MillimeterPerSecond:
      return 1e-3;
    case Unit::UsdGearing:
    case Unit::UsdOffsetMeter:
      return -1.0;
    case Unit::UsdOffsetDegree:
    case Unit::UsdGearingDegreePerDistance:
      return -1.0 / kDegreesPerRadian;
    case Unit::UsdGearingDistancePerDegree:
      return -kDegreesPerRadian;
    default:
      return 1.0;
  }
}
}  // namespace

double to_model_units(double authored, Unit unit) {
  if (unit == Unit::SecondsPerStep) return 1.0 / authored;
  return authored * factor(unit);
}
double from_model_units(double model_value, Unit unit) {
  if (unit == Unit::SecondsPerStep) return 1.0 / model_value;
  return model_value / factor(unit);
}

Unit model_unit(Unit unit) {
  switch (unit) {
    case Unit::Degree: return Unit::Radian;
    case Unit::DegreePerSecond: return Unit::RadianPerSecond;
    case Unit::NewtonMeterPerDegree: return Unit::NewtonMeterPerRadian;
    case Unit::NewtonMeterSecondPerDegree: return Unit::NewtonMeterSecondPerRadian;
    case Unit::MillimeterPerSecond: return Unit::MeterPerSecond;
    case Unit::UsdGearing: return Unit::None;
    case Unit::UsdOffsetDegree: return Unit::Radian;
    case Unit::UsdOffsetMeter: return Unit::Meter;
    case Unit::SecondsPerStep: return Unit::PerSecond;
    case Unit::UsdGearingDegreePerDistance: return Unit::RadianPerMeter;
    case Unit::UsdGearingDistancePerDegree: return Unit::MeterPerRadian;
    default: return unit;
  }
}

std::string_view unit_symbol(Unit unit) {
  switch (unit) {
    case Unit::None: return "";
    case Unit::Meter: return "m";
    case Unit::Kilogram: return "kg";
    case Unit::KilogramMeter2: return "kg·m²";
    case Unit::Radian: return "rad";
    case Unit::Degree: return "deg";
    case Unit::RadianPerSecond: return "rad/s";
    case Unit::DegreePerSecond: return "deg/s";
    case Unit::MeterPerSecond: return "m/s";
    case Unit::MillimeterPerSecond: return "mm/s";
    case Unit::Newton: return "N";
    case Unit::NewtonMeter: return "N·m";
    case Unit::NewtonMeterPerRadian: return "N·m/rad";
    case Unit::NewtonMeterPerDegree: return "N·m/deg";
    case Unit::NewtonMeterSecondPerRadian: return "N·m·s/rad";
    case Unit::NewtonMeterSecondPerDegree: return "N·m·s/deg";
    case Unit::NewtonPerMeter: return "N/m";
    case Unit::NewtonSecondPerMeter: return "N·s/m";
    case Unit::PerSecond: return "1/s";
    case Unit::UsdGearing: return "";
    case Unit::UsdOffsetDegree: return "deg";
    case Unit::UsdOffsetMeter: return "m";
    case Unit::SecondsPerStep: return "s";
    case Unit::UsdGearingDegreePerDistance: return "deg/m";
    case Unit::UsdGearingDistancePerDegree: return "m/deg";
    case Unit::RadianPerMeter: return "rad/m";
    case Unit::MeterPerRadian: return "m/rad";
  }
  return "";
}

double radians_from_degrees(double degrees) { return degrees / kDegreesPerRadian; }
double degrees_from_radians(double radians) { return radians * kDegreesPerRadian; }

}  // namespace assetlint
