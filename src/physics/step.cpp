#include "physics/step.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "util/numbers.h"

namespace assetlint::physics {

std::string_view solver_name(Solver solver) {
  switch (solver) {
    case Solver::TGS: return "TGS";
    case Solver::PGS: return "PGS";
    case Solver::MuJoCo: return "MuJoCo";
  }
  return "";
}

int SimulationRate::iterations() const {
  double n = position_iterations;
  if (min_position_iterations) n = std::max(n, *min_position_iterations);
  if (max_position_iterations) n = std::min(n, *max_position_iterations);
  return std::max(1, static_cast<int>(std::lround(n)));
}

namespace {
// "1/16000 s" when the step is the reciprocal of a round number, else "6.51e-5 s".
std::string seconds(double h) {
  const double per_second = 1.0 / h;
  if (std::abs(per_second - std::round(per_second)) < 1e-9 * per_second)
    return fmt::format("1/{} s", format_number(std::round(per_second)));
  return fmt::format("{} s", format_number(h, 3));
}
}  // namespace

std::string SimulationRate::step_text() const {
  return fmt::format("{}, h = {}", solver_name(solver), seconds(h()));
}

std::string SimulationRate::describe() const {
  const std::string rate = fmt::format("{} Hz ({})", format_number(timesteps_per_second), rate_origin);
  if (solver == Solver::MuJoCo) return fmt::format("MuJoCo, h = timestep = {} ({})", seconds(h()), rate);
  if (solver == Solver::PGS)
    return fmt::format("PGS ({}), h = dt = {} ({})", solver_origin, seconds(h()), rate);
  std::string count = fmt::format("{} position iterations ({})", format_number(position_iterations), iterations_origin);
  if (iterations() != static_cast<int>(std::lround(position_iterations)))
    count += fmt::format(", clamped to {} by the scene", iterations());
  return fmt::format("TGS ({}), h = dt/{} = {} ({} / {})", solver_origin, iterations(), seconds(h()), rate, count);
}

SimulationRate effective_simulation(const Asset& asset, const Settings& settings) {
  SimulationRate rate;
  const auto where = [&](const Span& span) {
    if (span.valid()) {
      const SourceFile& source = asset.source(span.file);
      // A binary (crate) layer has no lines: the object instead.
      if (source.binary()) return fmt::format("{} <{}>", source.path(), source.object_at(span.offset));
      return fmt::format("{}:{}", source.path(), span.line);
    }
    return std::string(asset.format == SourceFormat::Mjcf ? "MuJoCo's default timestep" : "stage default");
  };
  // The stage's own value wins, then configuration; the defaults stay otherwise.
  const auto pick = [&](const OptQuantity& stage, const std::optional<Configured<double>>& configured, double& value,
                        std::string& origin) {
    if (stage) {
      value = stage->value;
      origin = where(stage->span);
    } else if (configured) {
      value = configured->value;
      origin = configured->origin;
    }
  };
  pick(asset.scene.timesteps_per_second, settings.simulation.timesteps_per_second, rate.timesteps_per_second,
       rate.rate_origin);
  pick(asset.scene.position_iterations, settings.simulation.position_iterations, rate.position_iterations,
       rate.iterations_origin);
  pick(asset.scene.velocity_iterations, settings.simulation.velocity_iterations, rate.velocity_iterations,
       rate.velocity_iterations_origin);
  if (asset.scene.min_position_iterations) rate.min_position_iterations = asset.scene.min_position_iterations->value;
  if (asset.scene.max_position_iterations) rate.max_position_iterations = asset.scene.max_position_iterations->value;
  if (!asset.scene.solver.empty()) {
    rate.solver = asset.scene.solver == "PGS"      ? Solver::PGS
                  : asset.scene.solver == "MuJoCo" ? Solver::MuJoCo
                                                   : Solver::TGS;
    rate.solver_origin = where(asset.scene.solver_span);
  } else if (settings.simulation.solver) {
    rate.solver = settings.simulation.solver->value == "PGS" ? Solver::PGS : Solver::TGS;
    rate.solver_origin = settings.simulation.solver->origin;
  }
  if (!asset.scene.integrator.empty())
    if (auto integrator = parse_integrator(asset.scene.integrator)) {
      rate.integrator = *integrator;
      rate.integrator_origin = where(asset.scene.integrator_span);
    }
  return rate;
}

}  // namespace assetlint::physics
