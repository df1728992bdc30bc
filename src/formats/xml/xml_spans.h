#pragma once
// Spans of the scanner's start tags and attributes: what both XML document classes hand
// to the readers.
#include "formats/xml/xml_scanner.h"
#include "model/source.h"

namespace assetlint::xml {

// The start tag, '<' to '>'.
Span tag_span(const SourceFile& file, FileId id, const XmlStartTag& tag);
// An attribute's value without surrounding spaces.
Span value_span(const SourceFile& file, FileId id, const XmlAttributeSpan& attr);
// The whole `name="value"` text of an attribute.
Span attribute_span(const SourceFile& file, FileId id, const XmlAttributeSpan& attr);
// The index-th whitespace-separated token of an attribute's value (the value when there is none).
Span token_span(const SourceFile& file, FileId id, const XmlAttributeSpan& attr, std::size_t index);

}  // namespace assetlint::xml
