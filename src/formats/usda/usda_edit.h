#pragma once
// Adding an attribute line to a prim in USDA text, beside one it already authors.
#include <string>
#include <string_view>

namespace assetlint::usda {

struct AttributeLine {
  std::size_t offset = 0;  // where to insert: the start of the neighbour's line
  std::string text;        // the neighbour's indentation + the declaration + its line ending
};

// A new attribute declaration (`float drive:angular:physics:maxForce = 24`) on its own
// line just above the line holding the byte `neighbour` (an attribute the same prim spec
// already authors), with the same indentation and line ending. Inserting at a line's
// start never touches an edit of the neighbour's value.
AttributeLine attribute_before(std::string_view text, std::size_t neighbour, std::string_view declaration);

}  // namespace assetlint::usda
