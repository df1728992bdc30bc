#include "formats/urdf/srdf.h"

#include <tinyxml2.h>

#include <algorithm>
#include <filesystem>

namespace assetlint::urdf {
namespace {

std::optional<Srdf> parse(const std::string& path, const std::string& text, std::string& robot_name) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) return std::nullopt;
  const tinyxml2::XMLElement* robot = doc.FirstChildElement("robot");
  if (!robot) return std::nullopt;
  robot_name = robot->Attribute("name") ? robot->Attribute("name") : "";
  Srdf srdf{path, {}};
  for (const auto* el = robot->FirstChildElement("disable_collisions"); el;
       el = el->NextSiblingElement("disable_collisions")) {
    const char* a = el->Attribute("link1");
    const char* b = el->Attribute("link2");
    if (!a || !b) continue;
    srdf.disabled.push_back({a, b, el->Attribute("reason") ? el->Attribute("reason") : ""});
  }
  return srdf;
}

}  // namespace

const DisabledCollision* Srdf::find(const std::string& a, const std::string& b) const {
  for (const DisabledCollision& pair : disabled)
    if ((pair.link1 == a && pair.link2 == b) || (pair.link1 == b && pair.link2 == a)) return &pair;
  return nullptr;
}

std::optional<Srdf> srdf_beside(const std::string& directory, const std::string& robot, const FileSystem& files) {
  std::error_code ec;
  std::vector<std::string> candidates;
  for (const auto& entry : std::filesystem::directory_iterator(directory.empty() ? "." : directory, ec))
    if (entry.path().extension() == ".srdf") candidates.push_back(entry.path().string());
  std::sort(candidates.begin(), candidates.end());
  std::optional<Srdf> only;
  for (const std::string& path : candidates) {
    std::string error;
    const auto text = files.read(path, error);
    if (!text) continue;
    std::string name;
    auto srdf = parse(path, *text, name);
    if (!srdf) continue;
    if (name == robot) return srdf;
    if (candidates.size() == 1) only = std::move(srdf);
  }
  return only;
}

}  // namespace assetlint::urdf
