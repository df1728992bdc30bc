#include "physics/drive.h"

#include <fmt/format.h>

#include <cmath>

#include "physics/inertia.h"
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
double implicit_fraction(double dt, double frequency) {
  const double x = dt * frequency;
  return 1.0 / (1.0 + x * x);
}

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
// A link's inertia about a joint axis when its mass and inertia are authored.
std::optional<double> link_inertia(const Link* link, const Joint& joint, int side) {
  if (!link || !link->inertial || !link->inertial->mass_authored || !link->inertial->inertia_authored) return std::nullopt;
  if (link->inertial->mass.value <= 0) return std::nullopt;
  if (joint.type == JointType::Prismatic) return link->inertial->mass.value;
  return inertia_about_axis(*link->inertial, joint.frame_in_link[static_cast<std::size_t>(side)], joint.axis);
}
}  // namespace

EffectiveInertia effective_inertia(const Asset& asset, const Joint& joint) {
  EffectiveInertia best;
  for (const Joint* member : coupled_joints(asset, joint)) {
    const Link* links[2] = {asset.find_link(member->parent.text), asset.find_link(member->child.text)};
    for (int side = 0; side < 2; ++side) {
      auto inertia = link_inertia(links[side], *member, side);
      if (!inertia) {
        if (links[side]) best.unknown_links.push_back(links[side]->name.text);
        continue;
      }
      if (!best.known || *inertia < best.link_inertia) {
        best.known = true;
        best.link_inertia = *inertia;
        best.link = links[side];
        best.via = member;
      }
    }
  }
  best.armature = joint.armature ? joint.armature->value : 0.0;
  best.value = best.link_inertia + best.armature;
  return best;
}

std::string EffectiveInertia::describe() const {
  if (!known) return "unknown";
  const char* unit = via && via->type == JointType::Prismatic ? "kg" : "kg·m²";
  return fmt::format("{} {} (link '{}' about '{}'{})", format_number(value, 3), unit, link->name.text,
                     via->name.text,
                     armature > 0 ? fmt::format(" + armature {}", format_number(armature, 3)) : std::string());
}

SimulationRate effective_simulation(const Asset& asset, const Settings& settings) {
  SimulationRate rate;
  // The stage's own value wins, then configuration; the defaults stay otherwise.
  const auto pick = [&](const OptQuantity& stage, const std::optional<Configured<double>>& configured, double& value,
                        std::string& origin) {
    if (stage) {
      value = stage->value;
      origin = stage->span.valid() ? fmt::format("{}:{}", asset.source(stage->span.file).path(), stage->span.line)
                                   : std::string("stage default");
    } else if (configured) {
      value = configured->value;
      origin = configured->origin;
    }
  };
  pick(asset.scene.timesteps_per_second, settings.simulation.timesteps_per_second, rate.timesteps_per_second,
       rate.rate_origin);
  pick(asset.scene.position_iterations, settings.simulation.position_iterations, rate.position_iterations,
       rate.iterations_origin);
  if (!asset.scene.solver.empty()) rate.solver = asset.scene.solver;
  else if (settings.simulation.solver) rate.solver = settings.simulation.solver->value;
  return rate;
}

std::string SimulationRate::describe() const {
  return fmt::format("{} Hz ({}) × {} position iterations ({})", format_number(timesteps_per_second),
                     rate_origin, format_number(position_iterations), iterations_origin);
}

}  // namespace assetlint::physics
