#include "commands/tune.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "commands/command_input.h"
#include "commands/tune_apply.h"
#include "commands/tune_derivation.h"
#include "commands/tune_report.h"

namespace assetlint::commands {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitError = 2;

struct SpecFlag {
  const char* name;
  const char* help;
  std::optional<double> SpecFlags::*field;
  bool integer = false;
};

constexpr SpecFlag kSpecFlags[] = {
    {"--payload-kg", "Payload the gripper must hold, kg ([gripper] payload_kg)", &SpecFlags::payload_kg},
    {"--friction", "Friction coefficient between fingers and payload ([gripper] friction)", &SpecFlags::friction},
    {"--lever-arm-m", "Lever arm from the joint to the finger pad, m ([gripper] lever_arm_m)", &SpecFlags::lever_arm_m},
    {"--gravity", "Gravity, m/s² ([gripper] gravity; default 9.81, the guide uses 10)", &SpecFlags::gravity},
    {"--finger-speed-m-s", "Finger speed from the spec, m/s ([gripper] finger_speed_m_s)", &SpecFlags::finger_speed_m_s},
    {"--stroke-m", "Opening between the fingers, m ([gripper] stroke_m)", &SpecFlags::stroke_m},
    {"--target-delta-deg", "Target delta where the max force must still be reached, degrees ([gripper] target_delta_deg)",
     &SpecFlags::target_delta_deg},
    {"--torque-margin", "Round the per-joint torque up to a multiple of this, N·m ([gripper] torque_margin)",
     &SpecFlags::torque_margin},
    {"--rate", "Simulation rate, steps per second (wins over the stage and [simulation])", &SpecFlags::rate},
    {"--position-iterations", "Solver position iterations, 1 to 255 (wins over the stage and [simulation])",
     &SpecFlags::position_iterations, true},
};

}  // namespace

int run_tune(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"asset-lint tune: derives a joint drive from the gripper's spec, step by step, as NVIDIA's tuning "
               "guide does",
               "asset-lint tune"};
  std::string path;
  std::optional<std::string> joint, config;
  std::string format = "text";
  bool apply = false, diff = false;
  std::vector<std::string> flag_text(std::size(kSpecFlags));
  app.add_option("asset", path, "The .urdf, .xacro, .usda or MJCF .xml file")->required();
  app.add_option("--joint", joint, "The driven joint (default: [gripper] driven_joint, else the only driven joint)");
  for (std::size_t i = 0; i < std::size(kSpecFlags); ++i) app.add_option(kSpecFlags[i].name, flag_text[i], kSpecFlags[i].help);
  app.add_option("--config", config, "Use this asset-lint.toml (default: the nearest one above the asset)");
  app.add_option("--output-format", format, "text or json")->check(CLI::IsMember({"text", "json"}));
  app.add_flag("--apply", apply, "Write the recommended max force, max velocity, stiffness and damping");
  app.add_flag("--diff", diff, "Print what --apply would change as a unified diff; write nothing");
  CompositionScope scope;
  add_scope_options(app, scope);
  if (auto status = parse_command(app, args, "tune", out, err)) return *status;

  SpecFlags flags;
  for (std::size_t i = 0; i < std::size(kSpecFlags); ++i) {
    if (!app.count(kSpecFlags[i].name)) continue;
    std::string error;
    auto value = positive_flag(kSpecFlags[i].name, flag_text[i], error);
    if (value && kSpecFlags[i].integer && (*value != std::floor(*value) || *value > 255)) {
      error = fmt::format("{} must be a whole number from 1 to 255, got '{}'", kSpecFlags[i].name, flag_text[i]);
      value.reset();
    }
    if (!value) {
      err << "asset-lint tune: error: " << error << "\n";
      return kExitError;
    }
    flags.*(kSpecFlags[i].field) = *value;
  }

  CommandAsset input = load_command_asset(path, config, scope);
  if (input.error) {
    err << "asset-lint tune: error: " << *input.error << "\n";
    return kExitError;
  }
  const Settings settings = with_spec_flags(input.settings, flags);
  const Asset& asset = input.loaded.read.asset;
  std::string error;
  const Joint* tuned = tune_joint(asset, settings, joint, error);
  if (!tuned) {
    err << fmt::format("asset-lint tune: error: {}: {}\n", path, error);
    return kExitError;
  }
  const TuneDerivation derivation = derive(path, input.loaded.read, settings, *tuned);
  if (diff || apply) {
    // --diff prints only the diff; --apply prints the derivation, then what it wrote.
    if (!diff) {
      if (format == "json") write_tune_json(out, derivation);
      else write_tune_text(out, derivation);
    }
    return carry_out(plan_tune_apply(derivation, input.loaded.read, settings, config), diff, out, err);
  }
  if (format == "json") write_tune_json(out, derivation);
  else write_tune_text(out, derivation);
  return kExitOk;
}

}  // namespace assetlint::commands
