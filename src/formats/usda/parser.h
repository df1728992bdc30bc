#pragma once
// Recursive-descent parser for the USD text format (.usda).
//
//   SourceFile file(path, text);
//   ParseResult r = parse_layer(file, id);
//   if (!r.ok()) report(r.error().message, r.error().span);
//   const Layer& layer = r.layer();
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "formats/usda/ast.h"
#include "formats/usda/literals.h"
#include "model/source.h"

namespace assetlint::usda {

struct ParseError {
  std::string message;  // "expected '=' after attribute name 'physics:mass', found ')'"
  Span span;            // the offending token (line/column 1-based)
};

struct ParseOptions {
  // Deepest nesting of prims, variants, lists, tuples and dictionaries accepted.
  std::size_t max_depth = 256;
  // Numeric array values (`float3[] points = [...]`) with more items than this are kept
  // lazy: only their span and item count are stored.
  std::size_t eager_array_limit = 16;
  bool lazy_arrays = true;
};

class ParseResult {
 public:
  ParseResult(Layer layer) : v_(std::move(layer)) {}
  ParseResult(ParseError error) : v_(std::move(error)) {}

  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }
  const Layer& layer() const { return std::get<Layer>(v_); }
  Layer& layer() { return std::get<Layer>(v_); }
  const ParseError& error() const { return std::get<ParseError>(v_); }

 private:
  std::variant<Layer, ParseError> v_;
};

// Parses one whole layer. Never throws on bad input (only std::bad_alloc may escape).
ParseResult parse_layer(const SourceFile& file, FileId id, const ParseOptions& options = {});

// Parses the value written in file[begin, end) as it would be read in a layer: the value
// of metadata `metadata_key` (references, payload, ... as arc lists), or, with the key
// empty, the default or a time sample of an attribute of type `attribute_type` ("float3[]":
// a large numeric array stays lazy, as parse_layer keeps it).
std::variant<Value, ParseError> parse_value_at(const SourceFile& file, FileId id, std::size_t begin, std::size_t end,
                                               std::string_view metadata_key, std::string_view attribute_type);

// Parses the items of a lazy list value (or returns a copy of a materialized one's).
// `file` must be the file the value was parsed from.
std::variant<std::vector<Value>, ParseError> parse_elements(const Value& list, const SourceFile& file,
                                                            FileId id);
// Replaces a lazy list's items in place; returns the error if its text does not parse.
std::optional<ParseError> materialize(Value& list, const SourceFile& file, FileId id);

// Reads every number of a value in text order, flattening tuples and lists
// ([(1, 2, 3), (4, 5, 6)] gives 1..6). Works on lazy lists without building nodes.
// Returns false (and leaves `out` partly filled) if a non-number item is found.
bool read_numbers(const Value& value, std::string_view text, std::vector<double>& out);

}  // namespace assetlint::usda
