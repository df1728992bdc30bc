#include "formats/usdc/crate_values.h"


#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <cmath>
#include <cstring>

#include "formats/usdc/crate_types.h"
#include "formats/usdc/crate_usda_style.h"

namespace assetlint::usdc {
namespace {

constexpr int kMaxValueDepth = 32;
constexpr std::size_t kMinCompressedArray = 16;

template <class F>
std::string real(F v) {
  std::string out;
  append_real(out, v);
  return out;
}

bool identifier(std::string_view s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

}  // namespace

// Marks a value as being read, so that a value that contains itself is found.
class ValueReader::Guard {
 public:
  Guard(ValueReader& r, std::uint64_t key, const std::string& what) : r_(r), key_(key) {
    if (++r_.depth_ > kMaxValueDepth) fail(what, fmt::format("values nest deeper than {} levels", kMaxValueDepth));
    if (!r_.active_.insert(key).second) fail(what, "a value contains itself");
  }
  ~Guard() {
    --r_.depth_;
    r_.active_.erase(key_);
  }
  Guard(const Guard&) = delete;
  Guard& operator=(const Guard&) = delete;

 private:
  ValueReader& r_;
  std::uint64_t key_;
};

const char* item_op_keyword(ItemOp op) {
  switch (op) {
    case ItemOp::Add: return "add";
    case ItemOp::Prepend: return "prepend";
    case ItemOp::Append: return "append";
    case ItemOp::Delete: return "delete";
    case ItemOp::Reorder: return "reorder";
    default: return "";
  }
}

std::string quoted(std::string_view s) {
  const bool multiline = s.find('\n') != std::string_view::npos;
  std::string out = multiline ? "\"\"\"" : "\"";
  for (char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (ch == '"') out += "\\\"";
    else if (ch == '\\') out += "\\\\";
    else if (ch == '\n') out += multiline ? "\n" : "\\n";
    else if (ch == '\t') out += "\\t";
    else if (ch == '\r') out += "\\r";
    else if (c < 0x20 || c == 0x7F) out += fmt::format("\\x{:02x}", c);
    else out += ch;
  }
  out += multiline ? "\"\"\"" : "\"";
  return out;
}

std::string asset_literal(std::string_view s) {
  if (s.find('@') == std::string_view::npos) return fmt::format("@{}@", s);
  std::string out = "@@@";
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.substr(i, 3) == "@@@") {
      out += "\\@@@";
      i += 2;
    } else {
      out += s[i];
    }
  }
  return out + "@@@";
}

Cursor ValueReader::at(ValueRep rep, const std::string& what) const {
  Cursor c(file_.bytes(), what.c_str());
  c.seek(rep.payload());
  return c;
}

bool ValueReader::is_list_op(ValueRep rep) const {
  const unsigned t = rep.type();
  return (t >= kTokenListOp && t <= kUInt64ListOp) || t == kPayloadListOp || t == kUnregisteredValueListOp;
}

namespace {

std::string element_text(const CrateFile& file, const Element& e, const char* p, const std::string& what) {
  std::string out;
  append_element(out, file, e, p, what);
  return out;
}

}  // namespace

Literal ValueReader::literal(ValueRep rep, const std::string& what, int indent) {
  if (is_list_op(rep)) throw UnsupportedValue{what};
  if (rep.is_array()) {
    Literal out;
    out.type = array(rep, what, out.text);
    return out;
  }
  return scalar(rep, what, indent);
}

std::string ValueReader::append_literal(ValueRep rep, const std::string& what, int indent, std::string& out) {
  if (is_list_op(rep)) throw UnsupportedValue{what};
  if (rep.is_array()) return array(rep, what, out);
  Literal value = scalar(rep, what, indent);
  out += value.text;
  return std::move(value.type);
}

std::string ValueReader::element_bytes(ValueRep rep, const Element& element, const std::string& what) const {
  const Element* e = &element;
  const std::size_t size = size_of(e->num);
  std::string bytes(size * static_cast<std::size_t>(e->components), '\0');
  const std::uint32_t low = static_cast<std::uint32_t>(rep.payload());
  const bool always_inlined = e->components == 1 && size <= 4;
  if (always_inlined) {
    std::memcpy(bytes.data(), &low, size);
  } else if (rep.is_inlined()) {
    // Doubles stored as floats, 64-bit integers as 32-bit ones, vectors as int8
    // components, matrices as an int8 diagonal.
    if (e->num == Num::Double && e->components == 1) {
      const double d = load<float>(reinterpret_cast<const char*>(&low));
      std::memcpy(bytes.data(), &d, 8);
    } else if (e->num == Num::I64) {
      const std::int64_t v = static_cast<std::int32_t>(low);
      std::memcpy(bytes.data(), &v, 8);
    } else if (e->num == Num::U64) {
      const std::uint64_t v = low;
      std::memcpy(bytes.data(), &v, 8);
    } else if (!e->quat && e->components > 1) {
      std::int8_t small[4];
      std::memcpy(small, &low, 4);
      const int n = e->rows ? e->rows : e->components;
      for (int i = 0; i < e->components; ++i) {
        const bool diagonal = e->rows && i % (e->rows + 1) == 0;
        const int source = e->rows ? i / (e->rows + 1) : i;
        const double v = e->rows ? (diagonal ? small[source] : 0.0) : (i < n ? small[i] : 0);
        char* dst = bytes.data() + static_cast<std::size_t>(i) * size;
        switch (e->num) {
          case Num::Double: std::memcpy(dst, &v, 8); break;
          case Num::Float: { const float f = static_cast<float>(v); std::memcpy(dst, &f, 4); break; }
          case Num::I32: { const std::int32_t k = static_cast<std::int32_t>(v); std::memcpy(dst, &k, 4); break; }
          case Num::Half: {
            // int8 values are exact in half precision: build the bits from the float.
            const float f = static_cast<float>(v);
            std::uint32_t b;
            std::memcpy(&b, &f, 4);
            std::uint16_t h = static_cast<std::uint16_t>((b >> 16) & 0x8000);
            if (f != 0.0f) h |= static_cast<std::uint16_t>((((b >> 23) & 0xFF) - 112) << 10 | ((b >> 13) & 0x3FF));
            std::memcpy(dst, &h, 2);
            break;
          }
          default: break;
        }
      }
    } else {
      fail(what, fmt::format("value of type {} cannot be inlined", e->name));
    }
  } else {
    Cursor c = at(rep, what);
    c.read_bytes(bytes.data(), bytes.size());
  }
  return bytes;
}

Literal ValueReader::scalar(ValueRep rep, const std::string& what, int indent) {
  const unsigned type = rep.type();
  if (const Element* e = element_of(type)) {
    // An asset path value holds a token index (in arrays, string indexes).
    if (e->num == Num::AssetIdx)
      return {e->name, asset_literal(file_.token(static_cast<std::uint32_t>(rep.payload()), what.c_str()))};
    const std::string bytes = element_bytes(rep, *e, what);
    return {e->name, element_text(file_, *e, bytes.data(), what)};
  }
  const std::uint32_t low = static_cast<std::uint32_t>(rep.payload());
  switch (type) {
    case kValueBlock: return {"", "None"};
    case kSpecifier: return {"", low == 0 ? "def" : low == 1 ? "over" : "class"};
    case kPermission: return {"", low == 0 ? "public" : "private"};
    case kVariability: return {"", low == 0 ? "varying" : "uniform"};
    case kDictionary: {
      if (rep.is_inlined()) return {"dictionary", "{\n" + indentation(indent) + "}"};
      Guard guard(*this, rep.data, what);
      Cursor c = at(rep, what);
      return {"dictionary", dictionary(c, what, indent)};
    }
    case kTokenVector:
    case kStringVector:
    case kPathVector:
    case kDoubleVector: {
      Cursor c = at(rep, what);
      const std::size_t n = c.count(c.read<std::uint64_t>(), type == kDoubleVector ? 8 : 4, "items");
      std::string out = "[";
      for (std::size_t i = 0; i < n; ++i) {
        if (i) out += ", ";
        if (type == kDoubleVector) out += real(c.read<double>());
        else if (type == kTokenVector) out += quoted(file_.token(c.read<std::uint32_t>(), what.c_str()));
        else if (type == kStringVector) out += quoted(file_.string(c.read<std::uint32_t>(), what.c_str()));
        else out += "<" + file_.path(c.read<std::uint32_t>(), what.c_str()).text + ">";
      }
      const char* t = type == kDoubleVector ? "double[]" : type == kTokenVector ? "token[]" : type == kStringVector ? "string[]" : "";
      return {t, out + "]"};
    }
    case kPayload: {
      Cursor c = at(rep, what);
      return {"", arc(c, kPayloadListOp, what, indent)};
    }
    case kValue:
    case kUnregisteredValue: {
      Guard guard(*this, rep.data, what);
      Cursor c = at(rep, what);
      return vt_value(c, what, indent);
    }
    case kPathExpression: {
      Cursor c = at(rep, what);
      return {"pathExpression", quoted(file_.string(c.read<std::uint32_t>(), what.c_str()))};
    }
    case kRelocates: {
      Cursor c = at(rep, what);
      const std::size_t n = c.count(c.read<std::uint64_t>(), 8, "relocates");
      std::string out = "{\n";
      for (std::size_t i = 0; i < n; ++i) {
        const std::string from = file_.path(c.read<std::uint32_t>(), what.c_str()).text;
        const std::string to = file_.path(c.read<std::uint32_t>(), what.c_str()).text;
        out += indentation(indent + 1) + "<" + from + ">: <" + to + ">,\n";
      }
      return {"", out + indentation(indent) + "}"};
    }
    default: break;
  }
  throw UnsupportedValue{what};
}

ArrayItems ValueReader::array_items(ValueRep rep, const std::string& what) const {
  const Element* e = element_of(rep.type());
  if (!e) fail(what, fmt::format("type {} cannot be an array", rep.type()));
  ArrayItems result;
  result.element = e;
  if (rep.payload() == 0) return result;
  Cursor c = at(rep, what);
  const Version& v = file_.version();
  if (!v.at_least(0, 5)) c.read<std::uint32_t>();  // rank, written before 0.5.0
  const std::uint64_t claimed = v.at_least(0, 7) ? c.read<std::uint64_t>() : c.read<std::uint32_t>();
  const std::size_t size = size_of(e->num);
  const std::size_t element_bytes = size * static_cast<std::size_t>(e->components);
  std::string& data = result.storage;
  const bool integer = e->components == 1 && (e->num == Num::I32 || e->num == Num::U32 || e->num == Num::I64 || e->num == Num::U64);
  const bool real_number = e->components == 1 && (e->num == Num::Half || e->num == Num::Float || e->num == Num::Double);
  if (rep.is_compressed() && claimed >= kMinCompressedArray && ((integer && v.at_least(0, 5)) || (real_number && v.at_least(0, 6)))) {
    // At most ~1000 integers per compressed byte (LZ4 and 2-bit codes); checked again when decoded.
    if (claimed > std::uint64_t{c.remaining()} * 1024 + 1024) c.fail(fmt::format("{} array items claimed", claimed));
    const auto n = static_cast<std::size_t>(claimed);
    data.resize(n * element_bytes);
    const auto store = [&](std::size_t i, auto value) {
      using T = decltype(value);
      switch (e->num) {
        case Num::I32: { const auto x = static_cast<std::int32_t>(value); std::memcpy(&data[i * 4], &x, 4); break; }
        case Num::U32: { const auto x = static_cast<std::uint32_t>(value); std::memcpy(&data[i * 4], &x, 4); break; }
        case Num::I64: { const auto x = static_cast<std::int64_t>(value); std::memcpy(&data[i * 8], &x, 8); break; }
        case Num::U64: { const auto x = static_cast<std::uint64_t>(value); std::memcpy(&data[i * 8], &x, 8); break; }
        case Num::Float: { const auto x = static_cast<float>(value); std::memcpy(&data[i * 4], &x, 4); break; }
        case Num::Double: { const auto x = static_cast<double>(value); std::memcpy(&data[i * 8], &x, 8); break; }
        default: (void)sizeof(T); break;
      }
    };
    if (integer) {
      if (size == 8) {
        const auto ints = read_compressed_i64(c, n);
        for (std::size_t i = 0; i < n; ++i) store(i, ints[i]);
      } else {
        const auto ints = read_compressed_i32(c, n);
        for (std::size_t i = 0; i < n; ++i) std::memcpy(&data[i * 4], &ints[i], 4);
      }
    } else {
      const char code = c.read<char>();
      if (code == 'i') {
        const auto ints = read_compressed_i32(c, n);
        for (std::size_t i = 0; i < n; ++i) {
          if (e->num == Num::Half) {
            // Small integers are exact in half precision; write them as floats via the text.
            const float f = static_cast<float>(ints[i]);
            std::uint32_t b;
            std::memcpy(&b, &f, 4);
            std::uint16_t h = static_cast<std::uint16_t>((b >> 16) & 0x8000);
            if (f != 0.0f) h |= static_cast<std::uint16_t>((((b >> 23) & 0xFF) - 112) << 10 | ((b >> 13) & 0x3FF));
            std::memcpy(&data[i * 2], &h, 2);
          } else {
            store(i, ints[i]);
          }
        }
      } else if (code == 't') {
        const std::size_t lut_size = c.count(c.read<std::uint32_t>(), size, "lookup table entries");
        const std::string_view lut = c.take(lut_size * size);
        const auto indexes = read_compressed_u32(c, n);
        for (std::size_t i = 0; i < n; ++i) {
          if (indexes[i] >= lut_size) c.fail(fmt::format("lookup index {} of {}", indexes[i], lut_size));
          std::memcpy(&data[i * size], lut.data() + indexes[i] * size, size);
        }
      } else {
        c.fail(fmt::format("unknown compressed array code {}", static_cast<int>(code)));
      }
    }
  }
  if (data.empty()) {
    const std::size_t n = c.count(claimed, element_bytes, "array items");
    result.raw = c.take(n * element_bytes);
  }
  result.count = result.bytes().size() / element_bytes;
  return result;
}

std::string ValueReader::array(ValueRep rep, const std::string& what, std::string& out) {
  append_array(rep, what, out);
  return std::string(element_of(rep.type())->name) + "[]";
}

std::size_t ValueReader::append_array(ValueRep rep, const std::string& what, std::string& out) const {
  const ArrayItems a = array_items(rep, what);
  const Element* e = a.element;
  const std::size_t element_bytes = size_of(e->num) * static_cast<std::size_t>(e->components);
  const std::size_t n = a.count;
  // About ten characters a component and a separator: one allocation for mesh arrays.
  out.reserve(out.size() + n * (static_cast<std::size_t>(e->components) * 10 + 4) + 2);
  out += '[';
  for (std::size_t i = 0; i < n; ++i) {
    if (i) out += ", ";
    append_element(out, file_, *e, a.bytes().data() + i * element_bytes, what);
  }
  out += ']';
  return n;
}

std::string ValueReader::dictionary(Cursor& c, const std::string& what, int indent) {
  const std::size_t n = c.count(c.read<std::uint64_t>(), 12, "dictionary entries");
  std::string out = "{\n";
  for (std::size_t i = 0; i < n; ++i) {
    const std::string& key = file_.string(c.read<std::uint32_t>(), what.c_str());
    Literal value = vt_value(c, what + ":" + key, indent + 1);
    if (value.type.empty()) fail(what, fmt::format("dictionary entry '{}' has a value without a type", key));
    out += indentation(indent + 1) + value.type + " " + (identifier(key) ? key : quoted(key)) + " = " + value.text + "\n";
  }
  return out + indentation(indent) + "}";
}

ValueRep ValueReader::vt_rep(Cursor& c, const std::string& what) const {
  const std::size_t start = c.tell();
  const auto offset = c.read<std::int64_t>();
  if (offset < 0 || static_cast<std::uint64_t>(offset) > c.remaining() + 8) c.fail(fmt::format("value offset {} leaves the file", offset));
  c.seek(start + static_cast<std::uint64_t>(offset));
  const ValueRep rep{c.read<std::uint64_t>()};
  if (is_list_op(rep)) throw UnsupportedValue{what};
  return rep;
}

Literal ValueReader::vt_value(Cursor& c, const std::string& what, int indent) {
  return literal(vt_rep(c, what), what, indent);
}

std::vector<std::pair<std::string_view, ValueRep>> ValueReader::dictionary_entries(ValueRep rep, const std::string& what) const {
  std::vector<std::pair<std::string_view, ValueRep>> out;
  if (rep.type() != kDictionary || rep.is_array()) fail(what, fmt::format("expected a dictionary, found value type {}", rep.type()));
  if (rep.is_inlined()) return out;
  Cursor c = at(rep, what);
  const std::size_t n = c.count(c.read<std::uint64_t>(), 12, "dictionary entries");
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::string& key = file_.string(c.read<std::uint32_t>(), what.c_str());
    out.emplace_back(key, vt_rep(c, what));
  }
  return out;
}

std::string ValueReader::arc(Cursor& c, unsigned type, const std::string& what, int indent) {
  const std::string asset = file_.string(c.read<std::uint32_t>(), what.c_str());
  const std::string prim = file_.path(c.read<std::uint32_t>(), what.c_str()).text;
  double offset = 0.0, scale = 1.0;
  std::string custom;
  if (type == kReferenceListOp || file_.version().at_least(0, 8)) {
    offset = c.read<double>();
    scale = c.read<double>();
  }
  if (type == kReferenceListOp) {
    Guard guard(*this, (std::uint64_t{1} << 63) | c.tell(), what);
    const std::string dict = dictionary(c, what, indent + 1);
    if (dict.find('=') != std::string::npos) custom = dict;
  }
  std::string out = asset.empty() ? "" : asset_literal(asset);
  if (!prim.empty()) out += "<" + prim + ">";
  if (out.empty()) fail(what, "a reference names neither a layer nor a prim");
  std::vector<std::string> params;
  if (offset != 0.0) params.push_back("offset = " + real(offset));
  if (scale != 1.0) params.push_back("scale = " + real(scale));
  if (!custom.empty()) params.push_back("customData = " + custom);
  if (!params.empty()) {
    out += " (";
    for (std::size_t i = 0; i < params.size(); ++i) out += (i ? "; " : "") + params[i];
    out += ")";
  }
  return out;
}

std::vector<std::string> ValueReader::items(Cursor& c, unsigned type, const std::string& what, int indent) {
  const std::size_t min = type == kInt64ListOp || type == kUInt64ListOp ? 8 : 4;
  const std::size_t n = c.count(c.read<std::uint64_t>(), min, "list items");
  std::vector<std::string> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    switch (type) {
      case kTokenListOp: out.push_back(quoted(file_.token(c.read<std::uint32_t>(), what.c_str()))); break;
      case kStringListOp: out.push_back(quoted(file_.string(c.read<std::uint32_t>(), what.c_str()))); break;
      case kPathListOp: out.push_back("<" + file_.path(c.read<std::uint32_t>(), what.c_str()).text + ">"); break;
      case kReferenceListOp:
      case kPayloadListOp: out.push_back(arc(c, type, what, indent)); break;
      case kIntListOp: out.push_back(fmt::format("{}", c.read<std::int32_t>())); break;
      case kUIntListOp: out.push_back(fmt::format("{}", c.read<std::uint32_t>())); break;
      case kInt64ListOp: out.push_back(fmt::format("{}", c.read<std::int64_t>())); break;
      case kUInt64ListOp: out.push_back(fmt::format("{}", c.read<std::uint64_t>())); break;
      default: throw UnsupportedValue{what};
    }
  }
  return out;
}

ListOpValue ValueReader::list_op(ValueRep rep, const std::string& what) {
  const unsigned type = rep.type();
  if (type == kUnregisteredValueListOp) throw UnsupportedValue{what};
  Cursor c = at(rep, what);
  const auto bits = c.read<std::uint8_t>();
  ListOpValue out;
  out.is_explicit = bits & 1;
  // The file order: explicit, added, prepended, appended, deleted, ordered.
  const std::pair<unsigned, ItemOp> order[] = {{1u << 1, ItemOp::Explicit}, {1u << 2, ItemOp::Add},
                                               {1u << 5, ItemOp::Prepend},  {1u << 6, ItemOp::Append},
                                               {1u << 3, ItemOp::Delete},   {1u << 4, ItemOp::Reorder}};
  for (const auto& [bit, op] : order)
    if (bits & bit) out.parts.push_back({op, items(c, type, what, 1)});
  return out;
}

std::vector<std::string_view> ValueReader::tokens(ValueRep rep, const std::string& what) const {
  std::vector<std::string_view> out;
  if (rep.type() == kTokenVector || rep.type() == kStringVector) {
    Cursor c = at(rep, what);
    const std::size_t n = c.count(c.read<std::uint64_t>(), 4, "names");
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto index = c.read<std::uint32_t>();
      out.push_back(rep.type() == kTokenVector ? file_.token(index, what.c_str()) : file_.string(index, what.c_str()));
    }
    return out;
  }
  fail(what, fmt::format("expected a list of names, found value type {}", rep.type()));
}

std::string ValueReader::token(ValueRep rep, const std::string& what) {
  if (rep.type() != kToken || rep.is_array()) fail(what, fmt::format("expected a token, found value type {}", rep.type()));
  return file_.token(static_cast<std::uint32_t>(rep.payload()), what.c_str());
}

std::uint32_t ValueReader::enum_value(ValueRep rep, const std::string& what) {
  if (rep.type() != kSpecifier && rep.type() != kVariability && rep.type() != kPermission)
    fail(what, fmt::format("expected an enumerated value, found value type {}", rep.type()));
  return static_cast<std::uint32_t>(rep.payload());
}

bool ValueReader::boolean(ValueRep rep, const std::string& what) {
  if (rep.type() != kBool || rep.is_array()) fail(what, fmt::format("expected a bool, found value type {}", rep.type()));
  return (rep.payload() & 0xFF) != 0;
}

std::vector<std::pair<std::string, std::string>> ValueReader::string_map(ValueRep rep, const std::string& what) {
  if (rep.type() != kVariantSelectionMap) fail(what, fmt::format("expected variant selections, found value type {}", rep.type()));
  Cursor c = at(rep, what);
  const std::size_t n = c.count(c.read<std::uint64_t>(), 8, "selections");
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t i = 0; i < n; ++i) {
    std::string key = file_.string(c.read<std::uint32_t>(), what.c_str());
    std::string value = file_.string(c.read<std::uint32_t>(), what.c_str());
    out.emplace_back(std::move(key), std::move(value));
  }
  return out;
}

std::vector<std::pair<double, double>> ValueReader::layer_offsets(ValueRep rep, const std::string& what) {
  if (rep.type() != kLayerOffsetVector) fail(what, fmt::format("expected layer offsets, found value type {}", rep.type()));
  Cursor c = at(rep, what);
  const std::size_t n = c.count(c.read<std::uint64_t>(), 16, "layer offsets");
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i < n; ++i) {
    const double offset = c.read<double>();
    const double scale = c.read<double>();
    out.emplace_back(offset, scale);
  }
  return out;
}

std::vector<std::pair<std::string, Literal>> ValueReader::time_samples(ValueRep rep, const std::string& what, int indent) {
  if (rep.type() != kTimeSamples) fail(what, fmt::format("expected time samples, found value type {}", rep.type()));
  Cursor c = at(rep, what);
  const auto jump = [&] {
    const std::size_t start = c.tell();
    const auto offset = c.read<std::int64_t>();
    if (offset < 8) c.fail(fmt::format("time samples offset {} points backwards", offset));
    c.seek(start + static_cast<std::uint64_t>(offset));
  };
  jump();
  const ValueRep times_rep{c.read<std::uint64_t>()};
  std::vector<double> times;
  {
    Guard guard(*this, times_rep.data, what);
    if (times_rep.type() == kDoubleVector || (times_rep.type() == kDouble && times_rep.is_array())) {
      Cursor t = at(times_rep, what);
      if (times_rep.is_array() && !file_.version().at_least(0, 5)) t.read<std::uint32_t>();
      const std::uint64_t claimed =
          times_rep.type() == kDoubleVector || file_.version().at_least(0, 7) ? t.read<std::uint64_t>() : t.read<std::uint32_t>();
      const std::size_t n = t.count(claimed, 8, "sample times");
      for (std::size_t i = 0; i < n; ++i) times.push_back(t.read<double>());
    } else {
      fail(what, fmt::format("time samples: times of value type {}", times_rep.type()));
    }
  }
  jump();
  const std::size_t n = c.count(c.read<std::uint64_t>(), 8, "sample values");
  if (n != times.size()) c.fail(fmt::format("{} sample times and {} values", times.size(), n));
  std::vector<std::pair<std::string, Literal>> out;
  for (std::size_t i = 0; i < n; ++i) {
    const ValueRep value{c.read<std::uint64_t>()};
    out.emplace_back(real(times[i]), literal(value, what, indent));
  }
  return out;
}

}  // namespace assetlint::usdc
