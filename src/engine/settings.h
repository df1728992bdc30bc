#pragma once
// Everything a run is configured with: which rules, their options and severities.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/diagnostic.h"

namespace assetlint {

// Rule selection with globs (`mimic-*`): a rule runs when it matches a select
// pattern (all rules when there is none) and no ignore pattern.
struct RuleSelection {
  std::vector<std::string> select;
  std::vector<std::string> ignore;
  // Where each pattern was set ("asset-lint.toml:3", "--extend-ignore"), for --show-settings;
  // the first place a pattern was given wins.
  std::map<std::string, std::string, std::less<>> select_origins, ignore_origins;
  bool enabled(std::string_view rule_id) const;
};

bool glob_match(std::string_view pattern, std::string_view text);

// A value from configuration with where it was set ("asset-lint.toml:12", "--position-iterations").
template <typename T>
struct Configured {
  T value{};
  std::string origin;
};

struct SimulationSettings {
  std::optional<Configured<double>> timesteps_per_second;
  std::optional<Configured<double>> position_iterations;
  std::optional<Configured<double>> velocity_iterations;
  std::optional<Configured<std::string>> solver;  // "TGS" or "PGS"
};

// The gripper's spec sheet, from which the guide derives force and velocity limits.
struct GripperSpec {
  std::optional<Configured<double>> payload_kg;
  std::optional<Configured<double>> friction;
  std::optional<Configured<double>> lever_arm_m;
  Configured<double> gravity{9.81, "default"};
  std::optional<Configured<double>> finger_speed_m_s;
  std::optional<Configured<double>> stroke_m;
  Configured<double> target_delta_deg{5.0, "default"};
  // Round the per-joint torque up to a multiple of this many N·m (the guide: 3.33 → 4);
  // unset = no rounding. `tune --torque-margin` overrides it.
  std::optional<Configured<double>> torque_margin;
  std::optional<Configured<std::string>> driven_joint;
};

// The pass thresholds of `asset-lint verify` (docs/verify.md), each with where it was set.
struct VerifySettings {
  Configured<double> close_time_under{0.20, "default"};  // fraction of the spec's close time it may be faster
  Configured<double> close_time_over{0.25, "default"};   // fraction it may be slower
  Configured<double> peak_penetration_m{0.002, "default"};
  Configured<double> steady_penetration_m{0.001, "default"};
  Configured<double> slip_m{0.005, "default"};
  Configured<double> jitter_m_s{0.001, "default"};
  Configured<double> window_s{1.0, "default"};  // the steady period judged at the end of each scene
  // [verify.drives]: the drive tests of every actuated joint (docs/verify.md). Defaults are
  // SimReady's published ones where it has one; lengths for prismatic joints are asset-lint's.
  struct Drives {
    Configured<double> overshoot{0.5, "default (SimReady)"};        // fraction of the step
    Configured<double> settle_band{0.05, "default (SimReady)"};     // fraction of the step
    Configured<double> settle_time_s{5.0, "default (SimReady)"};
    Configured<double> sign_changes{20, "default (SimReady)"};      // velocity sign changes after the first peak
    Configured<double> sweep_return_rad{0.01, "default (SimReady)"};
    Configured<double> sweep_end_rad{0.1, "default (SimReady)"};
    Configured<double> sweep_return_m{0.001, "default"};
    Configured<double> sweep_end_m{0.01, "default"};
    Configured<double> velocity_over{0.05, "default (SimReady)"};   // fraction over the max joint velocity
    Configured<double> droop_rad{0.1, "default"};                   // static droop at the start pose
    Configured<double> droop_m{0.01, "default"};
    Configured<double> mimic_error_rad{0.01, "default"};
    Configured<double> mimic_error_m{0.001, "default"};
  } drives;
};

// Drive gains for formats that carry none (URDF), as an importer or actuator config sets them.
// PhysX units: N·m/rad, N·m·s/rad, kg·m², N·m (N/m, N·s/m, kg, N for prismatic joints).
struct DriveSettings {
  std::optional<Configured<double>> stiffness;
  std::optional<Configured<double>> damping;
  std::optional<Configured<double>> armature;
  std::optional<Configured<double>> max_force;
  std::optional<Configured<double>> max_velocity;   // PhysX's max joint velocity, rad/s (m/s)
  std::optional<Configured<double>> rotor_inertia;  // motor datasheet, kg·m²: justifies armature
  std::optional<Configured<double>> gear_ratio;
  std::optional<Configured<std::string>> type;  // "force" or "acceleration"
  std::string origin;                            // the [drives.<joint>] table
};

// per-file-ignores: rules skipped for files matching a path glob (relative to the
// configuration file's directory).
struct PerFileIgnore {
  std::string glob;
  std::vector<std::string> rules;
  std::string origin;  // "asset-lint.toml:12"
};

// [xacro] and --xacro-arg: the values of xacro arguments ($(arg name)).
struct XacroSettings {
  std::map<std::string, Configured<std::string>, std::less<>> args;
};

// [usd] and --variant: variant selections that replace the authored ones when a stage is
// composed (set name -> variant name); such a set is checked in that selection only.
struct UsdSettings {
  std::map<std::string, Configured<std::string>, std::less<>> variants;
};

// A MuJoCo release, major.minor.
struct MujocoVersion {
  int major = 3;
  int minor = 15;
};

// "3.15" or "3.15.0" (the patch is accepted and ignored); nothing when the text is no version.
std::optional<MujocoVersion> parse_mujoco_version(std::string_view text);

// [mujoco]: the MuJoCo an MJCF model is judged for. The default, "3.15", stands for 3.15 and
// later; "3.3" to "3.14" select what those releases compile differently (physics/dampratio.h).
struct MujocoSettings {
  Configured<std::string> version{"3.15", "default"};
  MujocoVersion parsed() const { return parse_mujoco_version(version.value).value_or(MujocoVersion{}); }
};

// [targets] consumers and --target: the programs the asset is judged for, as written
// ("mujoco@3.3", "gazebo@dart", "isaac-sim@6.1"; engine/consumers.h reads them). Empty: every
// consumer the file's format is commonly loaded by.
struct TargetSettings {
  std::vector<Configured<std::string>> consumers;
};

struct Settings {
  RuleSelection selection;
  TargetSettings targets;
  XacroSettings xacro;
  UsdSettings usd;
  MujocoSettings mujoco;
  std::vector<PerFileIgnore> per_file_ignores;
  SimulationSettings simulation;
  GripperSpec gripper;
  VerifySettings verify;
  std::map<std::string, DriveSettings, std::less<>> drives;
  std::string config_path;  // the asset-lint.toml in effect; empty when none
  // The checked tree, whose files composed USD layers may read (config/project_root.h):
  // `root` when set (--root), else the file's git work tree, else the directory of its
  // asset-lint.toml, else the deepest of `trees` (the directories named on the command
  // line and the working directory) that holds it.
  std::string root;
  std::vector<std::string> trees;
  bool allow_outside_root = false;
  std::map<std::string, Severity, std::less<>> severity_overrides;
  std::map<std::string, std::map<std::string, double, std::less<>>, std::less<>> rule_options;
  // Where each `[rules.<id>]` key was set ("asset-lint.toml:12"), keyed "<id>.<key>".
  std::map<std::string, std::string, std::less<>> rule_setting_origins;

  std::optional<double> rule_option(std::string_view rule, std::string_view option) const;
  Severity severity_for(std::string_view rule, Severity default_severity) const;
};

}  // namespace assetlint
