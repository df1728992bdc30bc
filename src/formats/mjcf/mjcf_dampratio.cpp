#include "formats/mjcf/mjcf_dampratio.h"

#include <fmt/format.h>

#include <cmath>

#include "physics/articulation.h"
#include "physics/joint_space_matrix.h"
#include "util/numbers.h"

namespace assetlint::mjcf {
namespace {

using physics::DampRatioRule;

std::string names(const std::vector<std::string>& links) {
  std::string list;
  for (std::size_t i = 0; i < links.size() && i < 3; ++i) list += (i ? ", '" : "'") + links[i] + "'";
  if (links.size() > 3) list += ", …";
  return list;
}

// The symbol and meaning of the joint inertia each rule divides by g².
const char* symbol(DampRatioRule rule) { return rule == DampRatioRule::OperationalSpace ? "m" : "M₀"; }
std::string meaning(DampRatioRule rule, const Joint& joint) {
  return rule == DampRatioRule::OperationalSpace
             ? fmt::format("m = 1/(M⁻¹)ᵢᵢ: the inertia '{}' reflects at the reference pose with every other joint free, "
                           "armature included",
                           joint.name.text)
             : fmt::format("M₀: the joint-space inertia of '{}' at the reference pose, every other joint held, armature "
                           "included",
                           joint.name.text);
}

// On a fixed tendon the inertia is the tendon's, written on the joint carrying the drive.
std::string tendon_meaning(DampRatioRule rule, const DampRatio& r, const Asset& asset) {
  std::string moments;
  for (const auto& [index, value] : r.moment)
    moments += fmt::format("{}{} on '{}'", moments.empty() ? "" : ", ", format_number(value, 6), asset.joints[index].name.text);
  return fmt::format("{}, for the tendon's moment J ({}), times g² = {}² of the tendon per unit of '{}'",
                     rule == DampRatioRule::OperationalSpace
                         ? "(J·M⁻¹·Jᵀ)⁻¹: the inertia the tendon reflects at the reference pose with every joint free"
                         : "Σ M₀ⱼ/Jⱼ²: each joint's M₀ (every other joint held) over its moment squared",
                     moments, format_number(std::abs(r.gear), 6), asset.joints[r.joint].name.text);
}

std::string why_unknown(const physics::ArticulatedInertia& inertia) {
  return !inertia.unknown_links.empty()
             ? fmt::format("the mass of {} comes from geoms asset-lint cannot measure (a mesh, a height field, a shell)",
                           names(inertia.unknown_links))
             : inertia.reason;
}

}  // namespace

void derive_dampratio_damping(const std::vector<DampRatio>& requests, DampRatioRule rule, Values& values, Asset& asset) {
  if (requests.empty()) return;
  const physics::Articulation articulation(asset);
  const physics::JointSpaceMatrix matrix(articulation);
  const DampRatioRule other = rule == DampRatioRule::OperationalSpace ? DampRatioRule::JointSpaceDiagonal
                                                                       : DampRatioRule::OperationalSpace;
  // The inertia each rule derives kv on, expressed on the joint carrying the drive (times g²
  // of its transmission): on a joint M₀ or 1/(M⁻¹)ᵢᵢ; on a fixed tendon MuJoCo's m for the
  // tendon's moment J, times g² (g: the tendon's rate per unit rate of that joint).
  const auto inertia_under = [&](DampRatioRule r, const DampRatio& request, const Joint& joint) {
    if (request.moment.empty())
      return r == DampRatioRule::OperationalSpace ? matrix.operational_inertia(joint) : articulation.joint_space_inertia(joint);
    physics::ArticulatedInertia m;
    if (r == DampRatioRule::OperationalSpace) {
      std::vector<std::pair<const Joint*, double>> moment;
      for (const auto& [index, value] : request.moment) moment.emplace_back(&asset.joints[index], value);
      m = matrix.operational_inertia(moment);
    } else {
      // Σ dof_M0ⱼ / Jⱼ² over the dofs the moment reaches (mj_setConst up to MuJoCo 3.14).
      m.known = true;
      for (const auto& [index, value] : request.moment) {
        if (value * value <= 1e-15) continue;
        const physics::ArticulatedInertia diagonal = articulation.joint_space_inertia(asset.joints[index]);
        if (!diagonal.known) return diagonal;
        m.value += diagonal.value / (value * value);
      }
    }
    m.value *= request.gear * request.gear;
    return m;
  };
  for (const DampRatio& r : requests) {
    Joint& joint = asset.joints[r.joint];
    if (!joint.drive) continue;
    Drive& drive = *joint.drive;
    const bool angular = is_angular(joint.type);
    const Unit unit = angular ? Unit::NewtonMeterSecondPerRadian : Unit::NewtonSecondPerMeter;
    const char* inertia_unit = angular ? "kg·m²" : "kg";
    const double joint_damping = r.joint_damping;
    const physics::ArticulatedInertia inertia = inertia_under(rule, r, joint);
    if (!inertia.known && r.ratio != 0) {
      const std::string why = why_unknown(inertia);
      drive.damping_unknown = fmt::format("kv from dampratio {} needs {} of '{}' ({}), unknown: {}", format_number(r.ratio),
                                          symbol(rule), joint.name.text, physics::dampratio_rule_versions(rule), why);
      values.unsupported(r.span, fmt::format("{}: damping unknown (dampratio needs the inertia at the reference pose)", r.label))
          .note(fmt::format("{} compile kv = 2·ζ·√(kp·{}/g²); {} of '{}' is unknown: {}.", physics::dampratio_rule_versions(rule),
                            symbol(rule), symbol(rule), joint.name.text, why))
          .note("The verdicts that need the drive's damping (damping ratio, natural frequency, armature) are skipped.");
      continue;
    }
    const double g2 = r.gear * r.gear;
    const double m = inertia.known ? inertia.value : 0.0;
    const double kv = r.ratio == 0 ? 0.0 : physics::dampratio_kv(r.ratio, r.kp, m, r.gear);
    const double total = kv * g2 + joint_damping;
    drive.damping = Quantity::unauthored(total, unit);
    const std::string gear = g2 != 1 ? fmt::format("/{}²", format_number(std::abs(r.gear))) : std::string();
    drive.damping_origin = fmt::format("{} derive kv from dampratio: kv = 2·ζ·√(kp·{}{}) = 2 × {} × √({} × {} {}{}) = {}",
                                       physics::dampratio_rule_versions(rule), symbol(rule), gear, format_number(r.ratio),
                                       format_number(r.kp), format_number(m, 6), inertia_unit, gear, format_number(kv, 6));
    if (g2 != 1) drive.damping_origin += fmt::format(", {} on the joint (× gear²)", format_number(kv * g2, 6));
    if (joint_damping > 0)
      drive.damping_origin += fmt::format(", plus the joint's damping {}: {}", format_number(joint_damping, 6), format_number(total, 6));
    drive.damping_origin += fmt::format(" ({})", r.moment.empty() ? meaning(rule, joint) : tendon_meaning(rule, r, asset));
    // The other release's kv, when it is known and differs by more than 10 %.
    const physics::ArticulatedInertia alternative = inertia_under(other, r, joint);
    if (r.ratio == 0 || !alternative.known || !(kv > 0)) continue;
    const double other_kv = physics::dampratio_kv(r.ratio, r.kp, alternative.value, r.gear);
    if (std::abs(other_kv - kv) <= 0.1 * kv) continue;
    drive.damping_other_release = fmt::format(
        "{} derive kv = {} instead ({:.2f}× this), on {} = {} {} with every other joint {}; [mujoco] version in "
        "asset-lint.toml selects the release",
        physics::dampratio_rule_versions(other), format_number(other_kv, 6), other_kv / kv, symbol(other),
        format_number(alternative.value, 6), inertia_unit, other == DampRatioRule::OperationalSpace ? "free" : "held");
  }
}

}  // namespace assetlint::mjcf
