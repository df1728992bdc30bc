#include "commands/tune_report.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "util/numbers.h"

namespace assetlint::commands {
namespace {


std::string with_unit(double value, const std::string& unit, int digits = 4) {
  return unit.empty() ? format_number(value, digits) : fmt::format("{} {}", format_number(value, digits), unit);
}

std::string origin_text(const std::string& origin) {
  return origin == "default" ? "the default (docs/tune.md)" : origin;
}

std::string result_text(const TuneResult& r) {
  std::string text = with_unit(r.value, r.unit);
  if (r.usd_value) text += fmt::format(" (USD: {})", with_unit(*r.usd_value, r.usd_unit));
  return text;
}

std::string missing_text(const TuneMissing& m) {
  if (m.flag.empty()) return fmt::format("missing {}: {}", m.what, m.key);
  return fmt::format("missing {}: set {} in asset-lint.toml or pass {}", m.what, m.key, m.flag);
}

nlohmann::json number_or_null(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

}  // namespace

void write_tune_text(std::ostream& out, const TuneDerivation& d) {
  out << fmt::format("Tuning {} joint '{}' of {}", joint_type_name(d.joint->type), d.joint->name.text, d.path);
  if (!d.mimics.empty())
    out << fmt::format(" (it drives {} mimic joint{})", d.mimics.size(), d.mimics.size() == 1 ? "" : "s");
  out << "\nSimulation: " << d.simulation << "\n";
  for (std::size_t i = 0; i < d.steps.size(); ++i) {
    const TuneStep& step = d.steps[i];
    out << fmt::format("\n{}. {}: {}\n", i + 1, step.title, step.formula);
    std::size_t width = 0;
    std::vector<std::string> values;
    for (const TuneInput& in : step.inputs) {
      std::string value = fmt::format("{} = {}", in.symbol, with_unit(in.value, in.unit));
      if (!in.as_written.empty()) value += fmt::format(" ({})", in.as_written);
      width = std::max(width, columns(value));
      values.push_back(std::move(value));
    }
    for (std::size_t j = 0; j < step.inputs.size(); ++j)
      out << fmt::format("     {}{}  {}, from {}\n", values[j], std::string(width - columns(values[j]), ' '),
                         step.inputs[j].what, origin_text(step.inputs[j].origin));
    for (const TuneMissing& m : step.missing) out << "     " << missing_text(m) << "\n";
    if (step.result) out << "   → " << result_text(*step.result) << "\n";
    else out << "   → not computed\n";
    for (const std::string& note : step.notes) out << "   " << note << "\n";
  }
  const TuneRecommendation& r = d.recommended;
  const auto find = [&](std::string_view name) -> const TuneResult* {
    for (const TuneStep& s : d.steps)
      if (s.name == name && s.result) return &*s.result;
    return nullptr;
  };
  std::vector<std::string> parts;
  if (r.max_force) parts.push_back("max force " + result_text(*find("max_drive_force")));
  if (r.max_velocity) parts.push_back("max joint velocity " + result_text(*find("max_joint_velocity")));
  if (r.stiffness) parts.push_back("stiffness " + result_text(*find("stiffness")));
  if (r.damping) parts.push_back("damping " + result_text(*find("damping")));
  out << "\n";
  if (parts.empty()) {
    out << "Nothing to recommend: the inputs above are missing.\n";
    return;
  }
  out << fmt::format("Recommended for '{}':", d.joint->name.text);
  for (std::size_t i = 0; i < parts.size(); ++i) out << (i ? "; " : " ") << parts[i];
  out << "\n";
}

void write_tune_json(std::ostream& out, const TuneDerivation& d) {
  nlohmann::json steps = nlohmann::json::array();
  for (const TuneStep& step : d.steps) {
    nlohmann::json inputs = nlohmann::json::array();
    for (const TuneInput& in : step.inputs) {
      nlohmann::json input = {{"symbol", in.symbol}, {"name", in.what}, {"value", in.value}, {"unit", in.unit},
                              {"origin", in.origin}};
      if (!in.as_written.empty()) input["as_written"] = in.as_written;
      inputs.push_back(std::move(input));
    }
    nlohmann::json missing = nlohmann::json::array();
    for (const TuneMissing& m : step.missing)
      missing.push_back({{"name", m.what}, {"key", m.key}, {"flag", m.flag.empty() ? nlohmann::json(nullptr) : nlohmann::json(m.flag)}});
    nlohmann::json result = nullptr;
    if (step.result) {
      result = {{"value", step.result->value}, {"unit", step.result->unit}};
      if (step.result->usd_value) {
        result["usd_value"] = *step.result->usd_value;
        result["usd_unit"] = step.result->usd_unit;
      }
    }
    steps.push_back({{"name", step.name}, {"title", step.title}, {"formula", step.formula}, {"inputs", inputs},
                     {"missing", missing}, {"result", result}, {"notes", step.notes}});
  }
  nlohmann::json summary = nlohmann::json::object();
  for (const auto& [key, value] : d.summary) summary[key] = number_or_null(value);
  nlohmann::json mimics = nlohmann::json::array();
  for (const Joint* joint : d.mimics) mimics.push_back(joint->name.text);
  const TuneRecommendation& r = d.recommended;
  nlohmann::json doc = {
      {"version", 1},
      {"path", d.path},
      {"joint", d.joint->name.text},
      {"joint_type", std::string(joint_type_name(d.joint->type))},
      {"mimics", mimics},
      {"simulation", d.simulation},
      {"steps", steps},
      {"summary", summary},
      {"recommended",
       {{"max_force", number_or_null(r.max_force)},
        {"max_joint_velocity", number_or_null(r.max_velocity)},
        {"stiffness", number_or_null(r.stiffness)},
        {"damping", number_or_null(r.damping)}}},
  };
  out << doc.dump(2) << "\n";
}

}  // namespace assetlint::commands
