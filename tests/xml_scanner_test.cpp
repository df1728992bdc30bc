#include <catch2/catch.hpp>

#include "formats/xml/xml_scanner.h"

using namespace assetlint::xml;

TEST_CASE("the scanner records exact attribute value ranges", "[urdf]") {
  const std::string text = "<?xml version=\"1.0\"?>\n<robot name='r'>\n  <limit lower=\"0\"  upper = \" 47 \"/>\n</robot>\n";
  const XmlScan scan = scan_xml(text);
  CHECK(scan.problems.empty());
  REQUIRE(scan.tags.size() == 2);
  CHECK(scan.tags[0].name == "robot");
  const XmlAttributeSpan* upper = scan.tags[1].attribute("upper");
  REQUIRE(upper);
  CHECK(text.substr(upper->value_offset, upper->value_length) == " 47 ");
  CHECK(scan.tags[1].attribute("lower")->value_length == 1);
  CHECK(text.substr(scan.document_begin, 5) == "<?xml");
  CHECK(text.substr(scan.document_end - 8, 8) == "</robot>");
}

TEST_CASE("the scanner reports the first well-formedness problem with its offset", "[urdf]") {
  SECTION("mismatched end tag") {
    const std::string text = "<robot><link></joint></robot>";
    const XmlScan scan = scan_xml(text);
    REQUIRE(scan.problems.size() == 1);
    CHECK(scan.problems[0].offset == 13);
    CHECK(scan.problems[0].message == "end tag '</joint>' does not match the open element '<link>'");
    CHECK_FALSE(scan.recoverable);
  }
  SECTION("unterminated attribute value") {
    const XmlScan scan = scan_xml("<robot name=\"r>\n<link/></robot>");
    REQUIRE(scan.problems.size() == 1);
    CHECK(scan.problems[0].offset == 12);
    CHECK_FALSE(scan.recoverable);
  }
  SECTION("text before the document is recoverable") {
    const std::string text = "String value is: <?xml version=\"1.0\"?><robot/>";
    const XmlScan scan = scan_xml(text);
    REQUIRE(scan.problems.size() == 1);
    CHECK(scan.problems[0].offset == 0);
    CHECK(scan.problems[0].length == 16);
    CHECK(scan.recoverable);
    CHECK(scan.document_begin == 17);
  }
  SECTION("trailing NUL bytes are recoverable") {
    const std::string text = std::string("<robot/>\n") + '\0';
    const XmlScan scan = scan_xml(text);
    REQUIRE(scan.problems.size() == 1);
    CHECK(scan.problems[0].offset == 9);
    CHECK(scan.problems[0].message == "1 NUL byte after the root element; strict XML parsers reject the file");
    CHECK(scan.document_end == 8);
  }
  SECTION("unclosed root") {
    const XmlScan scan = scan_xml("<robot><link/>");
    REQUIRE(scan.problems.size() == 1);
    CHECK(scan.problems[0].message == "element '<robot>' is never closed (end of file reached)");
  }
  SECTION("empty input") {
    const XmlScan scan = scan_xml("");
    REQUIRE(scan.problems.size() == 1);
    CHECK_FALSE(scan.recoverable);
  }
}

TEST_CASE("the scanner rejects control characters XML 1.0 forbids", "[urdf]") {
  const std::string text = "<robot name=\"r\x01\">\n</robot>\n";
  const XmlScan scan = scan_xml(text);
  REQUIRE(scan.problems.size() == 1);
  CHECK(scan.problems[0].offset == 14);
  CHECK(scan.problems[0].message == "control character U+0001 is not allowed in XML 1.0");
  CHECK_FALSE(scan.recoverable);
  CHECK(scan_xml("<robot name=\"r\">\t\r\n</robot>\n").problems.empty());
}
