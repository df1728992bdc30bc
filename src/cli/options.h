#pragma once
// The command line of `asset-lint [check]`: every option, parsed and checked.
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "config/resolver.h"
#include "engine/file_system.h"
#include "engine/work_budget.h"

namespace assetlint::cli {

struct Options {
  std::vector<std::string> paths;
  std::vector<std::string> select, ignore, extend_select, extend_ignore;
  bool select_given = false, ignore_given = false;
  std::string format = "text";
  std::string color = "auto";
  std::string fail_on = "warning";
  bool list_rules = false, version = false, show_files = false;
  std::string show_settings;  // --show-settings FILE
  bool fix = false, unsafe_fixes = false, diff = false, add_suppressions = false;
  bool statistics = false, exit_zero = false, quiet = false;
  std::string output_file;
  std::string stdin_filename;  // with the path "-": the file the text on stdin stands for
  std::string config_path;
  std::vector<std::string> exclude, extend_exclude;
  bool exclude_given = false, no_respect_gitignore = false, force_exclude = false;
  std::string baseline, write_baseline;  // --baseline FILE, --write-baseline FILE
  bool allow_outside_root = false;
  std::vector<std::string> xacro_args;  // --xacro-arg name:=value
  std::vector<std::string> package_paths;  // --package-path DIR
  std::vector<std::string> variants;    // --variant SET=NAME
  std::vector<std::string> targets;     // --target NAME (repeatable)
  std::uint64_t max_file_mib = ReadLimits::kDefaultMaxFileBytes >> 20;  // larger files and layers are not read
  double time_budget_s = kDefaultTimeBudgetSeconds;                     // per file; 0 = none
  std::string root;  // --root
  std::optional<double> timesteps_per_second;
  std::optional<unsigned> position_iterations;
  unsigned jobs = 1;
  // asset-lint compare
  std::vector<std::string> map_pairs;  // --map a=b
  double rtol = 1e-6;
  std::string fix_side;
};

// Parses `args` (after the command word). On --help prints the help to `out`; on a
// usage error names it on `err`. Either way returns the exit code instead of options.
struct ParsedOptions {
  std::optional<Options> options;
  int exit_code = 0;
};
ParsedOptions parse_options(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

// The options of `asset-lint [check]`, for the shell completions.
struct OptionName {
  std::string name;         // "--select" (the long name, else the short one)
  std::string description;  // the help's text
  bool takes_value = false;
};
std::vector<OptionName> option_names();

// Combinations of options that parse but make no sense together; names the first on `err`.
bool validate_options(const Options& options, std::ostream& err);

// The part of the options that overrides every configuration file.
config::CommandLineOverrides overrides_from(const Options& options);

}  // namespace assetlint::cli
