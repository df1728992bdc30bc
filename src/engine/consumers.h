#pragma once
// The programs an asset is loaded by, and what each reads and ignores of what the file says.
// Rules consult this profile instead of branching on the file's format: a fact about Isaac
// Sim, MuJoCo, Newton, Gazebo or ros2_control lives here once, with its source in
// docs/consumers.md.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/settings.h"
#include "model/asset.h"

namespace assetlint {

enum class ConsumerKind { IsaacSim, IsaacLab, Mujoco, Newton, Gazebo, Ros2Control };

// A release, major.minor.
struct Release {
  int major = 0;
  int minor = 0;
  friend bool operator<(const Release& a, const Release& b) {
    return a.major != b.major ? a.major < b.major : a.minor < b.minor;
  }
};

// Gazebo's physics engine (gz-sim loads one gz-physics plugin; DART is its default).
enum class GazeboEngine { Dart, BulletFeatherstone, Bullet, Tpe };

struct Consumer {
  ConsumerKind kind = ConsumerKind::IsaacSim;
  // isaac-sim and mujoco: the release judged for. Isaac Sim without one stands for any
  // release (a fact of one release only is then not claimed); MuJoCo without one takes
  // [mujoco] version.
  std::optional<Release> release;
  // gazebo only: the gz-physics engine named; without one no engine's fact is claimed.
  std::optional<GazeboEngine> engine;
  std::string origin;                        // "--target", "asset-lint.toml:4", "default for URDF"

  // As written in --target and [targets]: "mujoco@3.12", "gazebo@bullet-featherstone".
  std::string name() const;
  // For messages: "MuJoCo 3.12", "Gazebo (DART)", "Isaac Sim 6.1", "ros2_control".
  std::string label() const;
  // Gazebo's physics engine for messages: "DART", "bullet-featherstone" ("" when unnamed).
  std::string_view engine_label() const;
  bool is(ConsumerKind k) const { return kind == k; }
  bool released_before(Release r) const { return release && *release < r; }
  bool release_is(Release r) const { return release && release->major == r.major && release->minor == r.minor; }
};

// "isaac-sim", "isaac-sim@6.1", "mujoco@3.12", "gazebo@dart", "ros2_control"; nullopt with
// `error` saying what is wrong (the names asset-lint knows, a release it does not model).
std::optional<Consumer> parse_consumer(std::string_view text, std::string& error);
// Every consumer name --target accepts, for help texts and errors.
std::string_view consumer_names();

struct ConsumerProfile {
  std::vector<Consumer> consumers;
  // Named by [targets] consumers or --target; false: the consumers the file's format is
  // commonly loaded by.
  bool configured = false;

  template <typename Predicate>
  bool any(Predicate predicate) const {
    for (const Consumer& c : consumers)
      if (predicate(c)) return true;
    return false;
  }
  // The labels of the consumers `predicate` holds for, in profile order.
  template <typename Predicate>
  std::vector<std::string> labels(Predicate predicate) const {
    std::vector<std::string> out;
    for (const Consumer& c : consumers)
      if (predicate(c)) out.push_back(c.label());
    return out;
  }
  const Consumer* find(ConsumerKind kind) const;
};

// The consumers a file of `format` is judged for: the configured targets, else the format's
// usual consumers (URDF: all six; USD: Isaac Sim, Isaac Lab, Newton; MJCF: MuJoCo, Newton).
ConsumerProfile consumer_profile(SourceFormat format, const Settings& settings);
// The consumers every file format defaults to, for --show-settings.
std::string default_consumers_text(SourceFormat format);
// "A", "A and B", "A, B and C".
std::string join_labels(const std::vector<std::string>& labels);

// ---- What each consumer does with what a file says (docs/consumers.md has the sources). ----

// Whether the consumer bounds a joint's speed by the file's max joint velocity. MJCF has no
// such attribute, so no consumer of an MJCF file reads one.
bool reads_max_joint_velocity(const Consumer& c, SourceFormat format);
// Whether the consumer couples a URDF <mimic> follower to its joint (MuJoCo's URDF importer
// from 3.13, Isaac's importers, Newton, Gazebo with bullet-featherstone; Gazebo without an
// engine named is not claimed to drop it).
bool couples_urdf_mimic(const Consumer& c);
// Whether the consumer's URDF import keeps <dynamics damping> and <dynamics friction>
// (Isaac Sim 6.1's importer drops both).
bool keeps_urdf_dynamics(const Consumer& c);
// Whether the consumer simulates with PhysX (omni.physx reading the USD).
bool simulates_with_physx(const Consumer& c);

}  // namespace assetlint
