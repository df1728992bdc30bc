#pragma once
// The pieces each format's suppression scanner shares: the directive inside a comment
// (`asset-lint: ignore[...]`, `asset-lint: ignore-file[...]`) and a few character tests.
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "formats/suppressions.h"

namespace assetlint::suppression_syntax {

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
inline bool is_blank(char c) { return c == ' ' || c == '\t'; }
inline bool starts_with_at(std::string_view text, std::size_t at, std::string_view prefix) {
  return at <= text.size() && text.substr(at, prefix.size()) == prefix;
}

// Parses the directive in a comment's body, if it has one. `offset`/`length` locate the
// whole comment in the file.
std::optional<SuppressionComment> parse_directive(std::string_view body, std::size_t offset, std::size_t length);

// The suppression comments of an XML text (URDF), each with the element it covers.
std::vector<SuppressionComment> scan_xml(std::string_view text);
// The suppression comments of a USDA text, each with the prim or statement it covers.
std::vector<SuppressionComment> scan_usda(std::string_view text);

}  // namespace assetlint::suppression_syntax
