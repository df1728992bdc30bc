#include "formats/xml/scanned_document.h"

#include "formats/xml/xml_spans.h"

namespace assetlint::xml {

ScannedDocument::ScannedDocument(const SourceFile& file, FileId id) : file_(file), id_(id), scan_(scan_xml(file.view())) {
  for (const auto& problem : scan_.problems) errors_.push_back({file_.span(id_, problem.offset, problem.length), problem.message});
}

const Element* ScannedDocument::root() const {
  return scan_.recoverable && !scan_.tags.empty() ? &scan_.tags.front() : nullptr;
}

std::string_view ScannedDocument::document() const {
  return file_.view().substr(scan_.document_begin, scan_.document_end - scan_.document_begin);
}

const Element* ScannedDocument::at(std::uint32_t index, std::string_view name) const {
  while (index != Element::kNone) {
    const Element& el = scan_.tags[index];
    if (name.empty() || el.name == name) return &el;
    index = el.next_sibling;
  }
  return nullptr;
}

const Element* ScannedDocument::first_child(const Element* el, std::string_view name) const {
  return el ? at(el->first_child, name) : nullptr;
}

const Element* ScannedDocument::next_sibling(const Element* el, std::string_view name) const {
  return el ? at(el->next_sibling, name) : nullptr;
}

std::optional<std::string_view> ScannedDocument::raw_value(const Element* el, std::string_view attr) const {
  const XmlAttributeSpan* a = el ? el->attribute(attr) : nullptr;
  if (!a) return std::nullopt;
  return file_.view().substr(a->value_offset, a->value_length);
}

std::string_view ScannedDocument::value(const XmlAttributeSpan& attr) const {
  const std::string_view raw = file_.view().substr(attr.value_offset, attr.value_length);
  if ((!scan_.ampersand && !scan_.carriage_return) || !attribute_value_needs_decoding(raw)) return raw;
  return decoded_.emplace_back(decode_attribute_value(raw));
}

std::optional<std::string_view> ScannedDocument::value(const Element* el, std::string_view attr) const {
  const XmlAttributeSpan* a = el ? el->attribute(attr) : nullptr;
  if (!a) return std::nullopt;
  return value(*a);
}

Span ScannedDocument::element_span(const Element* el) const {
  return el ? tag_span(file_, id_, *el) : file_.span(id_, scan_.document_begin, 0);
}

Span ScannedDocument::value_span(const Element* el, std::string_view attr) const {
  const XmlAttributeSpan* a = el ? el->attribute(attr) : nullptr;
  return a ? xml::value_span(file_, id_, *a) : element_span(el);
}

Span ScannedDocument::attribute_span(const Element* el, std::string_view attr) const {
  const XmlAttributeSpan* a = el ? el->attribute(attr) : nullptr;
  return a ? xml::attribute_span(file_, id_, *a) : element_span(el);
}

}  // namespace assetlint::xml
