#include "config/drive_overrides.h"

namespace assetlint::config {
namespace {

OptQuantity configured(const std::optional<Configured<double>>& value, Unit unit) {
  if (!value) return std::nullopt;
  return Quantity::unauthored(value->value, unit);
}

}  // namespace

void apply_drive_settings(Asset& asset, const Settings& settings) {
  for (Joint& joint : asset.joints) {
    auto it = settings.drives.find(joint.name.text);
    if (it == settings.drives.end()) continue;
    const DriveSettings& config = it->second;
    const bool angular = is_angular(joint.type);
    if (!joint.drive) {
      joint.drive = Drive{};
      joint.drive->span = joint.name.span;
      joint.drive->origin = config.origin;
    }
    Drive& drive = *joint.drive;
    if (!drive.stiffness) drive.stiffness = configured(config.stiffness, angular ? Unit::NewtonMeterPerRadian : Unit::NewtonPerMeter);
    if (!drive.damping)
      drive.damping = configured(config.damping, angular ? Unit::NewtonMeterSecondPerRadian : Unit::NewtonSecondPerMeter);
    if (!drive.max_force) drive.max_force = configured(config.max_force, angular ? Unit::NewtonMeter : Unit::Newton);
    if (!joint.velocity)
      joint.velocity = configured(config.max_velocity, angular ? Unit::RadianPerSecond : Unit::MeterPerSecond);
    if (config.type && !drive.type_span.valid())
      drive.type = config.type->value == "acceleration" ? DriveType::Acceleration : DriveType::Force;
    if (!joint.armature) joint.armature = configured(config.armature, angular ? Unit::KilogramMeter2 : Unit::Kilogram);
    if (!joint.motor && config.rotor_inertia) {
      joint.motor = Motor{Quantity::unauthored(config.rotor_inertia->value, Unit::KilogramMeter2),
                          config.gear_ratio ? config.gear_ratio->value : 1.0, config.rotor_inertia->origin};
    }
  }
}

}  // namespace assetlint::config
