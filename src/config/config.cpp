#include "config/config.h"

#include <fmt/format.h>

#include <toml++/toml.h>

#include <algorithm>

#include "engine/consumers.h"
#include "rules/registry.h"

namespace assetlint::config {
namespace {

// Thrown inside the loader; turned into a ConfigError at the top.
struct Invalid {
  toml::source_region where;
  std::string message;
};

class Loader {
 public:
  Loader(std::string path, Settings& settings, FileSelectionConfig* files, std::filesystem::path base)
      : files_(files), base_(std::move(base)), path_(std::move(path)), settings_(settings) {}

  void load(const toml::table& root) {
    for (const auto& [key, node] : root) {
      const std::string_view name = key.str();
      if (name == "select") set_patterns(settings_.selection, true, rule_patterns(node, name));
      else if (name == "ignore") set_patterns(settings_.selection, false, rule_patterns(node, name));
      else if (name == "extend-select") append(extend_select_, rule_patterns(node, name));
      else if (name == "extend-ignore") append(extend_ignore_, rule_patterns(node, name));
      else if (name == "per-file-ignores" || name == "extend-per-file-ignores") per_file_ignores(table(node, name), name);
      else if (name == "exclude" || name == "extend-exclude" || name == "respect-gitignore") file_selection(node, name);
      else if (name == "simulation") simulation(table(node, name));
      else if (name == "gripper") gripper(table(node, name));
      else if (name == "verify") verify(table(node, name));
      else if (name == "drives") drives(table(node, name));
      else if (name == "rules") rules(table(node, name));
      else if (name == "xacro") xacro(table(node, name));
      else if (name == "usd") usd(table(node, name));
      else if (name == "mujoco") mujoco(table(node, name));
      else if (name == "targets") targets(table(node, name));
      else unknown(key, "");
    }
    // After the loop: `extend-select` adds to `select` wherever the two stand in the file.
    extend(settings_.selection, true, extend_select_);
    extend(settings_.selection, false, extend_ignore_);
  }

 private:
  RulePatterns extend_select_, extend_ignore_;
  FileSelectionConfig* files_;  // read only when asked for (nullptr: validated, not kept)
  std::filesystem::path base_;  // the configuration's directory, absolute

  std::string origin(const toml::node& node) const {
    return fmt::format("{}:{}", path_, node.source().begin.line);
  }

  [[noreturn]] void fail(const toml::node& node, std::string message) const { throw Invalid{node.source(), std::move(message)}; }

  // Points at the key itself, not its value.
  [[noreturn]] void unknown(const toml::key& key, std::string_view table_name) const {
    throw Invalid{key.source(), table_name.empty() ? fmt::format("unknown key '{}'", key.str())
                                                   : fmt::format("unknown key '{}' in [{}]", key.str(), table_name)};
  }

  const toml::table& table(const toml::node& node, std::string_view name) const {
    if (const auto* t = node.as_table()) return *t;
    fail(node, fmt::format("'{}' must be a table", name));
  }

  double number(const toml::node& node, std::string_view key, double min, bool min_exclusive) const {
    std::optional<double> value;
    if (const auto* i = node.as_integer()) value = static_cast<double>(i->get());
    else if (const auto* f = node.as_floating_point()) value = f->get();
    if (!value) fail(node, fmt::format("'{}' must be a number", key));
    if (*value < min || (min_exclusive && *value == min) || std::isnan(*value))
      fail(node, fmt::format("'{}' must be {} {}, got {}", key, min_exclusive ? ">" : "≥", min, *value));
    return *value;
  }

  std::optional<Configured<double>> positive(const toml::node& node, std::string_view key) const {
    return Configured<double>{number(node, key, 0.0, true), origin(node)};
  }
  std::optional<Configured<double>> non_negative(const toml::node& node, std::string_view key) const {
    return Configured<double>{number(node, key, 0.0, false), origin(node)};
  }

  std::string string(const toml::node& node, std::string_view key) const {
    if (const auto* s = node.as_string()) return s->get();
    fail(node, fmt::format("'{}' must be a string", key));
  }

  std::string choice(const toml::node& node, std::string_view key, std::initializer_list<std::string_view> allowed) const {
    std::string value = string(node, key);
    for (auto a : allowed)
      if (value == a) return value;
    std::string list;
    for (auto a : allowed) list += (list.empty() ? "" : ", ") + fmt::format("\"{}\"", a);
    fail(node, fmt::format("'{}' must be one of {}, got \"{}\"", key, list, value));
  }

  RulePatterns rule_patterns(const toml::node& node, std::string_view key) const {
    const auto* array = node.as_array();
    if (!array) fail(node, fmt::format("'{}' must be an array of rule ids or globs", key));
    RulePatterns patterns;
    for (const auto& item : *array) {
      std::string pattern = string(item, key);
      bool matched = false;
      for (const RuleInfo* rule : rules::catalog()) matched = matched || glob_match(pattern, rule->id);
      if (!matched) fail(item, fmt::format("'{}' matches no rule", pattern));
      patterns.push_back({std::move(pattern), origin(item)});
    }
    return patterns;
  }

  // exclude = ["vendor", "robots/old/**"], extend-exclude = [...], respect-gitignore = false
  void file_selection(const toml::node& node, std::string_view key) {
    FileSelectionConfig ignored;
    FileSelectionConfig& files = files_ ? *files_ : ignored;
    if (key == "respect-gitignore") {
      const auto* flag = node.as_boolean();
      if (!flag) fail(node, "'respect-gitignore' must be true or false");
      files.respect_gitignore = Configured<bool>{flag->get(), origin(node)};
      return;
    }
    const auto* array = node.as_array();
    if (!array) fail(node, fmt::format("'{}' must be an array of path globs", key));
    std::vector<ExcludePattern> patterns;
    for (const auto& item : *array) {
      std::string glob = string(item, key);
      if (glob.empty()) fail(item, fmt::format("'{}': a glob is empty", key));
      patterns.push_back({std::move(glob), base_.string(), origin(item)});
    }
    if (key == "exclude") files.exclude = std::move(patterns);
    else files.extend_exclude = std::move(patterns);
  }

  static void append(RulePatterns& to, RulePatterns more) {
    to.insert(to.end(), std::make_move_iterator(more.begin()), std::make_move_iterator(more.end()));
  }

  // per-file-ignores = { "legacy/**" = ["units-*"], "*.usda" = ["stale-schema-attribute"] }
  // (extend-per-file-ignores adds entries the same way).
  void per_file_ignores(const toml::table& t, std::string_view table_name) {
    for (const auto& [glob, node] : t) {
      if (glob.str().empty()) fail(node, fmt::format("{}: the file glob is empty", table_name));
      PerFileIgnore entry;
      entry.glob = std::string(glob.str());
      for (auto& rule : rule_patterns(node, fmt::format("{}.\"{}\"", table_name, glob.str())))
        entry.rules.push_back(std::move(rule.value));
      entry.origin = origin(node);
      settings_.per_file_ignores.push_back(std::move(entry));
    }
  }

  // [xacro] args = { name = "value" }, entry_points = ["robot.urdf.xacro"]
  void xacro(const toml::table& t) {
    for (const auto& [key, node] : t) {
      const std::string_view k = key.str();
      if (k == "args") {
        for (const auto& [arg, value] : table(node, "args")) {
          if (const auto* s = value.as_string()) settings_.xacro.args[std::string(arg.str())] = Configured<std::string>{s->get(), origin(value)};
          else if (const auto* b = value.as_boolean()) settings_.xacro.args[std::string(arg.str())] = Configured<std::string>{b->get() ? "true" : "false", origin(value)};
          else if (value.is_number()) settings_.xacro.args[std::string(arg.str())] = Configured<std::string>{value.is_integer() ? std::to_string(value.as_integer()->get()) : fmt::format("{}", value.as_floating_point()->get()), origin(value)};
          else fail(value, fmt::format("xacro argument '{}' must be a string, number or boolean", arg.str()));
        }
      } else if (k == "entry_points") {
        const auto* array = node.as_array();
        if (!array) fail(node, "'entry_points' must be an array of .xacro paths");
        std::vector<std::string> paths;
        for (const auto& item : *array) paths.push_back((base_ / string(item, "entry_points")).lexically_normal().string());
        if (files_) files_->xacro_entry_points = std::move(paths);
      } else {
        unknown(key, "xacro");
      }
    }
  }

  // [usd] variants = { PhysX = "Enabled" }
  void usd(const toml::table& t) {
    for (const auto& [key, node] : t) {
      if (key.str() != "variants") unknown(key, "usd");
      for (const auto& [set, value] : table(node, "variants")) {
        if (set.str().empty()) fail(value, "[usd] variants: a variant set name is empty");
        const std::string variant = string(value, fmt::format("variants.{}", set.str()));
        if (variant.empty()) fail(value, fmt::format("[usd] variants: the variant of '{}' is empty", set.str()));
        settings_.usd.variants[std::string(set.str())] = Configured<std::string>{variant, origin(value)};
      }
    }
  }

  // [targets] consumers = ["isaac-sim@6.1", "mujoco@3.12", "gazebo@dart"]
  void targets(const toml::table& t) {
    for (const auto& [key, node] : t) {
      if (key.str() != "consumers") unknown(key, "targets");
      const auto* array = node.as_array();
      if (!array) fail(node, "[targets] consumers must be an array of names such as [\"isaac-sim\", \"mujoco@3.12\"]");
      std::vector<Configured<std::string>> consumers;
      for (const auto& item : *array) {
        const std::string text = string(item, "consumers");
        std::string error;
        if (!parse_consumer(text, error)) fail(item, fmt::format("[targets] consumers: {}", error));
        consumers.push_back(Configured<std::string>{text, origin(item)});
      }
      settings_.targets.consumers = std::move(consumers);
    }
  }

  // [mujoco] version = "3.15"
  void mujoco(const toml::table& t) {
    for (const auto& [key, node] : t) {
      if (key.str() != "version") unknown(key, "mujoco");
      if (!node.is_string())
        fail(node, "[mujoco] version must be a string such as \"3.15\" (a number cannot tell 3.1 from 3.10)");
      const std::string text = node.as_string()->get();
      const auto version = parse_mujoco_version(text);
      if (!version) fail(node, fmt::format("[mujoco] version '{}' is not a MuJoCo release such as \"3.15\"", text));
      if (std::make_pair(version->major, version->minor) < std::make_pair(3, 3))
        fail(node, fmt::format("[mujoco] version '{}': asset-lint models MuJoCo 3.3 and later", text));
      settings_.mujoco.version = Configured<std::string>{text, origin(node)};
    }
  }

  void simulation(const toml::table& t) {
    for (const auto& [key, node] : t) {
      const std::string_view k = key.str();
      if (k == "timesteps_per_second") settings_.simulation.timesteps_per_second = positive(node, k);
      else if (k == "position_iterations") {
        const double n = number(node, k, 1.0, false);
        if (n != std::floor(n) || n > 255) fail(node, "'position_iterations' must be a whole number from 1 to 255");
        settings_.simulation.position_iterations = Configured<double>{n, origin(node)};
      } else if (k == "velocity_iterations") {
        const double n = number(node, k, 0.0, false);
        if (n != std::floor(n) || n > 255) fail(node, "'velocity_iterations' must be a whole number from 0 to 255");
        settings_.simulation.velocity_iterations = Configured<double>{n, origin(node)};
      } else if (k == "solver") settings_.simulation.solver = Configured<std::string>{choice(node, k, {"TGS", "PGS"}), origin(node)};
      else unknown(key, "simulation");
    }
  }

  void gripper(const toml::table& t) {
    GripperSpec& g = settings_.gripper;
    for (const auto& [key, node] : t) {
      const std::string_view k = key.str();
      if (k == "payload_kg") g.payload_kg = positive(node, k);
      else if (k == "friction") g.friction = positive(node, k);
      else if (k == "lever_arm_m") g.lever_arm_m = positive(node, k);
      else if (k == "gravity") g.gravity = *positive(node, k);
      else if (k == "finger_speed_m_s") g.finger_speed_m_s = positive(node, k);
      else if (k == "stroke_m") g.stroke_m = positive(node, k);
      else if (k == "target_delta_deg") g.target_delta_deg = *positive(node, k);
      else if (k == "torque_margin") g.torque_margin = positive(node, k);
      else if (k == "driven_joint") g.driven_joint = Configured<std::string>{string(node, k), origin(node)};
      else unknown(key, "gripper");
    }
  }

  void verify(const toml::table& t) {
    VerifySettings& v = settings_.verify;
    for (const auto& [key, node] : t) {
      const std::string_view k = key.str();
      if (k == "close_time_under") v.close_time_under = *positive(node, k);
      else if (k == "close_time_over") v.close_time_over = *positive(node, k);
      else if (k == "peak_penetration_m") v.peak_penetration_m = *positive(node, k);
      else if (k == "steady_penetration_m") v.steady_penetration_m = *positive(node, k);
      else if (k == "slip_m") v.slip_m = *positive(node, k);
      else if (k == "jitter_m_s") v.jitter_m_s = *positive(node, k);
      else if (k == "window_s") v.window_s = *positive(node, k);
      else if (k == "drives") verify_drives(table(node, "verify.drives"));
      else unknown(key, "verify");
    }
  }

  void verify_drives(const toml::table& t) {
    VerifySettings::Drives& d = settings_.verify.drives;
    const std::pair<std::string_view, Configured<double>*> keys[] = {
        {"overshoot", &d.overshoot},         {"settle_band", &d.settle_band},
        {"settle_time_s", &d.settle_time_s}, {"sign_changes", &d.sign_changes},
        {"sweep_return_rad", &d.sweep_return_rad}, {"sweep_end_rad", &d.sweep_end_rad},
        {"sweep_return_m", &d.sweep_return_m},     {"sweep_end_m", &d.sweep_end_m},
        {"velocity_over", &d.velocity_over}, {"droop_rad", &d.droop_rad},
        {"droop_m", &d.droop_m},             {"mimic_error_rad", &d.mimic_error_rad},
        {"mimic_error_m", &d.mimic_error_m}};
    for (const auto& [key, node] : t) {
      const std::string_view k = key.str();
      const auto* found = std::find_if(std::begin(keys), std::end(keys), [&](const auto& e) { return e.first == k; });
      if (found == std::end(keys)) unknown(key, "verify.drives");
      else *found->second = *positive(node, k);
    }
  }

  void drives(const toml::table& t) {
    for (const auto& [joint, node] : t) {
      const std::string table_name = fmt::format("drives.{}", joint.str());
      DriveSettings drive;
      drive.origin = origin(node);
      for (const auto& [key, value] : table(node, table_name)) {
        const std::string_view k = key.str();
        if (k == "stiffness") drive.stiffness = non_negative(value, k);
        else if (k == "damping") drive.damping = non_negative(value, k);
        else if (k == "armature") drive.armature = non_negative(value, k);
        else if (k == "max_force") drive.max_force = non_negative(value, k);
        else if (k == "max_velocity") drive.max_velocity = positive(value, k);
        else if (k == "rotor_inertia") drive.rotor_inertia = non_negative(value, k);
        else if (k == "gear_ratio") drive.gear_ratio = positive(value, k);
        else if (k == "type") drive.type = Configured<std::string>{choice(value, k, {"force", "acceleration"}), origin(value)};
        else unknown(key, table_name);
      }
      settings_.drives[std::string(joint.str())] = std::move(drive);
    }
  }

  void rules(const toml::table& t) {
    for (const auto& [id, node] : t) {
      const RuleInfo* rule = rules::find_rule(id.str());
      if (!rule) fail(node, fmt::format("unknown rule '{}' in [rules]", id.str()));
      const std::string table_name = fmt::format("rules.{}", id.str());
      for (const auto& [key, value] : table(node, table_name)) {
        const std::string_view k = key.str();
        settings_.rule_setting_origins[fmt::format("{}.{}", rule->id, k)] = origin(value);
        if (k == "severity") {
          settings_.severity_overrides[std::string(rule->id)] =
              *parse_severity(choice(value, k, {"info", "warning", "error"}));
          continue;
        }
        bool known = false;
        for (const auto& option : rule->options) known = known || option.name == k;
        if (!known) unknown(key, table_name);
        settings_.rule_options[std::string(rule->id)][std::string(k)] = number(value, k, -INFINITY, false);
      }
    }
  }

  std::string path_;
  Settings& settings_;
};

}  // namespace

std::string ConfigError::to_string() const {
  return line ? fmt::format("{}:{}:{}: {}", path, line, column, message) : fmt::format("{}: {}", path, message);
}

namespace {

void add_patterns(RuleSelection& selection, bool is_select, const RulePatterns& patterns) {
  auto& list = is_select ? selection.select : selection.ignore;
  auto& origins = is_select ? selection.select_origins : selection.ignore_origins;
  for (const auto& pattern : patterns) {
    list.push_back(pattern.value);
    origins.emplace(pattern.value, pattern.origin);
  }
}

}  // namespace

void set_patterns(RuleSelection& selection, bool is_select, const RulePatterns& patterns) {
  (is_select ? selection.select : selection.ignore).clear();
  (is_select ? selection.select_origins : selection.ignore_origins).clear();
  add_patterns(selection, is_select, patterns);
}

void extend(RuleSelection& selection, bool is_select, const RulePatterns& more) {
  if (more.empty()) return;
  if (is_select && selection.select.empty())
    add_patterns(selection, true, {{"*", "default (every rule), extended"}});
  add_patterns(selection, is_select, more);
}

RulePatterns patterns_from(const std::vector<std::string>& patterns, const std::string& origin) {
  RulePatterns out;
  for (const auto& pattern : patterns) out.push_back({pattern, origin});
  return out;
}

namespace {

template <class Parse>
std::optional<ConfigError> load_with(Parse parse, const std::string& path, Settings& settings,
                                     const std::string& display_path, FileSelectionConfig* files) {
  Settings updated = settings;
  try {
    toml::table root = parse();
    std::error_code ec;
    const std::filesystem::path base = std::filesystem::absolute(path, ec).lexically_normal().parent_path();
    Loader(display_path.empty() ? path : display_path, updated, files, base).load(root);
  } catch (const toml::parse_error& error) {
    return ConfigError{path, static_cast<std::uint32_t>(error.source().begin.line),
                       static_cast<std::uint32_t>(error.source().begin.column), std::string(error.description())};
  } catch (const Invalid& invalid) {
    return ConfigError{path, static_cast<std::uint32_t>(invalid.where.begin.line),
                       static_cast<std::uint32_t>(invalid.where.begin.column), invalid.message};
  }
  updated.config_path = path;
  settings = std::move(updated);
  return std::nullopt;
}

}  // namespace

std::optional<ConfigError> load(const std::string& path, Settings& settings, const std::string& display_path,
                                FileSelectionConfig* files) {
  return load_with([&] { return toml::parse_file(path); }, path, settings, display_path, files);
}

std::optional<ConfigError> load_text(std::string_view text, const std::string& path, Settings& settings,
                                     const std::string& display_path) {
  return load_with([&] { return toml::parse(text, path); }, path, settings, display_path, nullptr);
}

ConfigSearch search_config(const std::filesystem::path& file) {
  std::error_code ec;
  ConfigSearch search;
  search.first = std::filesystem::absolute(file, ec).parent_path();
  for (std::filesystem::path dir = search.first; !dir.empty(); dir = dir.parent_path()) {
    search.last = dir;
    const auto candidate = dir / kFileName;
    if (std::filesystem::is_regular_file(candidate, ec)) {
      // Shown in messages: relative to the working directory when it is below it.
      const auto relative = std::filesystem::relative(candidate, ec);
      search.found = !ec && !relative.empty() && *relative.begin() != ".." ? relative : candidate;
      return search;
    }
    // `.git` is a directory in a clone, a file in a linked work tree or a submodule.
    if (std::filesystem::exists(dir / ".git", ec)) {
      search.git_root = true;
      return search;
    }
    if (dir == dir.root_path()) break;
  }
  return search;
}

std::filesystem::path discover(const std::filesystem::path& file) { return search_config(file).found; }

}  // namespace assetlint::config
