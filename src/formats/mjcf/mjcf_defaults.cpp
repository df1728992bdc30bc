#include "formats/mjcf/mjcf_defaults.h"

#include <fmt/format.h>

#include "rules/reader_rules.h"

namespace assetlint::mjcf {

using tinyxml2::XMLElement;

std::string_view default_kind(std::string_view element) {
  if (element == "joint") return "joint";
  if (element == "equality") return "equality";
  if (element == "geom") return "geom";
  if (element == "tendon" || element == "fixed" || element == "spatial") return "tendon";
  if (element == "mesh") return "mesh";
  if (element == "general" || element == "motor" || element == "position" || element == "velocity" ||
      element == "intvelocity" || element == "damper" || element == "cylinder" || element == "muscle" ||
      element == "adhesion")
    return "actuator";
  return "";
}

void Defaults::read(const MjcfSources& sources, const XMLElement* top, std::vector<Diagnostic>& diagnostics) {
  const char* name = top->Attribute("class");
  const std::string cls = name ? name : "main";
  if (cls == "main" || !has_class("main")) {
    read_class(sources, top, cls, "", diagnostics);
  } else {
    read_class(sources, top, cls, "main", diagnostics);
  }
}

void Defaults::read_class(const MjcfSources& sources, const XMLElement* el, const std::string& name,
                          const std::string& parent, std::vector<Diagnostic>& diagnostics) {
  if (classes_.count(name) && name != "main") {
    diagnostics.push_back({std::string(rules::kParseError.id), rules::kParseError.default_severity,
                           sources.document_of(el).value_span(el, "class"),
                           fmt::format("default class '{}' is defined twice", name), std::nullopt, {}, {}, {}});
    return;
  }
  Kinds& kinds = classes_[name];
  if (!parent.empty() && kinds.empty()) kinds = classes_.at(parent);
  for (const XMLElement* c : sources.children(el)) {
    const std::string_view tag = c->Name();
    if (tag == "default") {
      const char* child = c->Attribute("class");
      if (!child || !*child) {
        diagnostics.push_back({std::string(rules::kParseError.id), rules::kParseError.default_severity,
                               sources.document_of(c).element_span(c), "nested <default> without a class name",
                               std::nullopt, {}, {}, {}});
        continue;
      }
      // Read after this class's own elements, so the child inherits all of them.
      continue;
    }
    const std::string_view kind = default_kind(tag);
    if (!kind.empty()) classes_[name][std::string(kind)].push_back(c);
  }
  for (const XMLElement* c : sources.children(el)) {
    const char* child = c->Attribute("class");
    if (std::string_view(c->Name()) == "default" && child && *child) read_class(sources, c, child, name, diagnostics);
  }
}

const std::vector<const XMLElement*>& Defaults::elements(std::string_view name, std::string_view kind) const {
  static const std::vector<const XMLElement*> none;
  auto c = classes_.find(name);
  if (c == classes_.end()) return none;
  auto k = c->second.find(kind);
  return k == c->second.end() ? none : k->second;
}

Attr Defaults::lookup(const XMLElement* el, const std::vector<const XMLElement*>& defaults, const char* name) {
  if (const char* v = el->Attribute(name)) return {el, v};
  for (auto it = defaults.rbegin(); it != defaults.rend(); ++it)
    if (const char* v = (*it)->Attribute(name)) return {*it, v};
  return {};
}

}  // namespace assetlint::mjcf
