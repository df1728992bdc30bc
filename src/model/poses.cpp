#include "model/poses.h"

#include <deque>
#include <set>

namespace assetlint {

std::map<std::string, Eigen::Isometry3d, std::less<>> link_poses(const Asset& asset) {
  std::map<std::string, Eigen::Isometry3d, std::less<>> poses;
  std::set<std::string_view> children;
  for (const Joint& joint : asset.joints)
    if (!joint.parent.text.empty()) children.insert(joint.child.text);
  for (const Link& link : asset.links)
    if (!children.count(link.name.text)) poses.emplace(link.name.text, Eigen::Isometry3d::Identity());
  // A joint from the world places its child by the joint's world-side frame.
  for (const Joint& joint : asset.joints)
    if (joint.parent.text.empty() && !joint.child.text.empty())
      poses[joint.child.text] = joint.frame_in_link[0] * joint.frame_in_link[1].inverse();
  // Breadth-first from the placed links: child = parent · (joint in parent) · (joint in child)⁻¹.
  std::multimap<std::string_view, const Joint*> by_parent;
  for (const Joint& joint : asset.joints)
    if (!joint.parent.text.empty()) by_parent.emplace(joint.parent.text, &joint);
  std::deque<std::string> queue;
  for (const auto& [name, pose] : poses) queue.push_back(name);
  while (!queue.empty()) {
    const std::string name = std::move(queue.front());
    queue.pop_front();
    const Eigen::Isometry3d parent = poses.at(name);
    auto [begin, end] = by_parent.equal_range(name);
    for (auto it = begin; it != end; ++it) {
      const Joint& joint = *it->second;
      if (poses.count(joint.child.text)) continue;
      poses.emplace(joint.child.text, parent * joint.frame_in_link[0] * joint.frame_in_link[1].inverse());
      queue.push_back(joint.child.text);
    }
  }
  return poses;
}

}  // namespace assetlint
