#pragma once
// A .xacro file as the expander walks it: elements, text and comments in order, every
// element and attribute with its place in the file.
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/source.h"

namespace assetlint::xacro {

struct XAttribute {
  std::string name;
  std::string value;  // as an XML parser hands it over (entities decoded)
  Span value_span;    // the value between the quotes
  bool verbatim = false;  // the file holds `value` byte for byte (no entity, no line break decoded)
};

struct XNode {
  enum class Kind { Element, Text, Comment };
  Kind kind = Kind::Element;
  std::string name;  // the element's name; the text or comment itself
  std::vector<XAttribute> attributes;
  std::vector<XNode> children;
  Span span;  // the start tag; for text and comments, the start of their line

  const XAttribute* attribute(std::string_view attr) const;
  const XNode* first_element() const;
};

struct SourceTree {
  std::shared_ptr<const SourceFile> file;
  FileId id = kNoFile;
  XNode root;
};

struct TreeError {
  Span span;
  std::string message;
};

// Parses `file` (spans carry `id`): the tree, or the first well-formedness problem.
std::optional<SourceTree> parse_tree(std::shared_ptr<const SourceFile> file, FileId id, TreeError& error);

}  // namespace assetlint::xacro
