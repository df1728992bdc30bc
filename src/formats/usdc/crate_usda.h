#pragma once
// A crate layer written as the USDA text OpenUSD would write for it, with the place of
// every prim and property in that text. asset-lint reads crate layers through this text
// (one parser, one layer structure for text and binary layers), and `asset-lint cat`
// prints it.
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "formats/usdc/crate_file.h"
#include "model/source.h"

namespace assetlint::usdc {

struct CrateText {
  std::string text;
  std::vector<ObjectLocation> objects;  // by offset
  Version version;
  // Fields left out because their value type has no USDA form here: "</a.b> spline".
  std::vector<std::string> skipped_fields;
};

// Reads a whole crate file. Never throws on bad input: a broken file gives the error
// with the section where it was found.
std::variant<CrateText, CrateError> crate_to_usda(std::string_view bytes);

// The source asset-lint reads a crate layer as (SourceFile::binary()); null with `error`
// set when the file cannot be read.
std::shared_ptr<const SourceFile> crate_source(const std::string& path, std::string_view bytes, std::string& error);

// "crate layer 'x.usd': PATHS: path entry 7 is reached twice"
std::string describe(const CrateError& error, std::string_view path);

}  // namespace assetlint::usdc
