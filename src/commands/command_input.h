#pragma once
// What the one-asset commands (tune, simulate) share: reading numeric flags strictly,
// and loading the asset with its configuration.
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "pipeline/lint.h"
#include "engine/settings.h"
#include "physics/step.h"

namespace CLI {
class App;
}

namespace assetlint::commands {

// Parses a command's words (those after its name) with `app`. When parsing ends the
// command, its exit status: 0 after printing the help to `out`, 2 after one error line
// "asset-lint NAME: error: …" on `err`.
std::optional<int> parse_command(CLI::App& app, const std::vector<std::string>& args, const std::string& name,
                                 std::ostream& out, std::ostream& err);

// A number given on the command line: finite and > 0 (or ≥ 0 with `allow_zero`). On
// failure, nullopt and one line in `error` naming the flag and what it got.
std::optional<double> positive_flag(const std::string& flag, const std::string& text, std::string& error,
                                    bool allow_zero = false);

// The asset and the settings it is checked with (its nearest asset-lint.toml, or
// `config` when given). On failure, `error` holds one line (config or read errors with
// file:line:col) and the asset is not usable.
struct CommandAsset {
  Settings settings;
  LoadedAsset loaded;
  std::optional<std::string> error;
};
// Where USD composition may read, as `check`'s --root and --allow-outside-root say.
struct CompositionScope {
  std::string root;  // empty: the file's git work tree, else its asset-lint.toml's directory
  bool allow_outside_root = false;
  std::vector<std::string> variants;  // --variant SET=NAME
  std::vector<std::string> package_paths;  // --package-path DIR: where ROS packages are found, and read
  std::vector<std::string> xacro_args;     // --xacro-arg name:=value
};
CommandAsset load_command_asset(const std::string& path, const std::optional<std::string>& config,
                                const CompositionScope& scope = {});

// Writes a report file (--plot, --csv); false with `error` naming the path when it cannot.
bool write_text_file(const std::string& path, const std::string& text, std::string& error);

// Adds --root, --allow-outside-root, --variant and --xacro-arg to a command.
void add_scope_options(CLI::App& app, CompositionScope& scope);

// The rate, iterations and solver a command steps at: the asset's (stage, then
// configuration, then PhysX defaults), except that values given on the command line
// (origin "--rate", "--position-iterations", "--solver") win over the stage too.
// --variant SET=NAME: the set and the variant; nullopt when the text is not of that form.
std::optional<std::pair<std::string, std::string>> variant_choice(const std::string& text);
// The check CLI11 runs on each --variant.
std::string check_variant_choice(const std::string& text);
// --xacro-arg name:=value, checked by CLI11 first; the check.
std::pair<std::string, std::string> xacro_argument(const std::string& text);
std::string check_xacro_argument(const std::string& text);

physics::SimulationRate command_rate(const Asset& asset, const Settings& settings);

}  // namespace assetlint::commands
