#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "formats/usda/lexer.h"
#include "formats/usda/parser.h"

using namespace assetlint::usda;

namespace {

struct Lexed {
  TokenKind kind;
  std::string text;
};

// All tokens of a body (no header), up to End or Error.
std::vector<Lexed> lex_all(std::string_view text) {
  Lexer lex(text);
  std::vector<Lexed> out;
  for (int guard = 0; guard < 10000; ++guard) {
    const Token t = lex.next();
    out.push_back({t.kind, std::string(lex.token_text(t))});
    if (t.kind == TokenKind::End || t.kind == TokenKind::Error) break;
  }
  return out;
}

std::vector<TokenKind> kinds(std::string_view text) {
  std::vector<TokenKind> out;
  for (const auto& t : lex_all(text)) out.push_back(t.kind);
  return out;
}

}  // namespace

TEST_CASE("usda lexer: header", "[usda][lexer]") {
  SECTION("plain") {
    Lexer lex("#usda 1.0\n(\n)");
    const Header h = lex.read_header();
    CHECK(h.ok);
    CHECK(h.version == "1.0");
    CHECK(h.version_offset == 6);
    CHECK(lex.next().kind == TokenKind::LParen);
  }
  SECTION("with BOM and CRLF") {
    Lexer lex("\xEF\xBB\xBF#usda 1.0\r\ndef");
    const Header h = lex.read_header();
    CHECK(h.ok);
    CHECK(h.version == "1.0");
    const Token t = lex.next();
    CHECK(t.kind == TokenKind::Identifier);
    CHECK(t.offset == 14);
    CHECK((t.flags & kTokenNewlineBefore) != 0);
  }
  SECTION("missing") {
    Lexer lex("def \"x\" {}");
    CHECK_FALSE(lex.read_header().ok);
  }
  SECTION("no version") {
    Lexer lex("#usda\n");
    CHECK_FALSE(lex.read_header().ok);
  }
  SECTION("another cookie") {
    Lexer lex("#sdf 1.4.32\n");
    CHECK_FALSE(lex.read_header().ok);
  }
}

TEST_CASE("usda lexer: punctuation and identifiers", "[usda][lexer]") {
  const auto toks = lex_all("( ) [ ] { } = , ; : & drive:angular:physics:stiffness x.connect "
                            "xformOp:translate.timeSamples Foo::Bar _a1 \xC3\xA9t\xC3\xA9");
  REQUIRE(toks.size() == 18);
  CHECK(toks[17].kind == TokenKind::End);
  CHECK(toks[0].kind == TokenKind::LParen);
  CHECK(toks[1].kind == TokenKind::RParen);
  CHECK(toks[2].kind == TokenKind::LBracket);
  CHECK(toks[3].kind == TokenKind::RBracket);
  CHECK(toks[4].kind == TokenKind::LBrace);
  CHECK(toks[5].kind == TokenKind::RBrace);
  CHECK(toks[6].kind == TokenKind::Equals);
  CHECK(toks[7].kind == TokenKind::Comma);
  CHECK(toks[8].kind == TokenKind::Semicolon);
  CHECK(toks[9].kind == TokenKind::Colon);
  CHECK(toks[10].kind == TokenKind::Ampersand);
  CHECK(toks[11].kind == TokenKind::Identifier);
  CHECK(toks[11].text == "drive:angular:physics:stiffness");
  CHECK(toks[12].text == "x.connect");
  CHECK(toks[13].text == "xformOp:translate.timeSamples");
  CHECK(toks[14].text == "Foo::Bar");
  CHECK(toks[15].text == "_a1");
  CHECK(toks[16].kind == TokenKind::Identifier);  // UTF-8 identifier
  CHECK(toks[16].text == "\xC3\xA9t\xC3\xA9");
}

TEST_CASE("usda lexer: a colon after a number or before a space is punctuation", "[usda][lexer]") {
  const auto toks = lex_all("{ 1: 2, 2.5 :3 } pre: held");
  REQUIRE(toks.size() == 13);
  CHECK(toks[1].text == "1");
  CHECK(toks[2].kind == TokenKind::Colon);
  CHECK(toks[5].text == "2.5");
  CHECK(toks[6].kind == TokenKind::Colon);
  CHECK(toks[9].text == "pre");
  CHECK(toks[10].kind == TokenKind::Colon);
  CHECK(toks[11].text == "held");
}

TEST_CASE("usda lexer: numbers", "[usda][lexer]") {
  const auto toks = lex_all("0 42 -7 +3 1.5 -0.25 .5 -.5 1. 1e3 2.5E-2 -1e+2 -inf +inf inf nan -nan 4294967295");
  REQUIRE(toks.size() == 19);
  const std::vector<std::string> expect = {"0",     "42",     "-7",    "+3",   "1.5",  "-0.25", ".5",
                                           "-.5",   "1.",     "1e3",   "2.5E-2", "-1e+2", "-inf", "+inf",
                                           "inf",   "nan",    "-nan",  "4294967295"};
  for (std::size_t i = 0; i < expect.size(); ++i) {
    INFO(i);
    CHECK(toks[i].text == expect[i]);
  }
  // bare inf and nan are identifiers to the lexer; signed ones are numbers
  CHECK(toks[12].kind == TokenKind::Number);
  CHECK(toks[13].kind == TokenKind::Number);
  CHECK(toks[14].kind == TokenKind::Identifier);
  CHECK(toks[15].kind == TokenKind::Identifier);
  CHECK(toks[16].kind == TokenKind::Number);
  CHECK(toks[0].kind == TokenKind::Number);

  CHECK(parse_number("42") == 42.0);
  CHECK(parse_number("-0.25") == -0.25);
  CHECK(parse_number("+3") == 3.0);
  CHECK(parse_number(".5") == 0.5);
  CHECK(parse_number("1.") == 1.0);
  CHECK(parse_number("2.5E-2") == Approx(0.025));
  CHECK(parse_number("-1e+2") == -100.0);
  CHECK(std::isinf(parse_number("inf")));
  CHECK(parse_number("-inf") < 0);
  CHECK(std::isinf(parse_number("-inf")));
  CHECK(std::isnan(parse_number("nan")));
  CHECK(std::isinf(parse_number("1e999")));
  CHECK(parse_number("1e-999") == 0.0);
  CHECK(parse_number("4294967295") == 4294967295.0);
}

TEST_CASE("usda lexer: number flags", "[usda][lexer]") {
  Lexer lex("3 3.0 3e1 -inf");
  CHECK((lex.next().flags & kTokenFloat) == 0);
  CHECK((lex.next().flags & kTokenFloat) != 0);
  CHECK((lex.next().flags & kTokenFloat) != 0);
  CHECK((lex.next().flags & kTokenFloat) != 0);
}

TEST_CASE("usda lexer: strings", "[usda][lexer]") {
  const auto toks = lex_all(R"('single' "double" "esc \" \\ \n" '''tri
ple''' """a "quoted" "" word
over lines""" "")");
  REQUIRE(toks.size() == 7);
  CHECK(toks[0].text == "'single'");
  CHECK(toks[1].text == "\"double\"");
  CHECK(toks[2].text == R"("esc \" \\ \n")");
  CHECK(toks[3].text == "'''tri\nple'''");
  CHECK(toks[4].text == "\"\"\"a \"quoted\" \"\" word\nover lines\"\"\"");
  CHECK(toks[5].text == "\"\"");
  for (int i = 0; i < 6; ++i) CHECK(toks[i].kind == TokenKind::String);

  CHECK(decode_string("'single'") == "single");
  CHECK(decode_string(R"("esc \" \\ \n")") == "esc \" \\ \n");
  CHECK(decode_string(R"("\t\x41\101\q")") == "\tAAq");
  CHECK(decode_string("'''tri\nple'''") == "tri\nple");
  CHECK(decode_string("\"\"\"a \"b\"\"\"") == "a \"b");
  CHECK(decode_string("\"\"") == "");
}

TEST_CASE("usda lexer: asset paths and prim paths", "[usda][lexer]") {
  const auto toks = lex_all(R"(@./a b.usd@ @@@weird@name.usd@@@ @@@x\@@@y@@@ </World/robot/joint.physics:body0> <> </A{v=x}B>)");
  REQUIRE(toks.size() == 7);
  CHECK(toks[0].kind == TokenKind::AssetPath);
  CHECK(toks[0].text == "@./a b.usd@");
  CHECK(toks[1].kind == TokenKind::AssetPath);
  CHECK(toks[1].text == "@@@weird@name.usd@@@");
  CHECK(toks[2].text == R"(@@@x\@@@y@@@)");
  CHECK(toks[3].kind == TokenKind::PathRef);
  CHECK(toks[3].text == "</World/robot/joint.physics:body0>");
  CHECK(toks[4].text == "<>");
  CHECK(toks[5].text == "</A{v=x}B>");
  CHECK(decode_asset_path("@./a b.usd@") == "./a b.usd");
  CHECK(decode_asset_path("@@@weird@name.usd@@@") == "weird@name.usd");
  CHECK(decode_asset_path(R"(@@@x\@@@y@@@)") == "x@@@y");
  // up to two extra '@' before the closing three belong to the path
  Lexer lex("@@@a@@@@@ b");
  const Token t = lex.next();
  CHECK(lex.token_text(t) == "@@@a@@@@@");
  CHECK(decode_asset_path(lex.token_text(t)) == "a@@");
}

TEST_CASE("usda lexer: comments and whitespace", "[usda][lexer]") {
  const auto toks = lex_all("a # py comment\n b // cpp comment\r\n c /* block\n over lines */ d/**/e");
  REQUIRE(toks.size() == 6);
  CHECK(toks[0].text == "a");
  CHECK(toks[1].text == "b");
  CHECK(toks[2].text == "c");
  CHECK(toks[3].text == "d");
  CHECK(toks[4].text == "e");
  CHECK(toks[5].kind == TokenKind::End);

  Lexer lex("a /* x\n */ b c");
  CHECK((lex.next().flags & kTokenNewlineBefore) == 0);
  CHECK((lex.next().flags & kTokenNewlineBefore) != 0);
  CHECK((lex.next().flags & kTokenNewlineBefore) == 0);
}

TEST_CASE("usda lexer: errors point at the offending byte", "[usda][lexer]") {
  struct Case {
    const char* text;
    std::size_t offset;
    std::string message;
  };
  const std::vector<Case> cases = {
      {"a \"unterminated\nb", 2, "unterminated string"},
      {"a '''never closed", 2, "unterminated triple-quoted string"},
      {"x @foo.usd\n", 2, "unterminated asset path"},
      {"x </a/b\n>", 2, "unterminated path (missing '>')"},
      {"x /* open", 2, "unterminated block comment"},
      {"x ? y", 2, "unexpected character"},
      {"x - y", 2, "expected a number after '-'"},
      {"1e+", 0, "malformed exponent in number"},
      {"a\0b", 1, "unexpected character"},
  };
  for (const auto& c : cases) {
    INFO(c.text);
    Lexer lex(std::string_view(c.text, std::char_traits<char>::length(c.text) + (c.offset == 1 ? 2 : 0)));
    Token t;
    do {
      t = lex.next();
    } while (t.kind != TokenKind::Error && t.kind != TokenKind::End);
    REQUIRE(t.kind == TokenKind::Error);
    CHECK(t.offset == c.offset);
    CHECK(std::string(lex.error_message()) == c.message);
    // after an error the lexer stays at the end
    CHECK(lex.next().kind == TokenKind::End);
  }
}

TEST_CASE("usda lexer: token offsets and lengths", "[usda][lexer]") {
  Lexer lex("  float drive:angular:physics:stiffness = 3\n");
  Token t = lex.next();
  CHECK(t.offset == 2);
  CHECK(t.length == 5);
  t = lex.next();
  CHECK(t.offset == 8);
  CHECK(t.length == 31);
  t = lex.next();
  CHECK(t.kind == TokenKind::Equals);
  CHECK(t.offset == 40);
  t = lex.next();
  CHECK(t.kind == TokenKind::Number);
  CHECK(t.offset == 42);
  CHECK(t.length == 1);
  CHECK(lex.next().kind == TokenKind::End);
  CHECK(kinds("").back() == TokenKind::End);
}

#include "formats/usda/array_scan.h"

TEST_CASE("usda array scan: numeric array literals", "[usda][lexer]") {
  auto scan = [](std::string_view t) { return scan_numeric_array(t, 0, 256); };
  auto s = scan("[1, 2.5, -3e-2, inf, -inf, nan, .5] tail");
  REQUIRE(s);
  CHECK(s->count == 7);
  CHECK(s->end == 35);
  s = scan("[(0, 0, 0), (1, 2, 3),\n # comment ]\n (4, 5, 6) /* c */, // x\n]");
  REQUIRE(s);
  CHECK(s->count == 3);
  CHECK(scan("[]")->count == 0);
  CHECK(scan("[1, 2,]")->count == 2);  // trailing comma
  CHECK(scan("[[1, 2], [3]]")->count == 2);
  CHECK_FALSE(scan("[1 2]"));
  CHECK_FALSE(scan("[1,, 2]"));
  CHECK_FALSE(scan("[, 1]"));
  CHECK_FALSE(scan("[(1, 2]"));
  CHECK_FALSE(scan("[()]"));
  CHECK_FALSE(scan("[1abc]"));
  CHECK_FALSE(scan("[1e]"));
  CHECK_FALSE(scan("[\"a\"]"));
  CHECK_FALSE(scan("[infinity]"));
  CHECK_FALSE(scan("[1, 2"));
  CHECK_FALSE(scan("[1 /* open"));
  CHECK_FALSE(scan_numeric_array("[[[[1]]]]", 0, 3));  // deeper than allowed
  CHECK(scan_numeric_array("x [1]", 2, 256)->end == 5);
}
