#include "commands/simulate_report.h"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "model/units.h"
#include "physics/servo_step.h"
#include "util/numbers.h"
#include "util/svg_chart.h"

namespace assetlint::commands {
namespace {

// Positions are shown in degrees for angular joints (people read degrees), metres otherwise.
double shown(const SimulationContext& c, double position) { return c.angular ? degrees_from_radians(position) : position; }
const char* position_unit(const SimulationContext& c) { return c.angular ? "deg" : "m"; }

std::string seconds(const std::optional<double>& t) { return t ? format_number(*t, 4) + " s" : "never"; }

std::string percent(double fraction) { return format_number(100.0 * fraction, 3) + " %"; }

std::vector<std::pair<std::string, std::string>> rows(const SimulationContext& c, const Metrics& m) {
  return {
      {"time to 90 %", seconds(m.time_to_90)},
      {"time to 98 %", seconds(m.time_to_98)},
      {"overshoot", percent(m.overshoot)},
      {"steady-state error", fmt::format("{} {}", format_number(shown(c, m.steady_state_error), 4), position_unit(c))},
      {"peak force", fmt::format("{} {}", format_number(m.peak_force, 4), c.force_unit)},
      {"final force", fmt::format("{} {}", format_number(m.final_force, 4), c.force_unit)},
      {"at max force", format_number(m.force_clamped_time, 4) + " s"},
      {"at max velocity", format_number(m.velocity_clamped_time, 4) + " s"},
      {"velocity sign changes", std::to_string(m.velocity_sign_changes)},
      {"diverged", m.diverged ? fmt::format("yes, at {}", seconds(m.diverged_at)) : "no"},
  };
}

nlohmann::json metrics_json(const Metrics& m) {
  const auto opt = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
  return {{"time_to_90_s", opt(m.time_to_90)},
          {"time_to_98_s", opt(m.time_to_98)},
          {"overshoot_fraction", m.overshoot},
          {"steady_state_error", m.steady_state_error},
          {"peak_force", m.peak_force},
          {"final_force", m.final_force},
          {"force_clamped_s", m.force_clamped_time},
          {"velocity_clamped_s", m.velocity_clamped_time},
          {"velocity_sign_changes", m.velocity_sign_changes},
          {"diverged", m.diverged},
          {"diverged_at_s", opt(m.diverged_at)},
          {"stalled", m.stalled}};
}

std::string engine_legend(const SimulationRun& run) {
  return run.engine == "implicit (PhysX)" ? "implicit drive (PhysX)" : run.engine;
}

std::string verdict(const SimulationContext& c, const SimulationSetup& s, const SimulationRun& run) {
  const Metrics& m = run.implicit_metrics;
  std::string text;
  if (m.stalled)
    text += fmt::format("The joint stalls: the load holds it {} {} short of the target with the drive at its max "
                        "force {} {}.\n",
                        format_number(shown(c, m.steady_state_error), 3), position_unit(c),
                        format_number(s.limits.force.max_force, 4), c.force_unit);
  else if (m.diverged) text += s.mujoco ? run.engine + " diverges here.\n" : "PhysX's implicit drive diverges here.\n";
  else if (std::abs(s.load) > s.limits.force.max_average_force(s.row.dt) && m.velocity_clamped_time > 0 && m.time_to_90)
    text += fmt::format("The load ({} {}) exceeds the max force, yet the joint moves on: the max joint velocity clamp "
                        "after each {} solve removes the velocity the load adds (PhysX 5.6.1 does the same).\n",
                        format_number(std::abs(s.load), 4), c.force_unit, physics::solver_name(s.row.solver));
  const double r = s.row.type == DriveType::Acceleration ? 1.0 : s.row.response;
  const std::string criterion = fmt::format("h²·k/I + 2·h·d/I = {} and h·d/I = {} (stable only below 4 and 2)",
                                            format_number(s.row.h * s.row.h * s.row.stiffness * r + 2 * s.row.h * s.row.damping * r, 3),
                                            format_number(s.row.h * s.row.damping * r, 3));
  if (s.mujoco) {
    const double radius = physics::servo_step(s.mujoco->integrator, s.row.h, s.mujoco->servo).spectral_radius();
    const double implicit = physics::servo_step(physics::MujocoIntegrator::ImplicitFast, s.row.h, s.mujoco->servo)
                                .spectral_radius();
    if (radius >= 1 && !m.diverged)
      text += fmt::format("{} is unstable at this step (spectral radius {} per step); only the force range keeps it "
                          "bounded.{}\n",
                          run.engine, format_number(radius, 3),
                          implicit < 1 ? fmt::format(" Under implicitfast, which solves kv implicitly, it would be "
                                                     "stable (spectral radius {}).",
                                                     format_number(implicit, 3))
                                       : std::string());
  }
  const std::string engine = s.mujoco ? run.engine : "PhysX's implicit row";
  if (run.explicit_metrics.diverged && !m.diverged)
    text += "The explicit spring diverges at this step where " + engine + " stays stable: " + criterion + ".\n";
  else if (!run.explicit_stable)
    text += "The explicit spring is unstable at this step, " + criterion +
            "; only the max force and max velocity clamps keep it bounded." +
            (s.mujoco ? "\n" : " PhysX's implicit row is stable at any step.\n");
  if (c.spec_close_time) {
    text += fmt::format("Close time: {} to 98 % against the spec's {} s ({}).\n", seconds(m.time_to_98),
                        format_number(*c.spec_close_time, 3), c.spec_origin);
  }
  return text;
}

}  // namespace

void write_simulation_text(std::ostream& out, const SimulationContext& c, const SimulationSetup& s,
                           const SimulationRun& run) {
  out << fmt::format("Simulating joint '{}' of {}: {} → {} {} over {} s\n", c.joint, c.path,
                     format_number(shown(c, s.from), 4), format_number(shown(c, s.target), 4), position_unit(c),
                     format_number(s.frames * s.row.dt, 4));
  for (const auto& line : c.setup) out << line << "\n";
  const auto implicit = rows(c, run.implicit_metrics), explicit_rows = rows(c, run.explicit_metrics);
  const std::size_t w0 = 22, w1 = std::max<std::size_t>(22, columns(run.engine) + 2);
  out << fmt::format("\n{:<{}}{:<{}}{}\n", "", w0, run.engine, w1, "explicit spring");
  for (std::size_t i = 0; i < implicit.size(); ++i)
    out << fmt::format("{:<{}}{:<{}}{}\n", implicit[i].first, w0, implicit[i].second, w1, explicit_rows[i].second);
  const std::string v = verdict(c, s, run);
  if (!v.empty()) out << "\n" << v;
}

void write_simulation_json(std::ostream& out, const SimulationContext& c, const SimulationSetup& s,
                           const SimulationRun& run) {
  nlohmann::json doc = {
      {"version", 1},
      {"path", c.path},
      {"joint", c.joint},
      {"from", s.from},
      {"target", s.target},
      {"position_unit", c.angular ? "rad" : "m"},
      {"force_unit", c.force_unit},
      {"duration_s", s.frames * s.row.dt},
      {"solver", std::string(physics::solver_name(s.row.solver))},
      {"dt_s", s.row.dt},
      {"h_s", s.row.h},
      {"substeps", s.row.substeps},
      {"stiffness", s.row.stiffness},
      {"damping", s.row.damping},
      {"inertia", c.inertia},
      {"inertia_origin", c.inertia_origin},
      {"engine", run.engine},
      {"integrator", s.mujoco ? nlohmann::json(std::string(physics::integrator_name(s.mujoco->integrator)))
                              : nlohmann::json(nullptr)},
      {"implicit_factor", s.mujoco ? nlohmann::json(nullptr) : nlohmann::json(s.row.x())},
      {"max_force", std::isfinite(s.limits.force.max_force) ? nlohmann::json(s.limits.force.max_force) : nlohmann::json(nullptr)},
      {"max_velocity", std::isfinite(s.limits.max_velocity) ? nlohmann::json(s.limits.max_velocity) : nlohmann::json(nullptr)},
      {"load", s.load},
      {"implicit", metrics_json(run.implicit_metrics)},
      {"explicit", metrics_json(run.explicit_metrics)},
      {"explicit_stable", run.explicit_stable},
      {"spec_close_time_s", c.spec_close_time ? nlohmann::json(*c.spec_close_time) : nlohmann::json(nullptr)},
      {"setup", c.setup},
  };
  out << doc.dump(2) << "\n";
}

void write_simulation_csv(std::ostream& out, const SimulationContext& c, const SimulationRun& run) {
  const char* p = c.angular ? "rad" : "m";
  out << fmt::format(
      "time_s,implicit_position_{0},implicit_velocity_{0}_s,implicit_force,explicit_position_{0},explicit_velocity_{0}_s,"
      "explicit_force\n",
      p);
  for (std::size_t i = 0; i < run.implicit.size(); ++i) {
    const Sample& a = run.implicit[i];
    out << fmt::format("{},{},{},{}", a.time, a.position, a.velocity, a.force);
    if (i < run.explicit_spring.size()) {
      const Sample& b = run.explicit_spring[i];
      out << fmt::format(",{},{},{}\n", b.position, b.velocity, b.force);
    } else {
      out << ",,,\n";
    }
  }
}

std::string simulation_svg(const SimulationContext& c, const SimulationSetup& s, const SimulationRun& run) {
  Chart chart;
  chart.title = fmt::format("{}: {} {} → {} {}, {}", c.joint, format_number(shown(c, s.from), 3), position_unit(c),
                            format_number(shown(c, s.target), 3), position_unit(c),
                            fmt::format("{} {} Hz, h = {} s", physics::solver_name(s.row.solver),
                                        format_number(1.0 / s.row.dt, 4), format_number(s.row.h, 3)));
  chart.x_label = "time (s)";
  chart.x_min = 0;
  chart.x_max = s.frames * s.row.dt;
  const auto series = [&](const std::vector<Sample>& samples, bool position, std::string label, std::string color,
                          bool dashed) {
    ChartSeries out{std::move(label), std::move(color), {}, {}, dashed};
    // At most ~2000 points: a plot does not need more.
    const std::size_t stride = std::max<std::size_t>(1, samples.size() / 2000);
    for (std::size_t i = 0; i < samples.size(); i += stride) {
      out.x.push_back(samples[i].time);
      out.y.push_back(position ? shown(c, samples[i].position) : samples[i].force);
    }
    return out;
  };
  const double span = std::abs(shown(c, s.target) - shown(c, s.from));
  const double lo = std::min(shown(c, s.from), shown(c, s.target)), hi = std::max(shown(c, s.from), shown(c, s.target));
  ChartPanel position;
  position.y_label = fmt::format("position ({})", position_unit(c));
  position.series.push_back(series(run.implicit, true, engine_legend(run), "#1f5fbf", false));
  position.series.push_back(series(run.explicit_spring, true,
                                   run.explicit_metrics.diverged ? "explicit spring (diverges)" : "explicit spring",
                                   "#d9480f", true));
  position.markers.push_back({"target", "#2b8a3e", shown(c, s.target)});
  position.clip = std::pair{lo - span, hi + span};
  ChartPanel force;
  force.y_label = fmt::format("drive force ({})", c.force_unit);
  force.series.push_back(series(run.implicit, false, engine_legend(run), "#1f5fbf", false));
  force.series.push_back(series(run.explicit_spring, false, "explicit spring", "#d9480f", true));
  const double cap = s.limits.force.max_average_force(s.row.dt);
  if (std::isfinite(cap)) {
    force.markers.push_back({"± max force", "#862e9c", cap});
    force.markers.push_back({"", "#862e9c", -cap});
    force.clip = std::pair{-2 * cap, 2 * cap};
    // Shade where the implicit drive sits at its max force.
    for (std::size_t i = 1; i < run.implicit.size(); ++i)
      if (std::abs(run.implicit[i].force) >= cap * (1 - 1e-6)) {
        if (!force.bands.empty() && std::abs(force.bands.back().to - run.implicit[i - 1].time) < 1e-12)
          force.bands.back().to = run.implicit[i].time;
        else
          force.bands.push_back({run.implicit[i - 1].time, run.implicit[i].time, "#862e9c"});
      }
    force.band_label = s.mujoco ? "servo at its force range" : "implicit drive at max force";
  } else {
    // No force limit: keep a diverging explicit spring from setting the scale; the spring
    // force over the whole step bounds what a sane drive shows.
    const double bound = std::max(2 * run.implicit_metrics.peak_force, s.row.stiffness * std::abs(s.target - s.from));
    if (bound > 0) force.clip = std::pair{-bound, bound};
  }
  if (std::isfinite(s.limits.max_velocity)) {
    for (std::size_t i = 1; i < run.implicit.size(); ++i)
      if (std::abs(run.implicit[i].velocity) >= s.limits.max_velocity * (1 - 1e-6)) {
        if (!position.bands.empty() && std::abs(position.bands.back().to - run.implicit[i - 1].time) < 1e-12)
          position.bands.back().to = run.implicit[i].time;
        else
          position.bands.push_back({run.implicit[i - 1].time, run.implicit[i].time, "#e67700"});
      }
    position.band_label = "implicit drive at max velocity";
  }
  chart.panels = {std::move(position), std::move(force)};
  return render_svg(chart);
}

}  // namespace assetlint::commands
