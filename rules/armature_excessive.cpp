#include <fmt/format.h>

#include <cmath>

#include "physics/drive.h"
#include "rules/drive_support.h"
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
    const DriveModel model(asset, settings);
    for (const Joint& joint : asset.joints) {
      if (!is_single_dof(joint.type) || !joint.armature || joint.armature->value <= 0) continue;
      const physics::EffectiveInertia inertia = physics::effective_inertia(model.articulation(), asset, joint);
      if (!inertia.known || inertia.link_inertia <= 0) continue;
      const double armature = joint.armature->value;
      const double ratio = armature / inertia.link_inertia;
      if (ratio <= factor) continue;
      // The datasheet justification the guide asks for: armature = G²·I_rotor.
      std::string motor_text;
      if (joint.motor) {
        const double reflected = joint.motor->gear_ratio * joint.motor->gear_ratio * joint.motor->rotor_inertia.value;
        if (armature <= reflected * (1 + 1e-6)) continue;
        motor_text = fmt::format("The declared motor ({}: G = {}, I_rotor = {} kg·m²) reflects only G²·I_rotor = {} kg·m².",
                                 joint.motor->origin, format_number(joint.motor->gear_ratio),
                                 format_number(joint.motor->rotor_inertia.value, 3), format_number(reflected, 3));
      }
      const char* unit = is_angular(joint.type) ? "kg·m²" : "kg";
      Diagnostic& d = out.report(
          joint.armature->span.valid() ? joint.armature->span : joint.name.span,
          fmt::format("armature {} {} of {} is {}× the lighter link's inertia (threshold {}×)", format_number(armature, 3),
                      unit, short_name(joint), format_number(ratio, 3), format_number(factor)));
      d.note(fmt::format("For {}, the lighter link '{}' about '{}' has {} {}{}; justify the armature from the motor datasheet, "
                         "armature = G²·I_rotor: it equals a rotor as heavy as that link behind a {}:1 gearbox.",
                         joint_label(joint), inertia.link->name.text, inertia.via->name.text,
                         format_number(inertia.link_inertia, 3), unit,
                         std::abs(inertia.gearing) != 1.0 ? fmt::format(" (reflected with gearing² {})", format_number(inertia.gearing * inertia.gearing, 3))
                                                : std::string(),
                         format_number(std::sqrt(ratio), 3)));
      if (!motor_text.empty()) d.note(std::move(motor_text));
      if (auto driven = model.spring_drive(joint); driven && !driven->acceleration()) {
        const double k = driven->stiffness;
        std::string effect = fmt::format("It lowers the drive's natural frequency on the lighter link from {} to {} rad/s",
                                         format_number(physics::natural_frequency(k, inertia.link_inertia), 3),
                                         format_number(physics::natural_frequency(k, inertia.value), 3));
        if (driven->articulated.known)
          effect += fmt::format("; with it the drive row's x on the articulation is {} ({})",
                                format_number(driven->row(driven->articulated.value).x(), 3), driven->rate.step_text());
        d.note(effect + fmt::format(". Inertias: {}.", driven->inertias_text()));
      }
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
