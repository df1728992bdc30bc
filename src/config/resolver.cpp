#include "config/resolver.h"

namespace assetlint::config {

SettingsResolver::SettingsResolver(CommandLineOverrides overrides, std::optional<std::string> explicit_config)
    : overrides_(std::move(overrides)), explicit_config_(std::move(explicit_config)) {}

const Settings& SettingsResolver::load(const std::string& config_path, std::optional<ConfigError>& error) {
  auto it = by_config_.find(config_path);
  if (it != by_config_.end()) return *it->second;
  auto settings = std::make_unique<Settings>();
  if (!config_path.empty()) error = config::load(config_path, *settings);
  if (overrides_.select) set_patterns(settings->selection, true, patterns_from(*overrides_.select, "--select"));
  if (overrides_.ignore) set_patterns(settings->selection, false, patterns_from(*overrides_.ignore, "--ignore"));
  extend(settings->selection, true, patterns_from(overrides_.extend_select, "--extend-select"));
  extend(settings->selection, false, patterns_from(overrides_.extend_ignore, "--extend-ignore"));
  if (overrides_.timesteps_per_second)
    settings->simulation.timesteps_per_second = Configured<double>{*overrides_.timesteps_per_second, "--timesteps-per-second"};
  if (overrides_.position_iterations)
    settings->simulation.position_iterations = Configured<double>{*overrides_.position_iterations, "--position-iterations"};
  settings->trees = overrides_.trees;
  settings->root = overrides_.root;
  settings->allow_outside_root = overrides_.allow_outside_root;
  for (const auto& [name, value] : overrides_.xacro_args) settings->xacro.args[name] = Configured<std::string>{value, "--xacro-arg"};
  for (const auto& [set, variant] : overrides_.variants) settings->usd.variants[set] = Configured<std::string>{variant, "--variant"};
  if (!overrides_.targets.empty()) {
    settings->targets.consumers.clear();
    for (const std::string& target : overrides_.targets) settings->targets.consumers.push_back({target, "--target"});
  }
  return *by_config_.emplace(config_path, std::move(settings)).first->second;
}

std::optional<ConfigError> SettingsResolver::prepare(const std::vector<std::string>& files) {
  std::lock_guard lock(mutex_);
  std::optional<ConfigError> error;
  if (explicit_config_) {
    load(*explicit_config_, error);
    return error;
  }
  for (const auto& file : files) {
    by_file_[file] = &load(discover(file).string(), error);
    if (error) return error;
  }
  if (files.empty()) load("", error);
  return error;
}

const Settings& SettingsResolver::for_file(const std::string& path) {
  std::lock_guard lock(mutex_);
  if (auto it = by_file_.find(path); it != by_file_.end()) return *it->second;
  std::optional<ConfigError> ignored;  // prepare() reported it
  return load(explicit_config_ ? *explicit_config_ : discover(path).string(), ignored);
}

std::function<const Settings&(const std::string&)> SettingsResolver::as_function() {
  return [this](const std::string& path) -> const Settings& { return for_file(path); };
}

const FileSelection& SettingsResolver::file_selection_for(const std::string& path) {
  const std::string config_path = explicit_config_ ? *explicit_config_ : discover(path).string();
  std::lock_guard lock(mutex_);
  if (auto it = selections_.find(config_path); it != selections_.end()) return it->second;
  std::optional<FileSelectionConfig> config;
  if (!config_path.empty()) {
    config.emplace();
    Settings unused;
    config::load(config_path, unused, "", &*config);  // an invalid file was reported by prepare()
  }
  return selections_.emplace(config_path, effective_file_selection(config, overrides_.files, overrides_.working_directory))
      .first->second;
}

}  // namespace assetlint::config
