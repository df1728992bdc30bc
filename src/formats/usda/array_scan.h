#pragma once
// Fast structural scan of numeric array literals (`[(0, 1.5, -2e-3), ...]`), used to
// skip large mesh arrays without tokenizing them into nodes.
#include <cstddef>
#include <optional>
#include <string_view>

namespace assetlint::usda {

struct ArrayScan {
  std::size_t end = 0;    // offset just past the closing ']'
  std::size_t count = 0;  // number of top-level items
};

// Scans the list starting at text[start] == '['. Accepts numbers (also inf, -inf, nan),
// nested tuples/lists of numbers, commas (a trailing one too), whitespace and comments.
// Returns nullopt for anything else, including malformed input: the caller then parses
// the list normally, which reports the precise error.
std::optional<ArrayScan> scan_numeric_array(std::string_view text, std::size_t start, std::size_t max_depth);

}  // namespace assetlint::usda
