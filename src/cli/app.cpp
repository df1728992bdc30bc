#include "cli/app.h"

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <iostream>

#include "cli/options.h"
#include "cli/report_writer.h"
#include "cli/rule_pages.h"
#include "commands/check.h"
#include "commands/compare_command.h"
#include "commands/exit_status.h"
#include "commands/fix.h"
#include "commands/stdin.h"
#include "commands/simulate.h"
#include "commands/tune.h"
#include "config/resolver.h"
#include "engine/file_system.h"
#include "pipeline/discovery.h"

namespace assetlint::cli {
namespace {

using commands::kExitClean;
using commands::kExitError;
using commands::kExitFindings;

int run_rule_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (args.size() != 2) {
    err << "asset-lint: error: usage: asset-lint rule RULE-ID\n";
    return kExitError;
  }
  return show_rule(args[1], out, err);
}

bool use_color(const Options& options, bool out_is_terminal) {
  return options.color == "always" ||
         (options.color == "auto" && out_is_terminal && options.output_file.empty() && !std::getenv("NO_COLOR"));
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
    return commands::run_compare(options.paths, {options.map_pairs, options.rtol, options.fix_side, options.fix},
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
  const PathExpansion expansion = expand_paths(options.paths);
  if (auto error = resolver.prepare(expansion.files)) {
    err << "asset-lint: error: " << error->to_string() << "\n";
    return kExitError;
  }
  if (options.fix || options.diff) {
    commands::FixCommandOptions fix_options;
    fix_options.diff = options.diff;
    fix_options.unsafe = options.unsafe_fixes;
    fix_options.jobs = options.jobs;
    fix_options.fail_on = *parse_severity(options.fail_on);
    return commands::run_fix_command(options.paths, resolver.as_function(), fix_options, out, err, write_report);
  }
  return commands::run_check(expansion, resolver.as_function(), commands::CheckOptions{options.jobs, *parse_severity(options.fail_on)}, err,
                             write_report);
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
  if (options.list_rules) {
    list_rules(out);
    return kExitClean;
  }
  if (!validate_options(options, err)) return kExitError;
  set_disk_limits(ReadLimits{options.max_file_mib << 20});
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

}  // namespace

int run(const std::vector<std::string>& args, std::istream& in, std::ostream& out, std::ostream& err,
        bool out_is_terminal) {
  if (!args.empty() && args.front() == "rule") return run_rule_command(args, out, err);
  if (!args.empty() && args.front() == "compare")
    return run_check_command({args.begin() + 1, args.end()}, in, out, err, out_is_terminal, true);
  if (!args.empty() && args.front() == "tune") return commands::run_tune({args.begin() + 1, args.end()}, out, err);
  if (!args.empty() && args.front() == "simulate")
    return commands::run_simulate({args.begin() + 1, args.end()}, out, err);
  if (!args.empty() && args.front() == "check")
    return run_check_command({args.begin() + 1, args.end()}, in, out, err, out_is_terminal);
  return run_check_command(args, in, out, err, out_is_terminal);
}

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, bool out_is_terminal) {
  return run(args, std::cin, out, err, out_is_terminal);
}

}  // namespace assetlint::cli
