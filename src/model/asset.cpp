#include "model/asset.h"

#include <algorithm>
#include <functional>

#include "util/slash_paths.h"

namespace assetlint {

const Link* Asset::find_link(std::string_view name) const {
  if (indexed()) {
    auto it = index_->links.find(name);
    return it == index_->links.end() ? nullptr : &links[it->second];
  }
  for (const auto& link : links)
    if (link.name.text == name) return &link;
  return nullptr;
}

const Joint* Asset::find_joint(std::string_view name) const {
  if (indexed()) {
    auto it = index_->joints.find(name);
    return it == index_->joints.end() ? nullptr : &joints[it->second];
  }
  for (const auto& joint : joints)
    if (joint.name.text == name) return &joint;
  return nullptr;
}

std::vector<const Joint*> Asset::mimic_followers(std::string_view name) const {
  std::vector<const Joint*> out;
  if (indexed()) {
    if (auto it = index_->followers.find(name); it != index_->followers.end())
      for (std::size_t i : it->second) out.push_back(&joints[i]);
    return out;
  }
  for (const auto& joint : joints)
    if (joint.mimic && joint.mimic->reference.text == name) out.push_back(&joint);
  return out;
}

std::vector<const Joint*> Asset::joints_at(std::string_view link) const {
  std::vector<const Joint*> out;
  if (indexed()) {
    if (auto it = index_->link_joints.find(link); it != index_->link_joints.end())
      for (std::size_t i : it->second) out.push_back(&joints[i]);
    return out;
  }
  for (const auto& joint : joints)
    if (joint.parent.text == link || joint.child.text == link) out.push_back(&joint);
  return out;
}

const Joint* Asset::followed_joint(const Joint& mimic) const {
  if (!mimic.mimic || !is_single_dof(mimic.type) || mimic.mimic->reference.text == mimic.name.text) return nullptr;
  const Joint* reference = find_joint(mimic.mimic->reference.text);
  if (!reference || reference == &mimic || reference->is_mimic() || !is_single_dof(reference->type)) return nullptr;
  return reference;
}

namespace {

// The position of `element` in `items`, when it is one of them.
template <class T>
std::optional<std::size_t> position_in(const std::vector<T>& items, const T& element) {
  const std::less<const T*> before;
  if (items.empty() || before(&element, items.data()) || !before(&element, items.data() + items.size()))
    return std::nullopt;
  return static_cast<std::size_t>(&element - items.data());
}

}  // namespace

std::optional<std::size_t> Asset::index_of(const Link& link) const { return position_in(links, link); }

std::optional<std::size_t> Asset::index_of(const Joint& joint) const { return position_in(joints, joint); }

const Link* Asset::side_link(const Joint& joint, int side) const {
  if (indexed())
    if (const auto i = index_of(joint)) {
      const std::size_t link = index_->joint_links[*i][side == 0 ? 0 : 1];
      return link == NameIndex::kNoLink ? nullptr : &links[link];
    }
  return find_link(side == 0 ? joint.parent.text : joint.child.text);
}

bool Asset::may_be_unread(std::string_view path) const {
  return std::any_of(unread_scopes.begin(), unread_scopes.end(),
                     [&](const std::string& scope) { return path_under(path, scope); });
}

void Asset::index_names() {
  auto index = std::make_shared<NameIndex>();
  index->link_count = links.size();
  index->joint_count = joints.size();
  index->links.reserve(links.size());
  index->joints.reserve(joints.size());
  for (std::size_t i = 0; i < links.size(); ++i) index->links.emplace(links[i].name.text, i);
  for (std::size_t i = 0; i < joints.size(); ++i) {
    index->joints.emplace(joints[i].name.text, i);
    if (joints[i].mimic) index->followers[joints[i].mimic->reference.text].push_back(i);
    index->link_joints[joints[i].parent.text].push_back(i);
    if (joints[i].child.text != joints[i].parent.text) index->link_joints[joints[i].child.text].push_back(i);
  }
  const auto link_named = [&](std::string_view name) {
    auto it = index->links.find(name);
    return it == index->links.end() ? NameIndex::kNoLink : it->second;
  };
  index->joint_links.reserve(joints.size());
  for (const Joint& joint : joints) index->joint_links.push_back({link_named(joint.parent.text), link_named(joint.child.text)});
  index_ = std::move(index);
}

std::string_view joint_type_name(JointType type) {
  switch (type) {
    case JointType::Revolute: return "revolute";
    case JointType::Continuous: return "continuous";
    case JointType::Prismatic: return "prismatic";
    case JointType::Fixed: return "fixed";
    case JointType::Floating: return "floating";
    case JointType::Planar: return "planar";
    case JointType::Spherical: return "spherical";
    case JointType::Generic: return "generic (D6)";
  }
  return "unknown";
}

const InheritedLiteral* Asset::shared_literal_at(const Span& span) const {
  for (const InheritedLiteral& literal : inherited_literals)
    if (literal.uses > 1 && literal.span.file == span.file && literal.span.offset < span.end() + (span.length == 0) &&
        span.offset < literal.span.end())
      return &literal;
  return nullptr;
}

}  // namespace assetlint
