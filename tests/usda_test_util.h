#pragma once
// Helpers shared by the USDA tests.
#include <memory>
#include <string>
#include <string_view>

#include "formats/usda/parser.h"
#include "model/source.h"

namespace usda_test {

// A parsed text together with the SourceFile it points into.
struct Parsed {
  std::unique_ptr<assetlint::SourceFile> file;
  assetlint::usda::ParseResult result;

  bool ok() const { return result.ok(); }
  const assetlint::usda::Layer& layer() const { return result.layer(); }
  const assetlint::usda::ParseError& error() const { return result.error(); }
  // The exact source bytes a span covers.
  std::string_view text(const assetlint::Span& s) const { return file->view().substr(s.offset, s.length); }
};

inline Parsed parse(std::string text, const assetlint::usda::ParseOptions& options = {}) {
  auto file = std::make_unique<assetlint::SourceFile>("test.usda", std::move(text));
  auto result = assetlint::usda::parse_layer(*file, 7, options);
  return Parsed{std::move(file), std::move(result)};
}

}  // namespace usda_test
