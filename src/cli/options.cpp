#include "cli/options.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <thread>

#include "rules/registry.h"

namespace assetlint::cli {
namespace {

void add_options(CLI::App& app, Options& o) {
  app.add_option("paths", o.paths, "Files or directories to check (directories: every *.urdf, *.usda, *.mjcf and MJCF *.xml below)");
  app.add_option("--select", o.select, "Only these rules (comma list, globs such as 'mimic-*')")
      ->delimiter(',')
      ->allow_extra_args(false);
  app.add_option("--ignore", o.ignore, "Skip these rules (comma list, globs)")->delimiter(',')->allow_extra_args(false);
  app.add_option("--output-format", o.format, "Output format: text, concise, json, sarif, github, gitlab or junit")
      ->check(CLI::IsMember({"text", "concise", "json", "sarif", "github", "gitlab", "junit"}));
  app.add_option("--stdin-filename", o.stdin_filename,
                 "With the path '-': lint standard input as this file (its configuration and layers); "
                 "with --fix, print the fixed text");
  app.add_option("--output-file", o.output_file, "Write the report to this file instead of standard output");
  app.add_flag("--statistics", o.statistics, "Print the number of findings per rule instead of the findings");
  app.add_option("--fail-on", o.fail_on,
                 "The least severe finding that makes the exit status 1: info, warning (default) or error")
      ->check(CLI::IsMember({"info", "warning", "error"}));
  app.add_flag("--exit-zero", o.exit_zero, "Exit 0 even when findings remain (still 2 on errors)");
  app.add_flag("-q,--quiet", o.quiet, "Text output: only the findings, no summary line");
  app.add_option("--color", o.color, "Colour the text output")->check(CLI::IsMember({"auto", "always", "never"}));
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
                 "The checked tree whose files USD composition may read (default: the file's git work tree, else "
                 "the directory of its asset-lint.toml, else the directory named or the working directory)")
      ->check(CLI::ExistingDirectory);
  app.add_flag("--allow-outside-root", o.allow_outside_root, "Let USD composition read layers outside the checked tree");
  app.add_option("--max-file-size", o.max_file_mib,
                 "Files and layers larger than this many MiB are not read (an error names them; default 512)")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 20));
  app.add_flag("--fix", o.fix, "Apply the safe fixes in place, then report what remains");
  app.add_flag("--unsafe-fixes", o.unsafe_fixes, "With --fix or --diff, also apply the unsafe fixes");
  app.add_flag("--diff", o.diff, "Print a unified diff of what --fix would change; write nothing");
  app.add_option("--map", o.map_pairs, "compare: pair a name of the first file with one of another (a=b)")
      ->allow_extra_args(false);
  app.add_option("--rtol", o.rtol, "compare: relative tolerance (default 1e-6)")->check(CLI::PositiveNumber);
  app.add_option("--fix-side", o.fix_side, "compare: the file whose values --fix rewrites");
  app.add_flag("--list-rules", o.list_rules, "List every rule and exit");
  app.add_flag("--version", o.version, "Print the version and exit");
  app.footer(
      "Commands:\n  asset-lint [check] PATH...   check files\n  asset-lint compare A B [C]   compare the physics of files in any format\n  asset-lint rule RULE-ID      print a rule's documentation\n\n"
      "Exit status: 0 nothing at or above --fail-on (default warning: infos never fail), 1 such findings\n"
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
  CLI::App app{"asset-lint: checks robot assets (URDF, USDA) against PhysX joint-tuning guidance", "asset-lint"};
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
  return {std::move(options), 0};
}

bool validate_options(const Options& o, std::ostream& err) {
  if (!validate_patterns(o.select, "--select", err) || !validate_patterns(o.ignore, "--ignore", err)) return false;
  const bool stdin_named = std::find(o.paths.begin(), o.paths.end(), "-") != o.paths.end();
  if (stdin_named && (o.paths.size() != 1 || o.stdin_filename.empty())) {
    err << "asset-lint: error: '-' (standard input) must be the only path, with --stdin-filename PATH\n";
    return false;
  }
  if (stdin_named && o.diff) {
    err << "asset-lint: error: --diff does not read standard input; use --fix to print the fixed text\n";
    return false;
  }
  if (o.diff && o.format != "text" && o.format != "concise") {
    err << "asset-lint: error: --diff prints a unified diff; it cannot be combined with --output-format " << o.format
        << "\n";
    return false;
  }
  if (o.statistics && o.format != "text" && o.format != "concise" && o.format != "json") {
    err << "asset-lint: error: --statistics works with --output-format text, concise or json\n";
    return false;
  }
  return true;
}

config::CommandLineOverrides overrides_from(const Options& o) {
  config::CommandLineOverrides overrides;
  if (o.select_given) overrides.select = o.select;
  if (o.ignore_given) overrides.ignore = o.ignore;
  overrides.timesteps_per_second = o.timesteps_per_second;
  if (o.position_iterations) overrides.position_iterations = static_cast<double>(*o.position_iterations);
  overrides.allow_outside_root = o.allow_outside_root;
  overrides.root = o.root;
  overrides.trees.push_back(std::filesystem::current_path().string());
  for (const auto& path : o.paths)
    if (std::error_code ec; std::filesystem::is_directory(path, ec)) overrides.trees.push_back(path);
  return overrides;
}

}  // namespace assetlint::cli
