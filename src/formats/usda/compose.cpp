#include "formats/usda/compose.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <unordered_set>

#include "formats/file_kind.h"
#include "formats/usda/parser.h"
#include "formats/usdc/crate_layer.h"
#include "formats/usdc/crate_file.h"
#include "rules/reader_rules.h"

namespace assetlint::usda {
namespace {

namespace fs = std::filesystem;

std::string normalize(const fs::path& p) {
  std::string s = p.lexically_normal().generic_string();
  if (s.size() > 1 && s.back() == '/') s.pop_back();
  return s.empty() ? std::string(".") : s;
}

bool starts_with_text_header(std::string_view text) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  return text.starts_with("#usda");
}

// One spec's list-op items for a metadata key: USD applies, within one spec, an explicit
// list alone, else delete, add, prepend, append in that order (SdfListOp::ApplyOperations).
template <class Item>
struct SpecListOps {
  bool explicit_set = false;
  std::vector<Item> explicit_items, deleted, added, prepended, appended;
};

template <class Item, class Key>
void apply_ops(std::vector<Item>& out, const SpecListOps<Item>& ops, Key key) {
  auto remove = [&](const Item& x) {
    out.erase(std::remove_if(out.begin(), out.end(), [&](const Item& y) { return key(y) == key(x); }), out.end());
  };
  auto contains = [&](const Item& x) {
    return std::any_of(out.begin(), out.end(), [&](const Item& y) { return key(y) == key(x); });
  };
  if (ops.explicit_set) {
    out = ops.explicit_items;
    return;
  }
  for (const Item& x : ops.deleted) remove(x);
  for (const Item& x : ops.added)
    if (!contains(x)) out.push_back(x);
  for (auto it = ops.prepended.rbegin(); it != ops.prepended.rend(); ++it) {
    remove(*it);
    out.insert(out.begin(), *it);
  }
  for (const Item& x : ops.appended) {
    remove(x);
    out.push_back(x);
  }
}

template <class Item>
void add_items(SpecListOps<Item>& ops, ListOp op, std::vector<Item> items) {
  auto& target = op == ListOp::Explicit  ? ops.explicit_items
                 : op == ListOp::Delete  ? ops.deleted
                 : op == ListOp::Prepend ? ops.prepended
                 : op == ListOp::Append  ? ops.appended
                                         : ops.added;
  if (op == ListOp::Reorder) return;
  if (op == ListOp::Explicit) ops.explicit_set = true;
  target.insert(target.end(), items.begin(), items.end());
}

std::string map_path(std::string_view authored, const SpecRef& spec) {
  if (spec.source_root.empty() || spec.source_root == spec.target_root) return std::string(authored);
  const std::string_view root = spec.source_root;
  if (authored.starts_with(root) && (authored.size() == root.size() || authored[root.size()] == '/' ||
                                     authored[root.size()] == '.'))
    return spec.target_root + std::string(authored.substr(root.size()));
  return std::string(authored);
}

using Selections = VariantSelections;

bool physics_name(std::string_view name) {
  for (std::string_view prefix : {"physics:", "physx", "drive:", "newton:", "mjc:"})
    if (name.starts_with(prefix)) return true;
  return false;
}

bool physics_schema(std::string_view schema) {
  for (std::string_view prefix : {"Physics", "Physx", "Newton", "Mjc"})
    if (schema.starts_with(prefix)) return true;
  return false;
}

// The spec's own opinions (not its children's) say something a physics engine reads.
bool authors_physics(const Prim& prim) {
  if (physics_schema(prim.type_name)) return true;
  for (const Metadata& m : prim.metadata) {
    if (m.key != "apiSchemas") continue;
    if (auto items = m.value.as_string_list())
      for (std::string_view item : *items)
        if (physics_schema(item)) return true;
  }
  for (const Attribute& a : prim.attributes)
    if (physics_name(a.name)) return true;
  for (const Relationship& r : prim.relationships)
    if (physics_name(r.name)) return true;
  return false;
}
constexpr std::size_t kNoVariant = static_cast<std::size_t>(-1);

struct Arc {
  CompositionArc arc;
  const SpecRef* owner = nullptr;
};

class Composer {
 public:
  Composer(const FileSystem& files, const ComposeOptions& options) : files_(files), options_(options) {}

  Stage run(std::shared_ptr<const SourceFile> root) {
    root_dir_ = options_.root_dir.empty() ? fs::path(root->path()).parent_path() : fs::path(options_.root_dir);
    root_dir_abs_ = normalize(fs::absolute(root_dir_.empty() ? fs::path(".") : root_dir_));
    const std::string key = normalize(root->path());
    stage_.sources.push_back(std::move(root));
    stage_.layers.emplace_back();
    by_path_[key] = Loaded{0, {}, Severity::Info, {}};
    if (options_.root_layer) stage_.layers[0] = options_.root_layer;
    else parse(0);
    if (!stage_.usable) return std::move(stage_);
    stage_.root_stack = stack(0);

    std::vector<Container> containers;
    for (FileId id : stage_.root_stack)
      if (stage_.layers[id]) containers.push_back({&stage_.layers[id]->prims, SpecRef{id, nullptr, 0, {}, {}}});
    std::vector<const Prim*> active;
    stage_.roots = compose_level(containers, "", static_cast<std::size_t>(-1), active, 0);
    mark_physics_variants();
    return std::move(stage_);
  }

 private:
  // A selected variant carries physics when a spec it contributes (on any prim) does.
  void mark_physics_variants() {
    for (const ComposedPrim& prim : stage_.prims)
      for (const SpecRef& s : prim.specs) {
        if (s.variant == kNoVariant || stage_.variant_sets[s.variant].physics || !authors_physics(*s.prim)) continue;
        for (std::size_t use = s.variant; use != kNoVariant; use = stage_.variant_sets[use].parent)
          stage_.variant_sets[use].physics = true;
      }
  }

  struct Loaded {
    std::optional<FileId> id;
    std::string problem;  // why it was not read
    Severity severity = Severity::Info;
    std::string detail;   // a note: how to read it after all
  };
  struct Container {
    const std::vector<Prim>* prims;
    SpecRef spec;  // the template for child specs (prim is the parent)
  };

  // `scope`: the prim whose opinions the arc would have brought ("" for a subLayer: the whole stage).
  // Null when the arc was reported already.
  Diagnostic* report(const Span& span, Severity severity, std::string message, std::string_view scope) {
    if (!reported_.insert({span.file, span.offset}).second) return nullptr;
    stage_.skipped.push_back({stage_.diagnostics.size(), std::string(scope)});
    stage_.diagnostics.push_back({std::string(rules::kLayerUnresolved.id), severity, span, std::move(message), std::nullopt, {}, {}, {}});
    return &stage_.diagnostics.back();
  }

  void parse(FileId id) {
    ParseResult r = parse_layer(*stage_.sources[id], id);
    if (!r.ok()) {
      stage_.diagnostics.push_back({std::string(rules::kParseError.id), rules::kParseError.default_severity,
                                    r.error().span, r.error().message, std::nullopt, {}, {}, {}});
      stage_.usable = false;
      return;
    }
    stage_.layers[id] = std::make_unique<Layer>(std::move(r.layer()));
  }

  // The layer an asset path names, read and parsed once; nullopt (reported) when it cannot be used.
  std::optional<FileId> resolve(FileId from, std::string_view asset, const Span& span, std::string_view scope) {
    const std::string shown(asset);
    if (asset.find("://") != std::string_view::npos) {
      report(span, Severity::Info, fmt::format("layer '{}' is not a local file; skipped", shown), scope);
      return std::nullopt;
    }
    fs::path path(asset);
    if (path.is_relative()) path = fs::path(stage_.sources[from]->path()).parent_path() / path;
    const std::string key = normalize(path);
    auto it = by_path_.find(key);
    if (it == by_path_.end()) it = by_path_.emplace(key, load(key)).first;
    if (!it->second.id) {
      Diagnostic* d = report(span, it->second.severity, fmt::format("layer '{}' {}", shown, it->second.problem), scope);
      if (d && !it->second.detail.empty()) d->note(it->second.detail);
      return std::nullopt;
    }
    return it->second.id;
  }

  // The checked tree as messages show it: relative to the working directory when it is
  // below it, so that reports do not carry machine paths.
  std::string shown_root() const {
    if (root_dir_.empty()) return ".";
    std::error_code ec;
    const fs::path relative = fs::path(root_dir_abs_).lexically_relative(fs::current_path(ec));
    if (!ec && !relative.empty() && *relative.begin() != "..") return relative.generic_string();
    return root_dir_.generic_string();
  }

  Loaded load(const std::string& key) {
    if (!options_.allow_outside_root) {
      const fs::path relative = fs::path(normalize(fs::absolute(key))).lexically_relative(root_dir_abs_);
      if (relative.empty() || *relative.begin() == "..")
        return {std::nullopt, "is outside the checked tree; skipped", Severity::Info,
                fmt::format("the checked tree is '{}' (the git work tree, else the directory of asset-lint.toml, else "
                            "the directory named); --root DIR or --allow-outside-root reads layers beyond it",
                            shown_root())};
    }
    std::string ext = fs::path(key).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    const char* binary = "is a binary USD package (.usdz), which asset-lint does not open; its opinions are skipped";
    if (ext == ".usdz") return {std::nullopt, binary, Severity::Info, {}};
    std::string error;
    std::optional<std::string> text = files_.read(key, error);
    if (!text) return {std::nullopt, fmt::format("cannot be read ({}); skipped", error), Severity::Info, {}};
    std::shared_ptr<const SourceFile> source;
    const auto id = static_cast<FileId>(stage_.sources.size());
    if (usdc::is_crate(*text)) {
      auto crate = usdc::read_crate_layer(key, *text, id, error);
      if (!crate) return {std::nullopt, "cannot be read; its opinions are skipped", Severity::Warning, error};
      stage_.sources.push_back(std::move(crate->source));
      stage_.layers.push_back(std::move(crate->layer));
      if (!stage_.layers[id]) parse(id);
      return {id, {}, Severity::Info, {}};
    } else if (is_lfs_pointer(*text)) {
      return {std::nullopt, lfs_pointer_message() + "; its opinions are skipped", Severity::Warning, {}};
    } else if (!starts_with_text_header(*text)) {
      return {std::nullopt, "is neither a USDA nor a crate layer; its opinions are skipped", Severity::Info, {}};
    } else {
      source = std::make_shared<const SourceFile>(key, std::move(*text));
    }
    stage_.sources.push_back(std::move(source));
    stage_.layers.emplace_back();
    parse(id);
    return {id, {}, Severity::Info, {}};
  }

  // A layer and its sublayers, strongest first; a layer reached twice keeps its first
  // (strongest) position.
  const std::vector<FileId>& stack(FileId id) {
    if (auto it = stacks_.find(id); it != stacks_.end()) return it->second;
    std::vector<FileId> out, chain;
    visit(id, out, chain);
    return stacks_[id] = std::move(out);
  }

  void visit(FileId id, std::vector<FileId>& out, std::vector<FileId>& chain) {
    out.push_back(id);
    chain.push_back(id);
    if (stage_.layers[id]) {
      if (const Metadata* m = stage_.layers[id]->find_metadata("subLayers")) {
        for (const CompositionArc& arc : composition_arcs(m->value)) {
          if (arc.asset.empty()) continue;
          auto sub = resolve(id, arc.asset, arc.span, "");
          if (!sub) continue;
          if (std::find(chain.begin(), chain.end(), *sub) != chain.end()) {
            report(arc.span, Severity::Warning,
                   fmt::format("sublayer cycle: '{}' already includes this layer; the arc is ignored", arc.asset), "");
            continue;
          }
          if (std::find(out.begin(), out.end(), *sub) != out.end()) continue;  // diamond
          visit(*sub, out, chain);
        }
      }
    }
    chain.pop_back();
  }

  // references then payloads, each composed across the specs (weakest applied first).
  std::vector<Arc> arcs_of(const std::vector<SpecRef>& specs, std::size_t count) {
    std::vector<Arc> all;
    for (const char* key : {"references", "payload"}) {
      std::vector<Arc> out;
      for (std::size_t i = count; i-- > 0;) {
        SpecListOps<Arc> ops;
        bool any = false;
        for (const Metadata& m : specs[i].prim->metadata) {
          if (m.key != key) continue;
          any = true;
          std::vector<Arc> items;
          for (const CompositionArc& a : composition_arcs(m.value)) items.push_back({a, &specs[i]});
          add_items(ops, m.op, std::move(items));
        }
        if (any)
          apply_ops(out, ops, [](const Arc& a) { return std::pair{a.arc.asset, a.arc.prim_path}; });
      }
      all.insert(all.end(), out.begin(), out.end());
    }
    return all;
  }

  // The strongest `variants` selection of each set among `specs` (strongest first), after the pins.
  Selections selections_of(const std::vector<SpecRef>& specs) const {
    Selections out = options_.pinned_variants;
    for (const SpecRef& s : specs)
      for (const Metadata& m : s.prim->metadata) {
        if (m.key != "variants") continue;
        for (const DictEntry& e : m.value.entries)
          if (auto name = e.value.as_string()) out.try_emplace(e.key, std::string(*name));
      }
    return out;
  }

  // The variant set names a node's layer stack lists (`variantSets`, list-edited, weakest applied first).
  static std::vector<std::string> variant_set_names(const std::vector<SpecRef>& node) {
    std::vector<std::string> out;
    for (std::size_t i = node.size(); i-- > 0;) {
      SpecListOps<std::string> ops;
      bool any = false;
      for (const Metadata& m : node[i].prim->metadata) {
        if (m.key != "variantSets") continue;
        auto items = m.value.as_string_list();
        if (!items) continue;
        any = true;
        add_items(ops, m.op, std::vector<std::string>(items->begin(), items->end()));
      }
      if (any) apply_ops(out, ops, [](const std::string& x) -> const std::string& { return x; });
    }
    return out;
  }

  // Appends one node of the prim index and what lies under it, strongest first: the node's
  // specs, its selected variants (in `variantSets` order, each with its own subtree), then
  // the targets of its references and payloads.
  void add_node(const std::vector<SpecRef>& node, const std::string& path, std::vector<const Prim*>& active,
                const Selections& selections, std::vector<SpecRef>& out, std::vector<VariantSetUse>& uses) {
    if (node.empty() || active.size() > 400) return;
    out.insert(out.end(), node.begin(), node.end());
    for (const std::string& set : variant_set_names(node)) {
      VariantSetUse use;
      use.prim = path;
      use.set = set;
      use.parent = node.front().variant;
      auto selected = selections.find(set);
      if (selected != selections.end()) use.selection = selected->second;
      use.pinned = options_.pinned_variants.count(set) > 0;
      std::vector<SpecRef> bodies;
      for (const SpecRef& s : node)
        for (const VariantSet& vs : s.prim->variant_sets) {
          if (vs.name != set) continue;
          if (!use.span.valid()) use.span = vs.name_span;
          for (const Variant& v : vs.variants)
            if (std::find(use.variants.begin(), use.variants.end(), v.name) == use.variants.end())
              use.variants.push_back(v.name);
          if (const Variant* v = use.selection.empty() ? nullptr : vs.find_variant(use.selection)) {
            SpecRef body = s;
            body.prim = &v->body;
            body.variant = first_use_ + uses.size();
            bodies.push_back(std::move(body));
          }
        }
      uses.push_back(std::move(use));
      add_node(bodies, path, active, selections, out, uses);
    }
    for (const Arc& a : arcs_of(node, node.size())) {
      const SpecRef& owner = *a.owner;
      std::optional<FileId> target;
      if (a.arc.asset.empty()) {
        target = owner.stack;
      } else {
        target = resolve(owner.file, a.arc.asset, a.arc.span, path);
      }
      if (!target || !stage_.layers[*target]) continue;
      std::string target_path(a.arc.prim_path);
      if (target_path.empty()) {
        auto default_prim = stage_.layers[*target]->default_prim();
        if (!default_prim) {
          report(a.arc.span, Severity::Info,
                 fmt::format("layer '{}' has no defaultPrim and the reference names no prim; skipped", a.arc.asset),
                 path);
          continue;
        }
        target_path = "/" + std::string(*default_prim);
      }
      std::vector<SpecRef> targets;
      for (FileId l : stack(*target)) {
        if (!stage_.layers[l]) continue;
        if (const Prim* p = stage_.layers[l]->find_prim(target_path))
          targets.push_back({l, p, *target, target_path, path, owner.variant});
      }
      if (targets.empty()) {
        report(a.arc.span, Severity::Info,
               fmt::format("referenced prim '{}' is not in {}; skipped", target_path,
                           a.arc.asset.empty() ? std::string("this layer stack") : fmt::format("'{}'", a.arc.asset)),
               path);
        continue;
      }
      // A cycle is an arc back to a site already being composed: the same prim of the same
      // layer stack. Sublayers that two stacks share (a materials layer every part file
      // includes) bring the same spec into both without any cycle, so the site is told by the
      // prim of the stack's own layer, or its strongest spec when that layer has none.
      const auto own = std::find_if(targets.begin(), targets.end(), [&](const SpecRef& t) { return t.file == *target; });
      const Prim* site = own != targets.end() ? own->prim : targets.front().prim;
      const bool cycle = std::find(active.begin(), active.end(), site) != active.end();
      if (cycle) {
        Diagnostic* d = report(a.arc.span, Severity::Warning,
                               fmt::format("reference cycle: the arc on '{}' leads back to '{}'; ignored", path, target_path),
                               path);
        if (d)
          d->note(fmt::format("'{}' is already composed from prim '{}'{}: USD refuses such an arc, so whatever it "
                              "was meant to bring in is missing in the simulator too.",
                              path, target_path, a.arc.asset.empty() ? std::string() : fmt::format(" of '{}'", a.arc.asset)));
        continue;
      }
      active.push_back(site);
      add_node(targets, path, active, selections, out, uses);
      active.pop_back();
    }
  }

  // Replaces `specs` (the prim's specs in the stage's layer stack) by the prim's whole index,
  // strongest first. A selection may be authored anywhere in the index, also in a layer that
  // a variant brings in: the index is rebuilt until the selections it holds are the ones it
  // was built with.
  void expand(std::vector<SpecRef>& specs, const std::string& path, std::vector<const Prim*>& active) {
    first_use_ = stage_.variant_sets.size();
    Selections selections = options_.pinned_variants;
    std::vector<SpecRef> out;
    std::vector<VariantSetUse> uses;
    for (int round = 0; round < 8; ++round) {
      out.clear();
      uses.clear();
      add_node(specs, path, active, selections, out, uses);
      Selections found = selections_of(out);
      if (found == selections) break;
      selections = std::move(found);
    }
    for (VariantSetUse& use : uses) stage_.variant_sets.push_back(std::move(use));
    specs = std::move(out);
  }

  std::vector<std::size_t> compose_level(const std::vector<Container>& containers, const std::string& parent_path,
                                         std::size_t parent, std::vector<const Prim*>& active, std::size_t depth) {
    std::vector<std::size_t> out;
    if (depth > 400) return out;
    // The specs of each child name, strongest first, names in first-seen order: one pass
    // over the containers (a scope with many children stays linear).
    std::vector<std::string_view> names;
    std::unordered_map<std::string_view, std::vector<SpecRef>> specs_of;
    for (const Container& c : containers)
      for (const Prim& p : *c.prims) {
        auto [it, fresh] = specs_of.try_emplace(p.name);
        if (fresh) names.push_back(p.name);
        SpecRef s = c.spec;
        s.prim = &p;
        it->second.push_back(std::move(s));
      }
    for (std::string_view name : names) {
      std::vector<SpecRef> specs = std::move(specs_of[name]);
      const std::string path = parent_path + "/" + std::string(name);
      if (stage_.index.count(path)) continue;
      const std::size_t before = active.size();
      for (const SpecRef& s : specs) active.push_back(s.prim);
      expand(specs, path, active);
      active.resize(before);
      for (const SpecRef& s : specs) active.push_back(s.prim);

      const std::size_t index = stage_.prims.size();
      stage_.index.emplace(path, index);
      out.push_back(index);
      {
        ComposedPrim prim;
        prim.path = path;
        prim.name = std::string(name);
        prim.parent = parent;
        for (const SpecRef& s : specs) {
          if (prim.type_name.empty()) prim.type_name = s.prim->type_name;
          if (s.prim->specifier == Specifier::Def) prim.defined = true;
        }
        compose_schemas(prim, specs);
        prim.specs = std::move(specs);
        stage_.prims.push_back(std::move(prim));
      }
      std::vector<Container> children;
      for (const SpecRef& s : stage_.prims[index].specs) children.push_back({&s.prim->children, s});
      auto kids = compose_level(children, path, index, active, depth + 1);
      stage_.prims[index].children = std::move(kids);
      active.resize(before);
    }
    return out;
  }

  static void compose_schemas(ComposedPrim& prim, const std::vector<SpecRef>& specs) {
    std::vector<std::string> out;
    std::set<std::string> deleted;
    for (std::size_t i = specs.size(); i-- > 0;) {
      SpecListOps<std::string> ops;
      bool any = false;
      for (const Metadata& m : specs[i].prim->metadata) {
        if (m.key != "apiSchemas") continue;
        auto items = m.value.as_string_list();
        if (!items) continue;
        any = true;
        std::vector<std::string> strings(items->begin(), items->end());
        if (m.op == ListOp::Delete) deleted.insert(strings.begin(), strings.end());
        add_items(ops, m.op, std::move(strings));
      }
      if (any) apply_ops(out, ops, [](const std::string& s) -> const std::string& { return s; });
    }
    for (const std::string& d : deleted)
      if (std::find(out.begin(), out.end(), d) == out.end()) prim.deleted_api_schemas.push_back(d);
    prim.api_schemas = std::move(out);
  }

  const FileSystem& files_;
  ComposeOptions options_;
  fs::path root_dir_;
  std::string root_dir_abs_;
  Stage stage_;
  std::unordered_map<std::string, Loaded> by_path_;
  std::unordered_map<FileId, std::vector<FileId>> stacks_;
  std::set<std::pair<FileId, std::size_t>> reported_;
  std::size_t first_use_ = 0;  // Stage::variant_sets index of the first set of the prim being expanded
};

}  // namespace

// --- ComposedPrim ---------------------------------------------------------------------
std::optional<AttributeOpinion> ComposedPrim::attribute(std::string_view n) const {
  for (const SpecRef& s : specs) {
    const Attribute* a = s.prim->find_attribute(n);
    if (!a || !a->default_value) continue;
    if (a->default_value->is_none()) return std::nullopt;  // blocked
    return AttributeOpinion{a, s.file};
  }
  return std::nullopt;
}

std::optional<RelationshipOpinion> ComposedPrim::relationship(std::string_view n) const {
  for (const SpecRef& s : specs) {
    const Relationship* r = s.prim->find_relationship(n);
    if (!r || r->targets.empty()) continue;
    RelationshipOpinion out{r, s.file, {}, {}};
    for (const Value* v : r->resolved_targets()) {
      out.targets.push_back(map_path(v->text, s));
      out.target_values.push_back(v);
    }
    return out;
  }
  return std::nullopt;
}

bool ComposedPrim::has_api_schema(std::string_view schema) const {
  return std::find(api_schemas.begin(), api_schemas.end(), schema) != api_schemas.end();
}

bool ComposedPrim::schema_deleted(std::string_view schema) const {
  return std::find(deleted_api_schemas.begin(), deleted_api_schemas.end(), schema) != deleted_api_schemas.end();
}

std::vector<AttributeOpinion> ComposedPrim::attributes() const {
  std::vector<AttributeOpinion> out;
  std::unordered_set<std::string_view> seen;
  for (const SpecRef& s : specs) {
    for (const Attribute& a : s.prim->attributes) {
      if (!a.default_value || !seen.insert(a.name).second) continue;
      if (!a.default_value->is_none()) out.push_back({&a, s.file});
    }
  }
  std::sort(out.begin(), out.end(), [](const AttributeOpinion& x, const AttributeOpinion& y) {
    return std::pair{x.file, x.attribute->span.offset} < std::pair{y.file, y.attribute->span.offset};
  });
  return out;
}

Span ComposedPrim::schema_span(std::string_view schema) const {
  for (const SpecRef& s : specs) {
    for (auto it = s.prim->metadata.rbegin(); it != s.prim->metadata.rend(); ++it) {
      const Metadata& m = *it;
      if (m.key != "apiSchemas" || m.op == ListOp::Delete) continue;
      if (m.value.kind == ValueKind::List) {
        for (const Value& e : m.value.elements)
          if (e.text == schema) return e.span;
      } else if (m.value.text == schema) {
        return m.value.span;
      }
    }
  }
  return span();
}

Span ComposedPrim::span() const {
  for (const SpecRef& s : specs)
    if (s.prim->specifier == Specifier::Def) return s.prim->name_span;
  return specs.empty() ? Span{} : specs.front().prim->name_span;
}

const ComposedPrim* Stage::find(std::string_view path) const {
  auto it = index.find(std::string(path));
  return it == index.end() ? nullptr : &prims[it->second];
}

Stage compose_stage(std::shared_ptr<const SourceFile> root, const FileSystem& files, const ComposeOptions& options) {
  return Composer(files, options).run(std::move(root));
}

}  // namespace assetlint::usda
