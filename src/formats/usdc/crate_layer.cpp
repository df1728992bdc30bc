#include "formats/usdc/crate_layer.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <functional>
#include <new>
#include <span>
#include <stdexcept>
#include <unordered_map>
#include <variant>

#include "formats/usda/literals.h"
#include "formats/usda/parser.h"
#include "formats/usdc/crate_file.h"
#include "formats/usdc/crate_held_array.h"
#include "formats/usdc/crate_spec_index.h"
#include "formats/usdc/crate_types.h"
#include "formats/usdc/crate_usda.h"
#include "formats/usdc/crate_usda_style.h"
#include "formats/usdc/crate_value_nodes.h"
#include "formats/usdc/crate_values.h"

namespace assetlint::usdc {
namespace {

// Content this reader leaves to the text path, which reads it or reports why it cannot.
struct UseText {};

usda::ListOp list_op_of(ItemOp op) {
  switch (op) {
    case ItemOp::Add: return usda::ListOp::Add;
    case ItemOp::Prepend: return usda::ListOp::Prepend;
    case ItemOp::Append: return usda::ListOp::Append;
    case ItemOp::Delete: return usda::ListOp::Delete;
    case ItemOp::Reorder: return usda::ListOp::Reorder;
    default: return usda::ListOp::Explicit;
  }
}

bool is_declaration_keyword(std::string_view word) {
  if (word.empty() || !std::strchr("rcuvadpo", word[0])) return false;
  for (std::string_view k : {"rel", "custom", "uniform", "config", "varying", "add", "append", "prepend", "delete",
                             "reorder", "def", "over", "class", "variantSet"})
    if (word == k) return true;
  return false;
}

// A namespaced identifier without '.' or '-' (what valid_name accepts and the parser reads
// as one name), in ASCII.
// Metadata the parser reads with its arc grammar (asset and prim paths only).
bool is_arc_key(std::string_view key) {
  return key == "references" || key == "payload" || key == "inherits" || key == "specializes";
}

bool is_plain_property_name(std::string_view s) {
  const auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (s.empty() || !letter(s[0]) || s.back() == ':') return false;
  for (char c : s)
    if (!letter(c) && !(c >= '0' && c <= '9') && c != ':') return false;
  return true;
}

// The fields the layer's structure is made of (the others are metadata).
enum class Key : std::uint8_t {
  Unresolved, Metadata, PrimChildren, Properties, VariantChildren, VariantSetChildren, TargetChildren,
  ConnectionChildren, Specifier, TypeName, Default, TimeSamples, TargetPaths, ConnectionPaths, Custom, Variability,
  PrimOrder, PropertyOrder, SubLayerOffsets, Count
};

Key key_named(std::string_view name) {
  static constexpr std::pair<std::string_view, Key> kKeys[] = {
      {"primChildren", Key::PrimChildren},     {"properties", Key::Properties},
      {"variantChildren", Key::VariantChildren}, {"variantSetChildren", Key::VariantSetChildren},
      {"targetChildren", Key::TargetChildren}, {"connectionChildren", Key::ConnectionChildren},
      {"specifier", Key::Specifier},           {"typeName", Key::TypeName},
      {"default", Key::Default},               {"timeSamples", Key::TimeSamples},
      {"targetPaths", Key::TargetPaths},       {"connectionPaths", Key::ConnectionPaths},
      {"custom", Key::Custom},                 {"variability", Key::Variability},
      {"primOrder", Key::PrimOrder},           {"propertyOrder", Key::PropertyOrder},
      {"subLayerOffsets", Key::SubLayerOffsets}};
  for (const auto& [n, k] : kKeys)
    if (n == name) return k;
  return Key::Metadata;
}

// Nested dictionaries deeper than this are left to the text path (which refuses them).
constexpr int kMaxDictionaryDepth = 32;

class Builder {
 public:
  Builder(const CrateFile& file, const SpecIndex& specs, FileId id) : file_(file), specs_(specs), values_(file), id_(id) {}

  CrateLayer run(const std::string& path) {
    usda::Layer layer;
    layer.file = id_;
    layer.version = "1.0";
    // The literals take about the USDA text's size, 2 to 5 times the crate's.
    text_.reserve(file_.bytes().size() * 4);
    objects_.push_back({0, ""});
    layer.header_span = mark();
    const auto root = specs_.root();
    SpecFields fields;
    if (root) fields = fields_of(file_.specs()[root->spec]);
    metadata(fields, 1, true, layer.metadata);
    if (root)
      for (const std::string_view name : names(fields, Key::PrimChildren)) prim(root->path, name, 0, layer.prims);
    auto source = std::make_shared<const SourceFile>(path, std::move(text_), std::move(objects_));
    source_ = source.get();
    read_values(layer);
    return {std::move(source), std::make_shared<const usda::Layer>(std::move(layer))};
  }

 private:
  // The spec of child `name` of path `parent`. A name that is not one path element (which
  // the text finds by the whole path it spells) is left to the text.
  std::optional<SpecAt> find(std::uint32_t parent, std::string_view name, bool property) const {
    if (!SpecIndex::is_element(name, property)) throw UseText{};
    return specs_.child(parent, name, property);
  }

  const std::string& path_text(std::uint32_t path) const { return file_.paths()[path].text; }

  // A field's name, compared with the structure's names once per token.
  Key key_of(const Field& f) {
    if (f.token >= keys_.size()) keys_.resize(f.token + 1, Key::Unresolved);
    if (keys_[f.token] == Key::Unresolved) keys_[f.token] = key_named(file_.token(f.token, "FIELDS"));
    return keys_[f.token];
  }

  // A spec's fields: the structure's by key (the first of each), and all in file order.
  struct SpecFields {
    std::array<const Field*, static_cast<std::size_t>(Key::Count)> by_key{};
    std::span<const std::uint32_t> all;
    const Field* operator[](Key key) const { return by_key[static_cast<std::size_t>(key)]; }
  };

  SpecFields fields_of(const Spec& spec) {
    SpecFields out;
    out.all = file_.field_set(spec);
    for (const std::uint32_t i : out.all) {
      const Field& f = file_.field(i);
      const Field*& slot = out.by_key[static_cast<std::size_t>(key_of(f))];
      if (!slot) slot = &f;
    }
    return out;
  }

  // Crate writes a value once and points every field that holds it there (the same
  // apiSchemas, the same property names on every link): a value read again is taken from
  // here by its rep, which names the same bytes.
  const ListOpValue& list_op(ValueRep rep) {
    const auto found = list_ops_.find(rep.data);
    if (found != list_ops_.end()) return found->second;
    return list_ops_.emplace(rep.data, values_.list_op(rep, kWhat)).first->second;
  }

  // A dictionary (customData, customLayerData) as the parser reads its literal, when every
  // entry is a dictionary or a value value_node builds; nullopt
  // otherwise (the literal is then written and parsed).
  std::optional<usda::Value> dictionary_node(ValueRep rep, int depth) {
    if (depth > kMaxDictionaryDepth) throw UseText{};  // a dictionary holding itself: the text path says so
    usda::Value v;
    v.kind = usda::ValueKind::Dictionary;
    v.span = mark();
    for (const auto& [key, entry] : values_.dictionary_entries(rep, kWhat)) {
      // The writer quotes a key that is not an identifier; None, inf and nan read as values.
      if (key == "None" || key == "inf" || key == "nan") return std::nullopt;
      const bool bare = valid_name(key, false);
      usda::DictEntry& e = v.entries.emplace_back();
      e.span = mark();
      e.key_span = mark();
      e.key_value.kind = bare ? usda::ValueKind::Identifier : usda::ValueKind::String;
      e.key_value.text = bare ? std::string(key) : as_read(key);
      e.key_value.span = e.key_span;
      e.key = e.key_value.text;
      if (entry.type() == kDictionary && !entry.is_array()) {
        e.type_name = "dictionary";
        auto nested = dictionary_node(entry, depth + 1);
        if (!nested) return std::nullopt;
        e.value = std::move(*nested);
        continue;
      }
      const Element* element = element_of(entry.type());
      if (!element) return std::nullopt;
      auto node = value_node(values_, file_, entry, kWhat, false, mark_, numbers_);
      if (!node) return std::nullopt;
      e.type_name = element->name;
      e.type_is_array = entry.is_array();
      e.value = std::move(*node);
    }
    v.count = v.entries.size();
    return v;
  }

  // Property names in the order the text writer lists them.
  const std::vector<std::string_view>& sorted_properties(const SpecFields& fields) {
    static const std::vector<std::string_view> kNone;
    const Field* f = fields[Key::Properties];
    if (!f) return kNone;
    const auto found = sorted_properties_.find(f->rep.data);
    if (found != sorted_properties_.end()) return found->second;
    std::vector<std::string_view> names = values_.tokens(f->rep, kWhat);
    if (!std::is_sorted(names.begin(), names.end(), dictionary_less))
      std::stable_sort(names.begin(), names.end(), dictionary_less);
    return sorted_properties_.emplace(f->rep.data, std::move(names)).first->second;
  }

  std::vector<std::string_view> names(const SpecFields& fields, Key key) {
    const Field* f = fields[key];
    if (!f) return {};
    return values_.tokens(f->rep, kWhat);
  }

  // --- the source: a line per object, a character per node, the values' literals ---------
  void advance_lines(std::size_t from) {
    for (std::size_t i = text_.find('\n', from); i != std::string::npos; i = text_.find('\n', i + 1)) {
      ++line_;
      line_start_ = i + 1;
    }
  }

  void locate(std::string path) {
    text_ += '\n';
    ++line_;
    line_start_ = text_.size();
    objects_.push_back({text_.size(), std::move(path)});
  }

  Span mark() {
    const std::size_t at = text_.size();
    text_ += ' ';
    return Span{id_, at, 1, line_, static_cast<std::uint32_t>(at - line_start_ + 1)};
  }

  // A value to read once the source exists (read_values): the literal written from `from` on.
  usda::Value placeholder(std::size_t from) {
    usda::Value v;
    v.lazy = true;
    v.span = Span{id_, from, text_.size() - from, line_, 1};
    advance_lines(from);
    text_ += ' ';
    return v;
  }

  // A numeric array value of a numeric array attribute: what the parser keeps lazy when it
  // has more than kEagerArrayItems items (parse_layer: is_non_numeric_type, eager_array_limit).
  static bool keeps_lazy(const usda::Attribute& a, ValueRep rep) {
    if (!a.is_array || !rep.is_array()) return false;
    for (std::string_view t : {"string", "token", "asset", "pathExpression", "opaque", "dictionary"})
      if (a.type_name == t) return false;
    const Element* e = element_of(rep.type());
    return e && e->num != Num::StringIdx && e->num != Num::TokenIdx && e->num != Num::AssetIdx;
  }

  // Such an array, longer than kEagerArrayItems (value_node took the shorter ones): kept
  // lazy as the parser keeps it, with the crate's own items instead of a literal.
  usda::Value lazy_array(ValueRep rep) {
    ArrayItems items = values_.array_items(rep, kWhat);
    if (items.count <= kEagerArrayItems) throw UseText{};
    usda::Value v;
    v.kind = usda::ValueKind::List;
    v.count = items.count;
    v.lazy = true;
    v.span = mark();
    v.held = hold_numeric_array(std::move(items), v.span);
    return v;
  }

  usda::Value literal(std::string_view text) {
    const std::size_t from = text_.size();
    text_ += text;
    return placeholder(from);
  }

  usda::Metadata item(usda::ListOp op, std::string key) {
    usda::Metadata m;
    m.span = mark();
    if (op != usda::ListOp::Explicit) m.op_span = m.span;
    m.op = op;
    m.key = std::move(key);
    m.key_span = mark();
    return m;
  }

  // `key = "a"` (bare) or `key = ["a", "b"]`, from the items' quoted forms.
  usda::Metadata name_item(usda::ListOp op, std::string key, const std::vector<std::string>& items, bool bare) {
    usda::Metadata m = item(op, std::move(key));
    const auto string = [this](const std::string& quoted_item) {
      usda::Value v;
      v.kind = usda::ValueKind::String;
      v.span = mark();
      v.text = usda::decode_string(quoted_item);
      return v;
    };
    if (bare) {
      m.value = string(items[0]);
      return m;
    }
    m.value.kind = usda::ValueKind::List;
    m.value.span = mark();
    m.value.elements.reserve(items.size());
    for (const std::string& i : items) m.value.elements.push_back(string(i));
    m.value.count = m.value.elements.size();
    return m;
  }

  usda::Metadata item(usda::ListOp op, std::string key, std::string_view value) {
    usda::Metadata m = item(op, std::move(key));
    m.value = literal(value);
    return m;
  }

  // --- structure, in the order of the text writer -----------------------------------------
  void metadata(const SpecFields& fields, int indent, bool layer, std::vector<usda::Metadata>& out) {
    for (const std::uint32_t index : fields.all) {
      const Field& f = file_.field(index);
      if (key_of(f) != Key::Metadata) continue;
      const std::string& key = file_.token(f.token, "FIELDS");
      const std::string& what = kWhat;
      try {
        if (key == "subLayers") {
          std::vector<std::pair<double, double>> offsets;
          if (const Field* o = fields[Key::SubLayerOffsets]) offsets = values_.layer_offsets(o->rep, what);
          const std::vector<std::string_view> layers = values_.tokens(f.rep, what);
          std::string text = "[";
          for (std::size_t i = 0; i < layers.size(); ++i) {
            text += asset_literal(layers[i]);
            if (i < offsets.size() && (offsets[i].first != 0.0 || offsets[i].second != 1.0))
              text += fmt::format(" (offset = {}; scale = {})", offsets[i].first, offsets[i].second);
            if (i + 1 < layers.size()) text += ", ";
          }
          out.push_back(item(usda::ListOp::Explicit, key, text + "]"));
          continue;
        }
        if (key == "variantSelection") {
          std::string text = "{\n";
          for (const auto& [set, selection] : values_.string_map(f.rep, what))
            text += "string " + (valid_name(set, false) ? set : quoted(set)) + " = " + quoted(selection) + "\n";
          out.push_back(item(usda::ListOp::Explicit, "variants", text + "}"));
          continue;
        }
        const std::string shown = key == "documentation" ? "doc" : key == "variantSetNames" ? "variantSets" : key;
        if (!valid_name(shown, false)) continue;
        if (values_.is_list_op(f.rep)) {
          const ListOpValue& op = list_op(f.rep);
          // Lists of names (apiSchemas, variantSets) are built as nodes; the others, arcs
          // among them, are read by the parser from their literal.
          const bool names = !is_arc_key(key) && std::all_of(op.parts.begin(), op.parts.end(), [](const auto& part) {
            return std::all_of(part.second.begin(), part.second.end(), [](const std::string& i) { return i[0] == '"'; });
          });
          if (op.is_explicit && op.parts.empty()) out.push_back(item(usda::ListOp::Explicit, shown, "None"));
          for (const auto& [kind, items] : op.parts) {
            if (items.empty() && kind == ItemOp::Explicit) out.push_back(item(usda::ListOp::Explicit, shown, "None"));
            else if (!names && items.size() == 1 && bare_when_single(key)) out.push_back(item(list_op_of(kind), shown, items[0]));
            else if (!names) out.push_back(item(list_op_of(kind), shown, bracketed(items, indent)));
            else out.push_back(name_item(list_op_of(kind), shown, items, items.size() == 1 && bare_when_single(key)));
          }
          continue;
        }
        if (key == "symmetryFunction") throw UseText{};  // the parser reads it with its statement only
        if (layer && key == "comment") {
          // A bare string in layer metadata, which the parser reads as the doc shorthand.
          const Literal value = values_.literal(f.rep, what, indent);
          if (value.type != "string" && value.type != "token") throw UseText{};
          usda::Metadata m = item(usda::ListOp::Explicit, "doc", value.text);
          m.is_doc_shorthand = true;
          out.push_back(std::move(m));
          continue;
        }
        usda::Metadata m = item(usda::ListOp::Explicit, shown);
        std::optional<usda::Value> node;
        if (!is_arc_key(key)) node = value_node(values_, file_, f.rep, what, true, mark_, numbers_);
        if (!node && f.rep.type() == kDictionary && !f.rep.is_array()) node = dictionary_node(f.rep, 0);
        if (node) {
          m.value = std::move(*node);
        } else {
          const std::size_t from = text_.size();
          try {
            values_.append_literal(f.rep, what, indent, text_);
          } catch (const UnsupportedValue&) {
            text_.resize(from);
            throw;
          }
          m.value = placeholder(from);
        }
        out.push_back(std::move(m));
      } catch (const UnsupportedValue&) {
        // Left out, as the text writer leaves it out.
      }
    }
  }

  void prim(std::uint32_t parent, std::string_view name, int indent, std::vector<usda::Prim>& siblings) {
    const auto at = find(parent, name, false);
    if (!at) return;
    const Spec& spec = file_.specs()[at->spec];
    if (spec.type != SpecType::Prim || indent > 120) throw UseText{};
    const SpecFields fields = fields_of(spec);
    usda::Prim p;
    p.specifier = usda::Specifier::Over;
    if (const Field* f = fields[Key::Specifier]) {
      const auto v = values_.enum_value(f->rep, kWhat);
      p.specifier = v == 0 ? usda::Specifier::Def : v == 1 ? usda::Specifier::Over : usda::Specifier::Class;
    }
    if (const Field* f = fields[Key::TypeName]) {
      p.type_name = values_.token(f->rep, kWhat);
      if (!valid_name(p.type_name, false)) throw UseText{};
    }
    locate(path_text(at->path));
    p.span = mark();
    p.specifier_span = p.span;
    if (!p.type_name.empty()) p.type_span = mark();
    p.name = as_read(name);
    p.name_span = mark();
    metadata(fields, indent + 1, false, p.metadata);
    p.open_brace_span = mark();
    body(fields, at->path, indent + 1, p);
    siblings.push_back(std::move(p));
  }

  usda::Value name_list(const std::vector<std::string_view>& names) {
    usda::Value list;
    list.kind = usda::ValueKind::List;
    list.span = mark();
    for (const std::string_view n : names) {
      usda::Value item;
      item.kind = usda::ValueKind::String;
      item.text = as_read(n);
      item.span = mark();
      list.elements.push_back(std::move(item));
    }
    list.count = list.elements.size();
    return list;
  }

  // Properties, children and variant sets of a prim or variant.
  void body(const SpecFields& fields, std::uint32_t path, int indent, usda::Prim& p) {
    for (const Key order : {Key::PrimOrder, Key::PropertyOrder}) {
      if (const Field* f = fields[order]) {
        usda::ReorderStatement r;
        r.span = mark();
        r.what = order == Key::PrimOrder ? "nameChildren" : "properties";
        r.names = name_list(values_.tokens(f->rep, kWhat));
        p.reorders.push_back(std::move(r));
      }
    }
    const std::vector<std::string_view>& properties = sorted_properties(fields);
    // Attributes and prims are large nodes: moved once each instead of on every regrowth.
    p.attributes.reserve(properties.size());
    p.property_order.reserve(properties.size());
    for (const std::string_view name : properties) property(path, name, indent, p);
    const std::vector<std::string_view> children = names(fields, Key::PrimChildren);
    p.children.reserve(children.size());
    for (const std::string_view name : children) {
      prim(path, name, indent, p.children);
      locate(path_text(path));
    }
    for (const std::string_view set_view : names(fields, Key::VariantSetChildren)) {
      const std::string set_name(set_view);
      const auto set_at = find(path, "{" + set_name + "=}", false);
      if (!set_at) continue;
      std::vector<std::pair<std::string, SpecAt>> variants;
      for (const std::string_view variant : names(fields_of(file_.specs()[set_at->spec]), Key::VariantChildren))
        if (const auto v = find(path, "{" + set_name + "=" + std::string(variant) + "}", false))
          variants.emplace_back(variant, *v);
      if (variants.empty()) continue;
      std::sort(variants.begin(), variants.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      usda::VariantSet set;
      set.span = mark();
      set.name = as_read(set_name);
      set.name_span = mark();
      for (const auto& [variant, v] : variants) {
        const SpecFields variant_fields = fields_of(file_.specs()[v.spec]);
        locate(path_text(v.path));
        usda::Variant var;
        var.span = mark();
        var.name_span = var.span;
        var.name = as_read(variant);
        var.body.specifier = usda::Specifier::Over;
        var.body.name = var.name;
        var.body.name_span = var.name_span;
        metadata(variant_fields, indent + 2, false, var.body.metadata);
        var.body.open_brace_span = mark();
        body(variant_fields, v.path, indent + 2, var.body);
        var.body.span = var.span;
        set.variants.push_back(std::move(var));
        locate(path_text(path));
      }
      p.variant_sets.push_back(std::move(set));
    }
  }

  void property(std::uint32_t owner, std::string_view name, int indent, usda::Prim& p) {
    const auto at = find(owner, name, true);
    if (!at) return;
    // Names and types the parser would read otherwise (`a.b` as a field of `a`, a type
    // that is a keyword) are left to it.
    if (!is_plain_property_name(name)) throw UseText{};
    const Spec& spec = file_.specs()[at->spec];
    const SpecFields fields = fields_of(spec);
    bool custom = false;
    if (const Field* f = fields[Key::Custom]) custom = values_.boolean(f->rep, kWhat);
    std::optional<std::uint32_t> variability;
    if (const Field* f = fields[Key::Variability]) variability = values_.enum_value(f->rep, kWhat);
    locate(path_text(at->path));
    if (spec.type == SpecType::Relationship) {
      usda::Relationship r;
      r.custom = custom;
      r.varying = variability == 0u;
      r.name = name;
      r.span = mark();
      r.name_span = mark();
      if (const Field* f = fields[Key::TargetPaths]) r.targets = path_lists(f->rep);
      metadata(fields, indent + 1, false, r.metadata);
      p.property_order.push_back({true, static_cast<std::uint32_t>(p.relationships.size())});
      p.relationships.push_back(std::move(r));
      return;
    }
    if (spec.type != SpecType::Attribute) throw UseText{};
    std::string type;
    if (const Field* f = fields[Key::TypeName]) type = values_.token(f->rep, kWhat);
    if (!valid_type_name(type) || is_declaration_keyword(type)) throw UseText{};
    // Built in place: an attribute is a large node.
    usda::Attribute& a = p.attributes.emplace_back();
    a.custom = custom;
    a.variability = variability == 1u ? usda::Variability::Uniform : usda::Variability::Varying;
    a.is_array = type.ends_with("[]");
    a.type_name = a.is_array ? type.substr(0, type.size() - 2) : type;
    a.name = name;
    a.span = mark();
    a.type_span = mark();
    a.name_span = mark();
    if (const Field* value = fields[Key::Default]) {
      const std::string& what = kWhat;
      const std::size_t from = text_.size();
      try {
        if (auto node = value_node(values_, file_, value->rep, what, false, mark_, numbers_)) {
          a.default_value = std::move(*node);
        } else if (keeps_lazy(a, value->rep)) {
          a.default_value = lazy_array(value->rep);
        } else {
          values_.append_literal(value->rep, what, indent, text_);
          a.default_value = placeholder(from);
        }
        a.default_declaration_span = mark();
      } catch (const UnsupportedValue&) {
        text_.resize(from);  // left out, as the text writer leaves it out
      }
    }
    metadata(fields, indent + 1, false, a.metadata);
    if (const Field* samples = fields[Key::TimeSamples]) {
      try {
        const auto list = values_.time_samples(samples->rep, kWhat, indent + 1);
        usda::TimeSamples ts;
        ts.span = mark();
        for (const auto& [time, v] : list) {
          usda::TimeSample s;
          s.time_span = mark();
          s.time = usda::parse_number(time);
          s.value = literal(v.text);
          ts.samples.push_back(std::move(s));
        }
        ts.declaration_span = mark();
        a.time_samples = std::move(ts);
      } catch (const UnsupportedValue&) {
        // Left out, as the text writer leaves it out.
      }
    }
    const Field* connections = fields[Key::ConnectionPaths];
    if (connections) a.connections = path_lists(connections->rep);
    // The text declares the attribute with its default or metadata, or else (a bare
    // declaration) when it has neither samples nor connections, or with those.
    const bool declared = a.default_value || !a.metadata.empty() || (!fields[Key::TimeSamples] && !connections) ||
                          a.time_samples || !a.connections.empty();
    if (!declared) {
      p.attributes.pop_back();
      return;
    }
    p.property_order.push_back({false, static_cast<std::uint32_t>(p.attributes.size() - 1)});
  }

  // The declarations of a path list op (`prepend rel x = </a>`), one per list.
  std::vector<usda::PathList> path_lists(ValueRep rep) {
    const ListOpValue& op = list_op(rep);
    std::vector<usda::PathList> out;
    const auto declaration = [&](usda::ListOp kind) -> usda::PathList& {
      out.emplace_back();
      out.back().op = kind;
      out.back().span = mark();
      out.back().declaration_span = out.back().span;
      return out.back();
    };
    if (op.is_explicit && op.parts.empty()) declaration(usda::ListOp::Explicit).none = true;
    for (const auto& [kind, items] : op.parts) {
      usda::PathList& list = declaration(list_op_of(kind));
      if (items.empty() && kind == ItemOp::Explicit) list.none = true;
      for (const std::string& item : items) {
        // Items are `<path>`; anything else is left to the parser (which rejects it).
        if (item.size() < 2 || item.front() != '<' || item.find('>') != item.size() - 1) throw UseText{};
        usda::Value path;
        path.kind = usda::ValueKind::Path;
        path.text = item.substr(1, item.size() - 2);
        path.span = mark();
        list.paths.push_back(std::move(path));
      }
    }
    return out;
  }

  // --- values, read from their literals -----------------------------------------------------
  void read_value(usda::Value& v, std::string_view metadata_key, std::string_view attribute_type) {
    if (v.kind != usda::ValueKind::None || !v.lazy) return;
    auto r = usda::parse_value_at(*source_, id_, v.span.offset, v.span.end(), metadata_key, attribute_type);
    if (!std::holds_alternative<usda::Value>(r)) throw UseText{};
    v = std::move(std::get<usda::Value>(r));
  }

  void read_values(std::vector<usda::Metadata>& list) {
    for (usda::Metadata& m : list) read_value(m.value, m.key, "");
  }

  void read_values(usda::Prim& p) {
    read_values(p.metadata);
    for (usda::Attribute& a : p.attributes) {
      const std::string type = a.full_type();
      if (a.default_value) read_value(*a.default_value, "", type);
      if (a.time_samples)
        for (usda::TimeSample& s : a.time_samples->samples) read_value(s.value, "", type);
      read_values(a.metadata);
    }
    for (usda::Relationship& r : p.relationships) read_values(r.metadata);
    for (usda::Prim& child : p.children) read_values(child);
    for (usda::VariantSet& set : p.variant_sets)
      for (usda::Variant& v : set.variants) read_values(v.body);
  }

  void read_values(usda::Layer& layer) {
    read_values(layer.metadata);
    for (usda::Prim& p : layer.prims) read_values(p);
  }

  // What the value reader names in its errors. An error here hands the file to the text
  // path, which reports it with the field it is in: it is never shown from here.
  const std::string kWhat = "crate layer";
  const CrateFile& file_;
  const SpecIndex& specs_;
  ValueReader values_;
  FileId id_;
  std::string text_;
  std::vector<ObjectLocation> objects_;
  std::uint32_t line_ = 1;
  std::size_t line_start_ = 0;
  const SourceFile* source_ = nullptr;
  std::vector<Key> keys_;  // by token index
  std::unordered_map<std::uint64_t, ListOpValue> list_ops_;                          // by rep
  std::unordered_map<std::uint64_t, std::vector<std::string_view>> sorted_properties_;  // by rep
  NumberCache numbers_;
  const std::function<Span()> mark_ = [this] { return mark(); };
};

}  // namespace

std::optional<CrateLayer> read_crate_layer(const std::string& path, std::string_view bytes, FileId id,
                                           std::string& error) {
  try {
    const CrateFile file(bytes);
    if (const auto specs = SpecIndex::build(file)) return Builder(file, *specs, id).run(path);
  } catch (const CrateError&) {
  } catch (const UnsupportedValue&) {
  } catch (const UseText&) {
  } catch (const std::bad_alloc&) {
  } catch (const std::length_error&) {
  }
  auto source = crate_source(path, bytes, error);
  if (!source) return std::nullopt;
  return CrateLayer{std::move(source), nullptr};
}

}  // namespace assetlint::usdc
