// The crate (binary USD) reader held to OpenUSD 22.11 (WASM, npm three-usdz-loader, run with
// Node): tests/usd_reference/export_layers.mjs opens every crate layer of fixtures/usdc and
// ../shared/corpus/usdc with OpenUSD and writes it back as USDA (SdfLayer::ExportToString).
// asset-lint's reading of the crate file must equal its reading of that text: the same
// specs, fields and values, and the same findings.
//
// Skipped with a message when `node` or the package is absent; with CI=true a failure.
#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "test_support.h"
#include "support/crate_files.h"
#include "support/openusd_oracle.h"

#include "engine/settings.h"
#include "formats/usda/parser.h"
#include "formats/usdc/crate_usda.h"
#include "pipeline/lint.h"

using assetlint::test::crate_files;
using assetlint::test::read_file;

namespace {

namespace fs = std::filesystem;
namespace usda = assetlint::usda;
namespace usdc = assetlint::usdc;

struct Reference {
  nlohmann::json json;
  std::string skipped;
  // `asset-lint cat` of each crate file, given to OpenUSD too: it must accept the text and
  // read the same layer from it.
  std::vector<std::string> cat_texts;
};

const Reference& reference() {
  static const Reference result = [] {
    Reference r;
    r.skipped = assetlint::test::openusd_missing();
    if (!r.skipped.empty()) return r;
    assetlint::test::TempDir dir;
    std::vector<std::string> args;
    for (const auto& f : crate_files()) args.push_back(f.string());
    for (const auto& f : crate_files()) {
      auto result = usdc::crate_to_usda(read_file(f));
      if (auto* e = std::get_if<usdc::CrateError>(&result)) FAIL(usdc::describe(*e, f.string()));
      r.cat_texts.push_back(std::get<usdc::CrateText>(result).text);
      const auto text = dir.path() / fmt::format("cat{}.usda", r.cat_texts.size());
      assetlint::test::write_file(text, r.cat_texts.back());
      args.push_back(text.string());
    }
    r.json = assetlint::test::run_openusd("export_layers.mjs", args, dir.path());
    return r;
  }();
  return result;
}

bool skip_without_openusd() { return assetlint::test::skip_without_reference("OpenUSD", reference().skipped); }

// A layer written out canonically: metadata sorted by key (USDA does not order it), prims,
// properties and children in their order, every value with its kind.
void dump_value(const usda::Value& v, std::string& out) {
  out += usda::value_kind_name(v.kind);
  out += ":";
  switch (v.kind) {
    case usda::ValueKind::Number: out += fmt::format("{}", v.number); break;
    case usda::ValueKind::String:
    case usda::ValueKind::Identifier:
    case usda::ValueKind::Path: out += v.text; break;
    case usda::ValueKind::AssetPath: out += "@" + v.text + "@<" + v.prim_path + ">"; break;
    case usda::ValueKind::Tuple:
    case usda::ValueKind::List:
      out += "[";
      for (const auto& e : v.elements) {
        dump_value(e, out);
        out += ",";
      }
      out += "]";
      break;
    default: break;
  }
  if (!v.entries.empty()) {
    std::vector<std::string> entries;
    for (const auto& e : v.entries) {
      std::string s = e.type_name + (e.type_is_array ? "[] " : " ") + e.key + "=";
      dump_value(e.value, s);
      entries.push_back(s);
    }
    std::sort(entries.begin(), entries.end());
    out += "{";
    for (const auto& e : entries) out += e + ";";
    out += "}";
  }
}

void dump_metadata(const std::vector<usda::Metadata>& list, const std::string& indent, std::string& out) {
  std::vector<std::string> lines;
  for (const auto& m : list) {
    std::string s = indent + "meta " + usda::list_op_name(m.op) + " " + m.key + " = ";
    dump_value(m.value, s);
    lines.push_back(s + "\n");
  }
  std::sort(lines.begin(), lines.end());
  for (const auto& l : lines) out += l;
}

void dump_prim(const usda::Prim& p, const std::string& path, const std::string& indent, std::string& out) {
  out += indent + usda::specifier_name(p.specifier) + " " + p.type_name + " " + path + "\n";
  const std::string in = indent + "  ";
  dump_metadata(p.metadata, in, out);
  for (const auto& r : p.reorders) {
    out += in + "reorder " + r.what + " ";
    dump_value(r.names, out);
    out += "\n";
  }
  // Property order is presentation only (OpenUSD's writer sorts them): compared by name.
  std::vector<usda::PropertyRef> order = p.property_order;
  const auto name_of = [&](const usda::PropertyRef& r) {
    return r.is_relationship ? p.relationships[r.index].name : p.attributes[r.index].name;
  };
  std::sort(order.begin(), order.end(), [&](const auto& a, const auto& b) { return name_of(a) < name_of(b); });
  for (const auto& ref : order) {
    if (ref.is_relationship) {
      const auto& r = p.relationships[ref.index];
      out += in + fmt::format("rel {} custom={} varying={}\n", r.name, r.custom, r.varying);
      for (const auto& t : r.targets) {
        out += in + "  targets " + usda::list_op_name(t.op) + (t.none ? " None " : " ");
        for (const auto& v : t.paths) dump_value(v, out);
        out += "\n";
      }
      dump_metadata(r.metadata, in + "  ", out);
    } else {
      const auto& a = p.attributes[ref.index];
      out += in + fmt::format("attr {} {} custom={} variability={}", a.full_type(), a.name, a.custom,
                              static_cast<int>(a.variability));
      if (a.default_value) {
        out += " = ";
        dump_value(*a.default_value, out);
      }
      out += "\n";
      if (a.time_samples)
        for (const auto& s : a.time_samples->samples) {
          out += in + fmt::format("  sample {}: ", s.time);
          dump_value(s.value, out);
          out += "\n";
        }
      for (const auto& c : a.connections) {
        out += in + "  connect " + usda::list_op_name(c.op) + " ";
        for (const auto& v : c.paths) dump_value(v, out);
        out += "\n";
      }
      dump_metadata(a.metadata, in + "  ", out);
    }
  }
  for (const auto& c : p.children) dump_prim(c, path + "/" + c.name, in, out);
  for (const auto& set : p.variant_sets) {
    out += in + "variantSet " + set.name + "\n";
    for (const auto& v : set.variants) dump_prim(v.body, path + "{" + set.name + "=" + v.name + "}", in + "  ", out);
  }
}

std::string dump_layer(const usda::Layer& layer) {
  std::string out;
  dump_metadata(layer.metadata, "", out);
  for (const auto& p : layer.prims) dump_prim(p, "/" + p.name, "", out);
  return out;
}

usda::Layer parse(const std::string& name, const std::string& text) {
  const assetlint::SourceFile file(name, text);
  usda::ParseOptions options;
  options.lazy_arrays = false;
  usda::ParseResult r = usda::parse_layer(file, 0, options);
  if (!r.ok()) FAIL(name << ": " << r.error().message << " at line " << r.error().span.line);
  return std::move(r.layer());
}

// The first line where two dumps differ, with both lines.
std::string first_difference(const std::string& a, const std::string& b) {
  std::size_t pos = 0, line = 1;
  while (pos < a.size() && pos < b.size()) {
    const auto ea = a.find('\n', pos), eb = b.find('\n', pos);
    const std::string la = a.substr(pos, ea - pos), lb = b.substr(pos, eb - pos);
    if (la != lb) return fmt::format("line {}:\n  asset-lint: {}\n  OpenUSD:    {}", line, la, lb);
    if (ea == std::string::npos || eb == std::string::npos) break;
    pos = ea + 1;
    ++line;
  }
  return a.size() == b.size() ? "" : fmt::format("one dump ends at line {}", line);
}

std::vector<std::string> findings(const assetlint::FileReport& report) {
  std::vector<std::string> out;
  for (const auto& d : report.diagnostics) out.push_back(d.rule + ": " + d.message);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("a crate layer reads as OpenUSD writes it in USDA, with the same findings", "[openusd][usdc]") {
  if (skip_without_openusd()) return;
  const auto& all = reference().json["layers"];
  const std::size_t n = crate_files().size();
  REQUIRE(all.size() == 2 * n);
  REQUIRE(n >= 3);
  std::size_t same_layer = 0, same_findings = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& entry = all[i];
    const std::string path = entry["path"].get<std::string>();
    INFO(path);
    REQUIRE_FALSE(entry["usda"].is_null());
    const std::string bytes = read_file(path);
    auto ours = usdc::crate_to_usda(bytes);
    if (auto* e = std::get_if<usdc::CrateError>(&ours)) FAIL(usdc::describe(*e, path));
    const auto& crate = std::get<usdc::CrateText>(ours);
    CHECK(crate.skipped_fields.empty());
    const std::string mine = dump_layer(parse(path + " (asset-lint)", crate.text));
    const std::string theirs = dump_layer(parse(path + " (OpenUSD)", entry["usda"].get<std::string>()));
    const std::string difference = first_difference(mine, theirs);
    CHECK(difference == "");
    if (difference.empty()) ++same_layer;

    const assetlint::Settings settings;
    const auto from_crate = assetlint::lint_text(path, bytes, settings);
    const auto from_text = assetlint::lint_text(path, entry["usda"].get<std::string>(), settings);
    CHECK_FALSE(from_crate.error);
    CHECK(findings(from_crate) == findings(from_text));
    if (findings(from_crate) == findings(from_text)) ++same_findings;
  }
  WARN(fmt::format("{} crate layers: {} read as OpenUSD writes them, {} with the same findings", n,
                   same_layer, same_findings));
}

TEST_CASE("asset-lint cat prints a crate layer as USDA that OpenUSD reads back to the same layer", "[openusd][usdc]") {
  if (skip_without_openusd()) return;
  const auto& all = reference().json["layers"];
  const auto files = crate_files();
  REQUIRE(all.size() == 2 * files.size());
  for (std::size_t i = 0; i < files.size(); ++i) {
    INFO(files[i].string());
    const auto& back = all[files.size() + i];
    REQUIRE_FALSE(back["usda"].is_null());  // OpenUSD accepts the text
    const std::string& text = reference().cat_texts[i];
    // What OpenUSD reads from the text is what asset-lint reads from the crate file, and
    // what asset-lint reads from the text it printed.
    const std::string ours = dump_layer(parse("cat", text));
    CHECK(first_difference(ours, dump_layer(parse("OpenUSD of cat", back["usda"].get<std::string>()))) == "");
    CHECK(first_difference(ours, dump_layer(parse("OpenUSD of crate", all[i]["usda"].get<std::string>()))) == "");
  }
}
