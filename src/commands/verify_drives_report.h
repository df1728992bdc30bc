#pragma once
// How the drive tests print: one line per joint and test, then each failure's cause and fix
// (text); the `verify` JSON contract with kinds step, sweep, hold, velocity, mimic; an SVG of
// small multiples, one panel per joint.
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "verify/drive_metrics.h"

namespace assetlint::commands {

struct DriveReport {
  std::string path;
  std::string engine_version;
  std::vector<std::string> translation;
  const verify::DrivePlan* plan = nullptr;
  std::vector<verify::DriveResult> results;  // joint by joint, each in test order
  long steps = 0;
  // --fine-tune: the joints given proposed gains, the plan with them and its results.
  std::vector<std::size_t> fine_tuned;
  const verify::DrivePlan* tuned_plan = nullptr;
  std::vector<verify::DriveResult> tuned_results;
  bool passed() const;
};

void write_drive_text(std::ostream& out, const DriveReport& report);
void write_drive_json(std::ostream& out, const DriveReport& report);
std::string drive_svg(const DriveReport& report);

}  // namespace assetlint::commands
