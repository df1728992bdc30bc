#include "formats/usda/ast.h"

#include <algorithm>

namespace assetlint::usda {

const char* value_kind_name(ValueKind kind) {
  switch (kind) {
    case ValueKind::None: return "None";
    case ValueKind::Number: return "number";
    case ValueKind::String: return "string";
    case ValueKind::Identifier: return "identifier";
    case ValueKind::AssetPath: return "asset path";
    case ValueKind::Path: return "path";
    case ValueKind::Tuple: return "tuple";
    case ValueKind::List: return "list";
    case ValueKind::Dictionary: return "dictionary";
  }
  return "value";
}

const char* list_op_name(ListOp op) {
  switch (op) {
    case ListOp::Explicit: return "explicit";
    case ListOp::Add: return "add";
    case ListOp::Append: return "append";
    case ListOp::Prepend: return "prepend";
    case ListOp::Delete: return "delete";
    case ListOp::Reorder: return "reorder";
  }
  return "?";
}

const char* specifier_name(Specifier s) {
  switch (s) {
    case Specifier::Def: return "def";
    case Specifier::Over: return "over";
    case Specifier::Class: return "class";
  }
  return "?";
}

// --- Value -------------------------------------------------------------------------
std::optional<double> Value::as_double() const {
  if (kind == ValueKind::Number) return number;
  return std::nullopt;
}

std::optional<bool> Value::as_bool() const {
  if (kind == ValueKind::Number) return number != 0.0;
  if (kind == ValueKind::Identifier) {
    if (text == "true") return true;
    if (text == "false") return false;
  }
  return std::nullopt;
}

std::optional<std::string_view> Value::as_string() const {
  if (kind == ValueKind::String || kind == ValueKind::Identifier) return std::string_view(text);
  return std::nullopt;
}

std::optional<std::string_view> Value::as_path() const {
  if (kind == ValueKind::Path) return std::string_view(text);
  return std::nullopt;
}

std::optional<std::vector<double>> Value::as_numbers() const {
  if (kind == ValueKind::Number) return std::vector<double>{number};
  if ((kind != ValueKind::Tuple && kind != ValueKind::List) || lazy) return std::nullopt;
  std::vector<double> out;
  out.reserve(elements.size());
  for (const Value& e : elements) {
    if (e.kind == ValueKind::Number) {
      out.push_back(e.number);
    } else if (auto inner = e.as_numbers()) {
      out.insert(out.end(), inner->begin(), inner->end());
    } else {
      return std::nullopt;
    }
  }
  return out;
}

std::optional<std::vector<std::string_view>> Value::as_string_list() const {
  if (kind == ValueKind::String || kind == ValueKind::Identifier) return std::vector<std::string_view>{text};
  if (kind == ValueKind::None) return std::vector<std::string_view>{};
  if (kind != ValueKind::List || lazy) return std::nullopt;
  std::vector<std::string_view> out;
  out.reserve(elements.size());
  for (const Value& e : elements) {
    if (e.kind != ValueKind::String && e.kind != ValueKind::Identifier) return std::nullopt;
    out.push_back(e.text);
  }
  return out;
}

const DictEntry* Value::find_entry(std::string_view key) const {
  for (const DictEntry& e : entries)
    if (e.key == key) return &e;
  return nullptr;
}

// --- metadata ------------------------------------------------------------------------
const Metadata* find_metadata(const std::vector<Metadata>& list, std::string_view key, std::optional<ListOp> op) {
  // The last authored entry wins within one block, as in USD.
  for (auto it = list.rbegin(); it != list.rend(); ++it) {
    if (it->key == key && (!op || it->op == *op)) return &*it;
  }
  return nullptr;
}

// --- Relationship --------------------------------------------------------------------
namespace {
template <class Item, class KeyOf>
std::vector<Item> apply_list_ops(const std::vector<std::pair<ListOp, std::vector<Item>>>& ops, KeyOf key) {
  for (auto it = ops.rbegin(); it != ops.rend(); ++it) {
    if (it->first == ListOp::Explicit) return it->second;
  }
  std::vector<Item> out;
  auto contains = [&](const std::vector<Item>& v, const Item& x) {
    return std::any_of(v.begin(), v.end(), [&](const Item& y) { return key(y) == key(x); });
  };
  for (const auto& [op, items] : ops) {
    if (op == ListOp::Prepend) {
      std::vector<Item> merged;
      for (const Item& x : items)
        if (!contains(merged, x)) merged.push_back(x);
      for (const Item& x : out)
        if (!contains(merged, x)) merged.push_back(x);
      out = std::move(merged);
    } else if (op == ListOp::Append || op == ListOp::Add) {
      for (const Item& x : items) {
        if (op == ListOp::Append) {
          out.erase(std::remove_if(out.begin(), out.end(), [&](const Item& y) { return key(y) == key(x); }), out.end());
          out.push_back(x);
        } else if (!contains(out, x)) {
          out.push_back(x);
        }
      }
    } else if (op == ListOp::Delete) {
      for (const Item& x : items)
        out.erase(std::remove_if(out.begin(), out.end(), [&](const Item& y) { return key(y) == key(x); }), out.end());
    }
  }
  return out;
}
}  // namespace

std::vector<const Value*> Relationship::resolved_targets() const {
  std::vector<std::pair<ListOp, std::vector<const Value*>>> ops;
  for (const PathList& l : targets) {
    std::vector<const Value*> items;
    for (const Value& v : l.paths) items.push_back(&v);
    ops.emplace_back(l.op, std::move(items));
  }
  return apply_list_ops(ops, [](const Value* v) { return std::string_view(v->text); });
}

// --- Prim ----------------------------------------------------------------------------
const Attribute* Prim::find_attribute(std::string_view n) const {
  for (const Attribute& a : attributes)
    if (a.name == n) return &a;
  return nullptr;
}

const Relationship* Prim::find_relationship(std::string_view n) const {
  for (const Relationship& r : relationships)
    if (r.name == n) return &r;
  return nullptr;
}

const Prim* Prim::find_child(std::string_view n) const {
  for (const Prim& c : children)
    if (c.name == n) return &c;
  return nullptr;
}

std::vector<std::string_view> Prim::api_schemas(ListOp op) const {
  std::vector<std::string_view> out;
  for (const Metadata& m : metadata) {
    if (m.key != "apiSchemas" || m.op != op) continue;
    if (auto items = m.value.as_string_list()) out.insert(out.end(), items->begin(), items->end());
  }
  return out;
}

std::vector<std::string_view> Prim::applied_api_schemas() const {
  std::vector<std::pair<ListOp, std::vector<std::string_view>>> ops;
  for (const Metadata& m : metadata) {
    if (m.key != "apiSchemas") continue;
    if (auto items = m.value.as_string_list()) ops.emplace_back(m.op, std::move(*items));
  }
  return apply_list_ops(ops, [](std::string_view s) { return s; });
}

bool Prim::has_api_schema(std::string_view schema) const {
  const auto applied = applied_api_schemas();
  return std::find(applied.begin(), applied.end(), schema) != applied.end();
}

std::optional<double> Prim::attribute_double(std::string_view n) const {
  const Attribute* a = find_attribute(n);
  if (a == nullptr || !a->default_value) return std::nullopt;
  return a->default_value->as_double();
}

std::optional<std::string_view> Prim::attribute_string(std::string_view n) const {
  const Attribute* a = find_attribute(n);
  if (a == nullptr || !a->default_value) return std::nullopt;
  return a->default_value->as_string();
}

const Variant* VariantSet::find_variant(std::string_view n) const {
  for (const Variant& v : variants)
    if (v.name == n) return &v;
  return nullptr;
}

// --- Layer ---------------------------------------------------------------------------
const Prim* Layer::find_root(std::string_view n) const {
  for (const Prim& p : prims)
    if (p.name == n) return &p;
  return nullptr;
}

const Prim* Layer::find_prim(std::string_view path) const {
  if (path.empty() || path[0] != '/') return nullptr;
  const std::vector<Prim>* level = &prims;
  const Prim* found = nullptr;
  std::size_t pos = 1;
  while (pos <= path.size()) {
    std::size_t slash = path.find('/', pos);
    if (slash == std::string_view::npos) slash = path.size();
    const std::string_view part = path.substr(pos, slash - pos);
    if (part.empty()) return slash == path.size() ? found : nullptr;
    found = nullptr;
    for (const Prim& p : *level) {
      if (p.name == part) {
        found = &p;
        break;
      }
    }
    if (found == nullptr) return nullptr;
    level = &found->children;
    pos = slash + 1;
  }
  return found;
}

std::optional<std::string_view> Layer::default_prim() const {
  const Metadata* m = find_metadata("defaultPrim");
  return m ? m->value.as_string() : std::nullopt;
}

std::optional<double> Layer::meters_per_unit() const {
  const Metadata* m = find_metadata("metersPerUnit");
  return m ? m->value.as_double() : std::nullopt;
}

std::optional<double> Layer::kilograms_per_unit() const {
  const Metadata* m = find_metadata("kilogramsPerUnit");
  return m ? m->value.as_double() : std::nullopt;
}

std::optional<std::string_view> Layer::up_axis() const {
  const Metadata* m = find_metadata("upAxis");
  return m ? m->value.as_string() : std::nullopt;
}

std::vector<std::string_view> Layer::sublayers() const {
  std::vector<std::string_view> out;
  if (const Metadata* m = find_metadata("subLayers")) {
    for (const CompositionArc& arc : composition_arcs(m->value)) out.push_back(arc.asset);
  }
  return out;
}

std::vector<CompositionArc> composition_arcs(const Value& value) {
  std::vector<CompositionArc> out;
  auto one = [&](const Value& v) {
    CompositionArc arc;
    arc.span = v.span;
    if (v.kind == ValueKind::AssetPath) {
      arc.asset = v.text;
      arc.prim_path = v.prim_path;
    } else if (v.kind == ValueKind::Path) {
      arc.prim_path = v.text;
    } else {
      return;
    }
    if (const DictEntry* e = v.find_entry("offset")) arc.offset = e->value.as_double();
    if (const DictEntry* e = v.find_entry("scale")) arc.scale = e->value.as_double();
    out.push_back(arc);
  };
  if (value.kind == ValueKind::List) {
    for (const Value& v : value.elements) one(v);
  } else {
    one(value);
  }
  return out;
}

}  // namespace assetlint::usda
