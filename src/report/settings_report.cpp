#include "report/settings_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "engine/consumers.h"
#include "formats/file_kind.h"
#include "physics/dampratio.h"
#include "rules/registry.h"
#include "util/numbers.h"

namespace assetlint {
namespace {

std::string quoted_list(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += fmt::format("{}\"{}\"", out.empty() ? "" : ", ", item);
  return "[" + out + "]";
}

// Where each pattern came from, in the list's order.
std::string origins(const std::vector<std::string>& patterns,
                    const std::map<std::string, std::string, std::less<>>& origin_of) {
  std::vector<std::string> out;
  for (const auto& pattern : patterns) {
    const auto it = origin_of.find(pattern);
    out.push_back(it == origin_of.end() ? "set by the caller" : it->second);
  }
  return fmt::format("{}", fmt::join(out, ", "));
}

void line(std::ostream& out, const std::string& assignment, const std::string& origin) {
  out << fmt::format("{:<40} # {}\n", assignment, origin);
}

void number(std::ostream& out, const char* key, const std::optional<Configured<double>>& value, const char* unset) {
  if (value) line(out, fmt::format("{} = {}", key, format_number(value->value)), value->origin);
  else out << fmt::format("# {} is not set: {}\n", key, unset);
}

// [targets]: the consumers the file is judged for, configured or the format's defaults.
void write_targets(std::ostream& out, const std::string& file, const Settings& settings) {
  out << "\n[targets]\n";
  if (!settings.targets.consumers.empty()) {
    std::vector<std::string> names, where;
    for (const auto& c : settings.targets.consumers) {
      names.push_back(c.value);
      where.push_back(c.origin);
    }
    line(out, fmt::format("consumers = {}", quoted_list(names)), fmt::format("{}", fmt::join(where, ", ")));
    out << "# findings that concern none of these consumers are not reported\n";
    return;
  }
  std::optional<SourceFormat> format;
  std::string_view name;
  switch (file_kind(file)) {
    case FileKind::Urdf: case FileKind::Xacro: format = SourceFormat::Urdf; name = "URDF"; break;
    case FileKind::Usda: case FileKind::Usd: case FileKind::BinaryUsd: format = SourceFormat::Usda; name = "USD"; break;
    case FileKind::Mjcf: format = SourceFormat::Mjcf; name = "MJCF"; break;
    case FileKind::Unsupported: break;
  }
  if (format)
    out << fmt::format("# consumers is not set: a {} file's usual ones, {}; a quirk only some of them have is an info\n",
                       name, default_consumers_text(*format));
  else
    out << "# consumers is not set: every consumer the file's format is commonly loaded by\n";
}

}  // namespace

namespace {

// Shown for a USD file, or when variants are pinned.
void write_usd(std::ostream& out, const std::string& file, const Settings& settings, const VariantRun* run) {
  if (!run && settings.usd.variants.empty()) return;
  out << "\n[usd]\n";
  if (settings.usd.variants.empty()) {
    out << "# variants is not set: the stage's selections, and every variant that carries physics\n";
  } else {
    std::vector<std::string> pins, where;
    for (const auto& [set, variant] : settings.usd.variants) {
      pins.push_back(fmt::format("{} = \"{}\"", set, variant.value));
      where.push_back(variant.origin);
    }
    line(out, fmt::format("variants = {{ {} }}", fmt::join(pins, ", ")), fmt::format("{}", fmt::join(where, ", ")));
  }
  if (!run) return;
  if (run->sets.empty()) {
    out << fmt::format("# {} has no variant sets\n", file);
    return;
  }
  out << fmt::format("# variant sets of {}:\n", file);
  for (const auto& use : run->sets) {
    std::vector<std::string> variants;
    for (const auto& v : use.variants) variants.push_back(fmt::format("\"{}\"", v));
    out << fmt::format("#   <{}> {} = [{}], {} \"{}\"\n", use.prim, use.set, fmt::join(variants, ", "),
                       use.pinned ? "pinned to" : "selects", use.selection);
  }
  // "; " between selections, as findings list them: one selection may name several sets
  // ("Newton=Enabled, NewtonSolver=Featherstone").
  out << fmt::format("# checked: the stage's selection{}{}\n", run->checked.empty() ? "" : "; ",
                     fmt::join(run->checked, "; "));
  if (!run->without_physics.empty())
    out << fmt::format("# not checked, no physics in them: {}\n", fmt::join(run->without_physics, "; "));
}

}  // namespace

void write_settings(std::ostream& out, const std::string& file, const Settings& settings,
                    const config::FileSelection& files, const std::string& checked_tree, const VariantRun* variants,
                    const std::string& config_lookup) {
  out << fmt::format("# Settings for {}\n", file);
  out << fmt::format("# configuration: {}\n", settings.config_path.empty() ? "none (defaults)" : settings.config_path);
  if (!config_lookup.empty()) out << fmt::format("# {}\n", config_lookup);
  out << fmt::format("# checked tree (USD composition reads inside it): {}\n\n", checked_tree);
  const std::string config_origin = settings.config_path.empty() ? "default" : settings.config_path;
  line(out, "select = " + quoted_list(settings.selection.select),
       settings.selection.select.empty() ? "default: every rule"
                                         : origins(settings.selection.select, settings.selection.select_origins));
  line(out, "ignore = " + quoted_list(settings.selection.ignore),
       settings.selection.ignore.empty() ? "default: none"
                                         : origins(settings.selection.ignore, settings.selection.ignore_origins));
  std::vector<std::string> off;
  for (const RuleInfo* rule : rules::catalog())
    if (!settings.selection.enabled(rule->id)) off.emplace_back(rule->id);
  out << fmt::format("# rules that run: {} of {}{}\n", rules::catalog().size() - off.size(), rules::catalog().size(),
                     off.empty() ? "" : fmt::format(" (not: {})", fmt::join(off, ", ")));
  line(out, "exclude = " + [&] {
    std::vector<std::string> globs;
    for (const auto& p : files.exclude) globs.push_back(p.glob);
    return quoted_list(globs);
  }(), [&] {
    std::vector<std::string> origins;
    for (const auto& p : files.exclude) origins.push_back(p.origin);
    return origins.empty() ? std::string("configuration") : fmt::format("{}", fmt::join(origins, ", "));
  }());
  line(out, fmt::format("respect-gitignore = {}", files.respect_gitignore.value ? "true" : "false"),
       files.respect_gitignore.origin);

  out << "\n[simulation]\n";
  number(out, "timesteps_per_second", settings.simulation.timesteps_per_second,
         "the stage's physxScene:timeStepsPerSecond, else PhysX's 60");
  number(out, "position_iterations", settings.simulation.position_iterations,
         "the articulation's own count, else PhysX's 32");
  number(out, "velocity_iterations", settings.simulation.velocity_iterations, "PhysX's 1");
  if (settings.simulation.solver)
    line(out, fmt::format("solver = \"{}\"", settings.simulation.solver->value), settings.simulation.solver->origin);
  else out << "# solver is not set: the stage's physxScene:solverType, else TGS\n";

  write_targets(out, file, settings);

  out << "\n[mujoco]\n";
  line(out, fmt::format("version = \"{}\"", settings.mujoco.version.value),
       fmt::format("{}; dampratio derives kv as {}", settings.mujoco.version.origin,
                   physics::dampratio_rule_versions(physics::dampratio_rule(settings.mujoco.parsed()))));

  const GripperSpec& g = settings.gripper;
  out << "\n[gripper]\n";
  number(out, "payload_kg", g.payload_kg, "no force derivation");
  number(out, "friction", g.friction, "no force derivation");
  number(out, "lever_arm_m", g.lever_arm_m, "no force derivation");
  line(out, fmt::format("gravity = {}", format_number(g.gravity.value)), g.gravity.origin);
  number(out, "finger_speed_m_s", g.finger_speed_m_s, "no velocity derivation");
  number(out, "stroke_m", g.stroke_m, "no velocity derivation");
  line(out, fmt::format("target_delta_deg = {}", format_number(g.target_delta_deg.value)), g.target_delta_deg.origin);
  number(out, "torque_margin", g.torque_margin, "no rounding");
  if (g.driven_joint) line(out, fmt::format("driven_joint = \"{}\"", g.driven_joint->value), g.driven_joint->origin);
  else out << "# driven_joint is not set: the joint the mimics follow\n";

  for (const auto& [joint, drive] : settings.drives) {
    out << fmt::format("\n[drives.{}]  # {}\n", joint, drive.origin);
    const std::pair<const char*, const std::optional<Configured<double>>*> values[] = {
        {"stiffness", &drive.stiffness}, {"damping", &drive.damping},       {"armature", &drive.armature},
        {"max_force", &drive.max_force}, {"max_velocity", &drive.max_velocity},
        {"rotor_inertia", &drive.rotor_inertia}, {"gear_ratio", &drive.gear_ratio}};
    for (const auto& [key, value] : values)
      if (*value) line(out, fmt::format("{} = {}", key, format_number((*value)->value)), (*value)->origin);
    if (drive.type) line(out, fmt::format("type = \"{}\"", drive.type->value), drive.type->origin);
  }

  write_usd(out, file, settings, variants);

  if (!settings.per_file_ignores.empty()) {
    out << "\n[per-file-ignores]\n";
    for (const auto& entry : settings.per_file_ignores)
      line(out, fmt::format("\"{}\" = {}", entry.glob, quoted_list(entry.rules)), entry.origin);
  }
  for (const RuleInfo* rule : rules::catalog()) {
    const auto severity = settings.severity_overrides.find(rule->id);
    const auto options = settings.rule_options.find(rule->id);
    if (severity == settings.severity_overrides.end() && options == settings.rule_options.end()) continue;
    out << fmt::format("\n[rules.{}]\n", rule->id);
    const auto origin_of = [&](std::string_view key) {
      const auto it = settings.rule_setting_origins.find(fmt::format("{}.{}", rule->id, key));
      return it == settings.rule_setting_origins.end() ? config_origin : it->second;
    };
    if (severity != settings.severity_overrides.end())
      line(out, fmt::format("severity = \"{}\"", severity_name(severity->second)), origin_of("severity"));
    if (options != settings.rule_options.end())
      for (const auto& [name, value] : options->second)
        line(out, fmt::format("{} = {}", name, format_number(value)), origin_of(name));
  }
}

}  // namespace assetlint
