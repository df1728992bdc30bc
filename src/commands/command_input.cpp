#include "commands/command_input.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "commands/exit_status.h"
#include "config/resolver.h"
#include "util/numbers.h"
#include "util/ros_package_path.h"

namespace assetlint::commands {

std::optional<int> parse_command(CLI::App& app, const std::vector<std::string>& args, const std::string& name,
                                 std::ostream& out, std::ostream& err) {
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    out << app.help();
    return kExitClean;
  } catch (const CLI::ParseError& e) {
    err << "asset-lint " << name << ": error: " << e.what() << "\n";
    return kExitError;
  }
  return std::nullopt;
}

std::optional<double> positive_flag(const std::string& flag, const std::string& text, std::string& error,
                                    bool allow_zero) {
  const auto value = parse_double(text);
  if (!value || !std::isfinite(*value) || *value < 0 || (*value == 0 && !allow_zero)) {
    error = fmt::format("{} must be a finite number {} 0, got '{}'", flag, allow_zero ? "≥" : ">", text);
    return std::nullopt;
  }
  return value;
}

void add_scope_options(CLI::App& app, CompositionScope& scope) {
  app.add_option("--root", scope.root,
                 "The checked tree: the only files a reference may make asset-lint read (default: the file's git work "
                 "tree, else the directory of its asset-lint.toml)")
      ->check(CLI::ExistingDirectory);
  app.add_flag("--allow-outside-root", scope.allow_outside_root, "Let references (includes, layers, meshes, links) read files outside that tree");
  app.add_option("--package-path", scope.package_paths,
                 "A directory of ROS packages that $(find pkg) and package:// resolve in, and that may be read "
                 "(repeatable; after ROS_PACKAGE_PATH)")
      ->check(CLI::ExistingDirectory)
      ->allow_extra_args(false);
  app.add_option("--variant", scope.variants,
                 "Select this variant in every USD variant set of that name, SET=NAME (repeatable; wins over "
                 "[usd] variants and the stage's own selection)")
      ->check(check_variant_choice)
      ->allow_extra_args(false);
  app.add_option("--xacro-arg", scope.xacro_args,
                 "A xacro argument's value, name:=value (repeatable; wins over [xacro] args)")
      ->check(check_xacro_argument)
      ->allow_extra_args(false);
}

std::optional<std::pair<std::string, std::string>> variant_choice(const std::string& text) {
  const auto at = text.find('=');
  if (at == std::string::npos || at == 0 || at + 1 == text.size()) return std::nullopt;
  return std::pair{text.substr(0, at), text.substr(at + 1)};
}

std::string check_variant_choice(const std::string& text) {
  return variant_choice(text) ? std::string() : "expected SET=NAME (a variant set and one of its variants)";
}

std::pair<std::string, std::string> xacro_argument(const std::string& text) {
  const auto at = text.find(":=");
  return {text.substr(0, at), text.substr(at + 2)};
}

std::string check_xacro_argument(const std::string& text) {
  return text.find(":=") == std::string::npos ? "expected name:=value" : std::string();
}

CommandAsset load_command_asset(const std::string& path, const std::optional<std::string>& config,
                                const CompositionScope& scope) {
  CommandAsset result;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    result.error = fmt::format("no such file: '{}'", path);
    return result;
  }
  config::CommandLineOverrides overrides;
  overrides.trees.push_back(std::filesystem::current_path(ec).string());
  overrides.root = scope.root;
  overrides.allow_outside_root = scope.allow_outside_root;
  add_package_paths(scope.package_paths);
  for (const auto& v : scope.variants) overrides.variants.push_back(*variant_choice(v));
  for (const auto& arg : scope.xacro_args) overrides.xacro_args.push_back(xacro_argument(arg));
  config::SettingsResolver resolver(overrides, config);
  if (auto problem = resolver.prepare({path})) {
    result.error = problem->to_string();
    return result;
  }
  result.settings = resolver.for_file(path);
  result.loaded = load_model(path, result.settings);
  if (result.loaded.error) {
    result.error = *result.loaded.error;
    return result;
  }
  if (!result.loaded.read.usable) {
    const Asset& asset = result.loaded.read.asset;
    std::string first = "the reader could not build a model";
    const WrittenAt& written_at = result.loaded.read.written_at;
    for (const Diagnostic& d : result.loaded.read.diagnostics) {
      if (d.severity != Severity::Error) continue;
      const Span span = written_at && d.span.valid() ? written_at(d.span) : d.span;
      first = span.valid() ? fmt::format("{}:{}:{}: {} [{}]", asset.source(span.file).path(), span.line, span.column,
                                         d.message, d.rule)
                           : d.message;
      break;
    }
    result.error = fmt::format("cannot read {}: {}", path, first);
  }
  return result;
}

bool write_text_file(const std::string& path, const std::string& text, std::string& error) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file << text;
  file.close();
  if (!file) error = fmt::format("cannot write '{}'", path);
  return static_cast<bool>(file);
}

physics::SimulationRate command_rate(const Asset& asset, const Settings& settings) {
  physics::SimulationRate rate = physics::effective_simulation(asset, settings);
  const auto& sim = settings.simulation;
  if (sim.timesteps_per_second && sim.timesteps_per_second->origin.starts_with("--")) {
    rate.timesteps_per_second = sim.timesteps_per_second->value;
    rate.rate_origin = sim.timesteps_per_second->origin;
  }
  if (sim.position_iterations && sim.position_iterations->origin.starts_with("--")) {
    rate.position_iterations = sim.position_iterations->value;
    rate.iterations_origin = sim.position_iterations->origin;
  }
  if (sim.solver && sim.solver->origin.starts_with("--")) {
    rate.solver = sim.solver->value == "PGS" ? physics::Solver::PGS : physics::Solver::TGS;
    rate.solver_origin = sim.solver->origin;
  }
  return rate;
}

}  // namespace assetlint::commands
