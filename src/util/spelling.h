#pragma once
// "Did you mean …?" for a mistyped command, rule id or option value.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace assetlint {

// Edits (insert, delete, substitute, swap two neighbours) that turn `a` into `b`.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate nearest `word`, when it is near enough to be a slip of the keyboard (one edit
// in a short word, up to a third of the word's letters in a long one); nullopt otherwise.
std::optional<std::string> nearest_spelling(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace assetlint
