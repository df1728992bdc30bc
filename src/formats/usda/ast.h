#pragma once
// Syntax tree of one .usda layer. Every node keeps the Span of the text it came from,
// so rules can point at (and fixes can rewrite) the exact bytes of a value.
//
// The tree is faithful to the file: prims keep their children, properties and metadata
// in file order. Property declarations of the same attribute (`float x = 1`,
// `float x.timeSamples = {...}`, `float x.connect = </p>`) are merged into one Attribute
// with a span for each part. Relationship list-ops (`prepend rel x = ...`) are kept as a
// list of target lists.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/source.h"

namespace assetlint::usda {

enum class ValueKind : std::uint8_t {
  None,        // the keyword None
  Number,      // 1, -2.5e3, inf, -inf, nan
  String,      // "text" (text holds the decoded contents)
  Identifier,  // bare word: true, false, mm, public, AnimationBlock
  AssetPath,   // @path@ (text = the path; for references also `path` and `entries`)
  Path,        // </Prim/Path.prop> (text = the path without <>)
  Tuple,       // (1, 2, 3)
  List,        // [1, 2, 3]; may be lazy (see Value::lazy)
  Dictionary,  // { type key = value ... } (entries), or {"a": "b"} / {</a>: </b>} maps
};

const char* value_kind_name(ValueKind kind);

struct DictEntry;
struct Value;

// The items of a lazy list kept outside the layer's text, as a binary layer stores them
// (a crate's mesh arrays): read only when asked, each number the one its text reads as.
class HeldItems {
 public:
  virtual ~HeldItems() = default;
  // Every number in text order, flattened as read_numbers reads a list.
  virtual void append_numbers(std::vector<double>& out) const = 0;
  // The items as the parser builds them from the text.
  virtual std::vector<Value> elements() const = 0;
};

struct Value {
  ValueKind kind = ValueKind::None;
  bool is_integer = false;  // Number written without '.', exponent, inf or nan
  // List whose elements were not materialized (large numeric arrays): `elements` is
  // empty and `count` holds the number of top-level items. Use materialize() or
  // read_numbers() (parser.h) to read them: from `held` when set, else from the text at `span`.
  bool lazy = false;
  Span span;            // the whole value as written (quotes, brackets included)
  double number = 0.0;  // Number
  std::string text;     // String/Identifier/AssetPath/Path contents, decoded
  std::size_t count = 0;        // Tuple/List: number of items (also when lazy)
  std::vector<Value> elements;  // Tuple/List items (empty when lazy)
  std::shared_ptr<const HeldItems> held;  // a lazy list's items, when not in the text
  // Dictionary entries. For an AssetPath/Path inside references/payload/subLayers,
  // the `( offset = 1; scale = 2 )` parameter block.
  std::vector<DictEntry> entries;
  // AssetPath in references/payload: the prim path after the asset (`@a.usd@</Prim>`).
  std::string prim_path;
  Span prim_path_span;

  bool is_none() const { return kind == ValueKind::None; }
  bool is_number() const { return kind == ValueKind::Number; }
  bool is_list() const { return kind == ValueKind::List; }

  // Typed readers; std::nullopt when the value has another kind.
  std::optional<double> as_double() const;
  // Number, or the identifiers true/false (as 1/0).
  std::optional<bool> as_bool() const;
  // String or Identifier contents (USD writes token values as strings).
  std::optional<std::string_view> as_string() const;
  // Path contents (without the angle brackets).
  std::optional<std::string_view> as_path() const;
  // Tuple of numbers, e.g. (1, 0, 0); lists of numbers too if materialized.
  std::optional<std::vector<double>> as_numbers() const;
  // A string/token, or a materialized list of them: ["a", "b"].
  std::optional<std::vector<std::string_view>> as_string_list() const;
  // Dictionary entry by key.
  const DictEntry* find_entry(std::string_view key) const;
};

// One `type key = value` item of a dictionary (type is "dictionary" for nested ones,
// empty for untyped maps such as prefixSubstitutions and relocates).
struct DictEntry {
  std::string type_name;  // e.g. "double3", "string", "dictionary"
  bool type_is_array = false;
  std::string key;
  Span span;  // the whole entry
  Span key_span;
  Value key_value;  // for {"a": "b"} / {</a>: </b>} maps: the key as a value
  Value value;
};

enum class ListOp : std::uint8_t { Explicit, Add, Append, Prepend, Delete, Reorder };
const char* list_op_name(ListOp op);

// A `key = value` item in a `( ... )` metadata block. A bare string as an item is the
// `doc` shorthand: key "doc", is_doc_shorthand = true.
struct Metadata {
  ListOp op = ListOp::Explicit;
  std::string key;
  Value value;
  Span span;  // whole item, from the list-op keyword (or key) to the end of the value
  Span key_span;
  Span op_span;  // the list-op keyword, when there is one
  bool is_doc_shorthand = false;
};

const Metadata* find_metadata(const std::vector<Metadata>& list, std::string_view key,
                              std::optional<ListOp> op = std::nullopt);

enum class Variability : std::uint8_t { Varying, Uniform, Config };

struct TimeSample {
  double time = 0.0;
  Span time_span;
  Value value;  // kind None for `1: None`
};

struct TimeSamples {
  Span span;  // the `{ ... }` block
  Span declaration_span;
  std::vector<TimeSample> samples;
};

// A list of paths: relationship targets or attribute connections.
struct PathList {
  ListOp op = ListOp::Explicit;
  bool none = false;  // `= None`
  Span span;          // the value as written
  Span declaration_span;
  std::vector<Value> paths;  // each of kind Path
};

struct Attribute {
  bool custom = false;
  Variability variability = Variability::Varying;
  std::string type_name;  // "float", "double3", "token", "quatf" (without "[]")
  bool is_array = false;  // declared as type[]
  std::string name;       // "drive:angular:physics:stiffness"
  Span span;              // the first declaration, from qualifiers to the end of its metadata
  Span type_span;
  Span name_span;  // the name only (without .timeSamples/.connect)
  // `= value` of the default declaration; kind None for `= None`; nullopt when the
  // attribute is declared without a value.
  std::optional<Value> default_value;
  Span default_declaration_span;
  std::optional<TimeSamples> time_samples;
  std::vector<PathList> connections;  // `x.connect = ...`, one per list-op
  std::optional<Value> spline;        // `x.spline = {...}`: kept as an unparsed span (kind None)
  std::vector<Metadata> metadata;     // from the `( ... )` block(s)

  const Metadata* find_metadata(std::string_view key) const { return usda::find_metadata(metadata, key); }
  std::string full_type() const { return is_array ? type_name + "[]" : type_name; }
};

struct Relationship {
  bool custom = false;
  bool varying = false;
  std::string name;  // "physics:body0"
  Span span;         // first declaration
  Span name_span;
  std::vector<PathList> targets;       // one per declaration (`rel x = ...`, `prepend rel x = ...`)
  std::optional<Value> default_target;  // `rel x.default = </p>`
  std::vector<Metadata> metadata;

  // Explicit targets if authored, else prepend + add + append minus delete (one layer's view).
  std::vector<const Value*> resolved_targets() const;
  const Metadata* find_metadata(std::string_view key) const { return usda::find_metadata(metadata, key); }
};

enum class Specifier : std::uint8_t { Def, Over, Class };
const char* specifier_name(Specifier s);

// `reorder nameChildren = [...]`, `reorder properties = [...]`, `reorder rootPrims = [...]`.
struct ReorderStatement {
  std::string what;  // "nameChildren", "properties" or "rootPrims"
  Value names;       // list of strings
  Span span;
};

struct VariantSet;

struct PropertyRef {
  bool is_relationship = false;
  std::uint32_t index = 0;  // into Prim::attributes or Prim::relationships
};

struct Prim {
  Specifier specifier = Specifier::Def;
  std::string type_name;  // empty when typeless (`def "x"`)
  std::string name;
  Span span;  // from the specifier to the closing brace
  Span specifier_span;
  Span type_span;
  Span name_span;  // the quoted name, quotes included
  Span open_brace_span;
  std::vector<Metadata> metadata;
  std::vector<Attribute> attributes;
  std::vector<Relationship> relationships;
  std::vector<PropertyRef> property_order;  // file order of first declarations
  std::vector<Prim> children;
  std::vector<VariantSet> variant_sets;
  std::vector<ReorderStatement> reorders;

  const Attribute* find_attribute(std::string_view name) const;
  const Relationship* find_relationship(std::string_view name) const;
  const Prim* find_child(std::string_view name) const;
  const Metadata* find_metadata(std::string_view key, std::optional<ListOp> op = std::nullopt) const {
    return usda::find_metadata(metadata, key, op);
  }
  // Items of `apiSchemas` authored with the given list-op (e.g. Prepend, Delete).
  std::vector<std::string_view> api_schemas(ListOp op) const;
  // Schemas this layer applies: explicit, or prepend + add + append, minus delete.
  std::vector<std::string_view> applied_api_schemas() const;
  bool has_api_schema(std::string_view schema) const;
  // Attribute default as a number / string, when authored with such a value.
  std::optional<double> attribute_double(std::string_view name) const;
  std::optional<std::string_view> attribute_string(std::string_view name) const;
};

// `"variantName" ( metadata ) { ...prim contents... }` inside a variantSet block. The
// contents are held in a Prim (specifier Over, name = the variant name).
struct Variant {
  std::string name;
  Span span;
  Span name_span;
  Prim body;
};

struct VariantSet {
  std::string name;
  Span span;
  Span name_span;
  std::vector<Variant> variants;

  const Variant* find_variant(std::string_view name) const;
};

struct Layer {
  FileId file = kNoFile;
  std::string version;  // from `#usda 1.0`
  Span header_span;
  std::vector<Metadata> metadata;
  std::vector<Prim> prims;
  std::vector<ReorderStatement> reorders;

  const Metadata* find_metadata(std::string_view key) const { return usda::find_metadata(metadata, key); }
  const Prim* find_root(std::string_view name) const;
  // Prim by absolute path without variant selections: "/World/robot/joint".
  const Prim* find_prim(std::string_view path) const;
  // Layer metadata helpers.
  std::optional<std::string_view> default_prim() const;
  std::optional<double> meters_per_unit() const;
  std::optional<double> kilograms_per_unit() const;
  std::optional<std::string_view> up_axis() const;
  std::vector<std::string_view> sublayers() const;
};

// One item of a references/payload/subLayers/inherits/specializes value.
struct CompositionArc {
  std::string_view asset;      // empty for an internal reference </Prim>
  std::string_view prim_path;  // empty when not given
  std::optional<double> offset;
  std::optional<double> scale;
  Span span;
};
// Reads a references/payload/subLayers/inherits/specializes value: a single item, a list
// of items, or None (empty).
std::vector<CompositionArc> composition_arcs(const Value& value);

// Calls fn(prim, path) for every prim (not inside variants) in depth-first order.
template <class Fn>
void for_each_prim(const std::vector<Prim>& prims, const std::string& parent, Fn&& fn) {
  for (const Prim& p : prims) {
    std::string path = parent + "/" + p.name;
    fn(p, path);
    for_each_prim(p.children, path, fn);
  }
}

}  // namespace assetlint::usda
