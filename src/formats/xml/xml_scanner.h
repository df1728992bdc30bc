#pragma once
// A strict, allocation-light XML scanner that records the byte range of every start
// tag and attribute value. tinyxml2 builds the document; this scanner supplies the
// exact positions tinyxml2 does not keep, and the first well-formedness problem.
#include <cstddef>
#include <optional>
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
  std::string_view name;
  std::size_t offset = 0;  // the '<'
  std::size_t end = 0;     // one past the '>'
  std::vector<XmlAttributeSpan> attributes;

  const XmlAttributeSpan* attribute(std::string_view attr_name) const;
};

struct XmlProblem {
  std::size_t offset = 0;
  std::size_t length = 1;
  std::string message;
};

struct XmlScan {
  std::vector<XmlStartTag> tags;      // every start tag in document order
  std::vector<XmlProblem> problems;   // well-formedness problems, in order
  // The byte range that holds the XML document proper (declaration to the root's end tag).
  // Text before or after it is reported as a problem and left out of it.
  std::size_t document_begin = 0;
  std::size_t document_end = 0;
  bool recoverable = true;  // false when the problem is inside the document itself
};

XmlScan scan_xml(std::string_view text);

}  // namespace assetlint::xml
