#include "formats/usdc/crate_value_nodes.h"

#include <algorithm>

#include "formats/usda/literals.h"
#include "formats/usdc/crate_types.h"

namespace assetlint::usdc {
namespace {

using Mark = std::function<Span()>;

}  // namespace

NumberCache::Read read_as_text(Num num, const char* p) {
  std::string text;
  append_stored_number(text, num, p);
  // What the lexer calls a float: a fraction, an exponent, inf or nan.
  return {usda::parse_number(text), text.find_first_of(".eEin") == std::string::npos};
}

namespace {

template <class Bits, class Map>
NumberCache::Read cached(Map& map, Num num, const char* p) {
  const auto [it, added] = map.try_emplace(load<Bits>(p));
  if (added) it->second = read_as_text(num, p);
  return it->second;
}

// Nodes are filled where they stand (a node is large: moving one costs as much as filling it).
// `file` names the strings, tokens and asset paths; a number needs none.
void component_node(usda::Value& v, const CrateFile* file, Num num, const char* p, const std::string& what,
                    const Mark& mark, NumberCache& numbers) {
  v.span = mark();
  switch (num) {
    case Num::StringIdx:
    case Num::TokenIdx: {
      const auto index = load<std::uint32_t>(p);
      v.kind = usda::ValueKind::String;
      v.text = as_read(num == Num::TokenIdx ? file->token(index, what.c_str()) : file->string(index, what.c_str()));
      return;
    }
    case Num::AssetIdx:
      v.kind = usda::ValueKind::AssetPath;
      v.text = usda::decode_asset_path(asset_literal(file->string(load<std::uint32_t>(p), what.c_str())));
      return;
    default: break;
  }
  const NumberCache::Read read = num == Num::Float    ? cached<std::uint32_t>(numbers.floats, num, p)
                                 : num == Num::Double ? cached<std::uint64_t>(numbers.doubles, num, p)
                                                      : read_as_text(num, p);
  v.kind = usda::ValueKind::Number;
  v.number = read.number;
  v.is_integer = read.is_integer;
}

void element_node(usda::Value& out, const CrateFile* file, const Element& e, const char* p, const std::string& what,
                  const Mark& mark, NumberCache& numbers) {
  if (e.components == 1) return component_node(out, file, e.num, p, what, mark, numbers);
  const std::size_t size = size_of(e.num);
  // Crate stores a quaternion x, y, z, w; USDA writes w first.
  const auto stored = [&](int i) { return p + static_cast<std::size_t>(e.quat ? (i + 3) % 4 : i) * size; };
  out.kind = usda::ValueKind::Tuple;
  out.span = mark();
  if (e.rows) {
    out.elements.resize(static_cast<std::size_t>(e.rows));
    for (int r = 0; r < e.rows; ++r) {
      usda::Value& row = out.elements[static_cast<std::size_t>(r)];
      row.kind = usda::ValueKind::Tuple;
      row.span = mark();
      row.elements.resize(static_cast<std::size_t>(e.rows));
      for (int k = 0; k < e.rows; ++k)
        component_node(row.elements[static_cast<std::size_t>(k)], file, e.num, stored(r * e.rows + k), what, mark, numbers);
      row.count = row.elements.size();
    }
  } else {
    out.elements.resize(static_cast<std::size_t>(e.components));
    for (int i = 0; i < e.components; ++i)
      component_node(out.elements[static_cast<std::size_t>(i)], file, e.num, stored(i), what, mark, numbers);
  }
  out.count = out.elements.size();
}

}  // namespace

void number_element_node(usda::Value& out, const Element& e, const char* p, const std::function<Span()>& mark,
                         NumberCache& numbers) {
  element_node(out, nullptr, e, p, "", mark, numbers);
}

std::string as_read(std::string_view s) {
  const bool plain = std::none_of(s.begin(), s.end(), [](char ch) {
    const auto c = static_cast<unsigned char>(ch);
    return c < 0x20 || c == 0x7F || ch == '"' || ch == '\\';
  });
  return plain ? std::string(s) : usda::decode_string(quoted(s));
}

std::optional<usda::Value> value_node(const ValueReader& values, const CrateFile& file, ValueRep rep,
                                      const std::string& what, bool in_metadata, const std::function<Span()>& mark,
                                      NumberCache& numbers) {
  if (values.is_list_op(rep)) return std::nullopt;
  const Element* e = element_of(rep.type());
  if (!e) return std::nullopt;
  if (rep.is_array()) {
    const ArrayItems a = values.array_items(rep, what);
    const bool numeric = e->num != Num::StringIdx && e->num != Num::TokenIdx && e->num != Num::AssetIdx;
    if (numeric && a.count > kEagerArrayItems) return std::nullopt;
    usda::Value list;
    list.kind = usda::ValueKind::List;
    list.span = mark();
    const std::size_t element_bytes = size_of(e->num) * static_cast<std::size_t>(e->components);
    list.elements.resize(a.count);
    for (std::size_t i = 0; i < a.count; ++i)
      element_node(list.elements[i], &file, *e, a.bytes().data() + i * element_bytes, what, mark, numbers);
    list.count = list.elements.size();
    return list;
  }
  if (e->num == Num::AssetIdx) {
    // An asset path value holds a token index (in arrays, string indexes).
    usda::Value v;
    v.kind = usda::ValueKind::AssetPath;
    v.span = mark();
    v.text = usda::decode_asset_path(asset_literal(file.token(static_cast<std::uint32_t>(rep.payload()), what.c_str())));
    return v;
  }
  const std::string bytes = values.element_bytes(rep, *e, what);
  if (in_metadata && e->num == Num::Bool) {
    usda::Value v;
    v.kind = usda::ValueKind::Identifier;
    v.span = mark();
    v.text = bytes[0] ? "true" : "false";
    return v;
  }
  usda::Value v;
  element_node(v, &file, *e, bytes.data(), what, mark, numbers);
  return v;
}

}  // namespace assetlint::usdc
