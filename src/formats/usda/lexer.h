#pragma once
// Tokenizer for the USD text format (.usda). Works directly on the file's bytes:
// tokens are offsets into the text, nothing is copied.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace assetlint::usda {

enum class TokenKind : std::uint8_t {
  End,         // end of input
  Error,       // lexical error; see Lexer::error_message()
  Identifier,  // name or keyword, may contain ':' and '.' parts (physics:body0, x.connect)
  Number,      // 1, -2.5, 1e-3, .5, -inf, +inf, -nan (bare inf/nan lex as Identifier)
  String,      // "..." '...' """...""" '''...''' (token text includes the quotes)
  AssetPath,   // @...@ or @@@...@@@ (token text includes the delimiters)
  PathRef,     // <...> (token text includes the angle brackets)
  LParen,
  RParen,
  LBracket,
  RBracket,
  LBrace,
  RBrace,
  Equals,
  Comma,
  Semicolon,
  Colon,
  Ampersand,  // only used by spline knots
};

const char* token_kind_name(TokenKind kind);

// Flags on a token.
enum TokenFlags : std::uint8_t {
  kTokenHasEscape = 1,     // String or AssetPath containing a backslash escape
  kTokenTripleQuoted = 2,  // """...""", '''...''' or @@@...@@@
  kTokenFloat = 4,         // Number with '.', exponent, inf or nan
  kTokenNewlineBefore = 8, // a line break (or a comment ending one) precedes the token
};

struct Token {
  TokenKind kind = TokenKind::End;
  std::uint8_t flags = 0;
  std::uint32_t length = 0;
  std::size_t offset = 0;

  std::size_t end() const { return offset + length; }
};

// The "#usda 1.0" first line.
struct Header {
  bool ok = false;
  std::string_view version;  // "1.0"
  std::size_t version_offset = 0;
  std::size_t body_offset = 0;  // where the first token after the header line may start
};

class Lexer {
 public:
  explicit Lexer(std::string_view text, std::size_t start = 0) : text_(text), pos_(start) {}

  // Reads the header line at the start of the text (after an optional UTF-8 BOM) and
  // positions the lexer after it. Returns ok=false when the header is missing or malformed.
  Header read_header();

  // The next token. After End or Error, keeps returning the same kind.
  Token next();

  std::string_view text() const { return text_; }
  std::string_view token_text(const Token& t) const { return text_.substr(t.offset, t.length); }
  std::size_t position() const { return pos_; }
  void reset(std::size_t pos) { pos_ = pos; }

  // For an Error token: what went wrong. The token's offset points at the offending byte
  // (or at the start of the unterminated construct).
  const char* error_message() const { return error_; }

 private:
  bool skip_space_and_comments(Token& err, bool& newline);
  Token next_token();
  Token make(TokenKind kind, std::size_t start, std::size_t end, std::uint8_t flags = 0) const;
  Token fail(const char* message, std::size_t at, std::size_t length = 1);
  Token lex_number(std::size_t start);
  Token lex_identifier(std::size_t start);
  Token lex_string(std::size_t start);
  Token lex_asset_path(std::size_t start);
  Token lex_path_ref(std::size_t start);

  std::string_view text_;
  std::size_t pos_ = 0;
  const char* error_ = "";
};

// Character classes shared with the parser.
inline bool is_ident_start(unsigned char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c >= 0x80;
}
inline bool is_ident_char(unsigned char c) { return is_ident_start(c) || (c >= '0' && c <= '9'); }
inline bool is_digit(unsigned char c) { return c >= '0' && c <= '9'; }

}  // namespace assetlint::usda
