#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

#include "rules/all_rules.h"
#include "rules/gripper_drive.h"
#include "rules/support.h"

namespace assetlint::rules {
namespace {

// The links `joint` moves: its child and everything below it.
std::vector<const Link*> carried(const Asset& asset, const Joint& joint) {
  std::vector<const Link*> out;
  std::vector<const Link*> queue{asset.side_link(joint, 1)};
  while (!queue.empty()) {
    const Link* link = queue.back();
    queue.pop_back();
    if (!link || std::find(out.begin(), out.end(), link) != out.end()) continue;
    out.push_back(link);
    for (const Joint* below : asset.joints_at(link->name.text))
      if (below->parent.text == link->name.text) queue.push_back(asset.side_link(*below, 1));
  }
  return out;
}

// A finger of the gripper (a branch its coupled joints move, from the first of them down) that
// has no collider anywhere: it passes through what it closes on.
class GraspFingerCollider final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings&, Reporter& out) const override {
    // A file without any collider models no contact at all (a drive description, a payload whose
    // colliders another layer applies): nothing to say about its fingers.
    if (std::none_of(asset.links.begin(), asset.links.end(), [](const Link& l) { return !l.collisions.empty(); }))
      return;
    const Joint* drive = gripper_drive(asset);
    if (!drive) return;
    std::vector<const Joint*> set = asset.mimic_followers(drive->name.text);
    set.push_back(drive);
    // The branches: coupled joints no other coupled joint moves. A gripper grasps when two of
    // them collide; a bar of a four-bar linkage without a collider is then no defect.
    std::vector<const Joint*> bare;
    std::size_t branches = 0;
    for (const Joint* joint : set) {
      const bool top = std::none_of(set.begin(), set.end(), [&](const Joint* other) {
        return other != joint && moves(asset, *other, *joint);
      });
      if (!top) continue;
      ++branches;
      const auto links = carried(asset, *joint);
      if (std::none_of(links.begin(), links.end(), [](const Link* l) { return !l->collisions.empty(); }))
        bare.push_back(joint);
    }
    if (bare.empty() || branches - bare.size() >= 2) return;
    std::string names;
    for (const Joint* j : bare) names += (names.empty() ? "'" : ", '") + j->name.text + "'";
    Diagnostic& d = out.report(bare.front()->span,
                               fmt::format("{} of the {} fingers of gripper '{}' {} no collider: it cannot grasp",
                                           bare.size(), branches, drive->name.text, bare.size() == 1 ? "has" : "have"));
    d.note(drive->name.span, fmt::format("'{}' drives the gripper; its coupled joints move {} finger branches. No link "
                                         "that {} move{} has a collision shape, so fewer than two fingers can touch "
                                         "an object.",
                                         drive->name.text, branches, names, bare.size() == 1 ? "s" : ""));
    d.note("The engine collides only collision shapes: a finger without one closes through the object, and the "
           "other finger alone pushes it away (PhysX and MuJoCo both leave visual geometry out of contact).");
    d.note(asset.format == SourceFormat::Urdf
               ? "Fix: give each finger (its pad at least) a <collision> element."
               : asset.format == SourceFormat::Mjcf
                     ? "Fix: give each finger a geom that collides (contype or conaffinity nonzero)."
                     : "Fix: apply PhysicsCollisionAPI to each finger's pad geometry.");
  }

 private:
  RuleInfo info_{"grasp-finger-collider",
                 "A gripper with fewer than two fingers that collide: it cannot grasp",
                 // An info until more grippers are read: on a USD payload whose pads are collision
                 // meshes of another layer, the finding could not be settled.
                 Severity::Info,
                 false,
                 RuleOrigin::Check,
                 {}};
};

}  // namespace

const Rule& grasp_finger_collider() {
  static const GraspFingerCollider rule;
  return rule;
}

}  // namespace assetlint::rules
