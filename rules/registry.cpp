#include "rules/registry.h"

#include <algorithm>

#include "rules/all_rules.h"
#include "rules/compare_rules.h"
#include "rules/reader_rules.h"

namespace assetlint::rules {

const std::vector<const Rule*>& checks() {
  static const std::vector<const Rule*> list{
      &structure_undefined_link(),
      &structure_mimic_reference(),
      &structure_joint_axis(),
      &structure_multiple_parents(),
      &limits_inverted(),
      &limits_ambiguous(),
      &units_angle_degrees(),
      &units_angle_radians(),
      &units_velocity_implausible(),
      &mimic_max_velocity(),
      &mimic_limit_conflict(),
      &inertia_invalid(),
      &mass_ratio(),
      &drive_max_force(),
      &drive_natural_frequency(),
      &drive_implicit_attenuation(),
      &drive_damping_ratio(),
      &armature_excessive(),
      &mimic_copied_drive_gains(),
      &mimic_drive_conflict(),
      &joint_max_velocity(),
      &grasp_slip(),
      &self_collision(),
      &units_collider_scale(),
      &inertia_com_outside(),
      &grasp_finger_collider(),
      &consumer_drops_value(),
      &mimic_constraint_invalid(),
      &joint_undriven(),
      &drive_target_outside_limits(),
  };
  return list;
}

const std::vector<const RuleInfo*>& catalog() {
  static const std::vector<const RuleInfo*> list = [] {
    std::vector<const RuleInfo*> all{&kParseError, &kUrdfInvalid, &kUrdfRepeatedElement, &kLayerUnresolved, &kStaleSchemaAttribute,
                                     &kMimicAxisInstance, &kUnusedSuppression, &kDriveInstanceIgnored,
                                     &kMimicLimitsRequired, &kMjcfUnsupported, &kXacroUnexpanded, &kCompareMismatch,
                                     &kCompareUnmatched};
    for (const Rule* rule : checks()) all.push_back(&rule->info());
    std::sort(all.begin(), all.end(), [](const RuleInfo* a, const RuleInfo* b) { return a->id < b->id; });
    return all;
  }();
  return list;
}

const RuleInfo* find_rule(std::string_view id) {
  for (const RuleInfo* info : catalog())
    if (info->id == id) return info;
  return nullptr;
}

}  // namespace assetlint::rules
