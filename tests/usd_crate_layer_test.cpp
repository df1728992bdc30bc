// The crate reader that builds the layer from the crate's specs (usdc::read_crate_layer,
// what checking reads) holds to the text path: for every crate layer of fixtures/usdc and
// the corpus, its layer is, node for node, the layer the parser reads from the USDA that
// `asset-lint cat` prints (kinds, numbers and their integer-ness, lazy arrays and their
// numbers, list ops, qualifiers, order), and every prim, property and variant is located
// at its object path. (The OpenUSD differential test holds the text path to OpenUSD.)
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "test_support.h"
#include "support/crate_files.h"

#include "formats/usda/parser.h"
#include "formats/usdc/crate_layer.h"
#include "formats/usdc/crate_usda.h"

using assetlint::test::crate_files;
using assetlint::test::fixtures_dir;
using assetlint::test::read_file;

namespace {

namespace fs = std::filesystem;
namespace usda = assetlint::usda;
namespace usdc = assetlint::usdc;

// Lazy lists up to this long are also compared as the nodes they materialize to.
constexpr std::size_t kMaterializedItems = 4096;

// Everything the parser decides about a node, spans aside; lazy lists by their numbers.
class Dump {
 public:
  explicit Dump(const assetlint::SourceFile& source) : source_(source) {}

  // How many lazy lists were compared as nodes.
  std::size_t materialized() const { return materialized_; }

  std::string layer(const usda::Layer& l) {
    out_ = "version " + l.version + "\n";
    metadata(l.metadata, "");
    for (const auto& r : l.reorders) reorder(r, "");
    for (const auto& p : l.prims) prim(p, "");
    return out_;
  }

 private:
  void value(const usda::Value& v) {
    out_ += fmt::format("{}{}{}{{", usda::value_kind_name(v.kind), v.is_integer ? " int" : "", v.lazy ? " lazy" : "");
    switch (v.kind) {
      case usda::ValueKind::Number: out_ += fmt::format("{}", v.number); break;
      case usda::ValueKind::Tuple:
      case usda::ValueKind::List:
        out_ += fmt::format("{} items:", v.count);
        if (v.lazy) {
          std::vector<double> numbers;
          out_ += usda::read_numbers(v, source_.view(), numbers) ? "" : "(unreadable)";
          for (double n : numbers) out_ += fmt::format(" {}", n);
          // And as nodes, as materialize() builds them (kinds, integer-ness, tuples).
          if (v.count <= kMaterializedItems) {
            auto items = usda::parse_elements(v, source_, v.span.file);
            REQUIRE(std::holds_alternative<std::vector<usda::Value>>(items));
            out_ += " nodes:";
            ++materialized_;
            for (const auto& e : std::get<std::vector<usda::Value>>(items)) value(e);
          }
        } else {
          for (const auto& e : v.elements) value(e);
        }
        break;
      default: out_ += v.text; break;
    }
    if (!v.prim_path.empty()) out_ += " prim " + v.prim_path;
    for (const auto& e : v.entries) {
      out_ += fmt::format(" [{}{} {} key=", e.type_name, e.type_is_array ? "[]" : "", e.key);
      value(e.key_value);
      out_ += " value=";
      value(e.value);
      out_ += "]";
    }
    out_ += "}";
  }

  void metadata(const std::vector<usda::Metadata>& list, const std::string& indent) {
    for (const auto& m : list) {
      out_ += fmt::format("{}meta {} {}{} = ", indent, usda::list_op_name(m.op), m.key, m.is_doc_shorthand ? " (doc)" : "");
      value(m.value);
      out_ += "\n";
    }
  }

  void reorder(const usda::ReorderStatement& r, const std::string& indent) {
    out_ += indent + "reorder " + r.what + " ";
    value(r.names);
    out_ += "\n";
  }

  void paths(const usda::PathList& list, const std::string& indent, const char* what) {
    out_ += fmt::format("{}{} {}{}", indent, what, usda::list_op_name(list.op), list.none ? " None" : "");
    for (const auto& p : list.paths) value(p);
    out_ += "\n";
  }

  void prim(const usda::Prim& p, const std::string& indent) {
    out_ += fmt::format("{}{} {} '{}'\n", indent, usda::specifier_name(p.specifier), p.type_name, p.name);
    const std::string in = indent + "  ";
    metadata(p.metadata, in);
    for (const auto& r : p.reorders) reorder(r, in);
    for (const auto& ref : p.property_order) {
      if (ref.is_relationship) {
        const auto& r = p.relationships[ref.index];
        out_ += fmt::format("{}rel {} custom={} varying={}\n", in, r.name, r.custom, r.varying);
        for (const auto& t : r.targets) paths(t, in + "  ", "targets");
        if (r.default_target) value(*r.default_target);
        metadata(r.metadata, in + "  ");
      } else {
        const auto& a = p.attributes[ref.index];
        out_ += fmt::format("{}attr {} {} custom={} variability={} spline={}", in, a.full_type(), a.name, a.custom,
                            static_cast<int>(a.variability), a.spline.has_value());
        if (a.default_value) {
          out_ += " = ";
          value(*a.default_value);
        }
        out_ += "\n";
        if (a.time_samples)
          for (const auto& s : a.time_samples->samples) {
            out_ += fmt::format("{}  sample {}: ", in, s.time);
            value(s.value);
            out_ += "\n";
          }
        for (const auto& c : a.connections) paths(c, in + "  ", "connect");
        metadata(a.metadata, in + "  ");
      }
    }
    for (const auto& c : p.children) prim(c, in);
    for (const auto& set : p.variant_sets) {
      out_ += in + "variantSet " + set.name + "\n";
      for (const auto& v : set.variants) prim(v.body, in + "  ");
    }
  }

  const assetlint::SourceFile& source_;
  std::size_t materialized_ = 0;
  std::string out_;
};

std::string first_difference(const std::string& a, const std::string& b) {
  std::size_t pos = 0, line = 1;
  while (pos < a.size() && pos < b.size()) {
    const auto ea = a.find('\n', pos), eb = b.find('\n', pos);
    const std::string la = a.substr(pos, ea - pos), lb = b.substr(pos, eb - pos);
    if (la != lb) return fmt::format("line {}:\n  built:  {}\n  parsed: {}", line, la, lb);
    if (ea == std::string::npos || eb == std::string::npos) break;
    pos = ea + 1;
    ++line;
  }
  return a.size() == b.size() ? "" : fmt::format("one dump ends at line {}", line);
}

// Every prim, property and variant of `prims` names its own path where it is located.
void check_locations(const assetlint::SourceFile& source, const std::vector<usda::Prim>& prims, const std::string& parent) {
  for (const auto& p : prims) {
    const std::string path = parent + "/" + p.name;
    CHECK(source.object_at(p.span.offset) == path);
    for (const auto& a : p.attributes) {
      CHECK(source.object_at(a.span.offset) == path + "." + a.name);
      if (a.default_value) CHECK(source.object_at(a.default_value->span.offset) == path + "." + a.name);
    }
    for (const auto& r : p.relationships) CHECK(source.object_at(r.span.offset) == path + "." + r.name);
    for (const auto& m : p.metadata) CHECK(source.object_at(m.value.span.offset) == path);
    check_locations(source, p.children, path);
    for (const auto& set : p.variant_sets)
      for (const auto& v : set.variants) {
        const std::string variant = path + "{" + set.name + "=" + v.name + "}";
        CHECK(source.object_at(v.span.offset) == variant);
        for (const auto& a : v.body.attributes) CHECK(source.object_at(a.span.offset) == variant + "." + a.name);
      }
  }
}

}  // namespace

TEST_CASE("a crate layer built from its specs is the layer its USDA text parses to", "[usdc]") {
  const auto files = crate_files();
  REQUIRE(files.size() >= 4);
  std::size_t materialized = 0;
  for (const auto& path : files) {
    INFO(path.string());
    const std::string bytes = read_file(path);
    std::string error;
    const auto built = usdc::read_crate_layer(path.string(), bytes, 3, error);
    REQUIRE(built);
    REQUIRE(built->layer);  // read without the text, not left to the parser
    CHECK(built->source->binary());
    CHECK(built->layer->file == 3);

    auto text = usdc::crate_to_usda(bytes);
    REQUIRE(std::holds_alternative<usdc::CrateText>(text));
    const assetlint::SourceFile source(path.string(), std::get<usdc::CrateText>(text).text);
    const auto parsed = usda::parse_layer(source, 3);
    REQUIRE(parsed.ok());
    Dump built_dump(*built->source);
    const std::string difference = first_difference(built_dump.layer(*built->layer), Dump(source).layer(parsed.layer()));
    CHECK(difference == "");
    check_locations(*built->source, built->layer->prims, "");
    materialized += built_dump.materialized();
  }
  CHECK(materialized > 0);  // some long arrays were compared as nodes too
}

TEST_CASE("a crate layer that cannot be read gives the text path's error", "[usdc]") {
  const std::string bytes = read_file(fixtures_dir() / "usdc" / "robotiq_2f85.usd");
  for (const std::size_t size : {std::size_t{40}, std::size_t{200}, bytes.size() / 2}) {
    INFO(size);
    const std::string cut = bytes.substr(0, size);
    std::string error, expected;
    CHECK_FALSE(usdc::read_crate_layer("cut.usd", cut, 0, error));
    CHECK_FALSE(usdc::crate_source("cut.usd", cut, expected));
    CHECK(error == expected);
    CHECK_FALSE(error.empty());
  }
}
