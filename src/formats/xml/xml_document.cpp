#include "formats/xml/xml_document.h"

#include <fmt/format.h>

#include <algorithm>

#include "formats/xml/xml_spans.h"

namespace assetlint::xml {

using tinyxml2::XMLElement;

XmlDocument::XmlDocument(const SourceFile& file, FileId id)
    : file_(file), id_(id), doc_(std::make_unique<tinyxml2::XMLDocument>(true, tinyxml2::COLLAPSE_WHITESPACE)) {
  scan_ = scan_xml(file_.view());
  for (const auto& problem : scan_.problems) errors_.push_back({file_.span(id_, problem.offset, problem.length), problem.message});
  if (!scan_.recoverable) return;
  const std::string_view text = document();
  if (doc_->Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
    const int line_in_document = std::max(1, doc_->ErrorLineNum());
    const std::uint32_t line = file_.position(scan_.document_begin).line + static_cast<std::uint32_t>(line_in_document) - 1;
    errors_.push_back({file_.span(id_, file_.line_start(line), 0), fmt::format("not well-formed XML: {}", doc_->ErrorStr())});
    return;
  }
  parsed_ = true;
  index_elements();
}

const XMLElement* XmlDocument::root() const { return parsed_ ? doc_->RootElement() : nullptr; }

std::string_view XmlDocument::document() const {
  return file_.view().substr(scan_.document_begin, scan_.document_end - scan_.document_begin);
}

// Pairs each tinyxml2 element with the scanner's start tag: both list elements in
// document order, so the n-th element of a pre-order walk is the n-th start tag.
void XmlDocument::index_elements() {
  std::size_t next = 0;
  bool consistent = true;
  auto visit = [&](auto&& self, const XMLElement* el) -> void {
    if (!el) return;
    if (next < scan_.tags.size() && scan_.tags[next].name == el->Name()) tags_[el] = &scan_.tags[next];
    else consistent = false;
    ++next;
    for (const XMLElement* c = el->FirstChildElement(); c; c = c->NextSiblingElement()) self(self, c);
  };
  visit(visit, doc_->RootElement());
  if (!consistent) tags_.clear();  // positions fall back to line starts
}

const XmlAttributeSpan* XmlDocument::attribute(const XMLElement* el, std::string_view attr) const {
  auto it = tags_.find(el);
  return it == tags_.end() ? nullptr : it->second->attribute(attr);
}

std::optional<std::string_view> XmlDocument::raw_value(const XMLElement* el, std::string_view attr) const {
  const XmlAttributeSpan* a = attribute(el, attr);
  if (!a) return std::nullopt;
  return file_.view().substr(a->value_offset, a->value_length);
}

Span XmlDocument::element_span(const XMLElement* el) const {
  if (!el) return file_.span(id_, scan_.document_begin, 0);
  if (auto it = tags_.find(el); it != tags_.end()) return tag_span(file_, id_, *it->second);
  const auto line = file_.position(scan_.document_begin).line + static_cast<std::uint32_t>(el->GetLineNum()) - 1;
  return file_.span(id_, file_.line_start(line), 0);
}

Span XmlDocument::value_span(const XMLElement* el, std::string_view attr) const {
  const XmlAttributeSpan* a = attribute(el, attr);
  return a ? xml::value_span(file_, id_, *a) : element_span(el);
}

Span XmlDocument::attribute_span(const XMLElement* el, std::string_view attr) const {
  const XmlAttributeSpan* a = attribute(el, attr);
  return a ? xml::attribute_span(file_, id_, *a) : element_span(el);
}

Span XmlDocument::token_span(const XMLElement* el, std::string_view attr, std::size_t index) const {
  const XmlAttributeSpan* a = attribute(el, attr);
  return a ? xml::token_span(file_, id_, *a, index) : element_span(el);
}

}  // namespace assetlint::xml
