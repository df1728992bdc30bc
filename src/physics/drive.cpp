#include "physics/drive.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "util/numbers.h"

namespace assetlint::physics {

double natural_frequency(double stiffness, double inertia) { return std::sqrt(stiffness / inertia); }
double damping_ratio(double damping, double stiffness, double inertia) {
  return damping / (2.0 * std::sqrt(stiffness * inertia));
}
double damping_for_ratio(double ratio, double stiffness, double inertia) {
  return 2.0 * ratio * std::sqrt(stiffness * inertia);
}
double stiffness_for_frequency(double frequency, double inertia) { return inertia * frequency * frequency; }
double inertia_for_frequency(double stiffness, double frequency) { return stiffness / (frequency * frequency); }
double inertial_time_constant(double inertia, double damping) { return inertia / damping; }

std::vector<const Joint*> coupled_joints(const Asset& asset, const Joint& joint) {
  const Joint* driver = &joint;
  if (joint.mimic) {
    if (const Joint* reference = asset.find_joint(joint.mimic->reference.text)) driver = reference;
  }
  std::vector<const Joint*> set{driver};
  for (const Joint* other : asset.mimic_followers(driver->name.text))
    if (other != driver) set.push_back(other);
  return set;
}

namespace {
// How far a coupled joint moves per unit of the driver: 1 for the driver, a mimic's multiplier.
double gearing_to_driver(const Joint& member, const Joint& driver) {
  return &member == &driver || !member.mimic ? 1.0 : member.mimic->multiplier.value;
}
}  // namespace

ArticulatedInertia mechanism_inertia(const Articulation& articulation, const Asset& asset, const Joint& joint) {
  const std::vector<const Joint*> set = coupled_joints(asset, joint);
  const double own = gearing_to_driver(joint, *set.front());
  std::vector<std::pair<const Joint*, double>> rates;
  for (const Joint* member : set)
    rates.emplace_back(member, own != 0 ? gearing_to_driver(*member, *set.front()) / own : 0.0);
  return articulation.coupled_inertia(rates);
}

EffectiveInertia effective_inertia(const Articulation& articulation, const Asset& asset, const Joint& joint) {
  EffectiveInertia best;
  const std::vector<const Joint*> set = coupled_joints(asset, joint);
  // Reflected to `joint`: a member moving g times as far as `joint` weighs in with g².
  const double own = gearing_to_driver(joint, *set.front());
  for (const Joint* member : set) {
    const double gearing = own != 0 ? gearing_to_driver(*member, *set.front()) / own : 0.0;
    for (int side = 0; side < 2; ++side) {
      const Body* body = articulation.side(*member, side);
      if (!body || body->world) continue;  // the world, or welded to it: never the lighter link
      auto inertia = articulation.inertia_about_axis(*body, *member, side);
      if (!inertia) {
        for (const auto& name : body->unknown_links)
          if (std::find(best.unknown_links.begin(), best.unknown_links.end(), name) == best.unknown_links.end())
            best.unknown_links.push_back(name);
        continue;
      }
      const double reflected = *inertia * gearing * gearing;
      if (!(reflected > 0)) continue;
      if (!best.known || reflected < best.link_inertia) {
        best.known = true;
        best.link_inertia = reflected;
        best.gearing = gearing;
        best.link = body->links.front();
        for (const Link* l : body->links)
          if (l->name.text == (side == 0 ? member->parent.text : member->child.text)) best.link = l;
        best.via = member;
      }
    }
  }
  best.armature = joint.armature ? joint.armature->value : 0.0;
  best.value = best.link_inertia + best.armature;
  return best;
}

EffectiveInertia effective_inertia(const Asset& asset, const Joint& joint) {
  return effective_inertia(Articulation(asset), asset, joint);
}

std::string EffectiveInertia::describe() const {
  if (!known) return "unknown";
  const char* unit = via && via->type == JointType::Prismatic ? "kg" : "kg·m²";
  return fmt::format("{} {} (link '{}' about '{}'{})", format_number(value, 3), unit, link->name.text,
                     via->name.text,
                     armature > 0 ? fmt::format(" + armature {}", format_number(armature, 3)) : std::string());
}

}  // namespace assetlint::physics
