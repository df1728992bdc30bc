// The URDF reader takes its elements from the scanner alone (src/formats/xml/scanned_document.h),
// where it used to parse with tinyxml2 too. This differential test holds the two equal: over
// every fixture and corpus XML file and mutated variants of them, whatever tinyxml2 rejects
// the scanner rejects, and where the scanner accepts, tinyxml2 builds the same elements with
// the same attribute values (entities and line breaks decoded).
#include <tinyxml2.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <optional>

#include "formats/xml/scanned_document.h"
#include "test_support.h"

using namespace assetlint;
namespace fs = std::filesystem;

namespace {

using Elements = std::vector<std::string>;  // pre-order: "name a=v b=w"

std::optional<Elements> tinyxml2_elements(std::string_view document) {
  tinyxml2::XMLDocument doc(true, tinyxml2::COLLAPSE_WHITESPACE);
  if (doc.Parse(document.data(), document.size()) != tinyxml2::XML_SUCCESS) return std::nullopt;
  Elements out;
  auto visit = [&](auto&& self, const tinyxml2::XMLElement* el) -> void {
    std::string line = el->Name();
    for (const tinyxml2::XMLAttribute* a = el->FirstAttribute(); a; a = a->Next())
      line += std::string(" ") + a->Name() + "=" + a->Value();
    out.push_back(std::move(line));
    for (const tinyxml2::XMLElement* c = el->FirstChildElement(); c; c = c->NextSiblingElement()) self(self, c);
  };
  if (doc.RootElement()) visit(visit, doc.RootElement());
  return out;
}

Elements scanner_elements(const xml::ScannedDocument& doc) {
  Elements out;
  auto visit = [&](auto&& self, const xml::Element* el) -> void {
    std::string line(el->name);
    for (const auto& a : el->attributes) line += " " + std::string(a.name) + "=" + std::string(doc.value(a));
    out.push_back(std::move(line));
    for (const xml::Element* c = doc.first_child(el); c; c = doc.next_sibling(c)) self(self, c);
  };
  visit(visit, doc.root());
  return out;
}

// Whether tinyxml2 parses the document the scanner delimits, when the scanner does not.
bool scan_xml_recoverable_document_parses(const std::string& text) {
  const xml::XmlScan scan = xml::scan_xml(text);
  const std::string_view document = std::string_view(text).substr(scan.document_begin, scan.document_end - scan.document_begin);
  return tinyxml2_elements(document).has_value();
}

struct Tally {
  std::size_t documents = 0, both_accept = 0, scanner_only_rejects = 0;
};

void check_document(const std::string& text, Tally& tally, const std::string& what) {
  INFO(what << "\n" << text.substr(0, 1500));
  ++tally.documents;
  const SourceFile file("t.xml", text);
  const xml::ScannedDocument scanned(file, 0);
  if (!scanned.root()) {
    // The scanner may be stricter (it wants whitespace between attributes, no '<' in values).
    if (scan_xml_recoverable_document_parses(text)) ++tally.scanner_only_rejects;
    return;
  }
  const auto expected = tinyxml2_elements(scanned.document());
  REQUIRE(expected);  // tinyxml2 rejects nothing the scanner accepts
  CHECK(scanner_elements(scanned) == *expected);
  ++tally.both_accept;
}

std::vector<std::string> mutants(const std::string& text) {
  std::vector<std::string> out;
  const xml::XmlScan scan = xml::scan_xml(text);
  if (scan.tags.size() < 2) return out;
  const std::size_t inner = scan.tags[1].offset;  // inside the root element
  for (const char* insert :
       {"<1a/>", "<a!b/>", "<.a/>", "<a.b-c:d_e/>", "<_a/>", "<\xc3\xa9t\xc3\xa9/>", "< a/>", "<a b='1'c='2'/>",
        "<a 1b='1'/>", "<a b$='1'/>", "<?pi data?>", "<?xml version=\"1.0\"?>", "<?xml-stylesheet x?>",
        "<!DOCTYPE x>", "<![CDATA[<x>]]>", "<a b=\"&#x41;&#66;&amp;&lt;&gt;&quot;&apos;\"/>",
        "<a b=\"&unknown; &amp\"/>", "<a b=\"l1\r\nl2\rl3\n\rl4\"/>", "<a b=\"\xc3\xa9\" c='\"'/>",
        "<a></a >", "<a></ a>", "<!-->x-->", "<!-->", "<a/ >", "<a b=\"1\" b=\"2\"/>", "text & more", "<a>", "</a>"}) {
    std::string m = text;
    m.insert(inner, insert);
    out.push_back(std::move(m));
  }
  // Nesting at and around tinyxml2's depth limit, closed and self-closing.
  for (std::size_t depth : {96, 97, 98, 99}) {
    std::string open, close;
    for (std::size_t i = 0; i < depth; ++i) open += "<n>", close += "</n>";
    std::string m = text;
    m.insert(inner, open + close);
    out.push_back(m);
    m = text;
    m.insert(inner, open + "<leaf/>" + close);
    out.push_back(std::move(m));
  }
  // Declarations and processing instructions before the root.
  out.push_back("<!-- c --><?xml version=\"1.0\"?>" + text.substr(scan.tags[0].offset));
  out.push_back("<!-- c --><?pi x?>" + text.substr(scan.tags[0].offset));
  out.push_back("<?pi x?><?xml version=\"1.0\"?>" + text.substr(scan.tags[0].offset));
  out.push_back("<?>" + text.substr(scan.tags[0].offset));
  out.push_back(text + "<?pi x?>");
  return out;
}

std::vector<fs::path> xml_files_under(const fs::path& dir) {
  std::vector<fs::path> files;
  if (dir.empty() || !fs::is_directory(dir)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    const auto ext = entry.path().extension();
    if (entry.is_regular_file() && (ext == ".urdf" || ext == ".xml" || ext == ".mjcf")) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("xml scanner: rejects whatever tinyxml2 rejects and reads the same elements and values", "[urdf][xml]") {
  Tally tally;
  std::vector<fs::path> files = xml_files_under(test::fixtures_dir());
  if (const fs::path corpus = test::corpus_dir(); !corpus.empty()) {
    for (const char* sub : {"urdf", "mjcf"})
      for (auto& f : xml_files_under(corpus / sub)) files.push_back(std::move(f));
  } else {
    WARN("../shared/corpus is absent: the scanner/tinyxml2 comparison covers the fixtures only");
  }
  REQUIRE(files.size() >= 20);
  for (const auto& file : files) {
    const std::string text = test::read_file(file);
    check_document(text, tally, file.string());
    for (const std::string& m : mutants(text)) check_document(m, tally, file.string() + " (mutant)");
  }
  INFO(tally.documents << " documents, " << tally.both_accept << " accepted by both, " << tally.scanner_only_rejects
                       << " rejected by the scanner alone");
  // Not vacuous: a third of the documents reach the element comparison, and the rest are
  // rejected by both or (a space missing between attributes, '< a>', <!DOCTYPE> inside an
  // element) by the stricter scanner alone.
  CHECK(tally.both_accept * 3 > tally.documents);
  CHECK(tally.scanner_only_rejects > 0);
}

TEST_CASE("xml scanner: nesting deeper than tinyxml2 allows is a located error", "[urdf][xml]") {
  std::string text = "<robot>";
  for (std::size_t i = 1; i < xml::kMaxXmlDepth; ++i) text += "<n>";
  const std::size_t too_deep = text.size();
  text += "<deep></deep>";
  for (std::size_t i = 1; i < xml::kMaxXmlDepth; ++i) text += "</n>";
  text += "</robot>";
  const xml::XmlScan scan = xml::scan_xml(text);
  REQUIRE(scan.problems.size() == 1);
  CHECK(scan.problems[0].offset == too_deep);
  CHECK(scan.problems[0].message == "elements nested deeper than 98 levels ('<deep>')");
  CHECK_FALSE(scan.recoverable);
}

TEST_CASE("xml scanner: attribute values decode entities and line breaks as XML parsers do", "[urdf][xml]") {
  CHECK(xml::decode_attribute_value("a&amp;b&lt;&gt;&quot;&apos;") == "a&b<>\"'");
  CHECK(xml::decode_attribute_value("&#65;&#x42;&#xe9;") == "AB\xc3\xa9");
  CHECK(xml::decode_attribute_value("&bogus; &amp") == "&bogus; &amp");
  CHECK(xml::decode_attribute_value("1\r\n2\r3\n\r4\n5") == "1\n2\n3\n4\n5");
  CHECK_FALSE(xml::attribute_value_needs_decoding("0 0 1\n"));
  CHECK(xml::attribute_value_needs_decoding("a&amp;b"));
}

TEST_CASE("xml scanner: a NUL byte anywhere in the document stops it, as it stops tinyxml2", "[urdf][xml]") {
  using namespace std::string_literals;
  for (const std::string& text : {"<robot><!-- a\0b --></robot>"s, "<robot name=\"a\0b\"/>"s,
                                  "<?xml version=\"1.0\"?><!-- \0 --><robot/>"s, "<robot/><!-- \0 -->"s}) {
    INFO(text);
    const xml::XmlScan scan = xml::scan_xml(text);
    REQUIRE(scan.problems.size() == 1);
    CHECK(scan.problems.back().offset == text.find('\0'));
    CHECK(scan.problems.back().message == "NUL byte inside the XML document");
    CHECK_FALSE(scan.recoverable);
  }
}
