#pragma once
// The common values of a crate layer (numbers, vectors, quaternions, matrices, tokens,
// strings, asset paths, and short arrays of them) built as the nodes the USDA parser reads
// from their literals, without writing the literals: numbers are formatted as the text
// writer formats them and read back as the parser reads them, so each node is the one the
// text gives. Other values are read from their literal (crate_layer.cpp).
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>

#include "formats/usda/ast.h"
#include "formats/usdc/crate_types.h"
#include "formats/usdc/crate_values.h"
#include "model/source.h"

namespace assetlint::usdc {

// Numeric arrays longer than this are left to the parser, which keeps them lazy.
inline constexpr std::size_t kEagerArrayItems = 16;

// Numbers as the parser reads their written form, by their stored bits: a layer repeats a
// few values (0, 1, the same limits and gains) many times.
struct NumberCache {
  struct Read {
    double number;
    bool is_integer;
  };
  std::unordered_map<std::uint32_t, Read> floats;
  std::unordered_map<std::uint64_t, Read> doubles;
};

// Nullopt for a value of another kind or a numeric array of more than kEagerArrayItems.
// `in_metadata`: a bool reads as the identifier true/false (the writer spells it so there).
// `mark` gives each node its span.
std::optional<usda::Value> value_node(const ValueReader& values, const CrateFile& file, ValueRep rep,
                                      const std::string& what, bool in_metadata, const std::function<Span()>& mark,
                                      NumberCache& numbers);

// A stored number (not a string, token or asset index) as the parser reads its written form.
NumberCache::Read read_as_text(Num num, const char* p);
// An element of numbers (scalar, vector, quaternion, matrix) as its node.
void number_element_node(usda::Value& out, const Element& e, const char* p, const std::function<Span()>& mark,
                         NumberCache& numbers);

// A name or string as the parser reads back its quoted form.
std::string as_read(std::string_view s);

}  // namespace assetlint::usdc
