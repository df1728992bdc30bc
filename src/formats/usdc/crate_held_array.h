#pragma once
// A crate layer's long numeric arrays (mesh points, normals, face indices) kept lazy as the
// USDA parser keeps them, but as the crate stores them: no text is written for them. Their
// numbers are read when asked (usda::read_numbers, usda::materialize), each the one its USDA
// text reads as (a float goes through its shortest written form).
#include <memory>

#include "formats/usda/ast.h"
#include "formats/usdc/crate_values.h"

namespace assetlint::usdc {

// The items of a numeric array value (not strings, tokens or asset paths); `items` is
// taken over (the file's bytes need not outlive the layer). `span` locates every node
// built from it.
std::shared_ptr<const usda::HeldItems> hold_numeric_array(ArrayItems items, Span span);

}  // namespace assetlint::usdc
