#include "cli/app.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdlib>
#include <functional>
#include <filesystem>
#include <fstream>
#include <thread>

#include "cli/rule_docs.h"
#include "commands/compare.h"
#include "commands/compare_fix.h"
#include "config/resolver.h"
#include "engine/linter.h"
#include "fix/command.h"
#include "report/concise_reporter.h"
#include "report/github_reporter.h"
#include "report/json_reporter.h"
#include "report/junit_reporter.h"
#include "report/sarif_reporter.h"
#include "report/statistics.h"
#include "report/summary.h"
#include "report/text_reporter.h"
#include "rules/registry.h"
#include "util/numbers.h"

namespace assetlint::cli {
namespace {

constexpr int kExitClean = 0;
constexpr int kExitFindings = 1;
constexpr int kExitError = 2;

void list_rules(std::ostream& out) {
  std::size_t width = 0;
  for (const RuleInfo* rule : rules::catalog()) width = std::max(width, rule->id.size());
  for (const RuleInfo* rule : rules::catalog()) {
    out << fmt::format("{:<{}}  {:<7}  {:<7}  {}\n", rule->id, width, severity_name(rule->default_severity),
                       rule->fixable ? "fixable" : "", rule->summary);
  }
}

int show_rule(const std::string& id, std::ostream& out, std::ostream& err) {
  const RuleInfo* rule = rules::find_rule(id);
  if (!rule) {
    err << fmt::format("asset-lint: error: unknown rule '{}'; `asset-lint --list-rules` lists them\n", id);
    return kExitError;
  }
  for (const auto& [doc_id, page] : rule_docs()) {
    if (doc_id == id) {
      out << page;
      if (!page.empty() && page.back() != '\n') out << "\n";
      break;
    }
  }
  out << fmt::format("\nDefault severity: {}. Fix: {}.\n", severity_name(rule->default_severity),
                     rule->fixable ? "available" : "none");
  if (!rule->options.empty()) {
    out << "Options ([rules." << rule->id << "] in asset-lint.toml):\n";
    for (const auto& option : rule->options)
      out << fmt::format("  {} = {}  {}\n", option.name, format_number(option.default_value, 6), option.description);
  }
  return kExitClean;
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

int run_compare(const std::vector<std::string>& paths, const std::vector<std::string>& map_pairs, double rtol,
                const std::string& fix_side, bool fix, config::SettingsResolver& resolver, std::ostream& out,
                std::ostream& err, const std::function<void(const std::vector<FileReport>&)>& write_report) {
  if (paths.size() < 2 || paths.size() > 3) {
    err << "asset-lint: error: usage: asset-lint compare A B [C]\n";
    return kExitError;
  }
  commands::CompareOptions options;
  options.rtol = rtol;
  for (const auto& pair : map_pairs) {
    const auto eq = pair.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == pair.size()) {
      err << fmt::format("asset-lint: error: --map '{}': expected NAME=OTHER_NAME\n", pair);
      return kExitError;
    }
    options.map.emplace_back(pair.substr(0, eq), pair.substr(eq + 1));
  }
  if (!fix_side.empty()) {
    for (std::size_t i = 0; i < paths.size(); ++i)
      if (paths[i] == fix_side || std::filesystem::path(paths[i]).filename() == fix_side) options.fix_side = static_cast<int>(i);
    if (options.fix_side < 0) {
      err << fmt::format("asset-lint: error: --fix-side '{}' is none of the compared files\n", fix_side);
      return kExitError;
    }
  }
  if (fix && options.fix_side < 0) {
    err << "asset-lint: error: compare --fix needs --fix-side FILE (which file is right is yours to say)\n";
    return kExitError;
  }
  if (auto error = resolver.prepare(paths)) {
    err << "asset-lint: error: " << error->to_string() << "\n";
    return kExitError;
  }
  std::string error;
  FileReport report = commands::compare_files(paths, resolver.as_function(), options, error);
  if (!error.empty()) {
    err << "asset-lint: error: " << error << "\n";
    return kExitError;
  }
  if (fix) {
    int changed = 0;
    if (auto failure = commands::apply_compare_fixes(report, resolver.as_function(), changed)) {
      err << "asset-lint: error: " << *failure << "\n";
      return kExitError;
    }
    report = commands::compare_files(paths, resolver.as_function(), options, error);
    if (!error.empty()) {
      err << "asset-lint: error: " << error << "\n";
      return kExitError;
    }
    out << fmt::format("compare: {} file{} fixed\n", changed, changed == 1 ? "" : "s");
  }
  write_report({report});
  return report.diagnostics.empty() ? kExitClean : kExitFindings;
}

}  // namespace

int run(const std::vector<std::string>& raw_args, std::ostream& out, std::ostream& err, bool out_is_terminal) {
  std::vector<std::string> args = raw_args;
  if (!args.empty() && args.front() == "rule") {
    if (args.size() != 2) {
      err << "asset-lint: error: usage: asset-lint rule RULE-ID\n";
      return kExitError;
    }
    return show_rule(args[1], out, err);
  }
  if (!args.empty() && args.front() == "check") args.erase(args.begin());
  const bool compare = !args.empty() && args.front() == "compare";
  if (compare) args.erase(args.begin());

  CLI::App app{"asset-lint: checks robot assets (URDF, USDA) against PhysX joint-tuning guidance", "asset-lint"};
  std::vector<std::string> paths;
  std::vector<std::string> select, ignore;
  std::string format = "text";
  std::string color = "auto";
  bool show_rules = false, show_version = false;
  bool fix = false, unsafe_fixes = false, diff = false;
  bool statistics = false, exit_zero = false, quiet = false;
  std::string output_file;
  std::string config_path;
  bool allow_outside_root = false;
  double timesteps = 0;
  unsigned iterations = 0;
  unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
  app.add_option("paths", paths, "Files or directories to check (directories: every *.urdf and *.usda below)");
  app.add_option("--select", select, "Only these rules (comma list, globs such as 'mimic-*')")
      ->delimiter(',')
      ->allow_extra_args(false);
  app.add_option("--ignore", ignore, "Skip these rules (comma list, globs)")->delimiter(',')->allow_extra_args(false);
  app.add_option("--output-format", format, "Output format: text, concise, json, sarif, github or junit")
      ->check(CLI::IsMember({"text", "concise", "json", "sarif", "github", "junit"}));
  app.add_option("--output-file", output_file, "Write the report to this file instead of standard output");
  app.add_flag("--statistics", statistics, "Print the number of findings per rule instead of the findings");
  app.add_flag("--exit-zero", exit_zero, "Exit 0 even when findings remain (still 2 on errors)");
  app.add_flag("-q,--quiet", quiet, "Text output: only the findings, no summary line");
  app.add_option("--color", color, "Colour the text output")->check(CLI::IsMember({"auto", "always", "never"}));
  app.add_option("-j,--jobs", jobs, "Files checked in parallel (default: one per core)")->check(CLI::Range(1u, 256u));
  app.add_option("--config", config_path, "Use this asset-lint.toml for every file (default: the nearest one above each file)")
      ->check(CLI::ExistingFile);
  app.add_option("--timesteps-per-second", timesteps, "Simulation rate, when the asset's stage authors none")
      ->check(CLI::PositiveNumber);
  app.add_option("--position-iterations", iterations, "Solver position iterations, when the asset authors none")
      ->check(CLI::Range(1u, 255u));
  app.add_flag("--allow-outside-root", allow_outside_root,
               "Let USD composition read layers outside the checked tree (the directory named, or the working "
               "directory)");
  app.add_flag("--fix", fix, "Apply the safe fixes in place, then report what remains");
  app.add_flag("--unsafe-fixes", unsafe_fixes, "With --fix or --diff, also apply the unsafe fixes");
  app.add_flag("--diff", diff, "Print a unified diff of what --fix would change; write nothing");
  std::vector<std::string> map_pairs;
  std::string fix_side;
  double rtol = 1e-6;
  app.add_option("--map", map_pairs, "compare: pair a name of the first file with one of the other (a=b)")
      ->allow_extra_args(false);
  app.add_option("--rtol", rtol, "compare: relative tolerance (default 1e-6)")->check(CLI::PositiveNumber);
  app.add_option("--fix-side", fix_side, "compare: the file whose values the fixes rewrite (with --fix)");
  app.add_flag("--list-rules", show_rules, "List every rule and exit");
  app.add_flag("--version", show_version, "Print the version and exit");
  app.footer(
      "Commands:\n  asset-lint [check] PATH...   check files\n  asset-lint compare A B [C]   compare the physics of "
      "files in any format\n  asset-lint rule RULE-ID      print a rule's documentation\n\n"
      "Exit status: 0 nothing reported, 1 findings remain, 2 usage, configuration or I/O error.\n"
      "With --diff: 0 nothing to change, 1 a diff was printed, 2 error.");

  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    out << app.help();
    return kExitClean;
  } catch (const CLI::ParseError& e) {
    err << "asset-lint: error: " << e.what() << "\n";
    return kExitError;
  }
  if (show_version) {
    out << "asset-lint " << ASSET_LINT_VERSION << "\n";
    return kExitClean;
  }
  if (show_rules) {
    list_rules(out);
    return kExitClean;
  }
  if (paths.empty()) {
    err << "asset-lint: error: no files to check; usage: asset-lint [check] PATH...\n";
    return kExitError;
  }
  if (!validate_patterns(select, "--select", err) || !validate_patterns(ignore, "--ignore", err)) return kExitError;
  if (statistics && format != "text" && format != "concise" && format != "json") {
    err << "asset-lint: error: --statistics works with --output-format text, concise or json\n";
    return kExitError;
  }
  std::ofstream report_file;
  if (!output_file.empty()) {
    report_file.open(output_file, std::ios::binary | std::ios::trunc);
    if (!report_file) {
      err << fmt::format("asset-lint: error: cannot write '{}'\n", output_file);
      return kExitError;
    }
  }
  std::ostream& report_out = output_file.empty() ? out : report_file;

  config::CommandLineOverrides overrides;
  if (app.count("--select")) overrides.select = select;
  if (app.count("--ignore")) overrides.ignore = ignore;
  if (app.count("--timesteps-per-second")) overrides.timesteps_per_second = timesteps;
  if (app.count("--position-iterations")) overrides.position_iterations = static_cast<double>(iterations);
  overrides.allow_outside_root = allow_outside_root;
  overrides.trees.push_back(std::filesystem::current_path().string());
  for (const auto& path : paths)
    if (std::filesystem::is_directory(path)) overrides.trees.push_back(path);
  config::SettingsResolver resolver(overrides, config_path.empty() ? std::nullopt : std::optional(config_path));

  const bool use_color = color == "always" || (color == "auto" && out_is_terminal && output_file.empty() &&
                                               !std::getenv("NO_COLOR"));
  auto write_report = [&](const std::vector<FileReport>& reports) {
    if (statistics && format == "json") write_statistics_json(report_out, reports);
    else if (statistics) {
      write_statistics_text(report_out, reports);
      const Summary s = summarize(reports);
      if (!quiet && s.fixable) report_out << "[*] fixable with `asset-lint --fix`\n";
    } else if (format == "json") write_json(report_out, reports);
    else if (format == "concise") write_concise(report_out, reports);
    else if (format == "github") write_github(report_out, reports);
    else if (format == "sarif") {
      std::error_code ec;
      write_sarif(report_out, reports, SarifOptions{std::filesystem::current_path(ec).string()});
    } else if (format == "junit") {
      write_junit(report_out, reports,
                  [&](const FileReport& r) { return rules_run_on(resolver.for_file(r.path), r.path); });
    } else write_text(report_out, reports, TextOptions{use_color, !quiet});
    report_out.flush();
  };
  // --exit-zero turns "findings remain" into success; errors stay errors.
  auto finish = [&](int code) {
    if (!output_file.empty() && !report_file) {
      err << fmt::format("asset-lint: error: cannot write '{}'\n", output_file);
      return kExitError;
    }
    return exit_zero && code == kExitFindings ? kExitClean : code;
  };
  if (compare) return finish(run_compare(paths, map_pairs, rtol, fix_side, fix, resolver, out, err, write_report));

  fix::FixCommandOptions fix_options;
  fix_options.diff = diff;
  fix_options.unsafe = unsafe_fixes;
  fix_options.jobs = jobs;

  PathExpansion expansion = expand_paths(paths);
  if (auto error = resolver.prepare(expansion.files)) {
    err << "asset-lint: error: " << error->to_string() << "\n";
    return kExitError;
  }
  if (fix || diff)
    return finish(fix::run_fix_command(paths, resolver.as_function(), fix_options, out, err, write_report));

  bool io_error = false;
  for (const auto& message : expansion.errors) {
    err << "asset-lint: error: " << message << "\n";
    io_error = true;
  }
  std::vector<FileReport> reports = lint_files(expansion.files, resolver.as_function(), jobs);
  drop_repeated_findings(reports);
  std::erase_if(reports, [&](const FileReport& report) {
    if (!report.error) return false;
    err << "asset-lint: error: " << *report.error << "\n";
    io_error = true;
    return true;
  });

  write_report(reports);
  if (io_error) return finish(kExitError);
  return finish(summarize(reports).total() == 0 ? kExitClean : kExitFindings);
}

}  // namespace assetlint::cli
