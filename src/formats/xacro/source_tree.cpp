#include "formats/xacro/source_tree.h"
#include <algorithm>

#include <fmt/format.h>
#include <tinyxml2.h>

#include "formats/xml/xml_scanner.h"
#include "formats/xml/xml_spans.h"

namespace assetlint::xacro {

const XAttribute* XNode::attribute(std::string_view attr) const {
  for (const auto& a : attributes)
    if (a.name == attr) return &a;
  return nullptr;
}

const XNode* XNode::first_element() const {
  for (const auto& c : children)
    if (c.kind == Kind::Element) return &c;
  return nullptr;
}

namespace {

class Builder {
 public:
  Builder(const SourceFile& file, FileId id, const xml::XmlScan& scan, std::size_t line_offset)
      : file_(file), id_(id), scan_(scan), line_offset_(line_offset) {}

  bool build(const tinyxml2::XMLElement* el, XNode& out) {
    out.kind = XNode::Kind::Element;
    out.name = el->Name();
    if (next_ >= scan_.tags.size() || scan_.tags[next_].name != out.name) return false;
    const xml::XmlStartTag& tag = scan_.tags[next_++];
    out.span = xml::tag_span(file_, id_, tag);
    for (const xml::XmlAttributeSpan& a : tag.attributes) {
      XAttribute attr;
      attr.name = std::string(a.name);
      const std::string_view raw = file_.view().substr(a.value_offset, a.value_length);
      attr.value = xml::decode_attribute_value(raw);
      // Attribute-value normalisation, as expat (xacro's parser) applies it: every line break
      // and tab reads as a space.
      for (char& c : attr.value)
        if (c == '\n' || c == '\t') c = ' ';
      attr.verbatim = attr.value == raw;
      attr.value_span = file_.span(id_, a.value_offset, a.value_length);
      out.attributes.push_back(std::move(attr));
    }
    int comment_end = -1;  // the line the comment just before ends on
    for (const tinyxml2::XMLNode* child = el->FirstChild(); child; child = child->NextSibling()) {
      // tinyxml2 drops the white space between two markup nodes, and xacro stops dropping the
      // comments before a xacro construct at a blank line: a blank line after a comment stays.
      if (comment_end >= 0 && !child->ToText() && child->GetLineNum() - comment_end >= 2)
        out.children.push_back(leaf(XNode::Kind::Text, "\n\n", comment_end));
      comment_end = -1;
      if (const auto* e = child->ToElement()) {
        XNode node;
        if (!build(e, node)) return false;
        out.children.push_back(std::move(node));
      } else if (const auto* t = child->ToText()) {
        out.children.push_back(leaf(XNode::Kind::Text, t->Value(), child->GetLineNum()));
      } else if (const auto* c = child->ToComment()) {
        out.children.push_back(leaf(XNode::Kind::Comment, c->Value(), child->GetLineNum()));
        const std::string& text = out.children.back().name;
        comment_end = child->GetLineNum() + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
      }
    }
    return true;
  }

 private:
  XNode leaf(XNode::Kind kind, const char* text, int line) const {
    XNode node;
    node.kind = kind;
    node.name = text ? text : "";
    const auto l = static_cast<std::uint32_t>(std::max(1, line) + static_cast<int>(line_offset_) - 1);
    node.span = file_.span(id_, file_.line_start(std::min(l, file_.line_count())), 0);
    return node;
  }

  const SourceFile& file_;
  FileId id_;
  const xml::XmlScan& scan_;
  std::size_t line_offset_;
  std::size_t next_ = 0;
};

}  // namespace

std::optional<SourceTree> parse_tree(std::shared_ptr<const SourceFile> file, FileId id, TreeError& error) {
  const xml::XmlScan scan = xml::scan_xml(file->view());
  if (!scan.problems.empty()) {
    const auto& p = scan.problems.front();
    // A problem at the end of the file (no root element) has no byte of its own to point at.
    const std::size_t size = file->view().size();
    const std::size_t offset = std::min(p.offset, size);
    error = {file->span(id, offset, std::min(p.length, size - offset)), p.message};
    return std::nullopt;
  }
  tinyxml2::XMLDocument doc(true, tinyxml2::PRESERVE_WHITESPACE);
  const std::string_view text = file->view().substr(scan.document_begin, scan.document_end - scan.document_begin);
  if (doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS || !doc.RootElement()) {
    error = {file->span(id, scan.document_begin, 0), fmt::format("not well-formed XML: {}", doc.ErrorStr())};
    return std::nullopt;
  }
  SourceTree tree;
  tree.file = file;
  tree.id = id;
  Builder builder(*file, id, scan, file->position(scan.document_begin).line);
  if (!builder.build(doc.RootElement(), tree.root)) {
    error = {file->span(id, scan.document_begin, 0), "the XML scanner and tinyxml2 read this file differently"};
    return std::nullopt;
  }
  return tree;
}

}  // namespace assetlint::xacro
