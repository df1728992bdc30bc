#pragma once
// Reads the values of a crate layer's fields and writes them as USDA literals, the way
// OpenUSD's text writer spells them (quaternions w first, floats in their shortest
// round-trip form, tokens quoted, asset paths in @...@).
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include "formats/usdc/crate_file.h"

namespace assetlint::usdc {

// A value of a type this reader does not write as USDA (splines, unregistered values):
// the field is left out of the layer.
struct UnsupportedValue {
  std::string what;
};

// A value as USDA writes it, with the type name a dictionary entry declares.
struct Literal {
  std::string type;  // "double3", "token[]", "dictionary"; empty for untyped values
  std::string text;
};

enum class ItemOp { Explicit, Add, Prepend, Append, Delete, Reorder };
const char* item_op_keyword(ItemOp op);  // "" for Explicit

// A list-op value (apiSchemas, references, relationship targets, ...): its item lists in
// the order USDA writes them.
struct ListOpValue {
  bool is_explicit = false;
  std::vector<std::pair<ItemOp, std::vector<std::string>>> parts;
};

struct Element;

// The items of an array value, decompressed: `count` elements, stored as crate stores them.
struct ArrayItems {
  const Element* element = nullptr;
  std::string storage;   // decoded items (compressed arrays)
  std::string_view raw;  // the items in the file (uncompressed arrays)
  std::size_t count = 0;
  std::string_view bytes() const { return storage.empty() ? raw : std::string_view(storage); }
};

class ValueReader {
 public:
  explicit ValueReader(const CrateFile& file) : file_(file) {}

  bool is_list_op(ValueRep rep) const;
  // `what` names the field in errors ("</robot.physics:mass> default").
  Literal literal(ValueRep rep, const std::string& what, int indent = 0);
  // The literal appended to `out` (mesh arrays are megabytes: not copied); returns its type.
  std::string append_literal(ValueRep rep, const std::string& what, int indent, std::string& out);
  ListOpValue list_op(ValueRep rep, const std::string& what);
  // A token vector or string vector, as views of the file's tokens.
  std::vector<std::string_view> tokens(ValueRep rep, const std::string& what) const;
  std::string token(ValueRep rep, const std::string& what);  // a token value, unquoted
  std::uint32_t enum_value(ValueRep rep, const std::string& what);         // specifier, variability, permission
  bool boolean(ValueRep rep, const std::string& what);
  std::vector<std::pair<std::string, std::string>> string_map(ValueRep rep, const std::string& what);
  std::vector<std::pair<double, double>> layer_offsets(ValueRep rep, const std::string& what);
  // The decoded items of an array value, and one element's stored bytes (inlined forms
  // expanded): what the nodes of crate_value_nodes.h are built from.
  ArrayItems array_items(ValueRep rep, const std::string& what) const;
  // An array value's literal appended to `out`; returns its item count.
  std::size_t append_array(ValueRep rep, const std::string& what, std::string& out) const;
  std::string element_bytes(ValueRep rep, const Element& element, const std::string& what) const;
  std::vector<std::pair<std::string, Literal>> time_samples(ValueRep rep, const std::string& what, int indent);
  // A dictionary value's entries (key, value), in file order; nested values are not checked
  // for containing themselves here: the caller limits its depth.
  std::vector<std::pair<std::string_view, ValueRep>> dictionary_entries(ValueRep rep, const std::string& what) const;

 private:
  class Guard;
  Literal scalar(ValueRep rep, const std::string& what, int indent);
  std::string array(ValueRep rep, const std::string& what, std::string& out);
  std::string dictionary(Cursor& c, const std::string& what, int indent);
  Literal vt_value(Cursor& c, const std::string& what, int indent);
  ValueRep vt_rep(Cursor& c, const std::string& what) const;
  std::string arc(Cursor& c, unsigned type, const std::string& what, int indent);
  std::vector<std::string> items(Cursor& c, unsigned type, const std::string& what, int indent);
  Cursor at(ValueRep rep, const std::string& what) const;

  const CrateFile& file_;
  std::unordered_set<std::uint64_t> active_;  // values being read (a value containing itself is an error)
  int depth_ = 0;
};

std::string quoted(std::string_view s);
std::string asset_literal(std::string_view s);

}  // namespace assetlint::usdc
