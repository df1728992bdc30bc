#include "verify/drive_plan.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "model/units.h"
#include "physics/drive_response.h"
#include "util/numbers.h"

namespace assetlint::verify {
namespace {

constexpr double kSettleBefore = 0.5;  // s: the robot settles under gravity before the target moves
constexpr double kHoldEnd = 0.5;       // s: the sweep's target rests at each limit
constexpr double kHoldReturn = 1.0;    // s: and back at the start
constexpr double kAfterSettle = 1.0;   // s: the step runs this long past the settle limit
constexpr double kSteadyRest = 0.5;    // s: or ends once every joint has been at rest this long
// The sweep's speed without a max joint velocity: 1 rad/s, 0.1 m/s.
constexpr double kDefaultRampAngular = 1.0, kDefaultRampLinear = 0.1;

std::optional<double> finite(const OptQuantity& q) {
  if (q && std::isfinite(q->value)) return q->value;
  return std::nullopt;
}

}  // namespace

std::string_view drive_test_name(DriveTestKind kind) {
  switch (kind) {
    case DriveTestKind::Step: return "step";
    case DriveTestKind::Sweep: return "sweep";
    case DriveTestKind::Hold: return "hold";
    case DriveTestKind::Velocity: return "velocity";
    case DriveTestKind::Mimic: return "mimic";
  }
  return "step";
}

std::optional<std::size_t> DrivePlan::index_of(std::string_view joint) const {
  for (std::size_t i = 0; i < joints.size(); ++i)
    if (joints[i].joint->name.text == joint) return i;
  return std::nullopt;
}

double scene_target(const DriveScene& scene, double t) {
  const auto& w = scene.waypoints;
  if (w.empty()) return 0;
  const auto after = std::find_if(w.begin(), w.end(), [&](const auto& p) { return p.first > t; });
  if (after == w.begin()) return w.front().second;
  if (after == w.end()) return w.back().second;
  const auto& [t0, y0] = *(after - 1);
  const auto& [t1, y1] = *after;
  return y0 + (y1 - y0) * (t - t0) / (t1 - t0);
}

DrivePlan plan_drive_tests(const Asset& asset, const Settings& settings) {
  DrivePlan plan;
  plan.asset = &asset;
  plan.limits = settings.verify.drives;
  std::set<std::string, std::less<>> children;
  for (const Joint& joint : asset.joints) {
    const bool to_world = !asset.find_link(joint.parent.text);
    if (joint.type == JointType::Floating || (to_world && joint.type != JointType::Fixed)) plan.base_pinned = true;
    if (!to_world) children.insert(joint.child.text);
  }
  for (const Link& link : asset.links)
    if (!children.count(link.name.text)) {
      plan.base = link.name.text;
      break;
    }
  for (const Link& link : asset.links)
    if (!children.count(link.name.text)) plan.static_links.insert(link.name.text);
  for (bool grew = true; grew;) {
    grew = false;
    for (const Joint& joint : asset.joints)
      if (!is_single_dof(joint.type) && plan.static_links.count(joint.parent.text) &&
          plan.static_links.insert(joint.child.text).second)
        grew = true;
  }
  for (const Joint& joint : asset.joints) {
    if (joint.type == JointType::Fixed || joint.type == JointType::Floating) continue;
    if (!is_single_dof(joint.type)) {
      plan.held_rigid.push_back(joint.name.text);
      continue;
    }
    if (joint.mimic && asset.find_joint(joint.mimic->reference.text)) continue;  // tested through its leader
    TestedJoint tested;
    tested.joint = &joint;
    tested.angular = is_angular(joint.type);
    if (joint.type != JointType::Continuous) {
      tested.lower = finite(joint.lower);
      tested.upper = finite(joint.upper);
      if (!tested.lower || !tested.upper || *tested.upper <= *tested.lower) tested.lower = tested.upper = std::nullopt;
    }
    tested.start = tested.lower ? std::clamp(0.0, *tested.lower, *tested.upper) : 0.0;
    for (const Joint* follower : asset.mimic_followers(joint.name.text))
      if (follower != &joint && is_single_dof(follower->type)) tested.followers.push_back(follower);
    const Drive* d = joint.drive ? &*joint.drive : nullptr;
    if (d && d->stiffness && d->stiffness->value > 0 && d->damping_unknown.empty()) {
      DriveSpec spec;
      spec.stiffness = d->stiffness->value;
      spec.damping = d->damping ? d->damping->value : 0.0;
      const Quantity* force = d->max_force ? &*d->max_force : joint.effort ? &*joint.effort : nullptr;
      if (force && force->value > 0 && std::isfinite(force->value)) spec.max_force = force->value;
      if (joint.velocity && joint.velocity->value > 0 && std::isfinite(joint.velocity->value))
        spec.max_velocity = joint.velocity->value;
      tested.drive = spec;
    } else if (d && !d->damping_unknown.empty()) {
      tested.no_drive = "its damping cannot be computed: " + d->damping_unknown;
    } else {
      tested.no_drive = d ? "its drive has no stiffness" : "no drive";
    }
    plan.joints.push_back(std::move(tested));
  }
  return plan;
}

std::vector<DriveScene> drive_scenes(const DrivePlan& plan) {
  std::vector<DriveScene> scenes;
  const auto& limits = plan.limits;
  for (std::size_t i = 0; i < plan.joints.size(); ++i) {
    const TestedJoint& j = plan.joints[i];
    if (!j.drive) continue;
    const std::string& name = j.joint->name.text;
    const double range = j.lower ? *j.upper - *j.lower : INFINITY;
    DriveScene step;
    step.name = fmt::format("step '{}'", name);
    step.kind = DriveTestKind::Step;
    step.joint = i;
    const double from = j.lower ? 0.5 * (*j.lower + *j.upper) : j.start;
    const double size = physics::drive_step_size(range, j.angular);
    step.step_at = kSettleBefore;
    step.rest_ends = kSteadyRest;
    step.duration = kSettleBefore + limits.settle_time_s.value + kAfterSettle;
    step.waypoints = {{0, from}, {kSettleBefore, from}, {kSettleBefore, from + size}};
    if (!(size > 0)) step.not_run = "not run: a prismatic joint without a finite range has no step size";
    scenes.push_back(step);

    DriveScene sweep;
    sweep.name = fmt::format("sweep '{}'", name);
    sweep.kind = DriveTestKind::Sweep;
    sweep.joint = i;
    if (!j.lower) {
      sweep.not_run = "not run: the joint has no finite limits to sweep to";
      scenes.push_back(sweep);
      continue;
    }
    const double speed =
        j.drive->max_velocity ? *j.drive->max_velocity : j.angular ? kDefaultRampAngular : kDefaultRampLinear;
    sweep.ramp = j.drive->max_velocity
                     ? fmt::format("the target ramps at the max joint velocity, {} {}/s", format_number(speed, 4), j.unit())
                     : fmt::format("no max joint velocity: the target ramps at {} {}/s", format_number(speed, 4), j.unit());
    sweep.speed = speed;
    sweep.rest = kHoldEnd;
    double t = kSettleBefore;
    sweep.waypoints = {{0, j.start}, {t, j.start}};
    const auto ramp_to = [&](double target, double rest) {
      t += std::abs(target - sweep.waypoints.back().second) / speed;
      sweep.waypoints.emplace_back(t, target);
      t += rest;
      sweep.waypoints.emplace_back(t, target);
      sweep.marks.push_back(t);
    };
    ramp_to(*j.upper, kHoldEnd);
    ramp_to(*j.lower, kHoldEnd);
    ramp_to(j.start, kHoldReturn);
    sweep.duration = t;
    scenes.push_back(sweep);
  }
  return scenes;
}

}  // namespace assetlint::verify
