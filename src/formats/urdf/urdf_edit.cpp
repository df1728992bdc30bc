#include "formats/urdf/urdf_edit.h"

namespace assetlint::urdf {

std::optional<std::size_t> start_tag_close(std::string_view text, std::size_t element_offset) {
  char quote = 0;
  for (std::size_t i = element_offset; i < text.size(); ++i) {
    const char c = text[i];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '>') {
      std::size_t at = i > element_offset && text[i - 1] == '/' ? i - 1 : i;
      while (at > element_offset && (text[at - 1] == ' ' || text[at - 1] == '\t')) --at;
      return at;
    }
  }
  return std::nullopt;
}

}  // namespace assetlint::urdf
