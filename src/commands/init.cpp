#include "commands/init.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "commands/exit_status.h"
#include "config/config.h"
#include "physics/gripper.h"
#include "pipeline/discovery.h"
#include "pipeline/lint.h"
#include "util/numbers.h"

namespace assetlint::commands {
namespace {

namespace fs = std::filesystem;

// What the assets say about the keys init writes.
struct Survey {
  std::size_t assets = 0;
  std::vector<std::string> unreadable;
  std::map<std::string, std::vector<std::string>> rates, iterations;  // value → "file:line"
  std::map<std::string, std::vector<std::string>> grippers;           // driven joint → files
  std::map<std::string, std::string> followers;                       // driven joint → its mimics
};

std::string where(const Asset& asset, const std::string& file, const Span& span) {
  if (!span.valid() || span.file >= asset.sources.size() || span.file != 0) return file;
  return fmt::format("{}:{}", file, span.line);
}

Survey survey(const std::vector<std::string>& files) {
  Survey s;
  for (const std::string& file : files) {
    LoadedAsset loaded = load_model(file, Settings{});
    if (loaded.error || !loaded.read.usable) {
      s.unreadable.push_back(file);
      continue;
    }
    ++s.assets;
    const Asset& asset = loaded.read.asset;
    if (const auto& rate = asset.scene.timesteps_per_second)
      s.rates[format_number(rate->value)].push_back(where(asset, file, rate->span));
    if (const auto& count = asset.scene.position_iterations)
      s.iterations[format_number(count->value)].push_back(where(asset, file, count->span));
    for (const Joint& joint : asset.joints) {
      if (joint.is_mimic() || !physics::drives_gripper(asset, joint)) continue;
      s.grippers[joint.name.text].push_back(file);
      std::string names;
      for (const Joint* follower : asset.mimic_followers(joint.name.text))
        names += (names.empty() ? "" : ", ") + follower->name.text;
      s.followers[joint.name.text] = names;
    }
  }
  return s;
}

// `key = value  # why`, or the key commented out with PhysX's default when the assets disagree
// or say nothing.
std::string simulation_key(const std::string& key, const std::map<std::string, std::vector<std::string>>& found,
                           const char* fallback, const char* meaning) {
  if (found.size() == 1)
    return fmt::format("{} = {}   # {}: as {} authors it\n", key, found.begin()->first, meaning,
                       found.begin()->second.front());
  std::string text = fmt::format("# {} = {}   # {}: PhysX's default; set the one your simulation uses\n", key, fallback,
                                 meaning);
  for (const auto& [value, places] : found) text += fmt::format("#   {} authors {}\n", places.front(), value);
  return text;
}

std::string configuration(const std::string& dir, const Survey& s) {
  std::string text = fmt::format(
      "# asset-lint.toml for the {} asset{} in {} (written by `asset-lint init`).\n"
      "# Every key: docs/configuration.md. What a check of a file uses, and where each value\n"
      "# came from: asset-lint --show-settings FILE\n\n",
      s.assets, s.assets == 1 ? "" : "s", dir);
  text +=
      "[simulation]\n"
      "# The rate the drive rules judge against, for files that author none (URDF, xacro); a USD\n"
      "# stage's or MJCF model's own rate wins for that file.\n";
  text += simulation_key("timesteps_per_second", s.rates, "60", "steps per second");
  text += simulation_key("position_iterations", s.iterations, "32", "solver position iterations");
  text += "\n[gripper]\n";
  if (s.grippers.size() == 1) {
    const auto& [joint, files] = *s.grippers.begin();
    text += fmt::format("driven_joint = \"{}\"   # its mimics: {} ({})\n", joint, s.followers.at(joint),
                        files.front());
  } else if (s.grippers.empty()) {
    text += "# No joint drives mimic fingers in these assets: name the gripper's driven joint if there is one.\n"
            "# driven_joint = \"\"\n";
  } else {
    text += "# Several joints drive mimic fingers; the spec below is about one of them:\n";
    for (const auto& [joint, files] : s.grippers)
      text += fmt::format("# driven_joint = \"{}\"   # its mimics: {} ({})\n", joint, s.followers.at(joint),
                          files.front());
  }
  text +=
      "# The spec sheet: fill these in from the gripper's datasheet. The drive rules and `tune`\n"
      "# derive the drive's force, speed and gains from them; until then they do not judge those.\n"
      "# payload_kg = 5          # the payload the gripper must hold, kg\n"
      "# friction = 0.3          # friction coefficient between the pads and the payload\n"
      "# lever_arm_m = 0.04      # from the driven joint to the finger pad, m\n"
      "# finger_speed_m_s = 0.15 # the fingers' top speed, m/s\n"
      "# stroke_m = 0.085        # between the fully open fingers, m\n"
      "# gravity = 9.81          # m/s²\n";
  return text;
}

}  // namespace

int run_init(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  constexpr const char* kUsage =
      "usage: asset-lint init [DIR]   write DIR/asset-lint.toml (default: .) for the assets found there\n";
  if (args.size() == 1 && (args[0] == "--help" || args[0] == "-h")) {
    out << kUsage;
    return kExitClean;
  }
  if (args.size() > 1 || (args.size() == 1 && args[0].starts_with("-"))) {
    err << "asset-lint: error: " << kUsage;
    return kExitError;
  }
  const std::string dir = args.empty() ? "." : args[0];
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    err << fmt::format("asset-lint: error: '{}' is not a directory\n", dir);
    return kExitError;
  }
  const fs::path target = fs::path(dir) / config::kFileName;
  if (fs::exists(target, ec)) {
    err << fmt::format("asset-lint: error: '{}' exists; init does not overwrite it (`asset-lint --show-settings "
                       "FILE` shows what it sets)\n",
                       target.lexically_normal().string());
    return kExitError;
  }
  const PathExpansion expansion = expand_paths({dir});
  const Survey found = survey(expansion.files);
  if (found.assets == 0) {
    err << fmt::format("asset-lint: error: no asset in '{}' could be read; nothing written\n", dir);
    return kExitError;
  }
  std::ofstream file(target, std::ios::binary | std::ios::trunc);
  file << configuration(dir, found);
  if (!file.flush()) {
    err << fmt::format("asset-lint: error: cannot write '{}'\n", target.string());
    return kExitError;
  }
  err << fmt::format("asset-lint: wrote {} for {} asset{}{}\n", target.lexically_normal().string(), found.assets,
                     found.assets == 1 ? "" : "s",
                     found.grippers.size() == 1 ? fmt::format(" (driven joint '{}')", found.grippers.begin()->first)
                                                : std::string());
  for (const std::string& path : found.unreadable)
    err << fmt::format("asset-lint: note: '{}' could not be read as a model; not surveyed\n", path);
  return kExitClean;
}

}  // namespace assetlint::commands
