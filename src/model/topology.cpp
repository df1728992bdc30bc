#include "model/topology.h"

#include <unordered_map>
#include <unordered_set>

namespace assetlint {

std::vector<RigidBody> moving_bodies(const Asset& asset) {
  std::unordered_multimap<std::string_view, const Joint*> fixed_children;
  for (const Joint& joint : asset.joints)
    if (joint.type == JointType::Fixed) fixed_children.emplace(joint.parent.text, &joint);

  // Joints that share a child link (broken files) share its welded set: computed once.
  std::unordered_map<std::string_view, std::vector<const Link*>> welded;
  std::vector<RigidBody> bodies;
  for (const Joint& joint : asset.joints) {
    if (joint.type == JointType::Fixed) continue;
    auto [cached, fresh] = welded.try_emplace(joint.child.text);
    if (fresh) {
      std::unordered_set<std::string_view> seen;
      std::vector<std::string_view> pending{joint.child.text};
      while (!pending.empty()) {
        const std::string_view name = pending.back();
        pending.pop_back();
        if (!seen.insert(name).second) continue;  // fixed-joint cycles in broken files
        if (const Link* link = asset.find_link(name)) cached->second.push_back(link);
        auto [begin, end] = fixed_children.equal_range(name);
        for (auto it = begin; it != end; ++it) pending.push_back(it->second->child.text);
      }
    }
    bodies.push_back(RigidBody{&joint, cached->second});
  }
  return bodies;
}

}  // namespace assetlint
