#include "util/binary_data.h"

namespace assetlint {

std::optional<std::size_t> first_binary_byte(std::string_view text, std::size_t window) {
  const std::size_t end = text.size() < window ? text.size() : window;
  for (std::size_t i = 0; i < end; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f') return i;
    if (c == 0x7F) return i;
  }
  return std::nullopt;
}

}  // namespace assetlint
