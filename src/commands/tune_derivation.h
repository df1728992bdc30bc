#pragma once
// The guide's drive derivation for one joint, step by step (docs/tune.md): each step
// names its formula, its inputs with where each came from, and its result. The numbers
// come from src/physics; this file only orders them and records their origins.
#include <optional>
#include <string>
#include <vector>

#include "engine/settings.h"
#include "formats/read_result.h"
#include "model/asset.h"

namespace assetlint::commands {

// An input of a step: a number with its unit (SI/PhysX) and its origin: the asset
// ("robot.urdf:57"), the configuration ("asset-lint.toml:4"), a flag ("--payload-kg"),
// a documented default ("default"), or an earlier step ("step 1").
struct TuneInput {
  std::string symbol;  // "m"
  std::string what;    // "payload"
  double value = 0;
  std::string unit;
  std::string origin;
  std::string as_written;  // how the asset writes it, when that differs ("47 deg")
};

// An input nobody supplied: the configuration key and the flag that would.
struct TuneMissing {
  std::string what;  // "payload"
  std::string key;   // "[gripper] payload_kg"
  std::string flag;  // "--payload-kg" (empty: no flag)
};

struct TuneResult {
  double value = 0;
  std::string unit;
  // The value to author in USD when its unit differs (per degree): 4.8 N·m/deg.
  std::optional<double> usd_value;
  std::string usd_unit;
};

struct TuneStep {
  std::string name;     // "grip_force": JSON key
  std::string title;    // "grip force"
  std::string formula;  // "F = m·g / μ"
  std::vector<TuneInput> inputs;
  std::vector<TuneMissing> missing;  // non-empty: no result
  std::optional<TuneResult> result;
  std::vector<std::string> notes;    // full sentences: rounding, comparisons, verdicts
};

// The spec inputs given on the command line; each wins over [gripper] (and, for the
// rate and iterations, over the stage).
struct SpecFlags {
  std::optional<double> payload_kg, friction, lever_arm_m, gravity, finger_speed_m_s, stroke_m, target_delta_deg,
      torque_margin, rate, position_iterations;
};
// `settings` with the flags' values in [gripper] and [simulation], each named by its flag.
Settings with_spec_flags(Settings settings, const SpecFlags& flags);

// The values the derivation recommends, in model units (what --apply writes).
struct TuneRecommendation {
  std::optional<double> max_force;     // N·m (N)
  std::optional<double> max_velocity;  // rad/s (m/s)
  std::optional<double> stiffness;     // N·m/rad (N/m)
  std::optional<double> damping;       // N·m·s/rad (N·s/m)
};

struct TuneDerivation {
  std::string path;
  const Joint* joint = nullptr;
  std::vector<const Joint*> mimics;  // the joints it moves through mimics
  std::string simulation;            // "TGS, 250 Hz (…) × 64 position iterations (…)"
  std::vector<TuneStep> steps;
  // Flat numbers (docs/tune.md lists the keys); nullopt where an input is missing.
  std::vector<std::pair<std::string, std::optional<double>>> summary;
  TuneRecommendation recommended;
};

// Which joint to tune: `requested` when given, else [gripper] driven_joint, else the
// only non-mimic single-DOF joint with a drive (else the only such joint at all). On
// failure, nullptr and one line saying why (unknown name, a mimic, ambiguous: the
// candidates listed). `joint_flag`: the option of the calling command that names a joint
// ("--joint"), or nullptr for a command without one: the message then names only
// [gripper] driven_joint, so it never suggests an option the command rejects.
const Joint* tune_joint(const Asset& asset, const Settings& settings, const std::optional<std::string>& requested,
                        std::string& error, const char* joint_flag = "--joint");

// Walks the guide's steps for `joint` (settings already carry the flags); values of a xacro
// file's expansion are shown at their place in the xacro source.
TuneDerivation derive(const std::string& path, const ReadResult& read, const Settings& settings, const Joint& joint);

}  // namespace assetlint::commands
