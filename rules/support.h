#pragma once
// Small helpers shared by rules: wording of quantities and building value edits.
#include <optional>
#include <string>

#include "engine/diagnostic.h"
#include "model/asset.h"

namespace assetlint::rules {

// A model value as the file writes it and, when the file's unit differs, as PhysX
// sees it: "146.5 deg/s (2.556 rad/s)" or "5700 N·m/rad".
std::string describe(double model_value, Unit file_unit, int significant = 4);
// A value read from a file: on a scaled USD stage (metersPerUnit or kilogramsPerUnit ≠ 1)
// the literal as written, then the SI/PhysX value: "300 in file units (3 m/s)".
std::string describe(const Quantity& q, int significant = 4);

// A new model value as it would be written into q's literal: "15 in file units (0.15 m/s)" on a
// scaled stage, else like describe(model_value, q.unit).
std::string describe_written(const Quantity& q, double model_value, int significant = 4);

// An edit that rewrites a quantity's literal with a new model value, in the file's unit.
Edit replace_value(const Quantity& q, double model_value, int significant = 6);

// A name's last '/'-separated element ("/gripper/finger" → "finger"): keeps primary messages
// short when names are USD prim paths; the diagnostic's span says where.
std::string short_path(const std::string& name);

// The velocity a mimic joint must reach (model units): |multiplier| times its followed
// joint's velocity limit; nothing when the joint is no single-DOF mimic or its followed
// joint has no positive single-DOF limit. mimic-max-velocity owns a mimic's velocity limit
// against this bound; other rules defer to it.
struct MimicDemand {
  const Joint* reference;
  const Quantity* reference_velocity;
  double velocity;
};
std::optional<MimicDemand> mimic_demand(const Asset& asset, const Joint& joint);
// Relative slack below that bound for limits written with fewer digits than the product.
inline constexpr double kMimicDemandSlack = 1e-6;

// "revolute joint 'J0'"
std::string joint_label(const Joint& joint);

}  // namespace assetlint::rules
