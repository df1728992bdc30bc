#pragma once
// How `asset-lint simulate` prints a run: a text table, JSON, CSV and the SVG plot
// (docs/simulate.md).
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "commands/simulate_run.h"

namespace assetlint::commands {

// What the run was set up from, in words and numbers, for every output.
struct SimulationContext {
  std::string path;
  std::string joint;
  bool angular = true;
  std::string force_unit = "N·m";
  std::vector<std::string> setup;  // lines: drive, step, inertia, row
  double inertia = 0;              // kg·m² (kg), the one stepped
  std::string inertia_origin;
  std::optional<double> spec_close_time;  // s, (stroke / 2) / finger speed
  std::string spec_origin;
};

void write_simulation_text(std::ostream& out, const SimulationContext& context, const SimulationSetup& setup,
                           const SimulationRun& run);
void write_simulation_json(std::ostream& out, const SimulationContext& context, const SimulationSetup& setup,
                           const SimulationRun& run);
// time_s, implicit position/velocity/force, explicit position/velocity/force (empty after divergence).
void write_simulation_csv(std::ostream& out, const SimulationContext& context, const SimulationRun& run);
std::string simulation_svg(const SimulationContext& context, const SimulationSetup& setup, const SimulationRun& run);

}  // namespace assetlint::commands
