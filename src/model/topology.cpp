#include "model/topology.h"

#include <array>
#include <cstdint>
#include <unordered_map>

namespace assetlint {
namespace {

// Every name a joint uses as parent or child, numbered: a defined link is its position in
// asset.links (resolved once by the asset's index), an undefined name (a broken file) gets
// a number after them. Walks then index vectors instead of hashing names.
class LinkNodes {
 public:
  explicit LinkNodes(const Asset& asset) : asset_(asset), count_(asset.links.size()) {
    ends_.reserve(asset.joints.size());
    for (const Joint& joint : asset.joints) ends_.push_back({node(joint, 0), node(joint, 1)});
  }
  std::size_t count() const { return count_; }
  std::size_t end(std::size_t joint, int side) const { return ends_[joint][side == 0 ? 0 : 1]; }
  const Link* link(std::size_t node) const { return node < asset_.links.size() ? &asset_.links[node] : nullptr; }

 private:
  std::size_t node(const Joint& joint, int side) {
    if (const Link* link = asset_.side_link(joint, side)) return *asset_.index_of(*link);
    const auto [it, fresh] = undefined_.try_emplace(side == 0 ? joint.parent.text : joint.child.text, count_);
    if (fresh) ++count_;
    return it->second;
  }

  const Asset& asset_;
  std::size_t count_;
  std::vector<std::array<std::size_t, 2>> ends_;
  std::unordered_map<std::string_view, std::size_t> undefined_;
};

}  // namespace

std::vector<RigidBody> moving_bodies(const Asset& asset) {
  const LinkNodes nodes(asset);
  const std::size_t n = nodes.count();
  // The fixed joints under each node, as one array sliced by `first` (CSR).
  std::vector<std::size_t> first(n + 1, 0);
  for (std::size_t j = 0; j < asset.joints.size(); ++j)
    if (asset.joints[j].type == JointType::Fixed) ++first[nodes.end(j, 0) + 1];
  for (std::size_t i = 0; i < n; ++i) first[i + 1] += first[i];
  std::vector<std::size_t> fixed_children(first[n]), fill(first.begin(), first.end() - 1);
  for (std::size_t j = 0; j < asset.joints.size(); ++j)
    if (asset.joints[j].type == JointType::Fixed) fixed_children[fill[nodes.end(j, 0)]++] = nodes.end(j, 1);

  // Joints that share a child link (broken files) share its welded set: computed once.
  std::vector<std::int64_t> welded_set(n, -1);
  std::vector<std::vector<const Link*>> sets;
  std::vector<std::size_t> seen_in(n, SIZE_MAX);  // the walk that last reached each node
  std::vector<RigidBody> bodies;
  for (std::size_t j = 0; j < asset.joints.size(); ++j) {
    const Joint& joint = asset.joints[j];
    if (joint.type == JointType::Fixed) continue;
    const std::size_t start = nodes.end(j, 1);
    if (welded_set[start] < 0) {
      welded_set[start] = static_cast<std::int64_t>(sets.size());
      std::vector<const Link*>& links = sets.emplace_back();
      std::vector<std::size_t> pending{start};
      while (!pending.empty()) {
        const std::size_t at = pending.back();
        pending.pop_back();
        if (seen_in[at] == j) continue;  // fixed-joint cycles in broken files
        seen_in[at] = j;
        if (const Link* link = nodes.link(at)) links.push_back(link);
        for (std::size_t k = first[at]; k < first[at + 1]; ++k) pending.push_back(fixed_children[k]);
      }
    }
    bodies.push_back(RigidBody{&joint, sets[static_cast<std::size_t>(welded_set[start])]});
  }
  return bodies;
}

}  // namespace assetlint
