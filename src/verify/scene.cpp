#include "verify/scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "model/units.h"
#include "util/numbers.h"

namespace assetlint::verify {
namespace {

constexpr double kSettle = 0.25;        // s after the close before anything is judged
constexpr double kLiftHeight = 0.05;    // m
constexpr double kLiftDuration = 0.5;   // s
constexpr double kAfterLift = 0.25;     // s held at the top
constexpr double kObjectShare = 0.9;    // of the pads' common extent across and along the fingers

// The time the drive needs to close: its target's ramp at the max velocity, else the spec's
// close time, else the stroke's own default of half a second.
double close_estimate(const VerifyPlan& plan) {
  const double stroke = std::abs(plan.layout.closed - plan.layout.open);
  double t = plan.drive.max_velocity ? stroke / *plan.drive.max_velocity : 0.0;
  if (plan.spec_close_time) t = std::max(t, *plan.spec_close_time);
  return t > 0 ? t : 0.5;
}

}  // namespace

std::string_view kind_name(SceneKind kind) {
  switch (kind) {
    case SceneKind::Close: return "close";
    case SceneKind::Grasp: return "grasp";
    case SceneKind::Hold: return "hold";
    case SceneKind::Lift: return "lift";
  }
  return "close";
}

double drive_target(const VerifyPlan& plan, double t) {
  const double open = plan.layout.open, closed = plan.layout.closed;
  if (!plan.drive.max_velocity) return closed;
  const double travel = std::min(std::abs(closed - open), *plan.drive.max_velocity * t);
  return open + (closed > open ? travel : -travel);
}

std::vector<SceneSpec> build_scenes(const VerifyPlan& plan, const Settings& settings) {
  const Asset& asset = *plan.asset;
  const GripperLayout& layout = plan.layout;
  const GripperSpec& spec = settings.gripper;
  const double window = settings.verify.window_s.value;
  const double t_close = close_estimate(plan);
  std::vector<SceneSpec> scenes;

  SceneSpec close;
  close.name = "close, empty";
  close.kind = SceneKind::Close;
  close.duration = 1.5 * t_close + kSettle;
  close.window = std::min(window, close.duration);
  if (!plan.spec_close_time)
    close.not_run = "no close time to judge against: set [gripper] stroke_m and finger_speed_m_s";
  scenes.push_back(close);

  // The three boxes: met almost open, halfway, and nearly closed.
  const double range = layout.closed - layout.open;
  const bool angular = is_angular(layout.driven->type);
  struct Width {
    double q;
    std::string why;
  };
  std::vector<Width> widths{{layout.open + 0.1 * range, "almost open (10 % of the stroke)"},
                            {layout.open + 0.5 * range, "halfway"}};
  if (angular) {
    const double delta = radians_from_degrees(spec.target_delta_deg.value);
    const double q = layout.closed - std::copysign(delta, range);
    if ((q - layout.open) / range > 0.5 && (q - layout.open) / range < 1.0)
      widths.push_back({q, fmt::format("nearly closed: the target delta {}° before closed ({})",
                                       format_number(spec.target_delta_deg.value), spec.target_delta_deg.origin)});
  } else if (auto q = layout.opening_for(asset, 0.01, plan.meshes); q && (*q - layout.open) / range > 0.5) {
    widths.push_back({*q, "nearly closed: the guide's 0.01 m box"});
  }
  if (widths.size() == 2) widths.push_back({layout.open + 0.9 * range, "nearly closed (90 % of the stroke)"});

  std::string missing;
  if (!spec.payload_kg) missing = "no payload: set [gripper] payload_kg (the object's mass)";
  else if (!spec.friction) missing = "no friction coefficient: set [gripper] friction (the object's μ)";

  std::vector<std::optional<ObjectSpec>> objects;
  std::vector<std::string> object_problems;
  for (const Width& w : widths) {
    const auto poses = layout.poses(asset, w.q);
    const Extent pad0 = layout.pad_extent(asset, 0, poses, layout.closing, plan.meshes);
    const Extent pad1 = layout.pad_extent(asset, 1, poses, layout.closing, plan.meshes);
    ObjectSpec object;
    object.opening = w.q;
    object.sized_for = w.why;
    object.width = pad1.low - pad0.high;
    const auto overlap = [&](const Eigen::Vector3d& u) {
      const Extent a = layout.pad_extent(asset, 0, poses, u, plan.meshes);
      const Extent b = layout.pad_extent(asset, 1, poses, u, plan.meshes);
      return Extent{std::max(a.low, b.low), std::min(a.high, b.high)};
    };
    const Extent lateral = overlap(layout.lateral), along = overlap(layout.approach);
    // 90 % of the pads' common extent: edges that coincide with the pads' make MuJoCo 2.2.2's box–box
    // collider report spurious deep contacts (docs/verify.md).
    object.depth = kObjectShare * (lateral.high - lateral.low);
    object.height = kObjectShare * (along.high - along.low);
    object.centre = 0.5 * (pad0.high + pad1.low) * layout.closing + 0.5 * (lateral.low + lateral.high) * layout.lateral +
                    0.5 * (along.low + along.high) * layout.approach;
    if (spec.payload_kg) object.mass = spec.payload_kg->value;
    if (spec.friction) object.friction = spec.friction->value;
    if (!(object.width > 0) || !(object.depth > 0) || !(object.height > 0)) {
      objects.push_back(std::nullopt);
      object_problems.push_back(fmt::format(
          "the pads do not face each other {} ({} {}): gap {} m, common depth {} m, common height {} m",
          w.why, format_number(angular ? degrees_from_radians(w.q) : w.q, 4), angular ? "deg" : "m",
          format_number(object.width, 3), format_number(object.depth, 3), format_number(object.height, 3)));
    } else {
      objects.push_back(object);
      object_problems.emplace_back();
    }
  }

  const double settled = t_close + kSettle;
  const auto object_name = [&](std::size_t i) {
    return objects[i] ? fmt::format("{} mm box", format_number(objects[i]->width * 1000, 3)) : widths[i].why;
  };
  for (std::size_t i = 0; i < widths.size(); ++i) {
    SceneSpec grasp;
    grasp.kind = SceneKind::Grasp;
    grasp.name = "grasp, gravity off, " + object_name(i);
    grasp.object = objects[i];
    grasp.duration = settled + window;
    grasp.window = window;
    grasp.not_run = !missing.empty() ? missing : object_problems[i];
    scenes.push_back(grasp);
  }
  for (std::size_t i = 0; i < widths.size(); ++i) {
    SceneSpec hold;
    hold.kind = SceneKind::Hold;
    hold.name = "hold, gravity on, " + object_name(i);
    hold.object = objects[i];
    hold.gravity = true;
    hold.gravity_on_at = settled;
    hold.judged_from = settled;
    hold.duration = settled + window;
    hold.window = window;
    hold.not_run = !missing.empty() ? missing : object_problems[i];
    scenes.push_back(hold);
  }
  // The lift holds the halfway box.
  SceneSpec lift;
  lift.kind = SceneKind::Lift;
  lift.name = fmt::format("lift {} mm, ", format_number(kLiftHeight * 1000)) + object_name(1);
  lift.object = objects[1];
  lift.gravity = true;
  lift.gravity_on_at = settled;
  lift.lift_start = settled + kSettle;
  lift.lift_duration = kLiftDuration;
  lift.lift_height = kLiftHeight;
  lift.judged_from = lift.lift_start;
  lift.duration = lift.lift_start + kLiftDuration + kAfterLift;
  lift.window = kAfterLift;
  lift.not_run = !missing.empty() ? missing : object_problems[1];
  scenes.push_back(lift);
  return scenes;
}

}  // namespace assetlint::verify
