#include "formats/urdf/urdf_reread.h"

#include <tinyxml2.h>

#include <memory>
#include <string_view>

namespace assetlint::urdf {
namespace {

// The <robot> element of the file `span` lies in, parsed into `doc`; nullptr when unreadable.
const tinyxml2::XMLElement* robot_of(const Asset& asset, const Span& span, tinyxml2::XMLDocument& doc) {
  if (asset.format != SourceFormat::Urdf || !span.valid() || span.file >= asset.sources.size()) return nullptr;
  const std::string& text = asset.source(span.file).text();
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS) return nullptr;
  const tinyxml2::XMLElement* root = doc.RootElement();
  return root && std::string_view(root->Name()) == "robot" ? root : nullptr;
}

}  // namespace

bool link_has_visual(const Asset& asset, const Link& link) {
  tinyxml2::XMLDocument doc;
  const tinyxml2::XMLElement* robot = robot_of(asset, link.span, doc);
  if (!robot) return false;
  for (const tinyxml2::XMLElement* el = robot->FirstChildElement("link"); el; el = el->NextSiblingElement("link")) {
    const char* name = el->Attribute("name");
    if (name && link.name.text == name) return el->FirstChildElement("visual") != nullptr;
  }
  return false;
}

physics::MujocoInertiaInput mujoco_inertia_input(const Asset& asset) {
  physics::MujocoInertiaInput input;
  tinyxml2::XMLDocument doc;
  const tinyxml2::XMLElement* robot = robot_of(asset, asset.robot_span, doc);
  const tinyxml2::XMLElement* mujoco = robot ? robot->FirstChildElement("mujoco") : nullptr;
  const tinyxml2::XMLElement* compiler = mujoco ? mujoco->FirstChildElement("compiler") : nullptr;
  if (!compiler) return input;
  compiler->QueryDoubleAttribute("boundinertia", &input.boundinertia);
  if (const char* balance = compiler->Attribute("balanceinertia")) input.balanceinertia = std::string_view(balance) == "true";
  return input;
}

}  // namespace assetlint::urdf
