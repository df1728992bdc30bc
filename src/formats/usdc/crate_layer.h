#pragma once
// A crate layer read into the layer structure the USDA parser builds, without writing the
// whole layer as text and parsing it back: prims, properties, specifiers, type names and
// targets are built from the crate's specs as the text writer (crate_usda.h) lays them
// out; values are written as the same USDA literals and read by the parser's value
// grammar, so each is the value the text gives (large numeric arrays lazy as there).
//
// The layer's source is binary (SourceFile::binary()): it holds those literals, with a
// line per object (prim, property, variant) so that every location in it names its object.
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "formats/usda/ast.h"
#include "model/source.h"

namespace assetlint::usdc {

struct CrateLayer {
  std::shared_ptr<const SourceFile> source;
  // Null when the layer is read through its whole text instead (crate_source(), for what
  // this reader leaves to the parser, such as a file the parser rejects): parse `source`.
  std::shared_ptr<const usda::Layer> layer;
};

// Reads the crate file `bytes` as layer `id` of a stage. Nullopt with `error` set when the
// file cannot be read.
std::optional<CrateLayer> read_crate_layer(const std::string& path, std::string_view bytes, FileId id,
                                           std::string& error);

}  // namespace assetlint::usdc
