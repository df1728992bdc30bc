#pragma once
// What the one-asset commands (tune, simulate) share: reading numeric flags strictly,
// and loading the asset with its configuration.
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "pipeline/lint.h"
#include "engine/settings.h"

namespace assetlint::commands {

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
CommandAsset load_command_asset(const std::string& path, const std::optional<std::string>& config);

}  // namespace assetlint::commands
