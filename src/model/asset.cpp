#include "model/asset.h"

namespace assetlint {

const Link* Asset::find_link(std::string_view name) const {
  for (const auto& link : links)
    if (link.name.text == name) return &link;
  return nullptr;
}

const Joint* Asset::find_joint(std::string_view name) const {
  for (const auto& joint : joints)
    if (joint.name.text == name) return &joint;
  return nullptr;
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

}  // namespace assetlint
