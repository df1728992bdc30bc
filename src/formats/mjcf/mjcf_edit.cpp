#include "formats/mjcf/mjcf_edit.h"

#include <fmt/format.h>

#include <cmath>

#include "util/numbers.h"

namespace assetlint::mjcf {

bool read_from_attribute(const SourceFile& file, const Quantity& q, std::string_view name) {
  if (!q.declaration.valid() || q.declaration.offset == q.span.offset) return false;
  const std::string_view text = file.view().substr(q.declaration.offset, q.declaration.length);
  if (!text.starts_with(name)) return false;
  const std::size_t rest = text.find_first_not_of(" \t\r\n", name.size());
  return rest != std::string_view::npos && text[rest] == '=';
}

std::optional<Edit> rescaled_range(const SourceFile& file, const Quantity& bound, double magnitude,
                                   std::string (*format)(double)) {
  const std::string_view text = file.view();
  if (!bound.span.valid() || bound.span.end() > text.size() || !(magnitude > 0)) return std::nullopt;
  // The quoted value around the token.
  const std::size_t open = text.find_last_of("\"'", bound.span.offset == 0 ? 0 : bound.span.offset - 1);
  if (open == std::string_view::npos) return std::nullopt;
  const std::size_t close = text.find(text[open], bound.span.end());
  if (close == std::string_view::npos) return std::nullopt;
  const std::string_view value = text.substr(open + 1, close - open - 1);
  const auto numbers = parse_doubles(value);
  if (!numbers || numbers->size() != 2) return std::nullopt;
  const double larger = std::max(std::abs((*numbers)[0]), std::abs((*numbers)[1]));
  if (!(larger > 0) || !std::isfinite(larger)) return std::nullopt;
  const auto end = [&](double v) {
    if (v == 0) return std::string("0");
    const std::string digits = format(std::abs(v) * magnitude / larger);
    return v < 0 ? "-" + digits : digits;
  };
  // Both ends in one edit: the leading whitespace and quoting around them stay as they were.
  const std::size_t first = value.find_first_not_of(" \t\r\n");
  const std::size_t last = value.find_last_not_of(" \t\r\n");
  return Edit{bound.span.file, open + 1 + first, last - first + 1,
              fmt::format("{} {}", end((*numbers)[0]), end((*numbers)[1]))};
}

}  // namespace assetlint::mjcf
