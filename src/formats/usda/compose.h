#pragma once
// Composition of a .usda layer with the local layers it names: `subLayers` (the layer
// stack, strongest first), `references` and `payload` arcs (to other .usda files, or
// internal `</Prim>` references), merging prim specs by path. The strongest opinion wins
// per attribute; `apiSchemas` list-ops compose across all specs.
//
//   Stage stage = compose_stage(root_file, files, {});
//   if (!stage.usable) ...;                  // a layer did not parse (parse-error reported)
//   const ComposedPrim* p = stage.find("/robot/joints/J0");
//   auto stiffness = p->attribute("drive:angular:physics:stiffness");
//
// Every layer read becomes a SourceFile (Stage::sources, FileId = index, [0] the root), so
// spans of the AST nodes a ComposedPrim hands out point into the layer that authored them.
// Variant sets compose as USD's LIVRPS order says: the sets a prim's layer stack lists in
// `variantSets` (list-edited), each selected by the strongest `variants` opinion of the prim's
// whole index (or pinned), weaker than the layer stack's own opinions and stronger than its
// references and payloads; a variant's arcs and nested sets sit under it.
//
// Layers that are missing, binary, or outside the allowed directory tree are skipped with
// a `layer-unresolved` note at the asset path; cycles are reported (warning) and cut.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "engine/diagnostic.h"
#include "engine/file_system.h"
#include "formats/usda/ast.h"
#include "model/source.h"

namespace assetlint::usda {

// Variant set name -> variant name.
using VariantSelections = std::map<std::string, std::string, std::less<>>;

struct ComposeOptions {
  // Layers outside this directory tree are not read. Empty: the root layer's directory.
  std::string root_dir;
  bool allow_outside_root = false;
  // Selections that replace the authored ones, for every prim with a variant set of that
  // name (a stronger layer selecting them on every such prim would do the same).
  VariantSelections pinned_variants;
  // The root layer, read already (a crate layer, usdc::read_crate_layer); null: parse the
  // root source.
  std::shared_ptr<const Layer> root_layer;
};

// A variant set on a composed prim, and the variant this composition selected in it.
struct VariantSetUse {
  std::string prim;                   // "/gripper"
  std::string set;                    // "PhysX"
  std::vector<std::string> variants;  // the variant names its layers define, first seen first
  std::string selection;              // "" when none is selected (or pinned)
  bool pinned = false;                // the selection comes from ComposeOptions::pinned_variants
  // The selected variant's opinions (its body, its descendants' and what its arcs bring
  // in) author physics: a Physics* prim type, a physics API schema or attribute.
  bool physics = false;
  Span span;                                          // the strongest `variantSet` name
  std::size_t parent = static_cast<std::size_t>(-1);  // the variant that holds this set (nested)
};

// One prim spec that contributes opinions to a composed prim.
struct SpecRef {
  FileId file = kNoFile;
  const Prim* prim = nullptr;
  FileId stack = kNoFile;  // the layer whose layer stack holds the spec (internal references resolve there)
  // Paths authored in the spec under `source_root` map to `target_root` on the stage
  // (a referenced prim's relationship targets). Both empty: identity.
  std::string source_root;
  std::string target_root;
  // The innermost selected variant (Stage::variant_sets) whose opinions this spec is part of.
  std::size_t variant = static_cast<std::size_t>(-1);
};

struct AttributeOpinion {
  const Attribute* attribute = nullptr;
  FileId file = kNoFile;
};

struct RelationshipOpinion {
  const Relationship* relationship = nullptr;
  FileId file = kNoFile;
  std::vector<std::string> targets;       // mapped into stage namespace
  std::vector<const Value*> target_values;  // the authored path literals (for spans)
};

struct ComposedPrim {
  std::string path;  // "/robot/joints/J0"
  std::string name;
  std::string type_name;  // strongest authored type name
  bool defined = false;   // some spec is a `def` (only-`over` prims are not on the stage)
  std::vector<SpecRef> specs;             // strongest first
  std::vector<std::string> api_schemas;   // composed applied schemas, in order
  std::vector<std::string> deleted_api_schemas;  // removed by a `delete` list-op and not re-added
  std::vector<std::size_t> children;      // indices into Stage::prims
  std::size_t parent = static_cast<std::size_t>(-1);

  // The strongest spec that gives the attribute a value (`= None` blocks weaker ones).
  std::optional<AttributeOpinion> attribute(std::string_view name) const;
  std::optional<RelationshipOpinion> relationship(std::string_view name) const;
  bool has_api_schema(std::string_view schema) const;
  bool schema_deleted(std::string_view schema) const;
  // The strongest opinion of every attribute authored on the prim with a value, ordered
  // by (file, offset) of the winning declaration.
  std::vector<AttributeOpinion> attributes() const;
  // Where a schema is applied: the string literal in the strongest `apiSchemas` entry
  // that adds it; the prim's name when none is found.
  Span schema_span(std::string_view schema) const;
  // The span of the strongest spec's prim name (quoted).
  Span span() const;
};

struct Stage {
  std::vector<std::shared_ptr<const SourceFile>> sources;  // by FileId; [0] the root layer
  std::vector<std::shared_ptr<const Layer>> layers;        // by FileId; null when not parsed
  std::vector<FileId> root_stack;                          // the root layer stack, strongest first
  std::vector<ComposedPrim> prims;                         // depth-first, parents before children
  std::vector<std::size_t> roots;                          // root prims, in order
  std::vector<Diagnostic> diagnostics;                     // parse-error, layer-unresolved
  // Arcs whose opinions did not reach the stage (missing, binary, outside the checked
  // tree, cyclic): their layer-unresolved diagnostic, and the prim whose opinions the arc
  // would have brought ("" for a subLayer: the whole stage).
  struct SkippedArc {
    std::size_t diagnostic;
    std::string scope;
  };
  std::vector<SkippedArc> skipped;
  std::vector<VariantSetUse> variant_sets;  // every variant set on the stage, in composition order
  bool usable = true;                                      // false: a layer has a syntax error

  const ComposedPrim* find(std::string_view path) const;
  const Layer* root_layer() const { return layers.empty() ? nullptr : layers[0].get(); }

  std::unordered_map<std::string, std::size_t> index;  // path -> prims index
};

// Reads `root` and every local layer it composes, through `files`.
Stage compose_stage(std::shared_ptr<const SourceFile> root, const FileSystem& files, const ComposeOptions& options = {});

}  // namespace assetlint::usda
