#pragma once
// A strict, allocation-light XML scanner that records the byte range of every start
// tag and attribute value, and the element tree they form. It rejects everything tinyxml2
// rejects (tests/xml_scanner_test.cpp compares them), so a reader can take its elements
// from here alone (the URDF reader does); the MJCF reader pairs them with tinyxml2's.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace assetlint::xml {

struct XmlAttributeSpan {
  std::string_view name;
  std::size_t name_offset = 0;
  std::size_t value_offset = 0;  // first byte inside the quotes
  std::size_t value_length = 0;
};

struct XmlStartTag {
  static constexpr std::uint32_t kNone = UINT32_MAX;

  std::string_view name;
  std::size_t offset = 0;  // the '<'
  std::size_t end = 0;     // one past the '>'
  std::span<const XmlAttributeSpan> attributes;  // in XmlScan::attribute_storage
  // The element tree, as indices into XmlScan::tags (kNone: there is none).
  std::uint32_t first_child = kNone;
  std::uint32_t next_sibling = kNone;

  const XmlAttributeSpan* attribute(std::string_view attr_name) const;
};

struct XmlProblem {
  std::size_t offset = 0;
  std::size_t length = 1;
  std::string message;
};

struct XmlScan {
  XmlScan() = default;
  XmlScan(XmlScan&&) = default;
  XmlScan& operator=(XmlScan&&) = default;
  XmlScan(const XmlScan&) = delete;  // the tags' attributes point into attribute_storage

  std::vector<XmlStartTag> tags;      // every start tag in document order
  std::vector<XmlAttributeSpan> attribute_storage;  // all tags' attributes, one allocation
  std::vector<XmlProblem> problems;   // well-formedness problems, in order
  // The byte range that holds the XML document proper (declaration to the root's end tag).
  // Text before or after it is reported as a problem and left out of it.
  std::size_t document_begin = 0;
  std::size_t document_end = 0;
  bool recoverable = true;  // false when the problem is inside the document itself
  // What the bytes hold (after a BOM), for readers that must know whether other parsers
  // read them alike.
  bool non_ascii = false;
  bool ampersand = false;
  bool carriage_return = false;
  std::vector<std::size_t> instructions;  // offsets of every '<?' the scan passed
  bool doctype_or_cdata = false;          // a '<!' other than a comment
};

// Elements may nest this deep (the root is level 1): tinyxml2's limit, kept so that both
// parsers accept the same documents.
inline constexpr std::size_t kMaxXmlDepth = 98;

XmlScan scan_xml(std::string_view text);

// An attribute value as an XML parser hands it over: the five predefined entities and
// character references decoded, line breaks (CR LF, LF CR, lone CR) read as LF.
std::string decode_attribute_value(std::string_view raw);
// Whether decode_attribute_value would change `raw`.
bool attribute_value_needs_decoding(std::string_view raw);

}  // namespace assetlint::xml
