#include "commands/verify_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "util/numbers.h"
#include "util/svg_chart.h"

namespace assetlint::commands {
namespace {

std::string mm(double metres) { return format_number(metres * 1000, 3) + " mm"; }

// The measurements of one scene, in the order a reader checks them.
std::string measurements(const verify::SceneResult& r, const VerifySettings& limits) {
  const verify::SceneMetrics& m = r.metrics;
  std::vector<std::string> parts;
  if (r.spec.kind == verify::SceneKind::Close) {
    parts.push_back(m.close_time_s ? fmt::format("close time {} s", format_number(*m.close_time_s, 3))
                                   : std::string("never closed"));
    if (m.spec_close_time_s)
      parts.push_back(fmt::format("spec {} s (−{} %/+{} %)", format_number(*m.spec_close_time_s, 3),
                                  format_number(limits.close_time_under.value * 100),
                                  format_number(limits.close_time_over.value * 100)));
    if (m.peak_finger_speed_m_s) parts.push_back(fmt::format("peak finger speed {} m/s", format_number(*m.peak_finger_speed_m_s, 3)));
  }
  if (m.peak_penetration_m)
    parts.push_back(fmt::format("penetration peak {} (< {}), steady {} (< {})", mm(*m.peak_penetration_m),
                                mm(limits.peak_penetration_m.value), mm(*m.steady_penetration_m),
                                mm(limits.steady_penetration_m.value)));
  if (m.grip_force_n)
    parts.push_back(m.required_grip_force_n
                        ? fmt::format("grip {} N (m·g/μ = {} N)", format_number(*m.grip_force_n, 4),
                                      format_number(*m.required_grip_force_n, 4))
                        : fmt::format("grip {} N", format_number(*m.grip_force_n, 4)));
  if (m.slip_m) parts.push_back(fmt::format("slip {} (< {})", mm(*m.slip_m), mm(limits.slip_m.value)));
  if (m.jitter_m_s)
    parts.push_back(fmt::format("jitter {} mm/s (< {} mm/s)", format_number(*m.jitter_m_s * 1000, 3),
                                format_number(limits.jitter_m_s.value * 1000, 3)));
  if (m.mimic_error_max) parts.push_back(fmt::format("mimic error {}", format_number(*m.mimic_error_max, 3)));
  std::string text;
  for (const auto& p : parts) text += (text.empty() ? "" : "; ") + p;
  return text;
}

// The fine-tuning's answer beside today's values, in the joint's units.
std::vector<std::string> fine_tune_lines(const VerifyReport& report) {
  const verify::FineTuneResult& f = *report.fine_tune;
  struct {
    verify::DriveSpec drive;
  } today{f.trials.empty() ? f.lowest : f.trials.front().drive};
  std::vector<std::string> lines;
  const char* force = report.angular ? "N·m" : "N";
  const char* per = report.angular ? "rad" : "m";
  if (!f.baseline_passed) {
    lines.push_back("Fine-tuning: not run, today's drive must pass every scene first.");
    for (const auto& note : f.notes) lines.push_back("  " + note);
    return lines;
  }
  lines.push_back(fmt::format("Fine-tuning ({} runs of every scene): can the max force and the stiffness be lowered "
                              "while every scene still passes?",
                              f.trials.size()));
  for (const auto& note : f.notes) lines.push_back("  " + note);
  if (!f.baseline_passed) return lines;
  if (today.drive.max_force && f.lowest.max_force)
    lines.push_back(fmt::format("  max force  {} {} → lowest passing {} {}", format_number(*today.drive.max_force, 4), force,
                                format_number(*f.lowest.max_force, 4), force));
  lines.push_back(fmt::format("  stiffness  {} {}/{} → lowest passing {} {}/{}", format_number(today.drive.stiffness, 4),
                              force, per, format_number(f.lowest.stiffness, 4), force, per));
  lines.push_back(fmt::format("  damping    {} {}·s/{} → {} {}·s/{} (the same damping ratio: d ∝ √k)",
                              format_number(today.drive.damping, 4), force, per, format_number(f.lowest.damping, 4),
                              force, per));
  return lines;
}

}  // namespace

bool VerifyReport::passed() const {
  // A scene not run was not verified: it never counts as passed.
  return std::all_of(scenes.begin(), scenes.end(), [](const auto& s) { return s.ran && s.passed; });
}

void write_verify_text(std::ostream& out, const VerifyReport& report, const VerifySettings& limits) {
  out << fmt::format("Verifying '{}' of {} in {} {}\n", report.joint, report.path, report.engine.name,
                     report.engine.version);
  out << "Inputs:\n";
  for (const auto& line : report.inputs) out << "  " << line << "\n";
  out << fmt::format("Engine: {} {}, timestep {} s, integrator {}, cone {}, impratio {}\n", report.engine.name,
                     report.engine.version, format_number(report.engine.timestep_s, 4), report.engine.integrator,
                     report.engine.cone, format_number(report.engine.impratio));
  for (const auto& line : report.engine.translation) out << "  " << line << "\n";
  out << fmt::format("Thresholds ([verify]): close time −{} %/+{} % ({}/{}), peak penetration {} ({}), steady {} ({}), "
                     "slip {} ({}), jitter {} mm/s ({}) over the last {} s ({})\n",
                     format_number(limits.close_time_under.value * 100), format_number(limits.close_time_over.value * 100),
                     limits.close_time_under.origin, limits.close_time_over.origin, mm(limits.peak_penetration_m.value),
                     limits.peak_penetration_m.origin, mm(limits.steady_penetration_m.value),
                     limits.steady_penetration_m.origin, mm(limits.slip_m.value), limits.slip_m.origin,
                     format_number(limits.jitter_m_s.value * 1000, 3), limits.jitter_m_s.origin,
                     format_number(limits.window_s.value), limits.window_s.origin);
  out << "\n";
  std::size_t passed = 0, failed = 0, skipped = 0;
  for (std::size_t i = 0; i < report.scenes.size(); ++i) {
    const verify::SceneResult& r = report.scenes[i];
    const std::string verdict = !r.ran ? "not run" : r.passed ? "pass" : "FAIL";
    (!r.ran ? skipped : r.passed ? passed : failed) += 1;
    out << fmt::format("{:>2}. {:<40} {:<7}  {}\n", i + 1, r.spec.name, verdict,
                       r.ran ? measurements(r, limits) : r.spec.not_run);
    if (r.ran && r.spec.object)
      out << fmt::format("      box {} × {} × {} mm, {} kg, μ {}, met {}\n", format_number(r.spec.object->width * 1000, 3),
                         format_number(r.spec.object->depth * 1000, 3), format_number(r.spec.object->height * 1000, 3),
                         format_number(r.spec.object->mass, 4), format_number(r.spec.object->friction, 3),
                         r.spec.object->sized_for);
    for (const auto& failure : r.failures) out << "      " << failure << "\n";
  }
  if (report.fine_tune) {
    out << "\n";
    for (const auto& line : fine_tune_lines(report)) out << line << "\n";
  }
  out << fmt::format("\n{}: {} passed, {} failed, {} not run{}.\n",
                     report.passed() ? "Passed" : failed ? "Failed" : "Not verified", passed, failed, skipped,
                     skipped ? " (a scene not run is not verified)" : "");
  out << fmt::format("Engine steps: {}\n", report.steps);
}

void write_verify_json(std::ostream& out, const VerifyReport& report) {
  using Json = nlohmann::ordered_json;
  Json doc;
  doc["file"] = report.path;
  doc["engine"] = Json{{"name", report.engine.name},       {"version", report.engine.version},
                       {"timestep_s", report.engine.timestep_s}, {"integrator", report.engine.integrator},
                       {"cone", report.engine.cone},       {"impratio", report.engine.impratio}};
  doc["passed"] = report.passed();
  Json scenes = Json::array();
  for (const verify::SceneResult& r : report.scenes) {
    Json scene;
    scene["name"] = r.spec.name;
    scene["kind"] = std::string(verify::kind_name(r.spec.kind));
    if (r.spec.object)
      scene["object"] = Json{{"shape", r.spec.object->shape},
                             {"width_m", r.spec.object->width},
                             {"mass_kg", r.spec.object->mass},
                             {"friction", r.spec.object->friction}};
    else
      scene["object"] = nullptr;
    scene["gravity"] = r.spec.gravity;
    scene["ran"] = r.ran;
    scene["passed"] = r.ran && r.passed;
    Json metrics = Json::object();
    const verify::SceneMetrics& m = r.metrics;
    const auto put = [&](const char* key, const std::optional<double>& v) {
      if (v) metrics[key] = *v;
    };
    put("close_time_s", m.close_time_s);
    put("spec_close_time_s", m.spec_close_time_s);
    put("peak_penetration_m", m.peak_penetration_m);
    put("steady_penetration_m", m.steady_penetration_m);
    put("grip_force_n", m.grip_force_n);
    put("required_grip_force_n", m.required_grip_force_n);
    put("slip_m", m.slip_m);
    put("jitter_m_s", m.jitter_m_s);
    put("mimic_error_max", m.mimic_error_max);
    if (m.diverged) metrics["diverged"] = *m.diverged;
    scene["metrics"] = metrics;
    Json failures = Json::array();
    if (!r.ran) failures.push_back("not run: " + r.spec.not_run);
    for (const auto& f : r.failures) failures.push_back(f);
    scene["failures"] = failures;
    scenes.push_back(scene);
  }
  doc["scenes"] = scenes;
  if (report.fine_tune) {
    const verify::FineTuneResult& f = *report.fine_tune;
    const verify::DriveSpec& today = f.trials.front().drive;
    const auto optional_number = [](const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); };
    doc["fine_tune"] = Json{{"baseline_passed", f.baseline_passed},
                            {"runs", f.trials.size()},
                            {"today", Json{{"max_force", optional_number(today.max_force)},
                                           {"stiffness", today.stiffness},
                                           {"damping", today.damping}}},
                            {"lowest", Json{{"max_force", optional_number(f.lowest.max_force)},
                                            {"stiffness", f.lowest.stiffness},
                                            {"damping", f.lowest.damping}}},
                            {"notes", f.notes}};
  }
  out << doc.dump(2) << "\n";
}

namespace {

// A scene's line in its panel's legend: its name and verdict, with what its first failure is
// about (the words before its numbers: "close time", "grip force", "slip", "diverged").
std::string legend(const verify::SceneResult& r) {
  if (r.passed) return r.spec.name + ": pass";
  const std::string& failure = r.failures.front();
  std::string about = failure.substr(0, failure.find_first_of("0123456789:"));
  while (!about.empty() && about.back() == ' ') about.pop_back();
  return r.spec.name + ": FAIL (" + about + ")";
}

// The panel a scene kind is judged in: what the verdict rests on, over time.
ChartPanel kind_panel(verify::SceneKind kind, const VerifySettings& limits) {
  ChartPanel panel;
  switch (kind) {
    case verify::SceneKind::Close: panel.y_label = "close: finger opening (mm)"; break;
    case verify::SceneKind::Grasp:
      panel.y_label = "grasp: penetration (mm)";
      panel.markers.push_back({"peak penetration limit", "#d62728", limits.peak_penetration_m.value * 1000});
      panel.markers.push_back({"steady penetration limit", "#ff7f0e", limits.steady_penetration_m.value * 1000});
      break;
    case verify::SceneKind::Hold:
      panel.y_label = "hold: slip since gravity on (mm)";
      panel.markers.push_back({"slip limit", "#d62728", limits.slip_m.value * 1000});
      break;
    case verify::SceneKind::Lift:
      panel.y_label = "lift: slip since the lift starts (mm)";
      panel.markers.push_back({"slip limit", "#d62728", limits.slip_m.value * 1000});
      break;
  }
  return panel;
}

}  // namespace

std::string verify_svg(const VerifyReport& report, const verify::VerifyPlan& plan, const VerifySettings& limits) {
  static const char* kColors[] = {"#1f77b4", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"};
  Chart chart;
  chart.title = fmt::format("asset-lint verify: '{}' of {} in {} {}", report.joint, report.path, report.engine.name,
                            report.engine.version);
  chart.x_label = "time (s)";
  chart.x_max = 0;
  // One panel per kind of scene, in the order the scenes run, so that no scene's line hides
  // another kind's; each shows the quantity its verdict rests on, with the thresholds.
  std::vector<std::pair<verify::SceneKind, ChartPanel>> panels;
  const auto panel_of = [&](verify::SceneKind kind) -> ChartPanel& {
    for (auto& [k, p] : panels)
      if (k == kind) return p;
    panels.emplace_back(kind, kind_panel(kind, limits));
    return panels.back().second;
  };
  for (const verify::SceneResult& r : report.scenes) {
    if (!r.ran || r.trajectory.samples.empty()) continue;
    ChartPanel& panel = panel_of(r.spec.kind);
    // A failing scene is drawn dashed; its legend says which threshold it missed.
    ChartSeries line{legend(r), kColors[panel.series.size() % std::size(kColors)], {}, {}, !r.passed};
    std::optional<Eigen::Vector3d> judged_start;
    for (const verify::Sample& s : r.trajectory.samples) {
      if (r.spec.kind == verify::SceneKind::Close) {
        std::map<std::string, Eigen::Isometry3d, std::less<>> poses{{plan.layout.pads[0], s.pads[0]},
                                                                      {plan.layout.pads[1], s.pads[1]}};
        line.x.push_back(s.t);
        line.y.push_back(plan.layout.gap(*plan.asset, poses, plan.meshes) * 1000);
      } else if (r.spec.kind == verify::SceneKind::Grasp) {
        line.x.push_back(s.t);
        line.y.push_back(s.penetration * 1000);
      } else if (s.t >= r.spec.judged_from - 1e-12) {
        const Eigen::Vector3d relative = s.object - 0.5 * (s.pads[0].translation() + s.pads[1].translation());
        if (!judged_start) judged_start = relative;
        line.x.push_back(s.t);
        line.y.push_back((relative - *judged_start).norm() * 1000);
      }
    }
    chart.x_max = std::max(chart.x_max, r.trajectory.samples.back().t);
    if (r.spec.kind == verify::SceneKind::Close && r.metrics.spec_close_time_s && panel.bands.empty()) {
      const double spec = *r.metrics.spec_close_time_s;
      panel.bands.push_back({spec * (1 - limits.close_time_under.value), spec * (1 + limits.close_time_over.value),
                             "#2ca02c"});
      panel.band_label = "close time the spec allows";
    }
    panel.series.push_back(std::move(line));
  }
  if (chart.x_max <= 0) chart.x_max = 1;
  for (auto& [kind, panel] : panels) chart.panels.push_back(std::move(panel));
  return render_svg(chart);
}

}  // namespace assetlint::commands
