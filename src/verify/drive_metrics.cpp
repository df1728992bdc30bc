#include "verify/drive_metrics.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/drive.h"
#include "physics/drive_response.h"
#include "physics/servo_step.h"
#include "util/numbers.h"

namespace assetlint::verify {
namespace {

constexpr int kHoldPoints = 41;           // the range is searched for gravity's largest pull at this many poses
constexpr double kSteadyWindow = 0.5;     // s: the steady value is the mean over the step scene's last half second
constexpr double kReversalSpeed = 0.01;   // of the step per second: slower motion is not counted as a reversal
constexpr double kSettleShare = 0.2;      // a proposed drive settles within this share of the settle limit

std::string n(double v) { return format_number(v, 3); }

const DriveSample& sample_at(const DriveTrajectory& trajectory, double t) {
  const auto& s = trajectory.samples;
  auto it = std::upper_bound(s.begin(), s.end(), t + 1e-9, [](double time, const DriveSample& x) { return time < x.t; });
  return it == s.begin() ? s.front() : *(it - 1);
}

// Divergence: a non-finite state, an engine warning, or kinetic energy past the scene's budget.
std::optional<std::string> divergence(const DriveTrajectory& trajectory) {
  if (trajectory.diverged) return trajectory.divergence;
  const DriveSample* peak = nullptr;
  for (const DriveSample& s : trajectory.samples)
    if (!peak || s.kinetic_energy > peak->kinetic_energy) peak = &s;
  if (peak && peak->kinetic_energy > trajectory.energy_budget)
    return fmt::format("kinetic energy reached {} J at {} s, more than the {} J the drive and gravity can supply: the "
                       "integration creates energy",
                       format_number(peak->kinetic_energy, 4), n(peak->t), format_number(trajectory.energy_budget, 4));
  return std::nullopt;
}

// The damping ratio, natural frequency and h·nf of the drive on the inertia the joint sees.
std::string servo_physics(const DrivePlan& plan, const TestedJoint& j, const JointLoads& loads) {
  const DriveSpec& d = *j.drive;
  const double zeta = physics::damping_ratio(d.damping, d.stiffness, loads.inertia);
  const double nf = physics::natural_frequency(d.stiffness, loads.inertia);
  return fmt::format("damping ratio ζ = d / (2·√(k·I)) = {} / (2·√({} × {})) = {} on the inertia the joint sees at its "
                     "start, every other joint held (I = Mᵢᵢ = {} {}); a linear servo overshoots {} %; nf = √(k/I) = {} "
                     "rad/s, h·nf = {}{}",
                     n(d.damping), n(d.stiffness), n(loads.inertia), n(zeta), n(loads.inertia),
                     j.angular ? "kg·m²" : "kg", n(physics::second_order_overshoot(zeta) * 100), n(nf),
                     n(plan.timestep * nf),
                     plan.timestep * nf > 2 ? " (above 2: MuJoCo integrates the spring explicitly, and it grows unless "
                                              "damping solved implicitly holds it)"
                                            : "");
}

std::string gains_fix(const TestedJoint& j, const DriveSpec& p) {
  std::string text = fmt::format("stiffness {} {}/{}, damping {} {}·s/{}", format_number(p.stiffness, 4), j.force_unit(),
                                 j.unit(), format_number(p.damping, 4), j.force_unit(), j.unit());
  if (p.max_force && (!j.drive || !j.drive->max_force || *p.max_force > *j.drive->max_force))
    text += fmt::format(", max force {} {}", format_number(*p.max_force, 4), j.force_unit());
  return text;
}

// The one line of configuration that gives a joint the proposed drive, in the asset's format and units.
std::string drive_line(const Asset& asset, const TestedJoint& j, const DriveSpec& p) {
  const std::string& name = j.joint->name.text;
  switch (asset.format) {
    case SourceFormat::Urdf:
      return fmt::format("[drives.{}] stiffness = {}, damping = {} in asset-lint.toml", name,
                         format_number(p.stiffness, 4), format_number(p.damping, 4));
    case SourceFormat::Usda: {
      // USD's angular drive gains are per degree.
      const double per = j.angular ? std::numbers::pi / 180 : 1.0;
      const char* instance = j.angular ? "angular" : "linear";
      return fmt::format("drive:{}:physics:stiffness = {} and drive:{}:physics:damping = {} (PhysicsDriveAPI:{}) on "
                         "the joint prim",
                         instance, format_number(p.stiffness * per, 4), instance, format_number(p.damping * per, 4),
                         instance);
    }
    case SourceFormat::Mjcf:
      return fmt::format("<position joint=\"{}\" kp=\"{}\" kv=\"{}\"/> in <actuator>", name,
                         format_number(p.stiffness, 4), format_number(p.damping, 4));
  }
  return {};
}

DriveResult base_result(const std::string& name, DriveTestKind kind, const TestedJoint& j) {
  DriveResult r;
  r.name = name;
  r.kind = kind;
  r.joint = j.joint->name.text;
  r.angular = j.angular;
  return r;
}

void finish(DriveResult& r) { r.passed = r.ran && r.failures.empty(); }

// A stepped scene's result up to its own measurements: true when that is all there is (the scene
// was not run, or it diverged, which is then judged with its cause and fix).
bool judged_before_measuring(DriveResult& r, const DrivePlan& plan, const TestedJoint& j, const JointLoads& loads,
                             const DriveScene& scene, const DriveTrajectory* tr, const DriveSpec& proposal) {
  r.scene = &scene;
  if (!tr) {
    r.failures.push_back(scene.not_run);
    return true;
  }
  r.ran = true;
  r.trajectory = tr;
  if (auto diverged = divergence(*tr)) {
    r.metrics.diverged = true;
    r.failures.push_back("diverged: " + *diverged);
    r.causes.push_back(servo_physics(plan, j, loads));
    r.fix = fmt::format("a finer step, or {}", gains_fix(j, proposal));
    finish(r);
    return true;
  }
  r.metrics.diverged = false;
  return false;
}

DriveResult judge_step(const DrivePlan& plan, const TestedJoint& j, const JointLoads& loads, const DriveScene& scene,
                       const DriveTrajectory* tr, const DriveSpec& proposal) {
  DriveResult r = base_result(scene.name, DriveTestKind::Step, j);
  const double target = scene.waypoints.back().second;
  const double size = target - scene.waypoints.front().second;
  if (tr) r.metrics.step_size = std::abs(size);
  if (judged_before_measuring(r, plan, j, loads, scene, tr, proposal)) return r;
  const auto& lim = plan.limits;
  const double end = tr->samples.back().t;
  const double q_before = sample_at(*tr, scene.step_at).q;
  double steady = 0;
  int count = 0;
  for (const DriveSample& s : tr->samples)
    if (s.t >= end - kSteadyWindow) steady += s.q, ++count;
  steady /= std::max(count, 1);
  r.metrics.steady_error = steady - target;
  const double moved = steady - q_before;
  int reversals = 0, direction = 0;
  const double eps = kReversalSpeed * std::abs(size);
  std::optional<double> settled2, settled5;
  for (const DriveSample& s : tr->samples) {
    if (s.t < scene.step_at) continue;
    const int now = s.velocity > eps ? 1 : s.velocity < -eps ? -1 : 0;
    if (now != 0 && direction != 0 && now != direction) ++reversals;
    if (now != 0) direction = now;
    const double error = std::abs(s.q - target);
    if (error > 0.02 * std::abs(size)) settled2.reset();
    else if (!settled2) settled2 = s.t - scene.step_at;
    if (error > lim.settle_band.value * std::abs(size)) settled5.reset();
    else if (!settled5) settled5 = s.t - scene.step_at;
  }
  // Overshoot past the value the joint settles at, a fraction of the move it made; a joint that
  // never settles has no such value, and its overshoot is taken past the target, a fraction of the step.
  const double reference = settled5 ? steady : target;
  const double move = settled5 ? moved : size;
  double peak = 0;
  for (const DriveSample& s : tr->samples)
    if (s.t >= scene.step_at) peak = std::max(peak, (s.q - reference) * (move >= 0 ? 1.0 : -1.0));
  // Below a millionth of the move, a peak is rounding, not overshoot.
  r.metrics.overshoot =
      std::abs(move) > 1e-3 * std::abs(size) && peak > 1e-6 * std::abs(move) ? peak / std::abs(move) : 0.0;
  r.metrics.sign_changes = std::max(0, reversals - 1);
  r.metrics.settle_time_s = settled5;
  r.metrics.settle_time_2pct_s = settled2;
  bool dynamics = false, steady_problem = false;
  if (*r.metrics.overshoot > lim.overshoot.value) {
    r.failures.push_back(fmt::format("overshoot {} % > {} %", n(*r.metrics.overshoot * 100), n(lim.overshoot.value * 100)));
    dynamics = true;
  }
  if (*r.metrics.sign_changes > lim.sign_changes.value) {
    r.failures.push_back(fmt::format("{} velocity sign changes after the first peak > {}", *r.metrics.sign_changes,
                                     n(lim.sign_changes.value)));
    dynamics = true;
  }
  if (!settled5 || *settled5 > lim.settle_time_s.value) {
    r.failures.push_back(settled5 ? fmt::format("settles within {} % in {} s > {} s", n(lim.settle_band.value * 100),
                                                n(*settled5), n(lim.settle_time_s.value))
                                  : fmt::format("never settles within {} % of the {} {} step (steady error {} {})",
                                                n(lim.settle_band.value * 100), n(std::abs(size)), j.unit(),
                                                n(*r.metrics.steady_error), j.unit()));
    if (std::abs(*r.metrics.steady_error) > lim.settle_band.value * std::abs(size)) steady_problem = true;
    else dynamics = true;
  }
  if (dynamics) r.causes.push_back(servo_physics(plan, j, loads));
  if (steady_problem) {
    const DriveSpec& d = *j.drive;
    const double friction = j.joint->joint_friction ? j.joint->joint_friction->value : 0.0;
    std::string cause = fmt::format(
        "steady error {} {}: gravity's {} {} at the target ÷ the stiffness {} = {} {}", n(*r.metrics.steady_error),
        j.unit(), n(std::abs(loads.gravity_at_step)), j.force_unit(), n(d.stiffness),
        n(physics::static_droop(loads.gravity_at_step, d.stiffness)), j.unit());
    if (friction > 0)
      cause += fmt::format(", plus up to the friction {} ÷ k = {} {}", n(friction), n(friction / d.stiffness), j.unit());
    if (d.max_force && std::abs(loads.gravity_at_step) > *d.max_force)
      cause += fmt::format("; gravity's pull exceeds the max force {} {}, so the drive cannot reach the target",
                           n(*d.max_force), j.force_unit());
    r.causes.push_back(cause);
  }
  if (!r.failures.empty()) r.fix = gains_fix(j, proposal);
  finish(r);
  return r;
}

DriveResult judge_sweep(const DrivePlan& plan, const TestedJoint& j, const JointLoads& loads, const DriveScene& scene,
                        const DriveTrajectory* tr, const DriveSpec& proposal) {
  DriveResult r = base_result(scene.name, DriveTestKind::Sweep, j);
  if (judged_before_measuring(r, plan, j, loads, scene, tr, proposal)) return r;
  const auto& lim = plan.limits;
  const double start = sample_at(*tr, scene.waypoints[1].first).q;
  r.metrics.end_error_upper = std::abs(sample_at(*tr, scene.marks[0]).q - *j.upper);
  r.metrics.end_error_lower = std::abs(sample_at(*tr, scene.marks[1]).q - *j.lower);
  r.metrics.end_error = std::max(*r.metrics.end_error_upper, *r.metrics.end_error_lower);
  r.metrics.return_error = std::abs(tr->samples.back().q - start);
  const double end_limit = j.angular ? lim.sweep_end_rad.value : lim.sweep_end_m.value;
  const double return_limit = j.angular ? lim.sweep_return_rad.value : lim.sweep_return_m.value;
  if (*r.metrics.end_error > end_limit)
    r.failures.push_back(fmt::format("end error {} {} (upper {}, lower {}) > {} {}", n(*r.metrics.end_error), j.unit(),
                                     n(*r.metrics.end_error_upper), n(*r.metrics.end_error_lower), n(end_limit), j.unit()));
  if (*r.metrics.return_error > return_limit)
    r.failures.push_back(
        fmt::format("return error {} {} > {} {}", n(*r.metrics.return_error), j.unit(), n(return_limit), j.unit()));
  if (!r.failures.empty()) {
    const DriveSpec& d = *j.drive;
    physics::Servo servo;
    servo.inertia = loads.inertia;
    servo.stiffness = d.stiffness;
    servo.actuator_damping = d.damping;
    const double lag = scene.speed * d.damping / d.stiffness;
    const double rate = physics::slowest_decay_rate(servo);
    r.causes.push_back(fmt::format(
        "a target moving at {} {}/s ({}) lags a spring-damper by v·d/k = {} {}; over the {} s rest at each limit it "
        "decays at the servo's slowest rate on I = {}, {} 1/s (ζ = {}), to about {} {}",
        n(scene.speed), j.unit(), scene.ramp, n(lag), j.unit(), n(scene.rest), n(loads.inertia), n(rate),
        n(servo.damping_ratio()), n(lag * std::exp(-rate * scene.rest)), j.unit()));
    r.causes.push_back(fmt::format("gravity pulls up to {} {} over the range (at {} {}): the spring {} leaves up to {} {}",
                                   n(loads.gravity_max), j.force_unit(), n(loads.gravity_max_at), j.unit(),
                                   n(d.stiffness), n(physics::static_droop(loads.gravity_max, d.stiffness)), j.unit()));
    r.fix = gains_fix(j, proposal);
  }
  finish(r);
  return r;
}

DriveResult judge_hold(const DrivePlan& plan, const TestedJoint& j, const JointLoads& loads, const DriveSpec& proposal) {
  DriveResult r = base_result(fmt::format("hold '{}'", j.joint->name.text), DriveTestKind::Hold, j);
  r.ran = true;
  const DriveSpec& d = *j.drive;
  r.metrics.gravity_torque_max = loads.gravity_max;
  r.metrics.gravity_torque_at = loads.gravity_max_at;
  r.metrics.droop = physics::static_droop(loads.gravity_at_start, d.stiffness);
  if (d.max_force) {
    r.metrics.effort_limit = *d.max_force;
    r.metrics.effort_margin = *d.max_force - loads.gravity_max;
    if (*r.metrics.effort_margin < 0) {
      r.failures.push_back(fmt::format("gravity torque {} {} at {} {} > effort limit {} {}", n(loads.gravity_max),
                                       j.force_unit(), n(loads.gravity_max_at), j.unit(), n(*d.max_force), j.force_unit()));
      r.causes.push_back(fmt::format("with the rest of the robot at its start pose, the links beyond the joint weigh {} {} "
                                     "on it at {} {} (MuJoCo's inverse dynamics, at rest): the drive cannot hold them there",
                                     n(loads.gravity_max), j.force_unit(), n(loads.gravity_max_at), j.unit()));
    }
  }
  const double droop_limit = j.angular ? plan.limits.droop_rad.value : plan.limits.droop_m.value;
  if (*r.metrics.droop > droop_limit) {
    r.failures.push_back(fmt::format("droop {} {} at the start pose > {} {}", n(*r.metrics.droop), j.unit(),
                                     n(droop_limit), j.unit()));
    r.causes.push_back(fmt::format("gravity's {} {} at the start ÷ the stiffness {} = {} {}", n(loads.gravity_at_start),
                                   j.force_unit(), n(d.stiffness), n(*r.metrics.droop), j.unit()));
  }
  if (!r.failures.empty()) r.fix = gains_fix(j, proposal);
  finish(r);
  return r;
}

DriveResult judge_velocity(const DrivePlan& plan, const TestedJoint& j, const DriveScene* scene, const DriveTrajectory* tr,
                           const DriveSpec& proposal) {
  DriveResult r = base_result(fmt::format("velocity '{}'", j.joint->name.text), DriveTestKind::Velocity, j);
  r.scene = scene;
  if (!j.drive->max_velocity) {
    r.failures.push_back(fmt::format("not run: no max joint velocity (MuJoCo has none): set [drives.{}] max_velocity",
                                     j.joint->name.text));
    return r;
  }
  if (!tr) {
    r.failures.push_back("not run: measured on the sweep, which was not run");
    return r;
  }
  r.ran = true;
  r.trajectory = tr;
  double peak = 0;
  for (const DriveSample& s : tr->samples) peak = std::max(peak, std::abs(s.velocity));
  const double limit = *j.drive->max_velocity;
  r.metrics.peak_velocity = peak;
  r.metrics.velocity_limit = limit;
  if (peak > limit * (1 + plan.limits.velocity_over.value)) {
    r.failures.push_back(fmt::format("peak speed {} {}/s > {} {}/s + {} %", n(peak), j.unit(), n(limit), j.unit(),
                                     n(plan.limits.velocity_over.value * 100)));
    r.causes.push_back("MuJoCo does not clamp the joint's speed as PhysX does; the target is ramped at the max velocity, "
                       "and the drive pushed the joint faster while it caught up");
    r.fix = "more damping, which slows the catching up: " + gains_fix(j, proposal);
  }
  finish(r);
  return r;
}

DriveResult judge_mimic(const DrivePlan& plan, const TestedJoint& j, const DriveScene* scene, const DriveTrajectory* tr) {
  DriveResult r = base_result(fmt::format("mimic '{}'", j.joint->name.text), DriveTestKind::Mimic, j);
  r.scene = scene;
  if (!tr) {
    r.failures.push_back("not run: measured on the sweep, which was not run");
    return r;
  }
  r.ran = true;
  r.trajectory = tr;
  double worst = 0;
  for (const DriveSample& s : tr->samples) worst = std::max(worst, s.mimic_error);
  r.metrics.mimic_error_max = worst;
  const bool angular = is_angular(j.followers.front()->type);
  const double limit = angular ? plan.limits.mimic_error_rad.value : plan.limits.mimic_error_m.value;
  if (worst > limit) {
    r.failures.push_back(fmt::format("follower tracking error {} {} > {} {}", n(worst), angular ? "rad" : "m", n(limit),
                                     angular ? "rad" : "m"));
    r.causes.push_back("the mimic constraint (a MuJoCo equality, time constant two steps) yields under the followers' "
                       "load, or a follower's own limits fight the mapped range (asset-lint check: mimic-limit-conflict)");
    r.fix = "widen the follower's limits to the mapped range";
  }
  finish(r);
  return r;
}

}  // namespace

JointLoads joint_loads(const DrivePlan& plan, const DriveEngine& engine, std::size_t joint) {
  const TestedJoint& j = plan.joints[joint];
  JointLoads loads;
  loads.inertia = engine.joint_inertia(joint);
  loads.gravity_at_start = engine.gravity_torque(joint, j.start);
  const double low = j.lower ? *j.lower : -std::numbers::pi, high = j.lower ? *j.upper : std::numbers::pi;
  for (int i = 0; i < kHoldPoints; ++i) {
    const double q = low + (high - low) * i / (kHoldPoints - 1);
    const double torque = std::abs(engine.gravity_torque(joint, q));
    if (torque > loads.gravity_max) loads.gravity_max = torque, loads.gravity_max_at = q;
  }
  const double mid = j.lower ? 0.5 * (*j.lower + *j.upper) : j.start;
  const double range = j.lower ? *j.upper - *j.lower : INFINITY;
  loads.gravity_at_step = engine.gravity_torque(joint, mid + physics::drive_step_size(range, j.angular));
  return loads;
}

DriveSpec proposed_drive(const DrivePlan& plan, std::size_t joint, const JointLoads& loads) {
  const TestedJoint& j = plan.joints[joint];
  DriveSpec p = j.drive ? *j.drive : DriveSpec{};
  if (!j.drive) {  // the limits the joint already has
    if (j.joint->effort && j.joint->effort->value > 0 && std::isfinite(j.joint->effort->value))
      p.max_force = j.joint->effort->value;
    if (j.joint->velocity && j.joint->velocity->value > 0 && std::isfinite(j.joint->velocity->value))
      p.max_velocity = j.joint->velocity->value;
  }
  const double droop = j.angular ? plan.limits.droop_rad.value : plan.limits.droop_m.value;
  const double settle =
      physics::stiffness_for_frequency(physics::frequency_to_settle(kSettleShare * plan.limits.settle_time_s.value), loads.inertia);
  // The step settles only if gravity's pull at its target leaves less than the settle band; half
  // of it, so that the other joints' own droop, which moves the links this one carries, fits too.
  const double range = j.lower ? *j.upper - *j.lower : INFINITY;
  const double band = 0.5 * plan.limits.settle_band.value * physics::drive_step_size(range, j.angular);
  const double step = band > 0 ? physics::stiffness_for_droop(loads.gravity_at_step, band) : 0.0;
  // Today's stiffness is kept when it already does all three: the fix changes as little as it can.
  p.stiffness = std::max({physics::stiffness_for_droop(loads.gravity_max, droop), settle, step,
                          j.drive ? j.drive->stiffness : 0.0});
  p.damping = physics::damping_for_ratio(1.0, p.stiffness, loads.inertia);
  if (p.max_force && *p.max_force < loads.gravity_max) p.max_force = loads.gravity_max;
  p.origin = "proposed";
  return p;
}

std::vector<DriveResult> judge_joint(const DrivePlan& plan, std::size_t joint, const JointLoads& loads,
                                     const DriveScene* step_scene, const DriveTrajectory* step,
                                     const DriveScene* sweep_scene, const DriveTrajectory* sweep) {
  const TestedJoint& j = plan.joints[joint];
  const DriveSpec proposal = proposed_drive(plan, joint, loads);
  std::vector<DriveResult> results;
  if (!j.drive) {
    DriveResult r = base_result(fmt::format("drive '{}'", j.joint->name.text), DriveTestKind::Step, j);
    r.failures.push_back("not run: " + j.no_drive);
    r.fix = drive_line(*plan.asset, j, proposal);
    results.push_back(std::move(r));
    return results;
  }
  if (step_scene) results.push_back(judge_step(plan, j, loads, *step_scene, step, proposal));
  if (sweep_scene) results.push_back(judge_sweep(plan, j, loads, *sweep_scene, sweep, proposal));
  results.push_back(judge_hold(plan, j, loads, proposal));
  results.push_back(judge_velocity(plan, j, sweep_scene, sweep, proposal));
  if (!j.followers.empty()) results.push_back(judge_mimic(plan, j, sweep_scene, sweep));
  return results;
}

}  // namespace assetlint::verify
