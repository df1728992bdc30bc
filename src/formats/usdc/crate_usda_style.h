#pragma once
// How OpenUSD's text writer lays out a crate layer's declarations: which fields are
// structure rather than metadata, the order of properties, the names it accepts bare, and
// list-op items written with or without brackets. Shared by the USDA writer (`cat`) and
// the reader that builds the layer without the text.
#include <string>
#include <string_view>
#include <vector>

namespace assetlint::usdc {

bool valid_name(std::string_view s, bool namespaced);
bool valid_type_name(std::string_view s);

// Fields that are the layer's structure, written as declarations rather than metadata.
bool is_structural_field(std::string_view key);

// List-op metadata that OpenUSD's text writer writes without brackets when it holds one item.
bool bare_when_single(std::string_view key);

// Names in the order OpenUSD's text writer lists properties: letters without regard to
// case ('_' before them), digit runs by value, then byte order.
bool dictionary_less(std::string_view a, std::string_view b);

// `[a, b]`, one item a line when the items carry parameters (`@a@ (offset = 1)`).
std::string bracketed(const std::vector<std::string>& items, int indent);

std::string indentation(int indent);

}  // namespace assetlint::usdc
