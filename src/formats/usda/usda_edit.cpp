#include "formats/usda/usda_edit.h"

namespace assetlint::usda {

AttributeLine attribute_before(std::string_view text, std::size_t neighbour, std::string_view declaration) {
  std::size_t start = neighbour == 0 ? std::string_view::npos : text.rfind('\n', neighbour - 1);
  start = start == std::string_view::npos ? 0 : start + 1;
  std::size_t indent_end = start;
  while (indent_end < text.size() && (text[indent_end] == ' ' || text[indent_end] == '\t')) ++indent_end;
  const std::size_t end = text.find('\n', neighbour);
  const bool crlf = end != std::string_view::npos && end > 0 && text[end - 1] == '\r';
  return AttributeLine{start, std::string(text.substr(start, indent_end - start)) + std::string(declaration) +
                                  (crlf ? "\r\n" : "\n")};
}

}  // namespace assetlint::usda
