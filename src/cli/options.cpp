#include "cli/options.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <thread>

#include "cli/command_table.h"
#include "commands/command_input.h"
#include "engine/consumers.h"
#include "rules/registry.h"

namespace assetlint::cli {
namespace {

void add_options(CLI::App& app, Options& o) {
  app.add_option("paths", o.paths, "Files or directories to check (directories: every *.urdf, *.usda, *.mjcf, MJCF *.xml and top-level *.xacro below)");
  app.add_option("--select", o.select, "Only these rules (comma list, globs such as 'mimic-*')")
      ->delimiter(',')
      ->allow_extra_args(false);
  app.add_option("--ignore", o.ignore, "Skip these rules (comma list, globs)")->delimiter(',')->allow_extra_args(false);
  app.add_option("--extend-select", o.extend_select, "Run these rules too, on top of --select or the configuration")
      ->delimiter(',')
      ->allow_extra_args(false);
  app.add_option("--extend-ignore", o.extend_ignore, "Skip these rules too, on top of --ignore or the configuration")
      ->delimiter(',')
      ->allow_extra_args(false);
  app.add_option("--exclude", o.exclude,
                 "Leave out of directory walks the paths matching these globs (replaces `exclude` and its default '.*')")
      ->delimiter(',')
      ->allow_extra_args(false);
  app.add_option("--extend-exclude", o.extend_exclude, "Leave these globs out too, on top of `exclude`")
      ->delimiter(',')
      ->allow_extra_args(false);
  app.add_flag("--no-respect-gitignore", o.no_respect_gitignore, "Walk into files and directories .gitignore ignores");
  app.add_flag("--force-exclude", o.force_exclude,
               "Apply the exclusions to paths named on the command line too (for pre-commit and editors)");
  app.add_option("--output-format", o.format, "Output format: text, full (text with the source lines), concise, json, sarif, github, gitlab or junit")
      ->check(CLI::IsMember({"text", "full", "concise", "json", "sarif", "github", "gitlab", "junit"}));
  app.add_option("--stdin-filename", o.stdin_filename,
                 "With the path '-': lint standard input as this file (its configuration and layers); "
                 "with --fix, print the fixed text");
  app.add_option("--output-file", o.output_file, "Write the report to this file instead of standard output");
  app.add_flag("--statistics", o.statistics, "Print the number of findings per rule instead of the findings");
  app.add_option("--fail-on", o.fail_on,
                 "The least severe finding that makes the exit status 1: info, warning (default) or error")
      ->check(CLI::IsMember({"info", "warning", "error"}));
  app.add_option("--baseline", o.baseline,
                 "Report only findings not recorded in this baseline file; name its entries that no longer occur");
  app.add_option("--write-baseline", o.write_baseline,
                 "Record every current finding in this baseline file (instead of reporting them) and exit 0");
  app.add_flag("--exit-zero", o.exit_zero, "Exit 0 even when findings remain (still 2 on errors)");
  app.add_flag("-q,--quiet", o.quiet, "Text output: only the findings, no summary line");
  app.add_option("--color", o.color,
                 "Colour the text output (auto: on a terminal; NO_COLOR or TERM=dumb turn it off, CLICOLOR_FORCE or "
                 "FORCE_COLOR on)")->check(CLI::IsMember({"auto", "always", "never"}));
  app.add_option("-j,--jobs", o.jobs, "Files checked in parallel (default: one per core)")->check(CLI::Range(1u, 256u));
  app.add_option("--config", o.config_path,
                 "Use this asset-lint.toml for every file (default: the nearest one above each file)")
      ->check(CLI::ExistingFile);
  app.add_option("--timesteps-per-second", o.timesteps_per_second,
                 "Simulation rate, when the asset's stage authors none")
      ->check(CLI::PositiveNumber);
  app.add_option("--position-iterations", o.position_iterations,
                 "Solver position iterations, when the asset authors none")
      ->check(CLI::Range(1u, 255u));
  app.add_option("--root", o.root,
                 "The checked tree, the only files a check may read (default: the file's git work tree, else "
                 "the directory of its asset-lint.toml, else the directory named or the working directory)")
      ->check(CLI::ExistingDirectory);
  app.add_flag("--allow-outside-root", o.allow_outside_root, "Let references (includes, layers, meshes, links) read files outside the checked tree");
  app.add_option("--package-path", o.package_paths,
                 "A directory of ROS packages that $(find pkg) and package:// resolve in, and that may be read "
                 "(repeatable; after ROS_PACKAGE_PATH)")
      ->check(CLI::ExistingDirectory)
      ->allow_extra_args(false);
  app.add_option("--xacro-arg", o.xacro_args, "A xacro argument's value, name:=value (repeatable; wins over [xacro] args)")
      ->check(commands::check_xacro_argument);
  app.add_option("--variant", o.variants,
                 "Check USD variant set SET in variant NAME only, SET=NAME (repeatable; wins over [usd] variants; "
                 "default: the stage's selection and every variant that carries physics)")
      ->check(commands::check_variant_choice)
      ->allow_extra_args(false);
  app.add_option("--target", o.targets,
                 "Judge the files for this consumer: isaac-sim[@6.1], isaac-lab, mujoco[@3.12], newton, "
                 "gazebo[@dart|@bullet-featherstone], ros2_control (repeatable; replaces [targets] consumers; default: "
                 "every consumer the file's format is commonly loaded by)")
      ->check([](const std::string& text) {
        std::string error;
        return parse_consumer(text, error) ? std::string() : error;
      })
      ->allow_extra_args(false);
  app.add_option("--max-file-size", o.max_file_mib,
                 "Files and layers larger than this many MiB are not read (an error names them; default 512)")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 20));
  app.add_option("--time-budget", o.time_budget_s,
                 "Stop checking a file after this many seconds and report it as not checked (default 60; 0: no limit)")
      ->check(CLI::Range(0.0, 1e6));
  app.add_flag("--fix", o.fix, "Apply the safe fixes in place, then report what remains");
  app.add_flag("--unsafe-fixes", o.unsafe_fixes, "With --fix or --diff, also apply the unsafe fixes");
  app.add_flag("--diff", o.diff, "Print a unified diff of what --fix would change; write nothing");
  app.add_option("--map", o.map_pairs, "compare: pair a name of the first file with one of another (a=b)")
      ->allow_extra_args(false);
  app.add_option("--rtol", o.rtol, "compare: relative tolerance (default 1e-6)")->check(CLI::PositiveNumber);
  app.add_option("--fix-side", o.fix_side, "compare: the file whose values --fix rewrites");
  app.add_flag("--add-suppressions", o.add_suppressions,
               "Add an inline suppression comment for every current finding (in each file's own syntax)");
  app.add_flag("--list-rules", o.list_rules, "List every rule and exit (--output-format json: as JSON)");
  app.add_flag("--show-files", o.show_files, "Print the files a run would check, one per line, and exit");
  app.add_option("--show-settings", o.show_settings,
                 "Print the settings a check of FILE would use, each with where it came from, and exit")
      // `--show-settings --variant A=B FILE` would otherwise show the settings of a file named "--variant".
      ->check([](const std::string& s) {
        return s.rfind("--", 0) == 0 ? "expects a FILE, not the option " + s + " (put options before --show-settings)"
                                     : std::string();
      });
  app.add_flag("--version", o.version, "Print the version and exit");
  app.footer("Commands:\n" + commands_help() +
             "\nExit status: 0 nothing at or above --fail-on (default warning: infos never fail), 1 such findings\n"
             "remain, 2 usage, configuration or I/O error.\n"
             "With --diff: 0 nothing to change, 1 a diff was printed, 2 error.");
}

// Each --select/--ignore pattern must name at least one rule: a typo would
// otherwise silently select nothing.
bool validate_patterns(const std::vector<std::string>& patterns, const char* flag, std::ostream& err) {
  for (const auto& pattern : patterns) {
    bool matched = false;
    for (const RuleInfo* rule : rules::catalog()) matched = matched || glob_match(pattern, rule->id);
    if (!matched) {
      err << fmt::format("asset-lint: error: {} '{}' matches no rule; `asset-lint --list-rules` lists them\n", flag,
                         pattern);
      return false;
    }
  }
  return true;
}

}  // namespace

ParsedOptions parse_options(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"asset-lint: checks robot assets (URDF, xacro, USD, MJCF) against joint-tuning guidance", "asset-lint"};
  Options options;
  options.jobs = std::max(1u, std::thread::hardware_concurrency());
  add_options(app, options);
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    out << app.help();
    return {std::nullopt, 0};
  } catch (const CLI::ParseError& e) {
    err << "asset-lint: error: " << e.what() << "\n";
    return {std::nullopt, 2};
  }
  options.select_given = app.count("--select") > 0;
  options.ignore_given = app.count("--ignore") > 0;
  options.exclude_given = app.count("--exclude") > 0;
  return {std::move(options), 0};
}

std::vector<OptionName> option_names() {
  CLI::App app;
  Options options;
  add_options(app, options);
  std::vector<OptionName> names;
  for (const CLI::Option* option : app.get_options()) {
    std::string name;
    if (!option->get_lnames().empty()) name = "--" + option->get_lnames().front();
    else if (!option->get_snames().empty()) name = "-" + option->get_snames().front();
    else continue;  // the positional paths
    names.push_back({name, option->get_description(), option->get_type_size_max() > 0});
  }
  return names;
}

bool validate_options(const Options& o, std::ostream& err) {
  if (!validate_patterns(o.select, "--select", err) || !validate_patterns(o.ignore, "--ignore", err) ||
      !validate_patterns(o.extend_select, "--extend-select", err) ||
      !validate_patterns(o.extend_ignore, "--extend-ignore", err))
    return false;
  const bool stdin_named = std::find(o.paths.begin(), o.paths.end(), "-") != o.paths.end();
  if (stdin_named && (o.paths.size() != 1 || o.stdin_filename.empty())) {
    err << "asset-lint: error: '-' (standard input) must be the only path, with --stdin-filename PATH\n";
    return false;
  }
  if (stdin_named && o.diff) {
    err << "asset-lint: error: --diff does not read standard input; use --fix to print the fixed text\n";
    return false;
  }
  if (o.diff && o.format != "text" && o.format != "full" && o.format != "concise") {
    err << "asset-lint: error: --diff prints a unified diff; it cannot be combined with --output-format " << o.format
        << "\n";
    return false;
  }
  if (o.add_suppressions && (o.fix || o.diff || stdin_named)) {
    err << "asset-lint: error: --add-suppressions edits files itself; it does not combine with --fix, --diff or "
           "standard input\n";
    return false;
  }
  if ((!o.baseline.empty() || !o.write_baseline.empty()) && (o.fix || o.diff || stdin_named)) {
    err << "asset-lint: error: --baseline and --write-baseline work on a check of files, not with --fix, --diff "
           "or standard input\n";
    return false;
  }
  if (!o.baseline.empty() && !o.write_baseline.empty()) {
    err << "asset-lint: error: give --baseline or --write-baseline, not both (--write-baseline alone rewrites it)\n";
    return false;
  }
  if (o.list_rules && o.format != "text" && o.format != "json") {
    err << "asset-lint: error: --list-rules prints text or --output-format json\n";
    return false;
  }
  if (o.statistics && o.format != "text" && o.format != "full" && o.format != "concise" && o.format != "json") {
    err << "asset-lint: error: --statistics works with --output-format text, concise or json\n";
    return false;
  }
  return true;
}

config::CommandLineOverrides overrides_from(const Options& o) {
  config::CommandLineOverrides overrides;
  if (o.select_given) overrides.select = o.select;
  if (o.ignore_given) overrides.ignore = o.ignore;
  overrides.extend_select = o.extend_select;
  if (o.exclude_given) overrides.files.exclude = o.exclude;
  overrides.files.extend_exclude = o.extend_exclude;
  overrides.files.no_respect_gitignore = o.no_respect_gitignore;
  overrides.files.force_exclude = o.force_exclude;
  std::error_code cwd_ec;
  overrides.working_directory = std::filesystem::current_path(cwd_ec).string();
  overrides.extend_ignore = o.extend_ignore;
  overrides.timesteps_per_second = o.timesteps_per_second;
  if (o.position_iterations) overrides.position_iterations = static_cast<double>(*o.position_iterations);
  overrides.allow_outside_root = o.allow_outside_root;
  for (const auto& arg : o.xacro_args) overrides.xacro_args.push_back(commands::xacro_argument(arg));
  for (const auto& v : o.variants) overrides.variants.push_back(*commands::variant_choice(v));
  overrides.targets = o.targets;
  overrides.root = o.root;
  overrides.trees.push_back(std::filesystem::current_path().string());
  for (const auto& path : o.paths)
    if (std::error_code ec; std::filesystem::is_directory(path, ec)) overrides.trees.push_back(path);
  return overrides;
}

}  // namespace assetlint::cli
