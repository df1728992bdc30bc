#include "verify/metrics.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "util/numbers.h"

namespace assetlint::verify {
namespace {

Eigen::Vector3d pad_midpoint(const Sample& s) { return 0.5 * (s.pads[0].translation() + s.pads[1].translation()); }

std::string mm(double metres) { return format_number(metres * 1000, 3) + " mm"; }

// With gravity off and the mount still, only the drive feeds the scene. Its force is bounded
// by F (the max force, else the spring's pull across the stroke s), so its potential at the
// start and the work its target's travel adds are each at most F·s: no body may hold more
// kinetic energy than 2·F·s. More is energy the integration made (a drive too stiff for the
// step), even when the state stays finite.
std::optional<std::string> energy_growth(const VerifyPlan& plan, const SceneSpec& scene, const Trajectory& trajectory) {
  if (scene.gravity || scene.lift_height > 0) return std::nullopt;
  const double stroke = std::abs(plan.layout.closed - plan.layout.open);
  const double spring = plan.drive.stiffness * stroke;
  const double force = plan.drive.max_force ? std::min(*plan.drive.max_force, spring) : spring;
  const double budget = 2 * force * stroke;
  const Sample* peak = nullptr;
  for (const Sample& s : trajectory.samples)
    if (!peak || s.kinetic_energy > peak->kinetic_energy) peak = &s;
  if (!peak || !(peak->kinetic_energy > budget)) return std::nullopt;
  const bool angular = is_angular(plan.layout.driven->type);
  return fmt::format("kinetic energy reached {} J at {} s, more than the {} J the drive can supply (2 × {} {} × the {} "
                     "{} stroke): the integration creates energy",
                     format_number(peak->kinetic_energy, 3), format_number(peak->t, 3), format_number(budget, 3),
                     format_number(force, 4), angular ? "N·m" : "N", format_number(stroke, 4), angular ? "rad" : "m");
}

}  // namespace

std::optional<double> close_time(const VerifyPlan& plan, const Trajectory& trajectory) {
  const double band = 0.02 * std::abs(plan.layout.closed - plan.layout.open);
  std::optional<double> since;
  for (const Sample& s : trajectory.samples) {
    if (std::abs(s.q - plan.layout.closed) <= band) {
      if (!since) since = s.t;
    } else {
      since.reset();
    }
  }
  return since;
}

double jitter(const Trajectory& trajectory, double from, bool with_object) {
  const auto& samples = trajectory.samples;
  double worst = 0;
  for (int body = with_object ? 0 : 1; body < 3; ++body) {
    double sum = 0;
    int count = 0;
    for (std::size_t i = 1; i < samples.size(); ++i) {
      if (samples[i - 1].t < from - 1e-12) continue;
      const auto position = [&](const Sample& s) {
        return body == 0 ? s.object : Eigen::Vector3d(s.pads[body - 1].translation());
      };
      const double v = (position(samples[i]) - position(samples[i - 1])).norm() / (samples[i].t - samples[i - 1].t);
      sum += v * v;
      ++count;
    }
    if (count) worst = std::max(worst, std::sqrt(sum / count));
  }
  return worst;
}

double slip(const Trajectory& trajectory, double from) {
  std::optional<Eigen::Vector3d> start;
  double worst = 0;
  for (const Sample& s : trajectory.samples) {
    if (s.t < from - 1e-12) continue;
    const Eigen::Vector3d r = s.object - pad_midpoint(s);
    if (!start) start = r;
    worst = std::max(worst, (r - *start).norm());
  }
  return worst;
}

SceneResult not_run(const SceneSpec& scene) {
  SceneResult result;
  result.spec = scene;
  return result;
}

SceneResult judge(const VerifyPlan& plan, const SceneSpec& scene, Trajectory trajectory, const VerifySettings& limits) {
  SceneResult result;
  result.spec = scene;
  result.ran = true;
  SceneMetrics& m = result.metrics;
  const auto& samples = trajectory.samples;
  const double window_from = scene.duration - scene.window;
  auto& failures = result.failures;

  double mimic = 0;
  for (const Sample& s : samples) mimic = std::max(mimic, s.mimic_error);
  if (!plan.layout.mimics.empty()) m.mimic_error_max = mimic;
  if (!trajectory.diverged) {
    if (auto growth = energy_growth(plan, scene, trajectory)) {
      trajectory.diverged = true;
      trajectory.divergence = *growth;
    }
  }
  m.diverged = trajectory.diverged;
  if (trajectory.diverged) failures.push_back("diverged: " + trajectory.divergence);

  if (scene.kind == SceneKind::Close) {
    m.spec_close_time_s = plan.spec_close_time;
    m.close_time_s = close_time(plan, trajectory);
    double speed = 0;
    for (std::size_t i = 1; i < samples.size(); ++i)
      for (int side = 0; side < 2; ++side)
        speed = std::max(speed, std::abs((samples[i].pads[side].translation() - samples[i - 1].pads[side].translation())
                                             .dot(plan.layout.closing)) /
                                    (samples[i].t - samples[i - 1].t));
    m.peak_finger_speed_m_s = speed;
    if (!m.close_time_s) {
      failures.push_back(fmt::format("never stays within 2 % of the stroke from closed in {} s",
                                     format_number(scene.duration, 3)));
    } else if (plan.spec_close_time) {
      const double spec = *plan.spec_close_time;
      const double low = spec * (1 - limits.close_time_under.value), high = spec * (1 + limits.close_time_over.value);
      if (*m.close_time_s < low || *m.close_time_s > high)
        failures.push_back(fmt::format("close time {} s outside {} to {} s (the spec's {} s −{} %/+{} %)",
                                       format_number(*m.close_time_s, 3), format_number(low, 3), format_number(high, 3),
                                       format_number(spec, 3), format_number(limits.close_time_under.value * 100),
                                       format_number(limits.close_time_over.value * 100)));
    }
  } else {
    double peak = 0, steady = 0, grip = 0;
    int count = 0;
    for (const Sample& s : samples) {
      peak = std::max(peak, s.penetration);
      if (s.t < window_from - 1e-12) continue;
      steady += s.penetration;
      grip += s.normal_force[0] + s.normal_force[1];
      ++count;
    }
    m.peak_penetration_m = peak;
    m.steady_penetration_m = count ? steady / count : 0.0;
    if (peak > limits.peak_penetration_m.value)
      failures.push_back(fmt::format("peak penetration {} > {}", mm(peak), mm(limits.peak_penetration_m.value)));
    if (*m.steady_penetration_m > limits.steady_penetration_m.value)
      failures.push_back(fmt::format("steady penetration {} > {}", mm(*m.steady_penetration_m),
                                     mm(limits.steady_penetration_m.value)));
    if (scene.kind != SceneKind::Lift) {
      m.grip_force_n = count ? grip / count : 0.0;
      m.required_grip_force_n = plan.required_grip_force;
      if (plan.required_grip_force && *m.grip_force_n < *plan.required_grip_force)
        failures.push_back(fmt::format("grip force {} N < m·g/μ = {} N", format_number(*m.grip_force_n, 4),
                                       format_number(*plan.required_grip_force, 4)));
      m.jitter_m_s = jitter(trajectory, window_from, true);
      if (*m.jitter_m_s > limits.jitter_m_s.value)
        failures.push_back(fmt::format("jitter {} mm/s > {} mm/s", format_number(*m.jitter_m_s * 1000, 3),
                                       format_number(limits.jitter_m_s.value * 1000, 3)));
    }
    if (scene.kind == SceneKind::Hold || scene.kind == SceneKind::Lift) {
      m.slip_m = slip(trajectory, scene.judged_from);
      if (*m.slip_m > limits.slip_m.value)
        failures.push_back(fmt::format("slip {} > {}", mm(*m.slip_m), mm(limits.slip_m.value)));
    }
  }
  result.passed = failures.empty();
  result.trajectory = std::move(trajectory);
  return result;
}

}  // namespace assetlint::verify
