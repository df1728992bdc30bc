#pragma once
// The guide's last question: can the max drive force and the stiffness be lowered while every
// scene still passes? Bisects the lowest max force at today's stiffness, then the lowest
// stiffness at that force, the damping re-derived for the same damping ratio (d ∝ √k at a
// fixed inertia). Engine-neutral: `passes` steps the scenes with a drive.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "verify/metrics.h"
#include "verify/scene.h"

namespace assetlint::verify {

struct FineTuneTrial {
  DriveSpec drive;
  bool passed = false;
};

struct FineTuneResult {
  bool baseline_passed = false;
  DriveSpec lowest;                  // the lowest passing drive found (today's when nothing could be lowered)
  std::vector<FineTuneTrial> trials;  // every drive tried, in order
  std::vector<std::string> notes;     // what could not be lowered, and why
};

// Bisection stops when the bracket is narrower than `tolerance` × today's value. Today's drive
// has passed every scene already (the verification's own run): it is not run again.
FineTuneResult fine_tune(const DriveSpec& today, const std::function<bool(const DriveSpec&)>& passes,
                         double tolerance = 0.02);

// The answer when today's drive fails a scene (`scenes`, the verification's run): nothing is
// lowered, and the notes say which scene fails first and which value of the drive to change.
FineTuneResult failing_baseline(const DriveSpec& today, const std::vector<SceneResult>& scenes);

}  // namespace assetlint::verify
