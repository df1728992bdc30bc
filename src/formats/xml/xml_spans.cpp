#include "formats/xml/xml_spans.h"

#include "util/numbers.h"

namespace assetlint::xml {

Span tag_span(const SourceFile& file, FileId id, const XmlStartTag& tag) {
  return file.span(id, tag.offset, tag.end - tag.offset);
}

Span value_span(const SourceFile& file, FileId id, const XmlAttributeSpan& attr) {
  const std::string_view raw = file.view().substr(attr.value_offset, attr.value_length);
  const std::string_view trimmed = trim(raw);
  const std::size_t lead = trimmed.empty() ? 0 : static_cast<std::size_t>(trimmed.data() - raw.data());
  return file.span(id, attr.value_offset + lead, trimmed.size());
}

Span attribute_span(const SourceFile& file, FileId id, const XmlAttributeSpan& attr) {
  return file.span(id, attr.name_offset, attr.value_offset + attr.value_length + 1 - attr.name_offset);
}

Span token_span(const SourceFile& file, FileId id, const XmlAttributeSpan& attr, std::size_t index) {
  const std::string_view raw = file.view().substr(attr.value_offset, attr.value_length);
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  std::size_t pos = 0;
  for (std::size_t n = 0;; ++n) {
    while (pos < raw.size() && space(raw[pos])) ++pos;
    if (pos >= raw.size()) return value_span(file, id, attr);
    std::size_t end = pos;
    while (end < raw.size() && !space(raw[end])) ++end;
    if (n == index) return file.span(id, attr.value_offset + pos, end - pos);
    pos = end;
  }
}

}  // namespace assetlint::xml
