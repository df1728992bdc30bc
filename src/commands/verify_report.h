#pragma once
// How `asset-lint verify` prints its results: text, JSON (docs/verify.md) and the SVG plot.
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "verify/engine.h"
#include "verify/fine_tune.h"
#include "verify/metrics.h"

namespace assetlint::commands {

struct VerifyReport {
  std::string path;
  std::string joint;
  std::vector<std::string> inputs;  // each input with where it came from
  verify::EngineInfo engine;
  std::vector<verify::SceneResult> scenes;
  bool angular = true;
  long steps = 0;  // engine steps over every scene
  std::optional<verify::FineTuneResult> fine_tune;
  bool passed() const;
};

void write_verify_text(std::ostream& out, const VerifyReport& report, const VerifySettings& limits);
void write_verify_json(std::ostream& out, const VerifyReport& report);
// One panel per kind of scene (close: finger opening; grasp: penetration; hold and lift: slip),
// every scene a line labelled with its verdict (dashed when it fails), the thresholds marked.
std::string verify_svg(const VerifyReport& report, const verify::VerifyPlan& plan, const VerifySettings& limits);

}  // namespace assetlint::commands
