#include "formats/mjcf/mjcf_actuators.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string_view>

#include "util/numbers.h"

namespace assetlint::mjcf {
namespace {

using tinyxml2::XMLElement;

// One actuator parameter and the literal it comes from: value = sign × authored.
struct Param {
  static Param fixed(double v) {
    Param p;
    p.value = v;
    return p;
  }
  double value = 0.0;
  Attr attr;                  // empty: MuJoCo's default
  const char* name = nullptr;
  std::size_t token = 0;
  double sign = 1.0;
};

struct Params {
  Param gain = Param::fixed(1.0);
  Param bias_position;  // biasprm[1] = −kp
  Param bias_velocity;  // −biasprm[2]: kv, or −ζ when the slot holds a damping ratio
  bool affine = false;
  std::string gaintype = "fixed";
  // gainprm[1] and gainprm[2]: an affine gain's length and velocity terms. With both 0 the gain
  // is the constant gainprm[0], as a fixed one is.
  double gain_length = 0, gain_velocity = 0;
  bool constant_gain() const { return gaintype == "fixed" || (gaintype == "affine" && gain_length == 0 && gain_velocity == 0); }
  Param gear = Param::fixed(1.0);
  Attr forcerange, ctrlrange;
  std::optional<bool> forcelimited, ctrllimited;
};

Param token_param(const Attr& attr, const char* name, std::size_t token, double sign) {
  Param p;
  p.attr = attr;
  p.name = name;
  p.token = token;
  p.sign = sign;
  auto numbers = parse_doubles(attr.value ? attr.value : "");
  if (!numbers || numbers->size() <= token) return Param{};  // not written here: the caller keeps what it had
  p.value = sign * (*numbers)[token];
  return p;
}

Attr own(const XMLElement* el, const char* name) { return Attr{el, el->Attribute(name)}; }

void apply(const XMLElement* el, Params& p, Values& values) {
  const std::string_view tag = el->Name();
  if (Attr a = own(el, "gear"); a && values.numbers(a, "gear")) p.gear = token_param(a, "gear", 0, 1.0);
  if (Attr a = own(el, "forcerange")) p.forcerange = a;
  if (Attr a = own(el, "ctrlrange")) p.ctrlrange = a;
  if (auto f = values.flag(own(el, "forcelimited"), "forcelimited")) p.forcelimited = f;
  if (auto f = values.flag(own(el, "ctrllimited"), "ctrllimited")) p.ctrllimited = f;
  if (tag == "general") {
    if (Attr a = own(el, "biastype")) p.affine = trim(a.value) == "affine";
    if (Attr a = own(el, "gaintype")) p.gaintype = std::string(trim(a.value));
    if (Attr a = own(el, "gainprm"); a && values.numbers(a, "gainprm")) {
      if (Param g = token_param(a, "gainprm", 0, 1.0); g.attr) p.gain = g;
      if (Param g = token_param(a, "gainprm", 1, 1.0); g.attr) p.gain_length = g.value;
      if (Param g = token_param(a, "gainprm", 2, 1.0); g.attr) p.gain_velocity = g.value;
    }
    // MuJoCo reads as many entries as the element writes and keeps the rest from the class
    // (xml_native_reader's ReadAttr without `exact`): biasprm="0 -250" under a class with
    // "0 -50 -5" compiles to (0, -250, -5).
    if (Attr a = own(el, "biasprm"); a && values.numbers(a, "biasprm")) {
      if (Param v = token_param(a, "biasprm", 1, -1.0); v.attr) p.bias_position = v;
      if (Param v = token_param(a, "biasprm", 2, -1.0); v.attr) p.bias_velocity = v;
    }
  } else if (tag == "position") {
    if (Attr a = own(el, "kp"); a && values.numbers(a, "kp", 1)) p.gain = token_param(a, "kp", 0, 1.0);
    p.bias_position = p.gain;  // biasprm[1] = −kp, read as the stiffness kp
    const Attr kv = own(el, "kv"), dampratio = own(el, "dampratio");
    if (kv && dampratio) {
      values.error(values.value_span(dampratio, "dampratio"), "<position>: kv and dampratio cannot both be defined")
          .note("MuJoCo refuses to compile the model: both write the actuator's velocity gain.");
    } else if (kv && values.numbers(kv, "kv", 1)) {
      if (Param v = token_param(kv, "kv", 0, 1.0); v.value >= 0) p.bias_velocity = v;
      else values.error(values.value_span(kv, "kv"), "<position kv>: must not be negative");
    } else if (dampratio && values.numbers(dampratio, "dampratio", 1)) {
      if (Param v = token_param(dampratio, "dampratio", 0, -1.0); v.value <= 0) p.bias_velocity = v;
      else values.error(values.value_span(dampratio, "dampratio"), "<position dampratio>: must not be negative");
    }
    p.affine = true;
    p.gaintype = "fixed";
  } else if (tag == "velocity") {
    // kv = gainprm[0] (1 unless a class or the element sets it); biasprm = (0, 0, −kv).
    if (Attr a = own(el, "kv"); a && values.numbers(a, "kv", 1)) p.gain = token_param(a, "kv", 0, 1.0);
    p.bias_position = Param{};
    p.bias_velocity = p.gain;
    p.affine = true;
    p.gaintype = "fixed";
  } else if (tag == "motor") {
    p.gain = Param::fixed(1.0);
    p.bias_position = p.bias_velocity = Param{};
    p.affine = false;
    p.gaintype = "fixed";
  }
}

OptQuantity quantity(const Param& p, Unit unit, double scale, Values& values) {
  if (!p.attr) return Quantity::unauthored(p.value * scale, unit);
  return values.quantity(p.attr, p.name, unit, p.token, p.sign * scale);
}

// The larger bound of a range attribute, as a quantity scaled to the joint.
OptQuantity range_bound(const Attr& a, const char* name, Unit unit, double scale, Values& values) {
  auto v = values.numbers(a, name, 2);
  if (!v) return std::nullopt;
  const std::size_t i = std::abs((*v)[1]) >= std::abs((*v)[0]) ? 1 : 0;
  const double sign = (*v)[i] < 0 ? -1.0 : 1.0;
  return values.quantity(a, name, unit, i, sign * scale);
}

// The asset's name index is built after the actuators are read: look the joint up directly.
Joint* joint_named(Asset& asset, std::string_view name) {
  auto it = std::find_if(asset.joints.begin(), asset.joints.end(), [&](const Joint& j) { return j.name.text == name; });
  return it == asset.joints.end() ? nullptr : &*it;
}

// MuJoCo damps a joint with its actuators' kv and the joint's own damping alike. One literal
// stays as written (a fix can rewrite it); two make a sum no single literal holds.
OptQuantity plus_joint_damping(const OptQuantity& actuator, const OptQuantity& joint_damping) {
  if (!joint_damping || joint_damping->value <= 0) return actuator;
  if (!actuator || actuator->value == 0) return joint_damping;
  return Quantity::unauthored(actuator->value + joint_damping->value, actuator->unit);
}

}  // namespace

namespace {

// The actuator's parameters with its class chain applied; nullopt for an unknown class.
std::optional<Params> actuator_params(const XMLElement* el, const Defaults& defaults, Values& values) {
  const char* cls = el->Attribute("class");
  if (cls && !defaults.has_class(cls)) {
    values.unknown_class(values.value_span(own(el, "class"), "class"), "class", cls);
    return std::nullopt;
  }
  Params p;
  for (const XMLElement* d : defaults.elements(cls ? cls : "main", "actuator")) apply(d, p, values);
  apply(el, p, values);
  return p;
}

std::string actuator_label(const XMLElement* el) {
  const char* name = el->Attribute("name");
  return name ? fmt::format("actuator '{}'", name) : fmt::format("<{}> actuator", el->Name());
}

// Kinds asset-lint does not step: one info says the element is not judged.
bool judged_kind(const XMLElement* el, const std::string& label, const std::string& moved, Values& values) {
  const std::string_view tag = el->Name();
  if (tag == "position" || tag == "general" || tag == "motor" || tag == "velocity") return true;
  // <pid> and the redesigned <dcmotor> (MuJoCo 3.12) carry controller state asset-lint does not step.
  const bool newer = tag == "pid" || tag == "dcmotor";
  values.unsupported(values.element_span(el), fmt::format("{} is not judged: asset-lint does not model <{}> actuators{}",
                                                          label, tag, newer ? " (MuJoCo 3.12 and later)" : ""))
      .note(fmt::format("No rule judges what it does to {} (its gains, damping or force bound); the joint "
                        "counts as actuated.",
                        moved));
  return false;
}

// What a fixed tendon adds to the drive of the joint carrying it: the other joints of its
// group (the mimics that move with it) and the tendon's moment on every joint it reaches.
struct TendonDrive {
  std::vector<std::pair<const Joint*, double>> group;  // joint, multiplier (1 for the joint itself)
  std::vector<std::pair<std::size_t, double>> moment;  // asset.joints index, gear·coef
};

void drive_joint(const XMLElement* el, const Params& p, const std::string& label, Joint* joint, double g,
                 const TendonDrive* tendon, const Compiler& compiler, Values& values, Asset& asset,
                 std::vector<DampRatio>& damp_ratios, std::vector<Damper>& dampers);

}  // namespace

void read_actuator(const XMLElement* el, const Defaults& defaults, const Compiler& compiler,
                   const FixedTendons& tendons, Values& values, Asset& asset, std::vector<DampRatio>& damp_ratios,
                   std::vector<Damper>& dampers, std::vector<const XMLElement*>& on_tendons) {
  const std::string label = actuator_label(el);
  const char* joint_name = el->Attribute("joint");
  if (!joint_name) joint_name = el->Attribute("jointinparent");
  if (!joint_name) {
    if (const char* tendon = el->Attribute("tendon"); tendon && tendons.contains(tendon)) {
      for (const TendonJoint& moved : tendons.at(tendon).joints)
        if (Joint* j = joint_named(asset, moved.joint)) j->actuation = Actuation::Actuated;
      on_tendons.push_back(el);
      return;
    }
    for (const char* other : {"tendon", "site", "body", "cranksite"})
      if (const char* target = el->Attribute(other)) {
        if (!actuator_params(el, defaults, values)) return;
        values.unsupported(values.element_span(el), fmt::format("{} acts through {} '{}'", label, other, target))
            .note("asset-lint models joint and fixed-tendon transmissions: no drive rule judges this actuator (its "
                  "stiffness, damping ratio, natural frequency or force bound), and no joint of the model is called "
                  "undriven, since it may move any of them.");
        return;
      }
    values.error(values.element_span(el), fmt::format("{} names no joint, tendon, site or body", label));
    return;
  }
  const std::optional<Params> params = actuator_params(el, defaults, values);
  if (!params) return;
  const Params& p = *params;
  Joint* joint = joint_named(asset, joint_name);
  if (!joint) {
    values.error(values.value_span(own(el, "joint"), "joint"), fmt::format("{} names unknown joint '{}'", label, joint_name));
    return;
  }
  joint->actuation = Actuation::Actuated;
  if (p.gear.attr && std::abs(p.gear.value) != 1.0 && p.gear.value != 0.0)
  {
    Transmission transmission;
    transmission.ratio = std::abs(p.gear.value);
    transmission.span = values.token_span(p.gear.attr, "gear", 0);
    joint->transmission = std::move(transmission);
  }
  if (!judged_kind(el, label, fmt::format("joint '{}'", joint_name), values)) return;
  drive_joint(el, p, label, joint, p.gear.value, nullptr, compiler, values, asset, damp_ratios, dampers);
}

void read_tendon_actuator(const XMLElement* el, const Defaults& defaults, const Compiler& compiler,
                          const FixedTendons& tendons, const std::unordered_map<std::string, double>& qpos0,
                          Values& values, Asset& asset, std::vector<DampRatio>& damp_ratios, std::vector<Damper>& dampers) {
  const std::optional<Params> params = actuator_params(el, defaults, values);
  if (!params) return;
  const Params& p = *params;
  const std::string label = actuator_label(el);
  const FixedTendon& tendon = tendons.at(el->Attribute("tendon"));
  if (!judged_kind(el, label, tendon.label, values)) return;
  const double g = p.gear.value;
  // Each joint of the tendon, or the joint it mimics: the groups that move as one.
  TendonDrive shared;
  std::vector<std::pair<Joint*, TendonDrive>> groups;
  std::vector<TendonShare> shares;
  double length0 = 0;
  for (const TendonJoint& share : tendon.joints) {
    Joint* joint = joint_named(asset, share.joint);
    if (!joint) {
      values.error(share.span, fmt::format("{} names unknown joint '{}'", tendon.label, share.joint));
      return;
    }
    shares.push_back({share.joint, g * share.coef, share.span});
    if (const auto at = qpos0.find(share.joint); at != qpos0.end()) length0 += g * share.coef * at->second;
    shared.moment.emplace_back(static_cast<std::size_t>(joint - asset.joints.data()), g * share.coef);
    Joint* leader = joint;
    double multiplier = 1.0;
    if (const Joint* followed = joint->is_mimic() ? asset.followed_joint(*joint) : nullptr) {
      leader = &asset.joints[*asset.index_of(*followed)];
      multiplier = joint->mimic->multiplier.value;
    }
    auto group = std::find_if(groups.begin(), groups.end(), [&](const auto& g2) { return g2.first == leader; });
    if (group == groups.end()) group = groups.insert(groups.end(), {leader, TendonDrive{{{leader, 1.0}}, {}}});
    if (leader != joint) group->second.group.emplace_back(joint, multiplier);
  }
  for (auto& [leader, drive] : groups) {
    if (!is_single_dof(leader->type)) continue;
    // The tendon's rate per unit rate of the group's joint.
    double ratio = 0;
    for (const TendonJoint& share : tendon.joints) {
      const Joint* joint = joint_named(asset, share.joint);
      for (const auto& [member, multiplier] : drive.group)
        if (member == joint) ratio += g * share.coef * multiplier;
    }
    if (ratio == 0) continue;  // the group's motion leaves the tendon's length unchanged: no drive on it
    drive.moment = shared.moment;
    Transmission transmission;
    transmission.ratio = std::abs(ratio);
    transmission.span = values.element_span(el);
    transmission.tendon = tendon.label;
    transmission.actuator = label;
    transmission.shares = shares;
    transmission.length0 = length0;
    leader->transmission = std::move(transmission);
    drive_joint(el, p, label, leader, ratio, &drive, compiler, values, asset, damp_ratios, dampers);
  }
}

namespace {

// Joint damping on the group's motion: each joint's damping times its multiplier², the
// joint's own literal kept when it is the only one.
OptQuantity group_damping(const Joint& joint, const TendonDrive* tendon) {
  OptQuantity sum = joint.joint_damping;
  if (!tendon) return sum;
  for (const auto& [member, multiplier] : tendon->group) {
    if (member == &joint || !member->joint_damping || member->joint_damping->value <= 0) continue;
    const double add = member->joint_damping->value * multiplier * multiplier;
    sum = Quantity::unauthored((sum ? sum->value : 0.0) + add, member->joint_damping->unit);
  }
  return sum;
}

void drive_joint(const XMLElement* el, const Params& p, const std::string& label, Joint* joint, double g,
                 const TendonDrive* tendon, const Compiler& compiler, Values& values, Asset& asset,
                 std::vector<DampRatio>& damp_ratios, std::vector<Damper>& dampers) {
  if (!is_single_dof(joint->type)) return;
  const bool angular = is_angular(joint->type);
  const bool force_limited = p.forcelimited.value_or(p.forcerange && compiler.autolimits);
  const bool ctrl_limited = p.ctrllimited.value_or(p.ctrlrange && compiler.autolimits);
  const Unit force_unit = angular ? Unit::NewtonMeter : Unit::Newton;

  if (!p.constant_gain()) {
    values.unsupported(values.element_span(el),
                       p.gaintype == "affine"
                           ? fmt::format("{}: an affine gain with a length or velocity term (gainprm[1], gainprm[2]) "
                                         "is not modelled",
                                         label)
                           : fmt::format("{}: gaintype '{}' is not modelled", label, p.gaintype));
    return;
  }
  // A damper (no spring: a velocity actuator) adds −kv·q̇ to whatever else drives the joint;
  // it is folded in once every actuator is read.
  if (p.affine && p.bias_position.value == 0 && p.bias_velocity.value > 0 &&
      !(p.bias_velocity.name && std::string_view(p.bias_velocity.name) == "dampratio")) {
    OptQuantity max_force;
    if (force_limited && p.forcerange) max_force = range_bound(p.forcerange, "forcerange", force_unit, std::abs(g), values);
    dampers.push_back({static_cast<std::size_t>(joint - asset.joints.data()),
                       quantity(p.bias_velocity, angular ? Unit::NewtonMeterSecondPerRadian : Unit::NewtonSecondPerMeter,
                                g * g, values),
                       max_force, values.element_span(el), label});
    return;
  }
  if (p.affine && (p.bias_position.value > 0 || p.bias_velocity.value > 0)) {
    if (joint->drive) return;  // a second servo on the joint: the first one is the drive the rules judge
    Drive drive;
    drive.span = values.element_span(el);
    drive.type_span = drive.span;
    drive.stiffness = quantity(p.bias_position, angular ? Unit::NewtonMeterPerRadian : Unit::NewtonPerMeter, g * g, values);
    // MuJoCo (mj_setConst) reads a positive biasprm[2] of a position-like actuator as a
    // damping ratio; kv follows from the inertia once the whole model is read.
    const bool position_like = p.gain.value == p.bias_position.value;
    const bool damp_ratio = p.bias_velocity.name && std::string_view(p.bias_velocity.name) == "dampratio";
    if (damp_ratio || (position_like && p.bias_velocity.value < 0)) {
      // The joint's own damping is added to the derived kv then.
      DampRatio request{static_cast<std::size_t>(joint - asset.joints.data()), -p.bias_velocity.value, p.gain.value, g,
                        tendon ? tendon->moment : std::vector<std::pair<std::size_t, double>>{},
                        values.token_span(p.bias_velocity.attr, p.bias_velocity.name, p.bias_velocity.token), label};
      const OptQuantity damping = group_damping(*joint, tendon);
      request.joint_damping = damping ? damping->value : 0.0;
      damp_ratios.push_back(std::move(request));
    } else {
      if (p.bias_velocity.attr || p.bias_velocity.value != 0)
        drive.damping = quantity(p.bias_velocity, angular ? Unit::NewtonMeterSecondPerRadian : Unit::NewtonSecondPerMeter,
                                 g * g, values);
      drive.damping = plus_joint_damping(drive.damping, group_damping(*joint, tendon));
    }
    if (force_limited && p.forcerange) drive.max_force = range_bound(p.forcerange, "forcerange", force_unit, std::abs(g), values);
    joint->drive = std::move(drive);
    return;
  }
  if (p.affine) return;  // an affine bias without a spring or damper term: not a drive
  // A motor (force = gain·ctrl): the control range bounds the force, the force range clamps it,
  // and the joint sees the smaller of the two through the gear (a gear of 10 with ctrlrange ±10
  // and forcerange ±100 pushes at most 100 N, not 1000).
  OptQuantity effort;
  if (force_limited && p.forcerange) effort = range_bound(p.forcerange, "forcerange", force_unit, std::abs(g), values);
  if (ctrl_limited && p.ctrlrange) {
    OptQuantity by_control = range_bound(p.ctrlrange, "ctrlrange", force_unit, std::abs(g * p.gain.value), values);
    if (by_control && (!effort || by_control->value < effort->value)) effort = by_control;
  }
  if (effort && !joint->effort) joint->effort = effort;
}

}  // namespace

void add_dampers(const std::vector<Damper>& dampers, Asset& asset) {
  for (const Damper& damper : dampers) {
    Joint& joint = asset.joints[damper.joint];
    const Quantity& kv = *damper.damping;
    if (!joint.drive) {
      // Only dampers on the joint: a velocity drive, as PhysX has one (stiffness 0). MuJoCo
      // damps the joint with the joint's own damping alike.
      Drive drive;
      drive.span = damper.span;
      drive.type_span = damper.span;
      drive.stiffness = Quantity::unauthored(0, is_angular(joint.type) ? Unit::NewtonMeterPerRadian : Unit::NewtonPerMeter);
      const double joint_damping = joint.joint_damping ? joint.joint_damping->value : 0.0;
      drive.damping = plus_joint_damping(kv, joint.joint_damping);
      drive.max_force = damper.max_force;
      if (joint_damping > 0)
        drive.damping_origin = fmt::format("{}: kv {}, plus the joint's damping {}: {}", damper.label,
                                           format_number(kv.value, 6), format_number(joint_damping, 6),
                                           format_number(kv.value + joint_damping, 6));
      joint.drive = std::move(drive);
      continue;
    }
    Drive& drive = *joint.drive;
    if (!drive.damping_unknown.empty()) continue;  // what it adds to stays unknown
    const double before = drive.damping ? drive.damping->value : 0.0;
    const std::string added = fmt::format("{} on the same joint, kv {} (MuJoCo applies kv·(ctrl − q̇): whatever its "
                                          "control, it damps the joint)",
                                          damper.label, format_number(kv.value, 6));
    if (before > 0) {
      const std::string origin = drive.damping_origin.empty()
                                     ? fmt::format("The servo's and the joint's damping {}", format_number(before, 6))
                                     : drive.damping_origin;
      // Two literals make up the damping then: no single one to rewrite.
      drive.damping = Quantity::unauthored(before + kv.value, kv.unit);
      drive.damping_origin = fmt::format("{}; plus {}: {}", origin, added, format_number(before + kv.value, 6));
    } else {
      drive.damping = kv;
      drive.damping_origin = fmt::format("The damping is {}", added);
    }
  }
}

}  // namespace assetlint::mjcf
