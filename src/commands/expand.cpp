#include "commands/expand.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>

#include "commands/command_input.h"
#include "commands/exit_status.h"
#include "config/project_root.h"
#include "engine/read_policy.h"
#include "config/resolver.h"
#include "engine/file_system.h"
#include "engine/work_budget.h"
#include "formats/xacro/xacro_reader.h"
#include "util/ros_package_path.h"

namespace assetlint::commands {

int run_expand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"asset-lint expand: prints the URDF a .xacro file expands to, as ROS's xacro does", "asset-lint expand"};
  std::string path, output;
  std::optional<std::string> config;
  app.add_option("file", path, "The .xacro file")->required();
  app.add_option("-o,--output", output, "Write the URDF to this file instead of standard output");
  app.add_option("--config", config, "Use this asset-lint.toml (default: the nearest one above the file)");
  CompositionScope scope;
  add_scope_options(app, scope);
  if (auto status = parse_command(app, args, "expand", out, err)) return *status;

  std::error_code ec;
  config::CommandLineOverrides overrides;
  overrides.trees.push_back(std::filesystem::current_path(ec).string());
  overrides.root = scope.root;
  overrides.allow_outside_root = scope.allow_outside_root;
  add_package_paths(scope.package_paths);
  for (const auto& arg : scope.xacro_args) overrides.xacro_args.push_back(xacro_argument(arg));
  config::SettingsResolver resolver(overrides, config);
  if (auto problem = resolver.prepare({path})) {
    err << "asset-lint expand: error: " << problem->to_string() << "\n";
    return kExitError;
  }
  const Settings& settings = resolver.for_file(path);
  std::string error;
  const ConfinedFileSystem files(disk(), config::read_policy(path, settings));
  std::optional<std::string> text = files.read(path, error);
  if (!text) {
    err << fmt::format("asset-lint expand: error: cannot read '{}': {}\n", path, error);
    return kExitError;
  }
  xacro::XacroOptions options;
  options.deadline = Deadline::for_one_file();
  options.root = config::checked_root(path, settings);
  for (const auto& [name, value] : settings.xacro.args) options.arguments[name] = xacro::ArgumentValue{value.value, value.origin, {}};
  const xacro::ExpandedText expanded =
      xacro::expand_to_text(std::make_shared<const SourceFile>(path, std::move(*text)), files, options);
  if (!expanded.text) {
    const xacro::ExpandError& e = *expanded.error;
    const auto path_of = [&](const Span& span) {
      return span.file < expanded.files.size() ? expanded.files[span.file]->path() : path;
    };
    err << fmt::format("{}:{}:{}: error: xacro: {}\n", path_of(e.span), e.span.line, e.span.column, e.message);
    for (const Note& n : e.notes) {
      if (n.span.valid()) err << fmt::format("{}:{}:{}: note: {}\n", path_of(n.span), n.span.line, n.span.column, n.message);
      else err << fmt::format("  note: {}\n", n.message);
    }
    return kExitError;
  }
  if (output.empty()) {
    out << *expanded.text;
    return kExitClean;
  }
  // As xacro does, -o creates the directories the output goes into.
  if (const std::filesystem::path parent = std::filesystem::path(output).parent_path(); !parent.empty())
    std::filesystem::create_directories(parent, ec);
  std::ofstream file(output, std::ios::binary);
  file << *expanded.text;
  if (!file) {
    err << fmt::format("asset-lint expand: error: cannot write '{}'\n", output);
    return kExitError;
  }
  return kExitClean;
}

}  // namespace assetlint::commands
