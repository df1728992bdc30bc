#include "crate_writer.h"

#include <lz4.h>

#include <cstring>
#include <limits>
#include <map>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>

namespace assetlint::test::crate {
namespace {

// Crate's value type numbers (OpenUSD crateDataTypes.h).
enum Type : std::uint64_t {
  kBool = 1, kFloat = 8, kDouble = 9, kString = 10, kToken = 11, kVec3f = 24, kTokenListOp = 32, kStringListOp = 33,
  kPathListOp = 34, kReferenceListOp = 35, kTokenVector = 41, kSpecifier = 42, kVariability = 44, kVariantSelectionMap = 45,
  kPayloadListOp = 55
};

constexpr std::uint64_t kInlinedBit = std::uint64_t{1} << 62;
constexpr std::uint32_t kFieldSetEnd = 0xFFFFFFFF;

class Bytes {
 public:
  template <class T>
  void put(T v) {
    const auto* p = reinterpret_cast<const char*>(&v);
    data_.append(p, sizeof v);
  }
  void append(const std::string& s) { data_ += s; }
  std::size_t size() const { return data_.size(); }
  std::string& data() { return data_; }

 private:
  std::string data_;
};

// TfFastCompression's form: a chunk count (0: one block) and one LZ4 block.
std::string fast_compress(const std::string& raw) {
  std::string out(static_cast<std::size_t>(LZ4_compressBound(static_cast<int>(raw.size()))) + 1, '\0');
  const int n = LZ4_compress_default(raw.data(), out.data() + 1, static_cast<int>(raw.size()), static_cast<int>(out.size() - 1));
  if (n <= 0) throw std::runtime_error("LZ4 compression failed");
  out.resize(static_cast<std::size_t>(n) + 1);
  return out;
}

// Crate's integer coding: the most common delta, 2-bit codes (0 common, 1/2/3 for a delta
// stored in a quarter, half or whole of the integer's width), then the stored deltas.
template <class Int>
std::string encode_ints(const std::vector<Int>& values) {
  using SInt = std::make_signed_t<Int>;
  using Small = std::conditional_t<sizeof(Int) == 4, std::int8_t, std::int16_t>;
  using Medium = std::conditional_t<sizeof(Int) == 4, std::int16_t, std::int32_t>;
  std::vector<SInt> deltas;
  SInt previous = 0;
  std::map<SInt, std::size_t> counts;
  for (Int v : values) {
    // Deltas wrap as unsigned integers do (the reader adds them back the same way).
    using UInt = std::make_unsigned_t<Int>;
    const SInt delta = static_cast<SInt>(static_cast<UInt>(v) - static_cast<UInt>(previous));
    deltas.push_back(delta);
    ++counts[delta];
    previous = static_cast<SInt>(v);
  }
  SInt common = 0;
  std::size_t best = 0;
  for (const auto& [delta, count] : counts)
    if (count >= best) {  // ties: the largest delta, as OpenUSD picks
      common = delta;
      best = count;
    }
  std::string codes((values.size() * 2 + 7) / 8, '\0');
  Bytes stored;
  for (std::size_t i = 0; i < deltas.size(); ++i) {
    const SInt d = deltas[i];
    unsigned code = 3;
    if (d == common) code = 0;
    else if (d >= std::numeric_limits<Small>::min() && d <= std::numeric_limits<Small>::max()) {
      code = 1;
      stored.put(static_cast<Small>(d));
    } else if (d >= std::numeric_limits<Medium>::min() && d <= std::numeric_limits<Medium>::max()) {
      code = 2;
      stored.put(static_cast<Medium>(d));
    } else {
      stored.put(d);
    }
    codes[i / 4] = static_cast<char>(codes[i / 4] | (code << (2 * (i % 4))));
  }
  Bytes out;
  if (values.empty()) return fast_compress("");
  out.put(common);
  out.append(codes);
  out.append(stored.data());
  return fast_compress(out.data());
}

// A list of integers as crate's structural sections store them: byte size, then the data.
template <class Int>
void put_ints(Bytes& out, const std::vector<Int>& values) {
  const std::string packed = encode_ints(values);
  out.put<std::uint64_t>(packed.size());
  out.append(packed);
}

// A path's parent and last element ("{PhysX=Enabled}", "finger", ".drive:x" as a property).
struct Element {
  std::string parent, name;
  bool property = false;
};

Element split(const std::string& path) {
  if (path.back() == '}') {
    const auto open = path.rfind('{');
    return {path.substr(0, open), path.substr(open), false};
  }
  const auto k = path.find_last_of("/}.");
  if (path[k] == '.') return {path.substr(0, k), path.substr(k + 1), true};
  if (path[k] == '/') return {k == 0 ? "/" : path.substr(0, k), path.substr(k + 1), false};
  return {path.substr(0, k + 1), path.substr(k + 1), false};
}

class Writer {
 public:
  std::string run(const std::vector<Spec>& given) {
    std::vector<Spec> specs = with_children(given);
    for (const Spec& s : specs) add_path(s.path);
    for (const Spec& s : specs) {
      std::vector<std::uint32_t> set;
      for (const auto& [name, value] : s.fields) {
        field_tokens_.push_back(token(name));
        field_reps_.push_back(rep(value));
        set.push_back(static_cast<std::uint32_t>(field_reps_.size() - 1));
      }
      spec_paths_.push_back(path_index_.at(s.path));
      spec_sets_.push_back(static_cast<std::uint32_t>(field_sets_.size()));
      spec_types_.push_back(static_cast<std::uint32_t>(s.type));
      field_sets_.insert(field_sets_.end(), set.begin(), set.end());
      field_sets_.push_back(kFieldSetEnd);
    }
    return layout();
  }

 private:
  // The specs with the children fields Sdf keeps for their paths.
  static std::vector<Spec> with_children(std::vector<Spec> specs) {
    std::unordered_map<std::string, std::size_t> index;
    for (std::size_t i = 0; i < specs.size(); ++i) index.emplace(specs[i].path, i);
    std::vector<TokenVector> prims(specs.size()), properties(specs.size()), sets(specs.size()), variants(specs.size());
    for (const Spec& s : specs) {
      if (s.path == "/") continue;
      const Element e = split(s.path);
      const auto parent = index.find(e.parent);
      if (parent == index.end()) throw std::invalid_argument("no spec for the parent of " + s.path);
      const std::size_t p = parent->second;
      switch (s.type) {
        case SpecType::Prim: prims[p].items.push_back(e.name); break;
        case SpecType::Attribute:
        case SpecType::Relationship: properties[p].items.push_back(e.name); break;
        case SpecType::VariantSet: sets[p].items.push_back(e.name.substr(1, e.name.size() - 3)); break;
        case SpecType::Variant: {
          const auto eq = e.name.find('=');
          const std::string set_path = e.parent + e.name.substr(0, eq + 1) + "}";
          const auto set = index.find(set_path);
          if (set == index.end()) throw std::invalid_argument("no variant set spec for " + s.path);
          variants[set->second].items.push_back(e.name.substr(eq + 1, e.name.size() - eq - 2));
          break;
        }
        default: break;
      }
    }
    for (std::size_t i = 0; i < specs.size(); ++i) {
      if (!prims[i].items.empty()) specs[i].fields.emplace_back("primChildren", prims[i]);
      if (!properties[i].items.empty()) specs[i].fields.emplace_back("properties", properties[i]);
      if (!sets[i].items.empty()) specs[i].fields.emplace_back("variantSetChildren", sets[i]);
      if (!variants[i].items.empty()) specs[i].fields.emplace_back("variantChildren", variants[i]);
    }
    return specs;
  }

  std::uint32_t token(const std::string& s) {
    const auto [it, added] = token_index_.emplace(s, static_cast<std::uint32_t>(tokens_.size()));
    if (added) tokens_.push_back(s);
    return it->second;
  }

  std::uint32_t string(const std::string& s) {
    const auto [it, added] = string_index_.emplace(s, static_cast<std::uint32_t>(strings_.size()));
    if (added) strings_.push_back(token(s));
    return it->second;
  }

  // Paths and their ancestors; the empty path (a payload to a layer's default prim) is the
  // one path outside the tree.
  std::uint32_t add_path(const std::string& path) {
    if (auto it = path_index_.find(path); it != path_index_.end()) return it->second;
    if (path.empty()) {
      const auto index = static_cast<std::uint32_t>(paths_.size());
      paths_.push_back({"", "", false});
      return path_index_[path] = index;
    }
    if (path != "/") add_path(split(path).parent);
    const auto index = static_cast<std::uint32_t>(paths_.size());
    paths_.push_back(path == "/" ? Element{"", "", false} : split(path));
    path_index_[path] = index;
    if (path != "/") children_[paths_.back().parent].push_back(path);
    return index;
  }

  std::uint64_t inlined(std::uint64_t type, std::uint32_t payload) { return kInlinedBit | (type << 48) | payload; }

  // A value stored in the data area; returns its rep.
  std::uint64_t stored(std::uint64_t type, const std::string& bytes) {
    const std::uint64_t offset = kBootstrapSize + data_.size();
    data_.append(bytes);
    return (type << 48) | offset;
  }

  template <class T>
  std::string list_op_bytes(const ListOp<T>& op, void (Writer::*item)(Bytes&, const T&)) {
    Bytes b;
    std::uint8_t bits = op.is_explicit ? 1 : 0;
    if (!op.explicit_items.empty()) bits |= 1 << 1;
    if (!op.deleted.empty()) bits |= 1 << 3;
    if (!op.prepended.empty()) bits |= 1 << 5;
    if (!op.appended.empty()) bits |= 1 << 6;
    b.put(bits);
    for (const auto* list : {&op.explicit_items, &op.prepended, &op.appended, &op.deleted}) {
      if (list->empty()) continue;
      b.put<std::uint64_t>(list->size());
      for (const T& x : *list) (this->*item)(b, x);
    }
    return b.data();
  }

  void token_item(Bytes& b, const std::string& s) { b.put(token(s)); }
  void string_item(Bytes& b, const std::string& s) { b.put(string(s)); }
  void path_item(Bytes& b, const std::string& s) { b.put(add_path(s)); }
  void payload_item(Bytes& b, const Payload& p) {
    b.put(string(p.asset));
    b.put(add_path(p.prim));
    b.put(0.0);  // layer offset
    b.put(1.0);  // layer scale
  }
  void reference_item(Bytes& b, const Reference& r) {
    payload_item(b, r);
    b.put<std::uint64_t>(0);  // custom data: an empty dictionary
  }

  std::uint64_t rep(const Value& value) {
    if (const auto* v = std::get_if<bool>(&value)) return inlined(kBool, *v ? 1 : 0);
    if (const auto* v = std::get_if<Float>(&value)) {
      std::uint32_t bits;
      std::memcpy(&bits, &v->value, 4);
      return inlined(kFloat, bits);
    }
    if (const auto* v = std::get_if<Double>(&value)) {
      // A double that a float holds exactly is inlined as that float, as OpenUSD writes it.
      const auto f = static_cast<float>(v->value);
      if (static_cast<double>(f) == v->value) {
        std::uint32_t bits;
        std::memcpy(&bits, &f, 4);
        return inlined(kDouble, bits);
      }
      Bytes b;
      b.put(v->value);
      return stored(kDouble, b.data());
    }
    if (const auto* v = std::get_if<Float3>(&value)) {
      Bytes b;
      for (float c : {v->x, v->y, v->z}) b.put(c);
      return stored(kVec3f, b.data());
    }
    if (const auto* v = std::get_if<Token>(&value)) return inlined(kToken, token(v->value));
    if (const auto* v = std::get_if<String>(&value)) return inlined(kString, string(v->value));
    if (const auto* v = std::get_if<Specifier>(&value)) return inlined(kSpecifier, static_cast<std::uint32_t>(*v));
    if (const auto* v = std::get_if<Variability>(&value)) return inlined(kVariability, static_cast<std::uint32_t>(*v));
    if (const auto* v = std::get_if<TokenVector>(&value)) {
      Bytes b;
      b.put<std::uint64_t>(v->items.size());
      for (const auto& t : v->items) b.put(token(t));
      return stored(kTokenVector, b.data());
    }
    if (const auto* v = std::get_if<Selections>(&value)) {
      Bytes b;
      b.put<std::uint64_t>(v->items.size());
      for (const auto& [set, name] : v->items) {
        b.put(string(set));
        b.put(string(name));
      }
      return stored(kVariantSelectionMap, b.data());
    }
    if (const auto* v = std::get_if<TokenListOp>(&value)) return stored(kTokenListOp, list_op_bytes<std::string>(*v, &Writer::token_item));
    if (const auto* v = std::get_if<StringListOp>(&value)) return stored(kStringListOp, list_op_bytes<std::string>(*v, &Writer::string_item));
    if (const auto* v = std::get_if<PathListOp>(&value)) return stored(kPathListOp, list_op_bytes<std::string>(*v, &Writer::path_item));
    if (const auto* v = std::get_if<ReferenceListOp>(&value))
      return stored(kReferenceListOp, list_op_bytes<Reference>(*v, &Writer::reference_item));
    const auto& op = std::get<PayloadListOp>(value);
    return stored(kPayloadListOp, list_op_bytes<Payload>(op, &Writer::payload_item));
  }

  // The path tree depth first: a jump says whether an entry has a child (the next entry)
  // and a sibling (0: the next entry, > 0: that many entries on, -1: none but a child, -2: neither).
  void tree(const std::string& path, std::vector<std::uint32_t>& indexes, std::vector<std::int32_t>& elements,
            std::vector<std::int32_t>& jumps) {
    const auto& siblings = children_[path];
    for (std::size_t k = 0; k < siblings.size(); ++k) {
      const std::string& p = siblings[k];
      const std::size_t at = indexes.size();
      const Element& e = paths_[path_index_.at(p)];
      indexes.push_back(path_index_.at(p));
      const auto t = static_cast<std::int32_t>(token(e.name));
      elements.push_back(e.property ? -t : t);
      jumps.push_back(0);
      const bool child = !children_[p].empty(), sibling = k + 1 < siblings.size();
      if (child) tree(p, indexes, elements, jumps);
      jumps[at] = child && sibling ? static_cast<std::int32_t>(indexes.size() - at) : sibling ? 0 : child ? -1 : -2;
    }
  }

  std::string layout() {
    // Every token is known before the tokens section is written: the path elements' too.
    std::vector<std::uint32_t> indexes{path_index_.at("/")};
    std::vector<std::int32_t> elements{0}, jumps{children_["/"].empty() ? -2 : -1};
    tree("/", indexes, elements, jumps);

    Bytes file;
    file.append(std::string(kBootstrapSize, '\0'));
    file.append(data_);
    struct Section {
      const char* name;
      std::uint64_t start, size;
    };
    std::vector<Section> toc;
    const auto section = [&](const char* name, const Bytes& body) {
      toc.push_back({name, file.size(), body.size()});
      file.append(const_cast<Bytes&>(body).data());
    };

    Bytes tokens;
    std::string chars;
    for (const auto& t : tokens_) chars += t + '\0';
    const std::string packed = fast_compress(chars);
    tokens.put<std::uint64_t>(tokens_.size());
    tokens.put<std::uint64_t>(chars.size());
    tokens.put<std::uint64_t>(packed.size());
    tokens.append(packed);
    section("TOKENS", tokens);

    Bytes strings;
    strings.put<std::uint64_t>(strings_.size());
    for (auto s : strings_) strings.put(s);
    section("STRINGS", strings);

    Bytes fields;
    fields.put<std::uint64_t>(field_tokens_.size());
    put_ints(fields, field_tokens_);
    std::string reps(field_reps_.size() * 8, '\0');
    if (!field_reps_.empty()) std::memcpy(reps.data(), field_reps_.data(), reps.size());
    const std::string packed_reps = fast_compress(reps);
    fields.put<std::uint64_t>(packed_reps.size());
    fields.append(packed_reps);
    section("FIELDS", fields);

    Bytes sets;
    sets.put<std::uint64_t>(field_sets_.size());
    put_ints(sets, field_sets_);
    section("FIELDSETS", sets);

    Bytes paths;
    paths.put<std::uint64_t>(paths_.size());
    paths.put<std::uint64_t>(indexes.size());
    put_ints(paths, indexes);
    put_ints(paths, elements);
    put_ints(paths, jumps);
    section("PATHS", paths);

    Bytes specs;
    specs.put<std::uint64_t>(spec_paths_.size());
    put_ints(specs, spec_paths_);
    put_ints(specs, spec_sets_);
    put_ints(specs, spec_types_);
    section("SPECS", specs);

    const std::uint64_t toc_offset = file.size();
    file.put<std::uint64_t>(toc.size());
    for (const Section& s : toc) {
      char name[16] = {};
      std::strncpy(name, s.name, sizeof name - 1);
      file.data().append(name, sizeof name);
      file.put(s.start);
      file.put(s.size);
    }
    std::string& bytes = file.data();
    std::memcpy(bytes.data(), "PXR-USDC", 8);
    bytes[8] = 0, bytes[9] = 8, bytes[10] = 0;  // version 0.8.0
    std::memcpy(bytes.data() + 16, &toc_offset, 8);
    return bytes;
  }

  static constexpr std::size_t kBootstrapSize = 88;  // magic, version, table of contents offset, reserved

  std::vector<std::string> tokens_;
  std::unordered_map<std::string, std::uint32_t> token_index_;
  std::vector<std::uint32_t> strings_;
  std::unordered_map<std::string, std::uint32_t> string_index_;
  std::vector<Element> paths_;
  std::unordered_map<std::string, std::uint32_t> path_index_;
  std::unordered_map<std::string, std::vector<std::string>> children_;
  std::vector<std::uint32_t> field_tokens_;
  std::vector<std::uint64_t> field_reps_;
  std::vector<std::uint32_t> field_sets_;
  std::vector<std::uint32_t> spec_paths_, spec_sets_, spec_types_;
  std::string data_;
};

}  // namespace

std::string write_crate(const std::vector<Spec>& specs) { return Writer().run(specs); }

Spec pseudo_root(std::vector<std::pair<std::string, Value>> metadata) {
  return {"/", SpecType::PseudoRoot, std::move(metadata)};
}

Spec prim(std::string path, Specifier specifier, std::string type_name, std::vector<std::pair<std::string, Value>> metadata) {
  Spec s{std::move(path), SpecType::Prim, {{"specifier", specifier}}};
  if (!type_name.empty()) s.fields.emplace_back("typeName", Token{std::move(type_name)});
  for (auto& m : metadata) s.fields.push_back(std::move(m));
  return s;
}

Spec attribute(std::string path, std::string type_name, Value value, Variability variability) {
  Spec s{std::move(path), SpecType::Attribute, {{"typeName", Token{std::move(type_name)}}, {"custom", false}}};
  if (variability == Variability::Uniform) s.fields.emplace_back("variability", variability);
  s.fields.emplace_back("default", std::move(value));
  return s;
}

Spec relationship(std::string path, std::vector<std::string> targets) {
  PathListOp op;
  op.is_explicit = true;
  op.explicit_items = std::move(targets);
  return {std::move(path), SpecType::Relationship, {{"custom", false}, {"variability", Variability::Uniform}, {"targetPaths", op}}};
}

Spec variant_set(const std::string& prim_path, const std::string& set) {
  return {prim_path + "{" + set + "=}", SpecType::VariantSet, {}};
}

Spec variant(const std::string& prim_path, const std::string& set, const std::string& name,
             std::vector<std::pair<std::string, Value>> metadata) {
  Spec s{prim_path + "{" + set + "=" + name + "}", SpecType::Variant, {{"specifier", Specifier::Over}}};
  for (auto& m : metadata) s.fields.push_back(std::move(m));
  return s;
}

TokenListOp prepend_tokens(std::vector<std::string> items) {
  TokenListOp op;
  op.prepended = std::move(items);
  return op;
}

StringListOp prepend_strings(std::vector<std::string> items) {
  StringListOp op;
  op.prepended = std::move(items);
  return op;
}

PayloadListOp prepend_payload(std::string asset, std::string prim) {
  PayloadListOp op;
  op.prepended.push_back({std::move(asset), std::move(prim)});
  return op;
}

ReferenceListOp prepend_reference(std::string asset, std::string prim) {
  ReferenceListOp op;
  op.prepended.push_back({{std::move(asset), std::move(prim)}});
  return op;
}

}  // namespace assetlint::test::crate
