#pragma once
// An XML file parsed by tinyxml2, with the exact byte positions tinyxml2 does not keep
// (from the scanner): what the URDF and MJCF readers build their spans from.
#include <tinyxml2.h>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "formats/xml/xml_scanner.h"
#include "model/source.h"

namespace assetlint::xml {

struct XmlError {
  Span span;
  std::string message;
};

class XmlDocument {
 public:
  // Parses `file`, whose spans carry FileId `id`. Well-formedness problems land in errors();
  // root() is null when the document could not be parsed at all.
  XmlDocument(const SourceFile& file, FileId id);

  const tinyxml2::XMLElement* root() const;
  const std::vector<XmlError>& errors() const { return errors_; }
  // The XML document proper, without text before or after it.
  std::string_view document() const;
  const XmlScan& scan() const { return scan_; }
  const SourceFile& file() const { return file_; }
  FileId id() const { return id_; }

  // Whether every element's byte positions are known (the scanner and tinyxml2 agree).
  bool positions_known() const { return !tags_.empty(); }
  // An attribute's value exactly as written, before entity expansion and whitespace
  // collapsing; nullopt when absent or when positions are unknown.
  std::optional<std::string_view> raw_value(const tinyxml2::XMLElement* el, std::string_view attr) const;

  // The start tag of an element (its line start when positions are unknown).
  Span element_span(const tinyxml2::XMLElement* el) const;
  // An attribute's value without surrounding spaces (the element when absent).
  Span value_span(const tinyxml2::XMLElement* el, std::string_view attr) const;
  // The whole `name="value"` text of an attribute.
  Span attribute_span(const tinyxml2::XMLElement* el, std::string_view attr) const;
  // The index-th whitespace-separated token of an attribute's value (the value when absent).
  Span token_span(const tinyxml2::XMLElement* el, std::string_view attr, std::size_t index) const;

 private:
  void index_elements();
  const XmlAttributeSpan* attribute(const tinyxml2::XMLElement* el, std::string_view attr) const;

  const SourceFile& file_;
  FileId id_;
  XmlScan scan_;
  std::unique_ptr<tinyxml2::XMLDocument> doc_;
  bool parsed_ = false;
  std::vector<XmlError> errors_;
  std::unordered_map<const tinyxml2::XMLElement*, const XmlStartTag*> tags_;
};

}  // namespace assetlint::xml
