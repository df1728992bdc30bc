#include "cli/app.h"

#include <fmt/format.h>

#include <cstdlib>
#include <string_view>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli/command_table.h"
#include "cli/completion.h"
#include "cli/options.h"
#include "cli/report_writer.h"
#include "cli/rule_pages.h"
#include "commands/add_suppressions.h"
#include "commands/cat.h"
#include "commands/check.h"
#include "commands/compare_command.h"
#include "commands/exit_status.h"
#include "commands/fix.h"
#include "commands/init.h"
#include "commands/stdin.h"
#include "commands/expand.h"
#include "commands/simulate.h"
#include "commands/tune.h"
#include "commands/verify.h"
#include "config/project_root.h"
#include "config/resolver.h"
#include "engine/file_system.h"
#include "pipeline/discovery.h"
#include "report/settings_report.h"
#include "util/spelling.h"
#include "util/ros_package_path.h"
#include "engine/work_budget.h"

namespace assetlint::cli {
namespace {

using commands::kExitClean;
using commands::kExitError;
using commands::kExitFindings;

// --color auto: NO_COLOR (set, not empty) turns colour off; CLICOLOR_FORCE or FORCE_COLOR
// (set, not empty, not "0") turn it on even off a terminal; TERM=dumb turns it off;
// otherwise colour only on a terminal, never into --output-file.
bool use_color(const Options& options, bool out_is_terminal) {
  if (options.color != "auto") return options.color == "always";
  auto value = [](const char* name) -> std::string_view {
    const char* v = std::getenv(name);
    return v ? v : "";
  };
  if (!value("NO_COLOR").empty()) return false;
  for (const char* force : {"CLICOLOR_FORCE", "FORCE_COLOR"})
    if (!value(force).empty() && value(force) != "0") return true;
  if (value("TERM") == "dumb") return false;
  return out_is_terminal && options.output_file.empty();
}

// Where the configuration of `path` was looked for, in words.
std::string config_lookup(const std::string& path, bool explicit_config) {
  if (explicit_config) return "looked for: none, --config names it";
  const config::ConfigSearch search = config::search_config(path);
  const std::string first = search.first.string(), last = search.last.string();
  const std::string where = first == last ? fmt::format("looked for {} in {}", config::kFileName, first)
                                          : fmt::format("looked for {} in {} and up to {}", config::kFileName, first, last);
  if (!search.found.empty()) return where;
  return where + (search.git_root ? ", the git work tree's root (the lookup stops there)" : ", the file system's root");
}

int show_settings(const std::string& file, config::SettingsResolver& resolver, bool explicit_config, std::ostream& out,
                  std::ostream& err) {
  const std::string path = spelled(file, std::filesystem::current_path());
  if (auto error = resolver.prepare({path})) {
    err << "asset-lint: error: " << error->to_string() << "\n";
    return kExitError;
  }
  const Settings& settings = resolver.for_file(path);
  std::string tree = config::checked_root(path, settings);
  const std::optional<VariantRun> variants = plan_variants(path, settings);
  write_settings(out, path, settings, resolver.file_selection_for(path), tree.empty() ? "the file's directory" : tree,
                 variants ? &*variants : nullptr, config_lookup(path, explicit_config));
  return kExitClean;
}

// Checks or fixes the files the options name (or standard input), writing the report to
// `report_out`.
int run_files(const Options& options, bool compare, std::istream& in, std::ostream& out, std::ostream& err,
              std::ostream& report_out, bool out_is_terminal) {
  config::SettingsResolver resolver(overrides_from(options), options.config_path.empty()
                                                                 ? std::nullopt
                                                                 : std::optional(options.config_path));
  const commands::WriteReport write_report =
      report_writer(options, use_color(options, out_is_terminal), resolver, report_out);
  if (compare) {
    if (auto error = resolver.prepare(options.paths)) {
      err << "asset-lint: error: " << error->to_string() << "\n";
      return kExitError;
    }
    // The summary heads a text report on the terminal; machine formats and --output-file
    // carry the findings alone.
    const bool text = options.format == "text" || options.format == "full" || options.format == "concise";
    const bool summary = text && !options.quiet && options.output_file.empty();
    return commands::run_compare(options.paths,
                                 {options.map_pairs, options.rtol, options.fix_side, options.fix, summary},
                                 resolver.as_function(), out, err, write_report);
  }
  if (options.paths == std::vector<std::string>{"-"}) {
    if (auto error = resolver.prepare({options.stdin_filename})) {
      err << "asset-lint: error: " << error->to_string() << "\n";
      return kExitError;
    }
    const commands::StdinOptions stdin_options{options.stdin_filename, options.fix, options.unsafe_fixes,
                                               *parse_severity(options.fail_on)};
    return commands::run_stdin(in, resolver.for_file(options.stdin_filename), stdin_options, out, err,
                               write_report);
  }
  const SelectionFor selection_for = [&resolver](const std::string& path) -> const config::FileSelection& {
    return resolver.file_selection_for(path);
  };
  if (!options.show_settings.empty()) return show_settings(options.show_settings, resolver, !options.config_path.empty(), out, err);
  const PathExpansion expansion = expand_paths(options.paths, selection_for);
  if (options.show_files) {
    commands::announce_expansion(expansion, err);
    for (const auto& file : expansion.files) out << file << "\n";
    return expansion.errors.empty() ? kExitClean : kExitError;
  }
  if (auto error = resolver.prepare(expansion.files)) {
    err << "asset-lint: error: " << error->to_string() << "\n";
    return kExitError;
  }
  if (options.fix || options.diff || options.add_suppressions) {
    commands::FixCommandOptions fix_options;
    if (options.add_suppressions) {
      fix_options.make_hook = commands::suppression_inserter;
      fix_options.written = commands::describe_added_suppressions;
    }
    fix_options.diff = options.diff;
    fix_options.unsafe = options.unsafe_fixes;
    fix_options.jobs = options.jobs;
    fix_options.fail_on = *parse_severity(options.fail_on);
    fix_options.selection_for = selection_for;
    return commands::run_fix_command(options.paths, resolver.as_function(), fix_options, out, err, write_report);
  }
  const commands::CheckOptions check_options{options.jobs, *parse_severity(options.fail_on), options.baseline,
                                             options.write_baseline};
  return commands::run_check(expansion, resolver.as_function(), check_options, err, write_report);
}

int run_check_command(const std::vector<std::string>& args, std::istream& in, std::ostream& out,
                      std::ostream& err, bool out_is_terminal, bool compare = false) {
  ParsedOptions parsed = parse_options(args, out, err);
  if (!parsed.options) return parsed.exit_code;
  Options& options = *parsed.options;
  if (options.paths.empty()) options.paths.push_back(".");  // like ruff: the working directory
  if (options.version) {
    out << "asset-lint " << ASSET_LINT_VERSION << "\n";
    return kExitClean;
  }
  if (!validate_options(options, err)) return kExitError;
  if (options.list_rules) {
    list_rules(out, options.format == "json");
    return kExitClean;
  }
  set_disk_limits(ReadLimits{options.max_file_mib << 20});
  set_time_budget(options.time_budget_s);
  add_package_paths(options.package_paths);
  std::ofstream report_file;
  if (!options.output_file.empty()) {
    report_file.open(options.output_file, std::ios::binary | std::ios::trunc);
    if (!report_file) {
      err << fmt::format("asset-lint: error: cannot write '{}'\n", options.output_file);
      return kExitError;
    }
  }
  const int code =
      run_files(options, compare, in, out, err, options.output_file.empty() ? out : report_file, out_is_terminal);
  if (!options.output_file.empty() && !report_file) {
    err << fmt::format("asset-lint: error: cannot write '{}'\n", options.output_file);
    return kExitError;
  }
  // --exit-zero turns "findings remain" into success; errors stay errors.
  return options.exit_zero && code == kExitFindings ? kExitClean : code;
}

// A first word that is no command and names nothing on disk is a mistyped command, not a
// path to report as unreadable (`asset-lint verfy robot.urdf`). Words that look like paths
// (a dot, a slash, a glob) are left to the check, which names them.
std::optional<int> unknown_command(const std::string& word, std::ostream& err) {
  if (word.empty() || word.starts_with("-") || word.find_first_of("./\\*?") != std::string::npos) return std::nullopt;
  std::error_code ec;
  if (std::filesystem::exists(word, ec)) return std::nullopt;
  if (auto nearest = nearest_spelling(word, command_names()))
    err << fmt::format("asset-lint: error: unknown command '{}'; did you mean '{}'?\n", word, *nearest);
  else
    err << fmt::format("asset-lint: error: '{}' is neither a command nor a file or directory; `asset-lint --help` "
                       "lists the commands\n",
                       word);
  return kExitError;
}

}  // namespace

int run(const std::vector<std::string>& args, std::istream& in, std::ostream& out, std::ostream& err,
        bool out_is_terminal) {
  const std::string command = args.empty() ? "" : args.front();
  const std::vector<std::string> rest = args.empty() ? args : std::vector<std::string>(args.begin() + 1, args.end());
  if (command == "rule") return run_rule_command(args, out, err);
  if (command == "completion") return run_completion_command(args, out, err);
  if (command == "compare") return run_check_command(rest, in, out, err, out_is_terminal, true);
  if (command == "cat") return commands::run_cat(rest, out, err);
  if (command == "init") return commands::run_init(rest, out, err);
  if (command == "tune") return commands::run_tune(rest, out, err);
  if (command == "verify") return commands::run_verify(rest, out, err);
  if (command == "expand") return commands::run_expand(rest, out, err);
  if (command == "simulate") return commands::run_simulate(rest, out, err);
  if (command == "check") return run_check_command(rest, in, out, err, out_is_terminal);
  if (auto code = unknown_command(command, err)) return *code;
  return run_check_command(args, in, out, err, out_is_terminal);
}

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, bool out_is_terminal) {
  return run(args, std::cin, out, err, out_is_terminal);
}

}  // namespace assetlint::cli
