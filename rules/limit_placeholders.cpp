#include "rules/limit_placeholders.h"

#include <fmt/format.h>

#include <cmath>

#include "rules/support.h"

namespace assetlint::rules {

bool is_power_of_ten(double value, int min_exponent) {
  if (!(value > 0) || !std::isfinite(value)) return false;
  const double exponent = std::round(std::log10(value));
  return exponent >= min_exponent && std::fabs(value - std::pow(10.0, exponent)) <= 1e-9 * value;
}

SharedValues::SharedValues(const Asset& asset, OptQuantity Joint::*field) : field_(field) {
  for (const Joint& joint : asset.joints)
    if (const OptQuantity& q = joint.*field; is_single_dof(joint.type) && q && !std::isnan(q->value)) ++count_[q->value];
}

std::size_t SharedValues::others(const Joint& joint) const {
  const OptQuantity& mine = joint.*field_;
  if (!mine || std::isnan(mine->value)) return 0;
  const auto it = count_.find(mine->value);
  if (it == count_.end()) return 0;
  return it->second - (is_single_dof(joint.type) ? 1 : 0);
}

std::size_t movable_joint_count(const Asset& asset) {
  std::size_t count = 0;
  for (const Joint& joint : asset.joints) count += is_single_dof(joint.type) ? 1 : 0;
  return count;
}

bool velocity_placeholder_on_every_joint(const Asset& asset, const Joint& joint, const SharedValues& velocities,
                                         std::size_t movable_joints) {
  if (asset.format != SourceFormat::Urdf || !joint.velocity || !is_power_of_ten(joint.velocity->value, 2)) return false;
  const std::size_t sharing = velocities.others(joint);
  return sharing > 0 && sharing + 1 >= movable_joints;
}

bool has_active_drive(const Joint& joint) {
  return joint.drive && ((joint.drive->stiffness && joint.drive->stiffness->value > 0) ||
                         (joint.drive->damping && joint.drive->damping->value > 0));
}

std::string LimitCheck::label() const { return (driven ? "driven " : "") + joint_label(joint); }

Diagnostic& report_sentinel(const LimitCheck& c, const Quantity& q, std::string_view what, bool judged,
                            std::string_view consumers, std::string_view bound_kind) {
  const bool convention = q.value == 0 || q.value == -1;
  Diagnostic& d = c.out.report(
      q.span, judged || !convention ? Severity::Warning : Severity::Info,
      convention ? fmt::format("{} {} of {} is a sentinel: unbounded in Isaac Sim{}", what, describe(q), c.label(),
                               q.value == 0 ? ", zero elsewhere" : " and Gazebo, negative elsewhere")
                 : fmt::format("{} {} of {} is negative", what, describe(q), c.label()));
  d.note(std::string(consumers));
  if (!convention)
    d.note(fmt::format("No consumer reads a negative bound other than −1 as a {}: a sign slip?", bound_kind));
  return d;
}

}  // namespace assetlint::rules
