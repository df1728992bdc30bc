#include "engine/consumers.h"

#include <fmt/format.h>

#include <array>
#include <charconv>

namespace assetlint {
namespace {

struct KindName {
  ConsumerKind kind;
  std::string_view name;
  std::string_view label;
};

constexpr std::array<KindName, 6> kKinds{{
    {ConsumerKind::IsaacSim, "isaac-sim", "Isaac Sim"},
    {ConsumerKind::IsaacLab, "isaac-lab", "Isaac Lab"},
    {ConsumerKind::Mujoco, "mujoco", "MuJoCo"},
    {ConsumerKind::Newton, "newton", "Newton"},
    {ConsumerKind::Gazebo, "gazebo", "Gazebo"},
    {ConsumerKind::Ros2Control, "ros2_control", "ros2_control"},
}};

struct EngineName {
  GazeboEngine engine;
  std::string_view name;
  std::string_view label;
};

constexpr std::array<EngineName, 4> kEngines{{
    {GazeboEngine::Dart, "dart", "DART"},
    {GazeboEngine::BulletFeatherstone, "bullet-featherstone", "bullet-featherstone"},
    {GazeboEngine::Bullet, "bullet", "Bullet"},
    {GazeboEngine::Tpe, "tpe", "TPE"},
}};

// The row of `table` whose `member` is `key` (every enum value has one; the first otherwise).
template <typename Entry, std::size_t N, typename Key>
const Entry& row(const std::array<Entry, N>& table, Key Entry::*member, Key key) {
  for (const Entry& entry : table)
    if (entry.*member == key) return entry;
  return table.front();
}

const KindName& kind_name(ConsumerKind kind) { return row(kKinds, &KindName::kind, kind); }
const EngineName& engine_name(GazeboEngine engine) { return row(kEngines, &EngineName::engine, engine); }

std::optional<Release> parse_release(std::string_view text) {
  Release r;
  const char* end = text.data() + text.size();
  auto [dot, error] = std::from_chars(text.data(), end, r.major);
  if (error != std::errc() || dot == end || *dot != '.') return std::nullopt;
  auto [rest, error2] = std::from_chars(dot + 1, end, r.minor);
  if (error2 != std::errc()) return std::nullopt;
  if (rest != end) {  // a patch number is accepted and ignored
    int patch = 0;
    if (*rest != '.' || std::from_chars(rest + 1, end, patch).ptr != end) return std::nullopt;
  }
  return r;
}

Consumer make(ConsumerKind kind, std::string origin) {
  Consumer c;
  c.kind = kind;
  c.origin = std::move(origin);
  return c;
}

}  // namespace

std::string Consumer::name() const {
  std::string out(kind_name(kind).name);
  if (release) out += fmt::format("@{}.{}", release->major, release->minor);
  if (engine) out += fmt::format("@{}", engine_name(*engine).name);
  return out;
}

std::string Consumer::label() const {
  std::string out(kind_name(kind).label);
  if (release) out += fmt::format(" {}.{}", release->major, release->minor);
  if (engine) out += fmt::format(" ({})", engine_name(*engine).label);
  return out;
}

std::string_view Consumer::engine_label() const { return engine ? engine_name(*engine).label : ""; }

std::string_view consumer_names() {
  return "isaac-sim[@MAJOR.MINOR], isaac-lab, mujoco[@MAJOR.MINOR], newton, "
         "gazebo[@dart|@bullet-featherstone|@bullet|@tpe], ros2_control";
}

std::optional<Consumer> parse_consumer(std::string_view text, std::string& error) {
  const std::size_t at = text.find('@');
  const std::string_view head = text.substr(0, at);
  const std::string_view tail = at == std::string_view::npos ? std::string_view() : text.substr(at + 1);
  const KindName* kind = nullptr;
  for (const KindName& k : kKinds)
    if (k.name == head) kind = &k;
  if (!kind) {
    error = fmt::format("unknown consumer '{}' (known: {})", text, consumer_names());
    return std::nullopt;
  }
  Consumer c = make(kind->kind, "");
  if (at == std::string_view::npos) return c;
  if (kind->kind == ConsumerKind::Gazebo) {
    for (const EngineName& e : kEngines)
      if (e.name == tail) {
        c.engine = e.engine;
        return c;
      }
    error = fmt::format("'{}': Gazebo's physics engine is one of dart, bullet-featherstone, bullet, tpe", text);
    return std::nullopt;
  }
  if (kind->kind != ConsumerKind::IsaacSim && kind->kind != ConsumerKind::Mujoco) {
    error = fmt::format("'{}': {} takes no version", text, kind->name);
    return std::nullopt;
  }
  c.release = parse_release(tail);
  if (!c.release) {
    error = fmt::format("'{}': the version is MAJOR.MINOR, such as {}", text,
                        kind->kind == ConsumerKind::Mujoco ? "mujoco@3.12" : "isaac-sim@6.1");
    return std::nullopt;
  }
  if (kind->kind == ConsumerKind::Mujoco && *c.release < Release{3, 3}) {
    error = fmt::format("'{}': asset-lint models MuJoCo 3.3 and later", text);
    return std::nullopt;
  }
  if (kind->kind == ConsumerKind::IsaacSim && *c.release < Release{5, 0}) {
    error = fmt::format("'{}': asset-lint models Isaac Sim 5.0 and later", text);
    return std::nullopt;
  }
  return c;
}

const Consumer* ConsumerProfile::find(ConsumerKind kind) const {
  for (const Consumer& c : consumers)
    if (c.kind == kind) return &c;
  return nullptr;
}

namespace {

std::vector<ConsumerKind> default_kinds(SourceFormat format) {
  switch (format) {
    case SourceFormat::Urdf:
      return {ConsumerKind::IsaacSim, ConsumerKind::IsaacLab, ConsumerKind::Mujoco,
              ConsumerKind::Newton,   ConsumerKind::Gazebo,   ConsumerKind::Ros2Control};
    case SourceFormat::Usda:
      return {ConsumerKind::IsaacSim, ConsumerKind::IsaacLab, ConsumerKind::Newton};
    case SourceFormat::Mjcf:
      return {ConsumerKind::Mujoco, ConsumerKind::Newton};
  }
  return {};
}

std::string_view format_name(SourceFormat format) {
  switch (format) {
    case SourceFormat::Urdf: return "URDF";
    case SourceFormat::Usda: return "USD";
    case SourceFormat::Mjcf: return "MJCF";
  }
  return "";
}

// MuJoCo without a version named is the [mujoco] release the file is judged for.
void apply_mujoco_setting(Consumer& c, const Settings& settings) {
  if (c.kind != ConsumerKind::Mujoco || c.release) return;
  const MujocoVersion v = settings.mujoco.parsed();
  c.release = Release{v.major, v.minor};
}

}  // namespace

ConsumerProfile consumer_profile(SourceFormat format, const Settings& settings) {
  ConsumerProfile profile;
  for (const Configured<std::string>& target : settings.targets.consumers) {
    std::string error;
    auto c = parse_consumer(target.value, error);
    if (!c) continue;  // the configuration loader and --target refuse such a name before any check
    c->origin = target.origin;
    apply_mujoco_setting(*c, settings);
    profile.consumers.push_back(std::move(*c));
  }
  profile.configured = !profile.consumers.empty();
  if (profile.configured) return profile;
  for (ConsumerKind kind : default_kinds(format)) {
    Consumer c = make(kind, fmt::format("default for {}", format_name(format)));
    apply_mujoco_setting(c, settings);
    profile.consumers.push_back(std::move(c));
  }
  return profile;
}

std::string default_consumers_text(SourceFormat format) {
  std::vector<std::string> names;
  for (ConsumerKind kind : default_kinds(format)) names.emplace_back(kind_name(kind).name);
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string join_labels(const std::vector<std::string>& labels) {
  std::string out;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (i > 0) out += i + 1 == labels.size() ? " and " : ", ";
    out += labels[i];
  }
  return out;
}

bool reads_max_joint_velocity(const Consumer& c, SourceFormat format) {
  if (format == SourceFormat::Mjcf) return false;  // MJCF has no max joint velocity to read
  return c.kind != ConsumerKind::Mujoco;           // xml_urdf.cc skips <limit velocity>: MuJoCo has none
}

bool couples_urdf_mimic(const Consumer& c) {
  switch (c.kind) {
    case ConsumerKind::Mujoco: return !c.released_before(Release{3, 13});
    case ConsumerKind::Gazebo: return !c.engine || *c.engine == GazeboEngine::BulletFeatherstone;
    case ConsumerKind::Ros2Control: return true;  // hardware_interface reads <mimic> into its joint info
    case ConsumerKind::IsaacSim:
    case ConsumerKind::IsaacLab:
    case ConsumerKind::Newton: return true;
  }
  return true;
}

bool keeps_urdf_dynamics(const Consumer& c) {
  return !(c.kind == ConsumerKind::IsaacSim && c.release_is(Release{6, 1}));
}

bool simulates_with_physx(const Consumer& c) {
  return c.kind == ConsumerKind::IsaacSim || c.kind == ConsumerKind::IsaacLab;
}

}  // namespace assetlint
