#include "rules/gripper_drive.h"

#include <algorithm>
#include <vector>

#include "physics/gripper.h"

namespace assetlint::rules {

bool moves(const Asset& asset, const Joint& upper, const Joint& lower) {
  std::vector<const Link*> seen;
  for (const Link* link = asset.side_link(lower, 0); link;) {
    if (std::find(seen.begin(), seen.end(), link) != seen.end()) return false;
    seen.push_back(link);
    const Joint* parent = nullptr;
    for (const Joint* j : asset.joints_at(link->name.text))
      if (j->child.text == link->name.text) parent = j;
    if (!parent) return false;
    if (parent == &upper) return true;
    link = asset.side_link(*parent, 0);
  }
  return false;
}

const Joint* gripper_drive(const Asset& asset) {
  for (const Joint& joint : asset.joints) {
    if (!is_single_dof(joint.type) || joint.is_mimic() || !physics::drives_gripper(asset, joint)) continue;
    std::vector<const Joint*> set = asset.mimic_followers(joint.name.text);
    set.push_back(&joint);
    for (std::size_t i = 0; i < set.size(); ++i)
      for (std::size_t k = i + 1; k < set.size(); ++k)
        if (!moves(asset, *set[i], *set[k]) && !moves(asset, *set[k], *set[i])) return &joint;
  }
  return nullptr;
}

}  // namespace assetlint::rules
