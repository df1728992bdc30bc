#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>
#include <vector>

#include "rules/all_rules.h"
#include "rules/limit_placeholders.h"
#include "rules/support.h"

namespace assetlint::rules {
namespace {

// A USD joint of a driven, mimic-coupled mechanism (a gripper, a coupled hand) that nothing
// moves: no drive with stiffness or damping, no mimic, and no loop closure that ties it to the
// driven joints. PhysX leaves
// such a joint free within its limits: the part it carries swings with gravity, contact and
// the reaction of its neighbours. A follower of a mimic (revolute or prismatic alike) is moved
// by its constraint and needs no drive of its own.
class JointUndriven final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings&, Reporter& out) const override {
    if (asset.format != SourceFormat::Usda) return;  // URDF holds no drives; MJCF says which joints are passive
    const Joint* driven = nullptr;
    for (const Joint& joint : asset.joints)
      if (has_active_drive(joint) && !joint.is_mimic()) {
        driven = &joint;
        break;
      }
    if (!driven) return;  // nothing in the file is driven: a passive mechanism, not a robot's joints left out
    // Only a mechanism that couples joints by mimic (a gripper, a coupled hand): there a joint
    // outside the coupling is a finger left out of it. Elsewhere free joints are designed in
    // (a mecanum wheel's rollers, casters, a pendulum's pivot).
    if (std::none_of(asset.joints.begin(), asset.joints.end(), [](const Joint& j) { return j.is_mimic(); })) return;
    const std::set<const Joint*> looped = joints_in_loops(asset);
    for (const Joint& joint : asset.joints) {
      if (!is_single_dof(joint.type) || joint.is_mimic() || joint.excluded_from_articulation || has_active_drive(joint))
        continue;
      if (looped.count(&joint)) continue;
      const Link* child = asset.side_link(joint, 1);
      if (child && child->kinematic) continue;
      report(asset, joint, *driven, out);
    }
  }

 private:
  // The joints of the loops that joints outside the articulation (physics:excludeFromArticulation)
  // close: each such joint ties its two links, and the branches from them up to their common
  // ancestor move together, driven or not.
  static std::set<const Joint*> joints_in_loops(const Asset& asset) {
    // A link that is body1 of a second joint is tied by that joint too: omni.physx makes one of
    // them a loop closure as it does an excluded one.
    std::map<std::string_view, const Joint*> inbound;  // child link -> the articulation joint that carries it
    std::vector<const Joint*> closures;
    for (const Joint& joint : asset.joints) {
      if (joint.excluded_from_articulation) closures.push_back(&joint);
      else if (!joint.child.text.empty() && !inbound.emplace(joint.child.text, &joint).second) closures.push_back(&joint);
    }
    auto branch = [&](std::string_view link) {
      std::set<const Joint*> joints;
      for (auto it = inbound.find(link); it != inbound.end() && joints.insert(it->second).second;
           it = inbound.find(it->second->parent.text)) {
      }
      return joints;
    };
    std::set<const Joint*> looped(closures.begin(), closures.end());
    // A chain of joints that returns to its start (each body the body1 of one joint, no root):
    // PhysX cuts it somewhere, and every joint on it belongs to the loop.
    for (const auto& [link, joint] : inbound) {
      std::vector<const Joint*> path;
      std::set<std::string_view> seen;
      for (auto it = inbound.find(link); it != inbound.end() && seen.insert(it->first).second;
           it = inbound.find(it->second->parent.text))
        path.push_back(it->second);
      if (!path.empty() && path.back()->parent.text == link) looped.insert(path.begin(), path.end());
    }
    for (const Joint* closure : closures) {
      const auto a = branch(closure->parent.text), b = branch(closure->child.text);
      for (const Joint* j : a)
        if (!b.count(j)) looped.insert(j);
      for (const Joint* j : b)
        if (!a.count(j)) looped.insert(j);
    }
    return looped;
  }

  static void report(const Asset& asset, const Joint& joint, const Joint& driven, Reporter& out) {
    const auto followers = asset.mimic_followers(joint.name.text);
    Diagnostic& d = out.report(joint.name.span, fmt::format("{} has no drive and no mimic: it dangles",
                                                            joint_label(joint)));
    d.related.push_back("SimReady DJ.004");
    d.note(fmt::format("Nothing moves '{}': no PhysicsDriveAPI:{} with stiffness or damping, no mimic joint and no loop "
                       "closure. PhysX leaves it free within its limits, so the part it carries swings under gravity, "
                       "contact and the reaction of its neighbours while '{}' is driven.",
                       short_path(joint.name.text), joint.type == JointType::Prismatic ? "linear" : "angular",
                       short_path(driven.name.text)));
    if (!followers.empty())
      d.note(followers.front()->name.span,
             fmt::format("{} joint{} mimic it, so {} dangle with it.", followers.size(), followers.size() == 1 ? "" : "s",
                         followers.size() == 1 ? "that one" : "they"));
    d.note(fmt::format("Couple it to the driven joint with PhysxMimicJointAPI (a finger that moves with '{}'), give it a "
                       "drive, or close the linkage it belongs to with a joint excluded from the articulation.",
                       short_path(driven.name.text)));
  }

  RuleInfo info_{"joint-undriven",
                 "A joint of a driven, mimic-coupled USD mechanism with no drive, no mimic and no loop closure: it "
                 "dangles",
                 Severity::Warning, false, RuleOrigin::Check, {}};
};

}  // namespace

const Rule& joint_undriven() {
  static const JointUndriven rule;
  return rule;
}

}  // namespace assetlint::rules
