#include <fmt/format.h>

#include <cmath>

#include "physics/drive.h"
#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

// The guide's armature section: armature an order of magnitude above the lighter
// link's inertia needs a motor datasheet behind it, armature = G²·I_rotor.
class ArmatureExcessive final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const double factor = rule_option(info_, settings, "max_ratio");
    for (const Joint& joint : asset.joints) {
      if (!is_single_dof(joint.type) || !joint.armature || joint.armature->value <= 0) continue;
      const physics::EffectiveInertia inertia = physics::effective_inertia(asset, joint);
      if (!inertia.known || inertia.link_inertia <= 0) continue;
      const double armature = joint.armature->value;
      const double ratio = armature / inertia.link_inertia;
      if (ratio <= factor) continue;
      // The datasheet justification the guide asks for: armature = G²·I_rotor.
      std::string motor_text;
      if (joint.motor) {
        const double reflected = joint.motor->gear_ratio * joint.motor->gear_ratio * joint.motor->rotor_inertia.value;
        if (armature <= reflected * (1 + 1e-6)) continue;
        motor_text = fmt::format("; the declared motor ({}: G = {}, I_rotor = {} kg·m²) reflects only {} kg·m²",
                                 joint.motor->origin, format_number(joint.motor->gear_ratio),
                                 format_number(joint.motor->rotor_inertia.value, 3), format_number(reflected, 3));
      }
      const bool angular = is_angular(joint.type);
      const char* unit = angular ? "kg·m²" : "kg";
      const double gear = std::sqrt(ratio);
      std::string message = fmt::format(
          "armature {} {} of {} is {}× the lighter link's {} {} about the axis (link '{}'; threshold {}×): "
          "justify it from the motor datasheet, armature = G²·I_rotor — it equals a rotor as heavy as that link "
          "behind a {}:1 gearbox",
          format_number(armature, 3), unit, joint_label(joint), format_number(ratio, 3),
          format_number(inertia.link_inertia, 3), unit, inertia.link->name.text, format_number(factor),
          format_number(gear, 3));
      message += motor_text;
      if (joint.drive && joint.drive->stiffness && joint.drive->stiffness->value > 0 &&
          joint.drive->type == DriveType::Force) {
        const double k = joint.drive->stiffness->value;
        message += fmt::format("; it lowers the drive's natural frequency from {} to {} rad/s",
                               format_number(physics::natural_frequency(k, inertia.link_inertia), 3),
                               format_number(physics::natural_frequency(k, inertia.value), 3));
      }
      out.report(joint.armature->span.valid() ? joint.armature->span : joint.name.span, std::move(message));
    }
  }

 private:
  RuleInfo info_{"armature-excessive",
                 "Joint armature an order of magnitude above the lighter link's inertia about the axis",
                 Severity::Warning,
                 false,
                 RuleOrigin::Check,
                 {{"max_ratio", 10.0, "report armature above this multiple of the lighter link's inertia about the axis"}}};
};

}  // namespace

const Rule& armature_excessive() {
  static const ArmatureExcessive rule;
  return rule;
}

}  // namespace assetlint::rules
