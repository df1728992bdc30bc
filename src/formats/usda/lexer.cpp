#include "formats/usda/lexer.h"

#include <limits>

namespace assetlint::usda {

const char* token_kind_name(TokenKind kind) {
  switch (kind) {
    case TokenKind::End: return "end of file";
    case TokenKind::Error: return "invalid token";
    case TokenKind::Identifier: return "identifier";
    case TokenKind::Number: return "number";
    case TokenKind::String: return "string";
    case TokenKind::AssetPath: return "asset path";
    case TokenKind::PathRef: return "path";
    case TokenKind::LParen: return "'('";
    case TokenKind::RParen: return "')'";
    case TokenKind::LBracket: return "'['";
    case TokenKind::RBracket: return "']'";
    case TokenKind::LBrace: return "'{'";
    case TokenKind::RBrace: return "'}'";
    case TokenKind::Equals: return "'='";
    case TokenKind::Comma: return "','";
    case TokenKind::Semicolon: return "';'";
    case TokenKind::Colon: return "':'";
    case TokenKind::Ampersand: return "'&'";
  }
  return "token";
}

namespace {
bool starts_with_at(std::string_view text, std::size_t pos, std::string_view what) {
  return text.size() >= pos + what.size() && text.compare(pos, what.size(), what) == 0;
}
bool is_space(unsigned char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }
}  // namespace

Header Lexer::read_header() {
  Header h;
  std::size_t p = 0;
  if (starts_with_at(text_, 0, "\xEF\xBB\xBF")) p = 3;
  if (!starts_with_at(text_, p, "#usda")) {
    pos_ = p;
    return h;
  }
  p += 5;
  const std::size_t after_magic = p;
  while (p < text_.size() && (text_[p] == ' ' || text_[p] == '\t')) ++p;
  const std::size_t vstart = p;
  while (p < text_.size() && !is_space(static_cast<unsigned char>(text_[p]))) ++p;
  h.version = text_.substr(vstart, p - vstart);
  h.version_offset = vstart;
  // Anything after the version on the header line is treated as a comment.
  h.ok = vstart > after_magic && !h.version.empty() && is_digit(static_cast<unsigned char>(h.version[0]));
  while (p < text_.size() && text_[p] != '\n' && text_[p] != '\r') ++p;
  h.body_offset = p;
  pos_ = p;
  return h;
}

Token Lexer::make(TokenKind kind, std::size_t start, std::size_t end, std::uint8_t flags) const {
  Token t;
  t.kind = kind;
  t.flags = flags;
  t.offset = start;
  const std::size_t len = end - start;
  t.length = len > std::numeric_limits<std::uint32_t>::max() ? std::numeric_limits<std::uint32_t>::max()
                                                             : static_cast<std::uint32_t>(len);
  return t;
}

Token Lexer::fail(const char* message, std::size_t at, std::size_t length) {
  error_ = message;
  if (at > text_.size()) at = text_.size();
  if (at + length > text_.size()) length = text_.size() - at;
  Token t = make(TokenKind::Error, at, at + length);
  // Stay stuck at the end so that every later call reports End/Error, never loops.
  pos_ = text_.size();
  return t;
}

bool Lexer::skip_space_and_comments(Token& err, bool& newline) {
  const std::size_t n = text_.size();
  const char* s = text_.data();
  std::size_t p = pos_;
  while (p < n) {
    const unsigned char c = static_cast<unsigned char>(s[p]);
    if (c == ' ' || c == '\t' || c == '\f' || c == '\v') {
      ++p;
    } else if (c == '\n' || c == '\r') {
      newline = true;
      ++p;
    } else if (c == '#' || (c == '/' && p + 1 < n && s[p + 1] == '/')) {
      while (p < n && s[p] != '\n' && s[p] != '\r') ++p;
    } else if (c == '/' && p + 1 < n && s[p + 1] == '*') {
      const std::size_t open = p;
      p += 2;
      for (;;) {
        if (p + 1 >= n) {
          err = fail("unterminated block comment", open, 2);
          return false;
        }
        if (s[p] == '\n' || s[p] == '\r') newline = true;
        if (s[p] == '*' && s[p + 1] == '/') {
          p += 2;
          break;
        }
        ++p;
      }
    } else {
      break;
    }
  }
  pos_ = p;
  return true;
}

Token Lexer::next() {
  Token err;
  bool newline = false;
  if (!skip_space_and_comments(err, newline)) return err;
  Token t = next_token();
  if (newline) t.flags |= kTokenNewlineBefore;
  return t;
}

Token Lexer::next_token() {
  const std::size_t n = text_.size();
  if (pos_ >= n) return make(TokenKind::End, n, n);
  const std::size_t start = pos_;
  const unsigned char c = static_cast<unsigned char>(text_[start]);
  auto punct = [&](TokenKind k) {
    pos_ = start + 1;
    return make(k, start, start + 1);
  };
  switch (c) {
    case '(': return punct(TokenKind::LParen);
    case ')': return punct(TokenKind::RParen);
    case '[': return punct(TokenKind::LBracket);
    case ']': return punct(TokenKind::RBracket);
    case '{': return punct(TokenKind::LBrace);
    case '}': return punct(TokenKind::RBrace);
    case '=': return punct(TokenKind::Equals);
    case ',': return punct(TokenKind::Comma);
    case ';': return punct(TokenKind::Semicolon);
    case ':': return punct(TokenKind::Colon);
    case '&': return punct(TokenKind::Ampersand);
    case '"':
    case '\'': return lex_string(start);
    case '@': return lex_asset_path(start);
    case '<': return lex_path_ref(start);
    case '-':
    case '+':
    case '.': return lex_number(start);
    default: break;
  }
  if (is_digit(c)) return lex_number(start);
  if (is_ident_start(c)) return lex_identifier(start);
  if (c == '/') return fail("unexpected character '/'", start);
  return fail("unexpected character", start);
}

Token Lexer::lex_number(std::size_t start) {
  const std::size_t n = text_.size();
  const char* s = text_.data();
  std::size_t p = start;
  std::uint8_t flags = 0;
  if (s[p] == '-' || s[p] == '+') ++p;
  auto keyword_at = [&](std::string_view kw) {
    return starts_with_at(text_, p, kw) &&
           (p + kw.size() == n || !is_ident_char(static_cast<unsigned char>(s[p + kw.size()])));
  };
  if (p > start && (keyword_at("inf") || keyword_at("nan"))) {
    pos_ = p + 3;
    return make(TokenKind::Number, start, pos_, kTokenFloat);
  }
  const std::size_t digits_start = p;
  while (p < n && is_digit(static_cast<unsigned char>(s[p]))) ++p;
  bool have_digits = p > digits_start;
  if (p < n && s[p] == '.') {
    const std::size_t after_dot = p + 1;
    std::size_t q = after_dot;
    while (q < n && is_digit(static_cast<unsigned char>(s[q]))) ++q;
    if (have_digits || q > after_dot) {
      have_digits = true;
      flags |= kTokenFloat;
      p = q;
    }
  }
  if (!have_digits) {
    if (s[start] == '.') return fail("unexpected character '.'", start);
    return fail(s[start] == '-' ? "expected a number after '-'" : "expected a number after '+'", start);
  }
  if (p < n && (s[p] == 'e' || s[p] == 'E')) {
    std::size_t q = p + 1;
    if (q < n && (s[q] == '+' || s[q] == '-')) ++q;
    const std::size_t exp_digits = q;
    while (q < n && is_digit(static_cast<unsigned char>(s[q]))) ++q;
    if (q == exp_digits) return fail("malformed exponent in number", start, q - start);
    flags |= kTokenFloat;
    p = q;
  }
  pos_ = p;
  return make(TokenKind::Number, start, p, flags);
}

Token Lexer::lex_identifier(std::size_t start) {
  const std::size_t n = text_.size();
  const char* s = text_.data();
  std::size_t p = start + 1;
  for (;;) {
    while (p < n && is_ident_char(static_cast<unsigned char>(s[p]))) ++p;
    if (p + 1 < n && s[p] == ':' && is_ident_char(static_cast<unsigned char>(s[p + 1]))) {
      p += 1;  // namespace separator: physics:body0
    } else if (p + 2 < n && s[p] == ':' && s[p + 1] == ':' && is_ident_start(static_cast<unsigned char>(s[p + 2]))) {
      p += 2;  // C++ style type namespace: Foo::Bar
    } else if (p + 1 < n && s[p] == '.' && is_ident_start(static_cast<unsigned char>(s[p + 1]))) {
      p += 1;  // property suffix: x.connect, x.timeSamples
    } else {
      break;
    }
  }
  pos_ = p;
  return make(TokenKind::Identifier, start, p);
}

Token Lexer::lex_string(std::size_t start) {
  const std::size_t n = text_.size();
  const char* s = text_.data();
  const char q = s[start];
  std::uint8_t flags = 0;
  if (start + 2 < n && s[start + 1] == q && s[start + 2] == q) {
    flags |= kTokenTripleQuoted;
    std::size_t p = start + 3;
    while (p < n) {
      if (s[p] == '\\') {
        flags |= kTokenHasEscape;
        p += 2;
        continue;
      }
      if (s[p] == q && p + 2 < n && s[p + 1] == q && s[p + 2] == q) {
        pos_ = p + 3;
        return make(TokenKind::String, start, pos_, flags);
      }
      ++p;
    }
    return fail("unterminated triple-quoted string", start, 3);
  }
  std::size_t p = start + 1;
  while (p < n) {
    const char c = s[p];
    if (c == '\\') {
      flags |= kTokenHasEscape;
      if (p + 1 < n && (s[p + 1] == '\n' || s[p + 1] == '\r')) break;
      p += 2;
      continue;
    }
    if (c == q) {
      pos_ = p + 1;
      return make(TokenKind::String, start, pos_, flags);
    }
    if (c == '\n' || c == '\r') break;
    ++p;
  }
  return fail("unterminated string", start, 1);
}

Token Lexer::lex_asset_path(std::size_t start) {
  const std::size_t n = text_.size();
  const char* s = text_.data();
  if (starts_with_at(text_, start, "@@@")) {
    std::size_t p = start + 3;
    std::uint8_t flags = kTokenTripleQuoted;
    while (p < n && s[p] != '\n' && s[p] != '\r') {
      if (s[p] == '\\' && starts_with_at(text_, p + 1, "@@@")) {
        flags |= kTokenHasEscape;
        p += 4;
        continue;
      }
      if (starts_with_at(text_, p, "@@@")) {
        // Closed by 3 to 5 '@': the last three close, earlier ones belong to the path.
        std::size_t e = p + 3;
        int extra = 0;
        while (extra < 2 && e < n && s[e] == '@') {
          ++e;
          ++extra;
        }
        pos_ = e;
        return make(TokenKind::AssetPath, start, e, flags);
      }
      ++p;
    }
    return fail("unterminated asset path", start, 3);
  }
  std::size_t p = start + 1;
  while (p < n && s[p] != '\n' && s[p] != '\r') {
    if (s[p] == '@') {
      pos_ = p + 1;
      return make(TokenKind::AssetPath, start, pos_);
    }
    ++p;
  }
  return fail("unterminated asset path", start, 1);
}

Token Lexer::lex_path_ref(std::size_t start) {
  const std::size_t n = text_.size();
  const char* s = text_.data();
  std::size_t p = start + 1;
  while (p < n && s[p] != '\n' && s[p] != '\r') {
    if (s[p] == '>') {
      pos_ = p + 1;
      return make(TokenKind::PathRef, start, pos_);
    }
    ++p;
  }
  return fail("unterminated path (missing '>')", start, 1);
}

}  // namespace assetlint::usda
