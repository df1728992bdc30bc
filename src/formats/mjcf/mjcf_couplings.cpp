#include "formats/mjcf/mjcf_couplings.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string_view>

#include <fmt/format.h>

#include "physics/articulation.h"
#include "physics/joint_space_matrix.h"
#include "physics/linkage.h"
#include "util/numbers.h"

namespace assetlint::mjcf {
namespace {

using tinyxml2::XMLElement;

// A limited fixed tendon whose range is at most this fraction of the length its joints could
// sweep on their own holds them to one another: a coupling, not a travel stop. (The OpenAI
// Shadow hand's ±0.001 m on a 0.024 m sweep is 8 %; its travel stops allow the whole sweep.)
constexpr double kCouplingWidth = 0.1;

struct Bodies {
  std::set<std::string> mocap;
  std::map<std::string, std::string> site_body;  // also wrap geoms: a tendon pulls on both
  std::map<std::string, Eigen::Vector3d> site_pos;  // sites written directly in their body: pos in its frame
};

void walk_bodies(const MjcfSources& sources, const XMLElement* parent, const std::string& body, Bodies& out) {
  for (const XMLElement* el : sources.children(parent)) {
    const std::string_view tag = el->Name();
    if (tag == "site" || tag == "geom") {
      if (const char* name = el->Attribute("name")) {
        out.site_body.emplace(name, body);
        const bool in_body = std::string_view(parent->Name()) == "body";
        const auto pos = parse_doubles(el->Attribute("pos") ? el->Attribute("pos") : "0 0 0");
        if (tag == "site" && in_body && pos && pos->size() == 3) out.site_pos.emplace(name, Eigen::Vector3d((*pos)[0], (*pos)[1], (*pos)[2]));
      }
    } else if (tag == "body" || tag == "frame") {
      const char* name = el->Attribute("name");
      const std::string here = tag == "frame" ? body : name ? std::string(name) : std::string();
      if (tag == "body" && name && el->Attribute("mocap") && trim(el->Attribute("mocap")) == "true")
        out.mocap.insert(name);
      walk_bodies(sources, el, here, out);
    }
  }
}

std::optional<std::size_t> joint_named(const Asset& asset, std::string_view name) {
  for (std::size_t i = 0; i < asset.joints.size(); ++i)
    if (asset.joints[i].name.text == name) return i;
  return std::nullopt;
}

// The joints between `body` and the world, nearest first (indices into asset.joints).
std::vector<std::size_t> path_to_root(const Asset& asset, const std::string& body) {
  std::vector<std::size_t> path;
  std::string at = body;
  for (std::size_t guard = 0; !at.empty() && at != "world" && guard <= asset.joints.size(); ++guard) {
    std::string parent;
    for (std::size_t i = 0; i < asset.joints.size(); ++i)
      if (asset.joints[i].child.text == at) {
        path.push_back(i);
        parent = asset.joints[i].parent.text;
      }
    at = parent;
  }
  return path;
}

// The body an equality names on one side: `bodyN`, else the body holding `siteN`; "world" when
// neither is written (MuJoCo's default for the second side).
std::optional<std::string> side(const XMLElement* el, const char* body, const char* site, const Bodies& bodies) {
  if (const char* b = el->Attribute(body)) return std::string(trim(b));
  if (const char* s = el->Attribute(site)) {
    const auto found = bodies.site_body.find(std::string(trim(s)));
    if (found == bodies.site_body.end()) return std::nullopt;
    return found->second.empty() ? std::string("world") : found->second;
  }
  return std::string("world");
}

struct ReadTendon {
  std::vector<std::string> joints;
  std::vector<TendonJoint> shares;
  bool coupling = false;
  Span span;
  std::string label;
};

ReadTendon read_fixed(const MjcfSources& sources, const XMLElement* fixed, const Defaults& defaults,
                      const Compiler& compiler, Values& values, const Asset& asset) {
  ReadTendon tendon;
  double sweep = 0;
  bool sweep_known = true;
  for (const XMLElement* j : sources.children(fixed)) {
    const char* name = j->Attribute("joint");
    if (!name || std::string_view(j->Name()) != "joint") continue;
    tendon.joints.emplace_back(trim(name));
    const auto index = joint_named(asset, tendon.joints.back());
    const Joint* joint = index ? &asset.joints[*index] : nullptr;
    const double coef = j->DoubleAttribute("coef", 1.0);
    tendon.shares.push_back({tendon.joints.back(), coef, values.element_span(j)});
    if (joint && joint->lower && joint->upper) sweep += std::abs(coef) * (joint->upper->value - joint->lower->value);
    else sweep_known = false;
  }
  const char* cls = fixed->Attribute("class");
  const auto& defs = defaults.elements(cls && defaults.has_class(cls) ? cls : "main", "tendon");
  const Attr range_attr = Defaults::lookup(fixed, defs, "range");
  const bool limited = values.flag(Defaults::lookup(fixed, defs, "limited"), "limited")
                           .value_or(static_cast<bool>(range_attr) && compiler.autolimits);
  if (limited && range_attr && sweep_known && sweep > 0)
    if (const auto range = values.numbers(range_attr, "range", 2))
      tendon.coupling = (*range)[1] - (*range)[0] <= kCouplingWidth * sweep;
  tendon.span = values.element_span(fixed);
  const char* name = fixed->Attribute("name");
  tendon.label = name ? "fixed tendon '" + std::string(trim(name)) + "'"
                      : "the fixed tendon at line " + std::to_string(tendon.span.line);
  return tendon;
}

// A spatial tendon that resists being stretched (limited, or with a stiffness), as a rope.
std::optional<Rope> read_rope(const MjcfSources& sources, const XMLElement* spatial, const Defaults& defaults,
                              const Compiler& compiler, Values& values, const Bodies& bodies) {
  const char* cls = spatial->Attribute("class");
  const auto& defs = defaults.elements(cls && defaults.has_class(cls) ? cls : "main", "tendon");
  const Attr range = Defaults::lookup(spatial, defs, "range");
  const bool limited =
      values.flag(Defaults::lookup(spatial, defs, "limited"), "limited").value_or(static_cast<bool>(range) && compiler.autolimits);
  const Attr stiffness = Defaults::lookup(spatial, defs, "stiffness");
  const auto stiffness_value = stiffness ? values.numbers(stiffness, "stiffness", 1) : std::nullopt;
  const bool springy = stiffness_value && (*stiffness_value)[0] > 0;
  if (!limited && !springy) return std::nullopt;
  Rope rope;
  for (const XMLElement* point : sources.children(spatial)) {
    const std::string_view tag = point->Name();
    const char* name = point->Attribute(tag == "site" ? "site" : tag == "geom" ? "geom" : "");
    if (!name || (tag != "site" && tag != "geom")) continue;
    const auto found = bodies.site_body.find(std::string(trim(name)));
    if (found != bodies.site_body.end()) rope.bodies.push_back(found->second);
  }
  rope.span = values.element_span(spatial);
  const char* name = spatial->Attribute("name");
  rope.label = name ? "spatial tendon '" + std::string(trim(name)) + "'"
                    : "the spatial tendon at line " + std::to_string(rope.span.line);
  return rope;
}

}  // namespace

Couplings read_couplings(const MjcfSources& sources, const Defaults& defaults, const Compiler& compiler,
                         const std::vector<const XMLElement*>& sections, Values& values, const Asset& asset) {
  Couplings out;
  Bodies bodies;
  for (const XMLElement* el : sections)
    if (std::string_view(el->Name()) == "worldbody") walk_bodies(sources, el, "", bodies);

  std::map<std::string, ReadTendon> named;
  for (const XMLElement* el : sections) {
    if (std::string_view(el->Name()) != "tendon") continue;
    for (const XMLElement* fixed : sources.children(el)) {
      if (std::string_view(fixed->Name()) == "spatial") {
        if (auto rope = read_rope(sources, fixed, defaults, compiler, values, bodies)) out.ropes.push_back(std::move(*rope));
        continue;
      }
      if (std::string_view(fixed->Name()) != "fixed") continue;
      ReadTendon tendon = read_fixed(sources, fixed, defaults, compiler, values, asset);
      if (tendon.coupling) out.tendons.push_back({tendon.joints, tendon.span, tendon.label});
      if (const char* name = fixed->Attribute("name")) {
        out.fixed[name] = FixedTendon{tendon.shares, tendon.span, tendon.label};
        named[std::string(trim(name))] = std::move(tendon);
      }
    }
  }
  for (const XMLElement* el : sections) {
    if (std::string_view(el->Name()) != "equality") continue;
    for (const XMLElement* c : sources.children(el)) {
      const std::string_view tag = c->Name();
      const char* cls = c->Attribute("class");
      const auto& defs = defaults.elements(cls && defaults.has_class(cls) ? cls : "main", "equality");
      if (values.flag(Defaults::lookup(c, defs, "active"), "active") == false) continue;
      if (tag == "joint") {
        const char* j1 = c->Attribute("joint1");
        const char* j2 = c->Attribute("joint2");
        if (j1)
          out.joint_pairs.push_back({std::string(trim(j1)), j2 ? std::string(trim(j2)) : std::string(), values.element_span(c)});
      } else if (tag == "tendon") {
        for (const char* attr : {"tendon1", "tendon2"})
          if (const char* t = c->Attribute(attr); t && named.contains(std::string(trim(t))))
            out.tendons.push_back({named.at(std::string(trim(t))).joints, values.element_span(c),
                                   named.at(std::string(trim(t))).label + " (held by a tendon equality)"});
      } else if (tag == "connect" || tag == "weld") {
        const auto a = side(c, "body1", "site1", bodies);
        const auto b = side(c, "body2", "site2", bodies);
        if (!a || !b) continue;
        if (bodies.mocap.contains(*a)) out.mocap_driven.push_back(*b);
        else if (bodies.mocap.contains(*b)) out.mocap_driven.push_back(*a);
        else {
          const Span span = values.element_span(c);
          Loop loop{*a, *b, span, fmt::format("the {} at line {}", tag, span.line), tag == "weld", std::nullopt};
          // The point held: `anchor` in body1's frame, or site1 (its position in its body).
          if (const char* anchor = c->Attribute("anchor"); c->Attribute("body1")) {
            const auto v = parse_doubles(anchor ? anchor : "0 0 0");
            if (v && v->size() == 3) loop.anchor = Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]);
          } else if (const char* site = c->Attribute("site1")) {
            if (const auto at = bodies.site_pos.find(std::string(trim(site))); at != bodies.site_pos.end()) loop.anchor = at->second;
          }
          out.loops.push_back(std::move(loop));
        }
      }
    }
  }
  return out;
}

void drive_through_couplings(const Couplings& couplings, Asset& asset) {
  for (const std::string& body : couplings.mocap_driven)
    for (const std::size_t i : path_to_root(asset, body)) asset.joints[i].actuation = Actuation::Actuated;
  // Until nothing changes: a coupling tendon may reach a joint through another one.
  for (bool changed = true; changed;) {
    changed = false;
    for (const CouplingTendon& tendon : couplings.tendons) {
      const auto& members = tendon.joints;
      const bool driven = std::any_of(members.begin(), members.end(), [&](const std::string& name) {
        const auto i = joint_named(asset, name);
        return i && asset.joints[*i].actuation == Actuation::Actuated;
      });
      if (!driven) continue;
      for (const std::string& name : members)
        if (const auto i = joint_named(asset, name); i && asset.joints[*i].actuation != Actuation::Actuated) {
          asset.joints[*i].actuation = Actuation::Actuated;
          changed = true;
        }
    }
  }
}

void note_rope_loads(const Couplings& couplings, Asset& asset) {
  for (const Rope& rope : couplings.ropes) {
    std::vector<std::vector<std::size_t>> paths;
    for (const std::string& body : rope.bodies) paths.push_back(path_to_root(asset, body));
    for (std::size_t j = 0; j < asset.joints.size(); ++j) {
      Joint& joint = asset.joints[j];
      if (!joint.drive || joint.hidden_load) continue;
      const auto moves = [&](const std::vector<std::size_t>& path) { return std::find(path.begin(), path.end(), j) != path.end(); };
      const bool winds = std::any_of(paths.begin(), paths.end(), moves);
      // A body that moves on joints of its own, not on this one: what the rope lifts.
      const auto load = std::find_if(paths.begin(), paths.end(), [&](const auto& path) { return !path.empty() && !moves(path); });
      if (!winds || load == paths.end()) continue;
      joint.hidden_load = HiddenLoad{fmt::format("it also pulls body '{}' through {}",
                                                 rope.bodies[static_cast<std::size_t>(load - paths.begin())], rope.label),
                                     rope.span, true};
    }
  }
}

namespace {

// The joints a loop ties together: on one body's path to the root and not on the other's.
std::vector<std::size_t> loop_members(const Asset& asset, const Loop& loop) {
  const std::vector<std::size_t> pa = path_to_root(asset, loop.body1), pb = path_to_root(asset, loop.body2);
  std::vector<std::size_t> members;
  for (const std::size_t i : pa)
    if (std::find(pb.begin(), pb.end(), i) == pb.end()) members.push_back(i);
  for (const std::size_t i : pb)
    if (std::find(pa.begin(), pa.end(), i) == pa.end()) members.push_back(i);
  return members;
}

std::string joint_list(const Asset& asset, const std::vector<std::size_t>& joints) {
  constexpr std::size_t kNamed = 3;
  std::string names;
  for (std::size_t k = 0; k < joints.size() && k < kNamed; ++k)
    names += (k == 0 ? "'" : k + 1 == joints.size() ? " and '" : ", '") + asset.joints[joints[k]].name.text + "'";
  if (joints.size() > kNamed) names += fmt::format(" and {} more", joints.size() - kNamed);
  return names;
}

// What each actuated joint also turns, coupling by coupling, in document order.
struct Turned {
  std::vector<std::size_t> joints;
  Span span;
  std::string label;
};
using TurnedBy = std::map<std::size_t, std::vector<Turned>>;

void note_turned(const Asset& asset, const std::vector<std::size_t>& members, const Span& span, const std::string& label,
                 TurnedBy& turned) {
  for (const std::size_t i : members) {
    if (asset.joints[i].actuation != Actuation::Actuated) continue;
    std::vector<std::size_t> others;
    for (const std::size_t j : members)
      if (j != i && asset.joints[j].type != JointType::Fixed && std::find(others.begin(), others.end(), j) == others.end())
        others.push_back(j);
    if (!others.empty()) turned[i].push_back({std::move(others), span, label});
  }
}

void write_turned(const TurnedBy& turned, Asset& asset) {
  for (const auto& [i, couplings] : turned) {
    Joint& joint = asset.joints[i];
    if (joint.hidden_load) continue;  // a rope's load, noted first
    std::string what = "it also turns ";
    for (std::size_t k = 0; k < couplings.size(); ++k) {
      const Turned& t = couplings[k];
      what += fmt::format("{}joint{} {} through {}", k == 0 ? "" : k + 1 == couplings.size() ? " and " : ", ",
                          t.joints.size() == 1 ? "" : "s", joint_list(asset, t.joints), t.label);
    }
    joint.hidden_load = HiddenLoad{std::move(what), couplings.front().span, false};
  }
}

}  // namespace

void note_coupled_loads(const Couplings& couplings, Asset& asset) {
  TurnedBy turned;
  // A loop closure the model holds (its anchor placed) whose mechanism can be solved is part
  // of what the drive rules judge the drive on (physics/linkage.h): nothing of it is hidden.
  std::unique_ptr<physics::Articulation> articulation;
  std::unique_ptr<physics::JointSpaceMatrix> matrix;
  const auto modelled = [&](const Loop& loop, const std::vector<std::size_t>& members) {
    if (!loop.anchor || loop.body1 == "world") return false;
    const auto driven = std::find_if(members.begin(), members.end(),
                                     [&](std::size_t i) { return asset.joints[i].actuation == Actuation::Actuated; });
    if (driven == members.end()) return true;  // no drive to hide it from
    if (!matrix) {
      asset.index_names();
      articulation = std::make_unique<physics::Articulation>(asset);
      matrix = std::make_unique<physics::JointSpaceMatrix>(*articulation);
    }
    const physics::Mechanism mechanism = physics::drive_mechanism(*matrix, asset, asset.joints[*driven]);
    // The drive rules fold the mechanism's inertia into the drive, not the damping of the joints
    // it moves: a loop whose other joints are damped still leaves that out.
    const bool damped = std::any_of(mechanism.joints.begin(), mechanism.joints.end(), [&](const Joint* j) {
      return j != &asset.joints[*driven] && j->joint_damping && j->joint_damping->value > 0;
    });
    return !damped && (mechanism.inertia.known || !mechanism.inertia.unknown_links.empty());
  };
  for (const Loop& loop : couplings.loops)
    if (const auto members = loop_members(asset, loop); !modelled(loop, members))
      note_turned(asset, members, loop.span, loop.label, turned);
  for (const CouplingTendon& tendon : couplings.tendons) {
    std::vector<std::size_t> members;
    for (const std::string& name : tendon.joints)
      if (const auto i = joint_named(asset, name)) members.push_back(*i);
    note_turned(asset, members, tendon.span, tendon.label, turned);
  }
  // A linear joint equality became a mimic, which the inertia rules follow; any other couples
  // the joints in a way they cannot.
  for (const JointPair& pair : couplings.joint_pairs) {
    const auto a = joint_named(asset, pair.first), b = joint_named(asset, pair.second);
    if (!a || !b) continue;
    const auto follows = [&](std::size_t x, std::size_t y) {
      return asset.joints[x].is_mimic() && asset.joints[x].mimic->reference.text == asset.joints[y].name.text;
    };
    if (follows(*a, *b) || follows(*b, *a)) continue;
    note_turned(asset, {*a, *b}, pair.span, fmt::format("the joint equality at line {}", pair.span.line), turned);
  }
  write_turned(turned, asset);
}

void mark_linkages(const Couplings& couplings, Asset& asset) {
  const auto index = [&](const std::string& name) { return joint_named(asset, name); };
  const auto drives = [&](std::optional<std::size_t> i) {
    return i && (asset.joints[*i].actuation == Actuation::Actuated || asset.joints[*i].actuation == Actuation::Linkage);
  };
  bool changed = false;
  const auto link = [&](std::optional<std::size_t> i) {
    if (i && asset.joints[*i].actuation == Actuation::Passive) {
      asset.joints[*i].actuation = Actuation::Linkage;
      changed = true;
    }
  };
  std::vector<std::vector<std::size_t>> loops;
  for (const Loop& loop : couplings.loops) loops.push_back(loop_members(asset, loop));
  // Until nothing changes: a chain of couplings passes the drive along.
  do {
    changed = false;
    for (const CouplingTendon& tendon : couplings.tendons)
      if (std::any_of(tendon.joints.begin(), tendon.joints.end(), [&](const std::string& m) { return drives(index(m)); }))
        for (const std::string& name : tendon.joints) link(index(name));
    for (const auto& [first, second, span] : couplings.joint_pairs) {
      if (second.empty()) continue;
      if (drives(index(first))) link(index(second));
      if (drives(index(second))) link(index(first));
    }
    for (const auto& members : loops)
      if (std::any_of(members.begin(), members.end(), [&](std::size_t i) { return drives(i); }))
        for (const std::size_t i : members) link(i);
  } while (changed);
}

}  // namespace assetlint::mjcf

namespace assetlint::mjcf {

std::vector<LoopClosure> loop_closures(const Couplings& couplings) {
  std::vector<LoopClosure> closures;
  for (const Loop& loop : couplings.loops) {
    if (!loop.anchor || loop.body1 == "world" || loop.body1.empty()) continue;
    closures.push_back({loop.body1, loop.body2 == "world" ? std::string() : loop.body2, *loop.anchor, loop.weld, loop.span,
                        loop.label});
  }
  return closures;
}

}  // namespace assetlint::mjcf
