#include "formats/usda/skipped_layers.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <string_view>

#include "util/slash_paths.h"

namespace assetlint::usda {
namespace {

constexpr std::size_t kMostNamed = 4;

// A prim whose own opinions the physics rules read: a joint, a body, a scene, an
// articulation; or a root prim (a whole robot brought in by reference).
bool physics_prim(const ComposedPrim& prim) {
  if (prim.type_name.find("Joint") != std::string::npos || prim.type_name == "PhysicsScene") return true;
  if (prim.parent == static_cast<std::size_t>(-1)) return true;
  return std::any_of(prim.api_schemas.begin(), prim.api_schemas.end(), [](const std::string& schema) {
    return schema == "PhysicsRigidBodyAPI" || schema == "PhysicsMassAPI" || schema == "PhysicsArticulationRootAPI" ||
           schema == "NewtonArticulationRootAPI" || schema.starts_with("PhysicsDriveAPI") ||
           schema.starts_with("PhysxJointAPI") || schema.starts_with("PhysxMimicJointAPI") ||
           schema == "NewtonMimicAPI" || schema == "NewtonJointAPI" || schema == "MjcJointAPI";
  });
}

bool mass_known(const Link* link) { return link && link->inertial && link->inertial->mass_authored; }

std::string quoted_list(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size() && i < kMostNamed; ++i) out += (i ? ", '" : "'") + names[i] + "'";
  if (names.size() > kMostNamed) out += fmt::format(" and {} more", names.size() - kMostNamed);
  return out;
}

void add_unique(std::vector<std::string>& list, const std::string& name) {
  if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
}

// The checks the asset could not run because values are missing in `scope`: joints
// declared under it or attached to a body under it. `expect_joints`: the scope is where
// joints are declared (the whole stage, a root prim, a joint), so finding none is a loss.
std::vector<std::string> lost_checks(const Asset& asset, const std::string& scope, bool expect_joints) {
  std::vector<std::string> notes;
  std::size_t joints_in_scope = 0;
  std::vector<std::string> massless_driven;
  std::vector<std::string> massless_links;
  std::vector<std::string> unlinked_joints, undefined_bodies;
  for (const Joint& joint : asset.joints) {
    if (!path_under(joint.name.text, scope) && !path_under(joint.parent.text, scope) &&
        !path_under(joint.child.text, scope))
      continue;
    ++joints_in_scope;
    for (const Name* body : {&joint.parent, &joint.child})
      if (!body->text.empty() && path_under(body->text, scope) && !asset.find_link(body->text)) {
        add_unique(unlinked_joints, joint.name.text);
        add_unique(undefined_bodies, body->text);
      }
    if (!joint.drive) continue;
    bool lacking = false;
    for (const Name* body : {&joint.parent, &joint.child}) {
      if (body->text.empty()) continue;
      const Link* link = asset.find_link(body->text);
      if (link && !mass_known(link)) {
        add_unique(massless_links, body->text);
        lacking = true;
      }
    }
    if (lacking) add_unique(massless_driven, joint.name.text);
  }
  if (!undefined_bodies.empty())
    notes.push_back(fmt::format("structure-undefined-link not checked for {}: no layer read defines {}, which this "
                                "layer may define",
                                quoted_list(unlinked_joints), quoted_list(undefined_bodies)));
  if (joints_in_scope == 0) {
    if (!expect_joints) return notes;
    notes.push_back(fmt::format("no joint {} was read: the joint, drive, mimic and inertia rules checked nothing there",
                                scope.empty() ? std::string("of the stage") : fmt::format("under '{}'", scope)));
  } else if (!massless_driven.empty()) {
    notes.push_back(fmt::format("drive-natural-frequency, drive-implicit-attenuation and drive-damping-ratio not checked "
                                "for {}: no layer read gives a mass to {}",
                                quoted_list(massless_driven), quoted_list(massless_links)));
  }
  return notes;
}

// Joints authored with `def` under `scope` that are not on the stage because an ancestor has
// only `over`s: the layer that defines the ancestor may be the one not read.
std::optional<std::string> hidden_joints(const Stage& stage, const std::string& scope) {
  std::vector<std::string> joints, parents;
  for (const ComposedPrim& prim : stage.prims) {
    if (!prim.defined || prim.type_name.find("Joint") == std::string::npos || !path_under(prim.path, scope)) continue;
    for (std::size_t up = prim.parent; up != static_cast<std::size_t>(-1); up = stage.prims[up].parent)
      if (!stage.prims[up].defined) {
        add_unique(joints, prim.path);
        add_unique(parents, stage.prims[up].path);
        break;
      }
  }
  if (joints.empty()) return std::nullopt;
  return fmt::format("{} joint{} not read ({}): {} defined in no layer read (only `over`s), which this layer may "
                     "define",
                     joints.size(), joints.size() == 1 ? "" : "s", quoted_list(joints),
                     parents.size() == 1 ? fmt::format("'{}' is", parents.front())
                                         : fmt::format("{} are", quoted_list(parents)));
}

}  // namespace

void weigh_skipped_arcs(const Stage& stage, ReadResult& result) {
  for (const Stage::SkippedArc& arc : stage.skipped) {
    if (arc.diagnostic >= result.diagnostics.size()) continue;
    if (std::find(result.asset.unread_scopes.begin(), result.asset.unread_scopes.end(), arc.scope) ==
        result.asset.unread_scopes.end())
      result.asset.unread_scopes.push_back(arc.scope);
    bool expect_joints = true;
    if (!arc.scope.empty()) {
      const ComposedPrim* prim = stage.find(arc.scope);
      if (!prim || !physics_prim(*prim)) continue;
      expect_joints = prim->parent == static_cast<std::size_t>(-1) || prim->type_name.find("Joint") != std::string::npos;
    }
    std::vector<std::string> lost = lost_checks(result.asset, arc.scope, expect_joints);
    if (const auto hidden = hidden_joints(stage, arc.scope)) lost.push_back(*hidden);
    if (lost.empty()) continue;
    Diagnostic& d = result.diagnostics[arc.diagnostic];
    d.severity = std::max(d.severity, Severity::Warning);
    for (const std::string& note : lost) d.note(note);
  }
}

}  // namespace assetlint::usda
