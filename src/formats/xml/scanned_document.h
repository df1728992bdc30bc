#pragma once
// An XML file read by the scanner alone: its element tree with exact byte positions and
// attribute values as an XML parser hands them over. One pass over the bytes, no second
// parser: what the URDF reader builds its model from.
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "formats/xml/xml_document.h"
#include "formats/xml/xml_scanner.h"
#include "model/source.h"

namespace assetlint::xml {

using Element = XmlStartTag;

class ScannedDocument {
 public:
  // Scans `file`, whose spans carry FileId `id`. Well-formedness problems land in errors();
  // root() is null when the document is not well-formed.
  ScannedDocument(const SourceFile& file, FileId id);

  const Element* root() const;
  const std::vector<XmlError>& errors() const { return errors_; }
  // The XML document proper, without text before or after it.
  std::string_view document() const;
  const XmlScan& scan() const { return scan_; }
  const SourceFile& file() const { return file_; }

  // The first child element of `el` named `name` (any name when empty), and the next sibling likewise.
  const Element* first_child(const Element* el, std::string_view name = {}) const;
  const Element* next_sibling(const Element* el, std::string_view name = {}) const;

  // An attribute's value exactly as written between the quotes; nullopt when absent.
  std::optional<std::string_view> raw_value(const Element* el, std::string_view attr) const;
  // An attribute's value with entities and line breaks decoded; nullopt when absent.
  std::optional<std::string_view> value(const Element* el, std::string_view attr) const;
  std::string_view value(const XmlAttributeSpan& attr) const;

  Span element_span(const Element* el) const;
  // An attribute's value without surrounding spaces (the element when absent).
  Span value_span(const Element* el, std::string_view attr) const;
  // The whole `name="value"` text of an attribute (the element when absent).
  Span attribute_span(const Element* el, std::string_view attr) const;

 private:
  const Element* at(std::uint32_t index, std::string_view name) const;

  const SourceFile& file_;
  FileId id_;
  XmlScan scan_;
  std::vector<XmlError> errors_;
  mutable std::deque<std::string> decoded_;  // values with entities or CRs, decoded once asked for
};

}  // namespace assetlint::xml
