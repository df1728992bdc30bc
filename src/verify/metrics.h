#pragma once
// The measurements of a verification scene and its verdict against the [verify] thresholds
// (docs/verify.md), from the positions and contacts a backend sampled: engine-neutral.
#include <optional>
#include <string>
#include <vector>

#include "engine/settings.h"
#include "verify/scene.h"
#include "verify/trajectory.h"

namespace assetlint::verify {

// Each metric is set only where it applies to the scene's kind.
struct SceneMetrics {
  std::optional<double> close_time_s, spec_close_time_s, peak_finger_speed_m_s;
  std::optional<double> peak_penetration_m, steady_penetration_m;
  std::optional<double> grip_force_n, required_grip_force_n;
  std::optional<double> slip_m, jitter_m_s, mimic_error_max;
  std::optional<bool> diverged;
};

struct SceneResult {
  SceneSpec spec;
  bool ran = false;
  bool passed = false;
  SceneMetrics metrics;
  std::vector<std::string> failures;  // one sentence per threshold missed
  Trajectory trajectory;
};

// Time from which the driven joint stays within 2 % of the stroke from the closed position.
std::optional<double> close_time(const VerifyPlan& plan, const Trajectory& trajectory);
// RMS finite-difference speed of the object and each pad over samples at or after `from`; the largest.
double jitter(const Trajectory& trajectory, double from, bool with_object);
// The largest displacement of the object relative to the pads' midpoint since `from`.
double slip(const Trajectory& trajectory, double from);

SceneResult judge(const VerifyPlan& plan, const SceneSpec& scene, Trajectory trajectory, const VerifySettings& limits);
// A scene that was not stepped: `spec.not_run` says why.
SceneResult not_run(const SceneSpec& scene);

}  // namespace assetlint::verify
