#include "commands/command_input.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "config/resolver.h"
#include "util/numbers.h"

namespace assetlint::commands {

std::optional<double> positive_flag(const std::string& flag, const std::string& text, std::string& error,
                                    bool allow_zero) {
  const auto value = parse_double(text);
  if (!value || !std::isfinite(*value) || *value < 0 || (*value == 0 && !allow_zero)) {
    error = fmt::format("{} must be a finite number {} 0, got '{}'", flag, allow_zero ? "≥" : ">", text);
    return std::nullopt;
  }
  return value;
}

CommandAsset load_command_asset(const std::string& path, const std::optional<std::string>& config) {
  CommandAsset result;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    result.error = fmt::format("no such file: '{}'", path);
    return result;
  }
  config::CommandLineOverrides overrides;
  overrides.trees.push_back(std::filesystem::current_path(ec).string());
  config::SettingsResolver resolver(overrides, config);
  if (auto problem = resolver.prepare({path})) {
    result.error = problem->to_string();
    return result;
  }
  result.settings = resolver.for_file(path);
  result.loaded = load_asset(path, result.settings);
  if (result.loaded.error) {
    result.error = *result.loaded.error;
    return result;
  }
  if (!result.loaded.read.usable) {
    const Asset& asset = result.loaded.read.asset;
    std::string first = "the reader could not build a model";
    for (const Diagnostic& d : result.loaded.read.diagnostics) {
      if (d.severity != Severity::Error) continue;
      first = d.span.valid() ? fmt::format("{}:{}:{}: {} [{}]", asset.source(d.span.file).path(), d.span.line,
                                           d.span.column, d.message, d.rule)
                             : d.message;
      break;
    }
    result.error = fmt::format("cannot read {}: {}", path, first);
  }
  return result;
}

}  // namespace assetlint::commands
