#pragma once
// MJCF <default> classes. The top-level <default> is class "main"; a nested
// <default class="c"> inherits from the class around it. An element takes its values
// from its own attributes, then from its class (its `class` attribute, else the
// `childclass` of the nearest body that names one, else "main"), then that class's
// ancestors. All actuator kinds share one default record per class, in the order written.
#include <tinyxml2.h>

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "formats/mjcf/mjcf_sources.h"

namespace assetlint::mjcf {

// Where an attribute's value comes from: the element that writes it (the instance or a default).
struct Attr {
  const tinyxml2::XMLElement* element = nullptr;
  const char* value = nullptr;
  explicit operator bool() const { return value != nullptr; }
};

class Defaults {
 public:
  // Reads one top-level <default> element (and the classes nested in it).
  void read(const MjcfSources& sources, const tinyxml2::XMLElement* top, std::vector<Diagnostic>& diagnostics);

  bool has_class(std::string_view name) const { return classes_.count(std::string(name)) > 0; }
  // The default elements of `kind` ("joint", "equality", "actuator") in class `name`, outermost first.
  const std::vector<const tinyxml2::XMLElement*>& elements(std::string_view name, std::string_view kind) const;

  // The attribute on `el`, else on the nearest default element that writes it.
  static Attr lookup(const tinyxml2::XMLElement* el, const std::vector<const tinyxml2::XMLElement*>& defaults,
                     const char* name);

 private:
  void read_class(const MjcfSources& sources, const tinyxml2::XMLElement* el, const std::string& name,
                  const std::string& parent, std::vector<Diagnostic>& diagnostics);

  using Kinds = std::map<std::string, std::vector<const tinyxml2::XMLElement*>, std::less<>>;
  std::map<std::string, Kinds, std::less<>> classes_;
};

// Which default record an element kind uses ("" for kinds the model does not read).
std::string_view default_kind(std::string_view element);

}  // namespace assetlint::mjcf
