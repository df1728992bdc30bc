#include "commands/verify_drives_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "util/numbers.h"
#include "util/svg_chart.h"

namespace assetlint::commands {
namespace {

std::string n(double v) { return format_number(v, 3); }

std::string percent(double fraction) { return n(fraction * 100) + " %"; }

// The figures of one test beside their thresholds, in the joint's units.
std::string figures(const verify::DriveResult& r, const verify::DrivePlan& plan) {
  const verify::DriveMetrics& m = r.metrics;
  const auto& lim = plan.limits;
  const char* unit = r.angular ? "rad" : "m";
  const char* force = r.angular ? "N·m" : "N";
  std::vector<std::string> parts;
  switch (r.kind) {
    case verify::DriveTestKind::Step:
      if (!m.overshoot) break;
      parts.push_back(fmt::format("overshoot {} (≤ {})", percent(*m.overshoot), percent(lim.overshoot.value)));
      parts.push_back(m.settle_time_s ? fmt::format("settles to {} in {} s (≤ {} s)", percent(lim.settle_band.value),
                                                    n(*m.settle_time_s), n(lim.settle_time_s.value))
                                      : fmt::format("never within {}", percent(lim.settle_band.value)));
      parts.push_back(m.settle_time_2pct_s ? fmt::format("to 2 % in {} s", n(*m.settle_time_2pct_s))
                                           : std::string("never within 2 %"));
      parts.push_back(fmt::format("{} sign changes (≤ {})", *m.sign_changes, n(lim.sign_changes.value)));
      parts.push_back(fmt::format("steady error {} {}", n(*m.steady_error), unit));
      break;
    case verify::DriveTestKind::Sweep:
      if (!m.end_error) break;
      parts.push_back(fmt::format("end errors {} / {} {} (≤ {})", n(*m.end_error_upper), n(*m.end_error_lower), unit,
                                  n(r.angular ? lim.sweep_end_rad.value : lim.sweep_end_m.value)));
      parts.push_back(fmt::format("return error {} {} (≤ {})", n(*m.return_error), unit,
                                  n(r.angular ? lim.sweep_return_rad.value : lim.sweep_return_m.value)));
      if (r.scene) parts.push_back(r.scene->ramp);
      break;
    case verify::DriveTestKind::Hold:
      parts.push_back(fmt::format("gravity torque ≤ {} {} (at {} {})", n(*m.gravity_torque_max), force,
                                  n(*m.gravity_torque_at), unit));
      parts.push_back(m.effort_limit ? fmt::format("effort limit {} {} (margin {})", n(*m.effort_limit), force,
                                                   n(*m.effort_margin))
                                     : std::string("no effort limit"));
      parts.push_back(fmt::format("droop {} {} (≤ {})", n(*m.droop), unit,
                                  n(r.angular ? lim.droop_rad.value : lim.droop_m.value)));
      break;
    case verify::DriveTestKind::Velocity:
      if (!m.peak_velocity) break;
      parts.push_back(fmt::format("peak {} {}/s (≤ {} {}/s + {})", n(*m.peak_velocity), unit, n(*m.velocity_limit), unit,
                                  percent(lim.velocity_over.value)));
      break;
    case verify::DriveTestKind::Mimic:
      if (m.mimic_error_max) parts.push_back(fmt::format("follower error ≤ {}", n(*m.mimic_error_max)));
      break;
  }
  if (m.diverged && *m.diverged) parts.insert(parts.begin(), "diverged");
  std::string text;
  for (const auto& p : parts) text += (text.empty() ? "" : ", ") + p;
  return text;
}

std::string verdict(const verify::DriveResult& r) { return !r.ran ? "not run" : r.passed ? "pass" : "FAIL"; }

std::string gains(const verify::DriveSpec& d, const verify::TestedJoint& j) {
  std::string text = fmt::format("k {} {}/{}, d {} {}·s/{}", format_number(d.stiffness, 4), j.force_unit(), j.unit(),
                                 format_number(d.damping, 4), j.force_unit(), j.unit());
  if (d.max_force) text += fmt::format(", max force {} {}", format_number(*d.max_force, 4), j.force_unit());
  return text;
}

// Whether every test of a joint that ran in the second run passed, and what failed.
std::vector<std::string> tuned_failures(const DriveReport& report, const std::string& joint) {
  std::vector<std::string> failures;
  for (const auto& r : report.tuned_results)
    if (r.joint == joint && r.ran && !r.passed)
      for (const auto& f : r.failures) failures.push_back(fmt::format("{}: {}", verify::drive_test_name(r.kind), f));
  return failures;
}

std::vector<std::string> fine_tune_lines(const DriveReport& report) {
  std::vector<std::string> lines;
  for (std::size_t index : report.fine_tuned) {
    const verify::TestedJoint& today = report.plan->joints[index];
    const verify::TestedJoint& tuned = report.tuned_plan->joints[index];
    const auto failures = tuned_failures(report, today.joint->name.text);
    std::string verdict = failures.empty() ? "every test that runs passes" : "still fails " + failures.front();
    lines.push_back(fmt::format("{}: {} → {}: {}", today.joint->name.text,
                                today.drive ? gains(*today.drive, today) : std::string("no drive"),
                                gains(*tuned.drive, tuned), verdict));
  }
  return lines;
}

}  // namespace

bool DriveReport::passed() const {
  return std::all_of(results.begin(), results.end(), [](const auto& r) { return r.passed; });
}

void write_drive_text(std::ostream& out, const DriveReport& report) {
  const verify::DrivePlan& plan = *report.plan;
  out << fmt::format("asset-lint verify: the drive tests of {} in MuJoCo {}\n", report.path, report.engine_version);
  for (const auto& line : report.translation) out << "  " << line << "\n";
  std::size_t width = 0;
  for (const auto& r : report.results) width = std::max(width, r.joint.size());
  out << "\n";
  std::size_t passed = 0;
  for (const auto& r : report.results) {
    passed += r.passed;
    const std::string kind(r.ran || r.kind != verify::DriveTestKind::Step || r.scene ? verify::drive_test_name(r.kind)
                                                                                     : "drive");
    std::string detail = r.ran ? figures(r, plan) : r.failures.front();
    if (!r.ran && !r.fix.empty() && !r.scene) detail += fmt::format(": add {}", r.fix);
    out << fmt::format("  {:<{}}  {:<8}  {:<7}  {}\n", r.joint, width, kind, verdict(r), detail);
  }
  bool header = false;
  for (const auto& r : report.results) {
    if (!r.ran || r.passed) continue;
    if (!header) out << "\nFailures:\n";
    header = true;
    out << fmt::format("  {} ({}):", r.joint, verify::drive_test_name(r.kind));
    for (std::size_t i = 0; i < r.failures.size(); ++i) out << (i ? "; " : " ") << r.failures[i];
    out << "\n";
    for (const auto& cause : r.causes) out << "    cause: " << cause << "\n";
    if (!r.fix.empty()) out << "    fix: " << r.fix << "\n";
  }
  if (!report.fine_tuned.empty()) {
    out << "\nFine-tuning: the proposed gains, the robot tested again with them:\n";
    for (const auto& line : fine_tune_lines(report)) out << "  " << line << "\n";
  }
  out << fmt::format("\n{} of {} tests passed; {} engine steps. {}\n", passed, report.results.size(), report.steps,
                     report.passed() ? "Every drive does what its gains promise." : "Not verified.");
}

void write_drive_json(std::ostream& out, const DriveReport& report) {
  const verify::DrivePlan& plan = *report.plan;
  nlohmann::ordered_json j;
  j["file"] = report.path;
  j["engine"] = {{"name", "mujoco"}, {"version", report.engine_version}, {"timestep_s", plan.timestep},
                 {"integrator", "implicit"}};
  j["base"] = {{"link", plan.base}, {"pinned", plan.base_pinned}};
  j["passed"] = report.passed();
  nlohmann::ordered_json scenes = nlohmann::ordered_json::array();
  for (const auto& r : report.results) {
    nlohmann::ordered_json s;
    s["name"] = r.name;
    s["kind"] = std::string(verify::drive_test_name(r.kind));
    s["joint"] = r.joint;
    s["ran"] = r.ran;
    s["passed"] = r.passed;
    nlohmann::ordered_json m = nlohmann::ordered_json::object();
    const verify::DriveMetrics& x = r.metrics;
    const auto put = [&](const char* key, const std::optional<double>& v) {
      if (v) m[key] = *v;
    };
    put("step_size", x.step_size);
    put("overshoot", x.overshoot);
    put("settle_time_s", x.settle_time_s);
    put("settle_time_2pct_s", x.settle_time_2pct_s);
    if (x.sign_changes) m["sign_changes"] = *x.sign_changes;
    put("steady_error", x.steady_error);
    put("end_error", x.end_error);
    put("end_error_upper", x.end_error_upper);
    put("end_error_lower", x.end_error_lower);
    put("return_error", x.return_error);
    put("peak_velocity", x.peak_velocity);
    put("velocity_limit", x.velocity_limit);
    put("gravity_torque_max", x.gravity_torque_max);
    put("gravity_torque_at", x.gravity_torque_at);
    put("effort_limit", x.effort_limit);
    put("effort_margin", x.effort_margin);
    put("droop", x.droop);
    put("mimic_error_max", x.mimic_error_max);
    if (x.diverged) m["diverged"] = *x.diverged;
    s["metrics"] = m;
    s["failures"] = r.failures;
    s["causes"] = r.causes;
    if (!r.fix.empty()) s["fix"] = r.fix;
    scenes.push_back(std::move(s));
  }
  j["scenes"] = std::move(scenes);
  if (!report.fine_tuned.empty()) {
    nlohmann::ordered_json joints = nlohmann::ordered_json::array();
    const auto spec = [](const verify::DriveSpec& d) {
      nlohmann::ordered_json o{{"stiffness", d.stiffness}, {"damping", d.damping}};
      o["max_force"] = d.max_force ? nlohmann::ordered_json(*d.max_force) : nlohmann::ordered_json();
      return o;
    };
    for (std::size_t index : report.fine_tuned) {
      const verify::TestedJoint& today = report.plan->joints[index];
      const auto failures = tuned_failures(report, today.joint->name.text);
      joints.push_back({{"joint", today.joint->name.text},
                        {"today", today.drive ? spec(*today.drive) : nlohmann::ordered_json()},
                        {"proposed", spec(*report.tuned_plan->joints[index].drive)},
                        {"passed", failures.empty()},
                        {"failures", failures}});
    }
    j["fine_tune"] = {{"runs", 2}, {"joints", std::move(joints)}};
  }
  j["steps"] = report.steps;
  out << j.dump(2) << "\n";
}

std::string drive_svg(const DriveReport& report) {
  Chart chart;
  chart.title = fmt::format("asset-lint verify: each drive's step in MuJoCo {}", report.engine_version);
  chart.x_label = "time since the step (s)";
  chart.x_max = 0;
  chart.panel_height = 160;
  for (const auto& r : report.results) {
    if (r.kind != verify::DriveTestKind::Step || !r.trajectory || !r.scene) continue;
    // The joint's verdict: its first failing test, whatever the test.
    std::string failed;
    for (const auto& other : report.results)
      if (other.joint == r.joint && other.ran && !other.passed && failed.empty())
        failed = fmt::format("{}: {}", verify::drive_test_name(other.kind), other.failures.front());
    ChartPanel panel;
    panel.y_label = fmt::format("'{}' ({})", r.joint, r.angular ? "rad" : "m");
    ChartSeries target{"target", "#7f7f7f", {}, {}, true};
    ChartSeries response{failed.empty() ? "response: pass" : "response: FAIL, " + failed,
                         failed.empty() ? "#1f77b4" : "#d62728", {}, {}, !failed.empty()};
    // About 600 points a line: a panel is 800 px wide.
    const std::size_t stride = std::max<std::size_t>(1, r.trajectory->samples.size() / 600);
    for (std::size_t i = 0; i < r.trajectory->samples.size(); i += stride) {
      const verify::DriveSample& s = r.trajectory->samples[i];
      if (s.t < r.scene->step_at) continue;
      target.x.push_back(s.t - r.scene->step_at);
      target.y.push_back(s.target);
      response.x.push_back(s.t - r.scene->step_at);
      response.y.push_back(s.q);
    }
    if (response.x.empty()) continue;
    chart.x_max = std::max(chart.x_max, response.x.back());
    const double lo = r.scene->waypoints.front().second, hi = r.scene->waypoints.back().second;
    panel.clip = std::make_pair(std::min(lo, hi) - std::abs(hi - lo), std::max(lo, hi) + std::abs(hi - lo));
    panel.series.push_back(std::move(target));
    panel.series.push_back(std::move(response));
    chart.panels.push_back(std::move(panel));
  }
  if (chart.x_max <= 0) chart.x_max = 1;
  return render_svg(chart);
}

}  // namespace assetlint::commands
