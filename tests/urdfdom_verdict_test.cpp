// Differential test of the urdfdom skip (src/formats/urdf/urdfdom_verdict.h): asset-lint
// reports urdf-invalid (or a parse error) exactly when urdfdom rejects the document, a
// predicted verdict is urdfdom's own message for message, over every fixture, every corpus
// URDF and mutated variants of each, and urdfdom is really skipped on most of the corpus.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <functional>

#include "formats/urdf/urdf_reader.h"
#include "formats/urdf/urdfdom_check.h"
#include "formats/urdf/urdfdom_verdict.h"
#include "formats/xml/scanned_document.h"
#include "formats/xml/xml_scanner.h"
#include "pipeline/urdf_verdict.h"
#include "test_support.h"

using namespace assetlint;
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> urdfs_under(const fs::path& dir) {
  std::vector<fs::path> files;
  if (dir.empty() || !fs::is_directory(dir)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".urdf") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

struct Verdicts {
  bool asset_lint_rejects = false;  // parse-error, urdf-invalid or an undefined link
  bool urdf_invalid = false;
  bool urdfdom_rejects = false;
  bool urdfdom_ran = false;
  bool rejection_predicted = false;
};

Verdicts compare(const std::string& name, const std::string& text) {
  Verdicts v;
  const std::size_t before = urdf::urdfdom_runs();
  const ReadResult r = urdf::read_urdf(std::make_shared<const SourceFile>(name, text));
  v.urdfdom_ran = urdf::urdfdom_runs() != before;
  for (const auto& d : r.diagnostics) {
    if (d.rule == "urdf-invalid") v.urdf_invalid = true;
  }
  v.asset_lint_rejects = rejects_as_urdfdom_would(r);
  const std::vector<std::string> urdfdom = urdf::urdfdom_errors(text);
  v.urdfdom_rejects = !urdfdom.empty();
  const SourceFile file(name, text);
  const auto predicted = urdf::predicted_urdfdom_errors(xml::ScannedDocument(file, 0));
  if (predicted) CHECK(*predicted == urdfdom);  // what the reader reports instead of running urdfdom
  v.rejection_predicted = predicted && !predicted->empty();
  return v;
}

// Variants of `text` with one attribute value changed or removed, or one self-closing
// element removed: what makes urdfdom reject (missing effort, a bad number, a repeated
// name, a joint whose child is its parent, ...) and what does not.
std::vector<std::string> mutants(const std::string& text, std::size_t max_attributes) {
  const xml::XmlScan scan = xml::scan_xml(text);
  std::vector<std::pair<const xml::XmlStartTag*, const xml::XmlAttributeSpan*>> attributes;
  for (const auto& tag : scan.tags)
    for (const auto& a : tag.attributes) attributes.emplace_back(&tag, &a);
  std::vector<std::string> out;
  // Comments holding what urdfdom's verdict must ignore ('&', UTF-8, bytes that are not
  // UTF-8) and declarations spaced as xacro writes them.
  if (!scan.tags.empty()) {
    const std::size_t after_root = scan.tags.front().end;
    for (const char* comment : {"<!-- Copyright \xc2\xa9 A & B <x> -->", "<!-- \xff\xfe -->", "<!--x--->"}) {
      std::string m = text;
      m.insert(after_root, comment);
      out.push_back(std::move(m));
    }
  }
  if (text.starts_with("<?xml version=\"1.0\"")) {
    for (const char* declaration : {"<?xml version = \"1.0\" ?>", "<?xml version=\"1.0\"\n  encoding=\"UTF-8\"?>",
                                    "<?xml version='1.0'?>", "<?xml version = \"1.1\" ?>"}) {
      std::string m = text;
      m.replace(0, text.find("?>") + 2, declaration);
      out.push_back(std::move(m));
    }
  }
  const std::size_t step = std::max<std::size_t>(1, attributes.size() / std::max<std::size_t>(1, max_attributes));
  for (std::size_t i = 0; i < attributes.size(); i += step) {
    const auto& [tag, a] = attributes[i];
    const std::string value = text.substr(a->value_offset, a->value_length);
    auto with = [&](const std::string& replacement) {
      std::string m = text;
      m.replace(a->value_offset, a->value_length, replacement);
      out.push_back(std::move(m));
    };
    for (const char* r : {"", "x", "1 2", "1e999", "0x10", " 1", "1.", "-0", "nan", "1\t2 3", "1 2 3"}) with(r);
    with(value + " ");
    with(value + "\n");
    // The value of the previous attribute with the same name: repeated link or joint
    // names, self-parented joints, two parents, mimics of themselves.
    for (std::size_t k = i; k-- > 0;)
      if (attributes[k].second->name == a->name) {
        with(text.substr(attributes[k].second->value_offset, attributes[k].second->value_length));
        break;
      }
    std::string renamed = text;  // tinyxml 1 rejects a name starting with ':', tinyxml2 does not
    renamed[a->name_offset] = ':';
    out.push_back(std::move(renamed));
    std::string removed = text;
    removed.erase(a->name_offset, a->value_offset + a->value_length + 1 - a->name_offset);
    out.push_back(std::move(removed));
    if (tag->end >= 2 && text[tag->end - 2] == '/') {
      std::string without = text;
      without.erase(tag->offset, tag->end - tag->offset);
      out.push_back(std::move(without));
    }
  }
  return out;
}

struct Tally {
  std::size_t documents = 0, skipped = 0, urdfdom_accepts = 0, rejections_predicted = 0;
};

void check_all(const std::vector<fs::path>& files, std::size_t max_attributes, Tally& originals, Tally& variants) {
  for (const auto& file : files) {
    const std::string text = test::read_file(file);
    auto check = [&](const std::string& doc, Tally& tally, const std::string& what) {
      INFO(file.string() << " " << what << "\n" << doc.substr(0, 2000));
      const Verdicts v = compare(file.filename().string(), doc);
      // Never accept what urdfdom rejects; never call urdf-invalid what urdfdom accepts.
      if (v.urdfdom_rejects) CHECK(v.asset_lint_rejects);
      else CHECK_FALSE(v.urdf_invalid);
      ++tally.documents;
      if (!v.urdfdom_ran) ++tally.skipped;
      if (v.rejection_predicted) ++tally.rejections_predicted;
      if (!v.urdfdom_rejects) ++tally.urdfdom_accepts;
    };
    check(text, originals, "as written");
    for (const std::string& m : mutants(text, max_attributes)) check(m, variants, "mutant");
  }
}

}  // namespace

TEST_CASE("urdfdom verdict: skipped only where urdfdom accepts, over every fixture and its mutants", "[urdfdom]") {
  const auto files = urdfs_under(test::fixtures_dir());
  REQUIRE(files.size() >= 20);
  Tally originals, variants;
  check_all(files, 40, originals, variants);
  INFO(originals.skipped << " of " << originals.documents << " fixtures and " << variants.skipped << " of "
                         << variants.documents << " mutants skipped urdfdom");
  CHECK(variants.documents > 1000);
  // Not vacuous: the skip applies to most fixtures urdfdom accepts, and the mutants
  // include documents on both sides.
  CHECK(originals.skipped * 10 >= originals.urdfdom_accepts * 8);
  CHECK(variants.skipped > 0);
  CHECK(variants.urdfdom_accepts < variants.documents);
  CHECK(variants.rejections_predicted > 0);  // mutants without a <limit> are refused without urdfdom
}

TEST_CASE("urdfdom verdict: skipped only where urdfdom accepts, over the corpus and its mutants", "[urdfdom][corpus]") {
  const auto files = urdfs_under(test::corpus_dir().empty() ? fs::path() : test::corpus_dir() / "urdf");
  if (files.empty()) {
    WARN("../shared/corpus/urdf is absent: urdfdom differential corpus test skipped");
    return;
  }
  Tally originals, variants;
  check_all(files, 2, originals, variants);
  INFO(originals.skipped << " of " << originals.documents << " corpus files (" << originals.urdfdom_accepts
                         << " accepted by urdfdom) and " << variants.skipped << " of " << variants.documents
                         << " mutants skipped urdfdom");
  CHECK(originals.skipped * 10 >= originals.urdfdom_accepts * 8);
  CHECK(variants.skipped > 0);
  // The corpus's own refusals for a missing <limit> (Drake's PR2, the Factory Franka).
  CHECK(originals.rejections_predicted >= 2);
}

TEST_CASE("urdfdom verdict: a '%' in the document is text, not a console_bridge conversion", "[urdfdom]") {
  // urdfdom passes "Unable to parse component [x%n] …" to console_bridge as its format string;
  // read as a conversion, %n writes through a stray pointer and the process aborts.
  const std::string doc = R"(<robot name="r">
  <link name="a%s"><visual><origin xyz="x%n%s 0 0"/><geometry><box size="1 1 1"/></geometry></visual></link>
  <joint name="j" type="fixed%s"><parent link="a%s"/><child link="b"/></joint>
  <link name="b"/>
</robot>)";
  const std::vector<std::string> errors = urdf::urdfdom_errors(doc);
  CHECK(std::any_of(errors.begin(), errors.end(), [](const std::string& e) { return e.find("[x%n%s]") != std::string::npos; }));
  CHECK(std::any_of(errors.begin(), errors.end(), [](const std::string& e) { return e.find("[fixed%s]") != std::string::npos; }));
  compare("percent.urdf", doc);
  // Names stay distinct: a%b and a%%b are two links, not one repeated.
  const std::string two = R"(<robot name="r"><link name="a%b"/><link name="a%%b"/><joint name="j" type="fixed"><parent link="a%b"/><child link="a%%b"/></joint></robot>)";
  CHECK(urdf::urdfdom_errors(two).empty());
}
