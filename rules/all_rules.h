#pragma once
// One accessor per model rule; rules/registry.cpp lists them in order.
#include "engine/rule.h"

namespace assetlint::rules {

const Rule& structure_undefined_link();
const Rule& structure_mimic_reference();
const Rule& structure_joint_axis();
const Rule& structure_multiple_parents();
const Rule& limits_inverted();
const Rule& limits_ambiguous();
const Rule& units_angle_degrees();
const Rule& units_angle_radians();
const Rule& units_velocity_implausible();
const Rule& mimic_max_velocity();
const Rule& mimic_limit_conflict();
const Rule& inertia_invalid();
const Rule& mass_ratio();
const Rule& drive_max_force();
const Rule& drive_natural_frequency();
const Rule& drive_implicit_attenuation();
const Rule& drive_damping_ratio();
const Rule& armature_excessive();
const Rule& mimic_copied_drive_gains();
const Rule& mimic_drive_conflict();
const Rule& joint_max_velocity();
const Rule& grasp_slip();
const Rule& self_collision();
const Rule& units_collider_scale();
const Rule& inertia_com_outside();
const Rule& grasp_finger_collider();
const Rule& consumer_drops_value();
const Rule& mimic_constraint_invalid();
const Rule& joint_undriven();
const Rule& drive_target_outside_limits();

}  // namespace assetlint::rules
