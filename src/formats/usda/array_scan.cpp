#include "formats/usda/array_scan.h"

#include <cstring>
#include <vector>

namespace assetlint::usda {

namespace {

inline bool digit(char c) { return static_cast<unsigned>(c - '0') < 10u; }
inline bool ident_char(char c) {
  const auto u = static_cast<unsigned char>(c);
  return digit(c) || (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') || u == '_' || u >= 0x80;
}

// Skips one number at s[p]; returns the offset after it, or 0 if it is not a number.
inline std::size_t skip_number(const char* s, std::size_t n, std::size_t p) {
  if (s[p] == '-' || s[p] == '+') ++p;
  if (p + 3 <= n && (std::memcmp(s + p, "inf", 3) == 0 || std::memcmp(s + p, "nan", 3) == 0)) {
    p += 3;
    return (p < n && ident_char(s[p])) ? 0 : p;
  }
  const std::size_t d0 = p;
  while (p < n && digit(s[p])) ++p;
  bool have = p > d0;
  if (p < n && s[p] == '.') {
    std::size_t q = p + 1;
    while (q < n && digit(s[q])) ++q;
    if (have || q > p + 1) {
      have = true;
      p = q;
    }
  }
  if (!have) return 0;
  if (p < n && (s[p] == 'e' || s[p] == 'E')) {
    std::size_t q = p + 1;
    if (q < n && (s[q] == '+' || s[q] == '-')) ++q;
    const std::size_t e0 = q;
    while (q < n && digit(s[q])) ++q;
    if (q == e0) return 0;
    p = q;
  }
  // A number must not run into a name (e.g. "1abc").
  if (p < n && ident_char(s[p])) return 0;
  return p;
}

}  // namespace

std::optional<ArrayScan> scan_numeric_array(std::string_view text, std::size_t start, std::size_t max_depth) {
  const char* s = text.data();
  const std::size_t n = text.size();
  if (start >= n || s[start] != '[') return std::nullopt;
  // closers[d] is the bracket that closes nesting level d.
  char closers[64];
  const std::size_t cap = max_depth < sizeof(closers) ? max_depth : sizeof(closers);
  std::size_t depth = 0;
  std::size_t count = 0;
  bool expect_value = true;  // after an opening bracket or a comma
  bool just_opened = false;
  std::size_t p = start;
  while (p < n) {
    const char c = s[p];
    switch (c) {
      case ' ':
      case '\t':
      case '\n':
      case '\r':
        ++p;
        continue;
      case '[':
      case '(':
        if (!expect_value || depth == cap) return std::nullopt;
        if (depth == 1) ++count;
        closers[depth++] = c == '[' ? ']' : ')';
        just_opened = true;
        ++p;
        continue;
      case ']':
      case ')':
        if (depth == 0 || closers[depth - 1] != c) return std::nullopt;
        // (expect_value && !just_opened) is a trailing comma, which USD allows.
        if (expect_value && just_opened && c == ')') return std::nullopt;  // empty tuple
        --depth;
        ++p;
        expect_value = false;
        just_opened = false;
        if (depth == 0) return ArrayScan{p, count};
        continue;
      case ',':
        if (expect_value) return std::nullopt;
        expect_value = true;
        just_opened = false;
        ++p;
        continue;
      case '#':
        while (p < n && s[p] != '\n' && s[p] != '\r') ++p;
        continue;
      case '/':
        if (p + 1 < n && s[p + 1] == '/') {
          while (p < n && s[p] != '\n' && s[p] != '\r') ++p;
          continue;
        }
        if (p + 1 < n && s[p + 1] == '*') {
          const char* close = nullptr;
          for (std::size_t q = p + 2; q + 1 < n; ++q) {
            if (s[q] == '*' && s[q + 1] == '/') {
              close = s + q;
              break;
            }
          }
          if (close == nullptr) return std::nullopt;
          p = static_cast<std::size_t>(close - s) + 2;
          continue;
        }
        return std::nullopt;
      default: {
        if (!expect_value) return std::nullopt;
        const std::size_t after = skip_number(s, n, p);
        if (after == 0) return std::nullopt;
        if (depth == 1) ++count;
        expect_value = false;
        just_opened = false;
        p = after;
        continue;
      }
    }
  }
  return std::nullopt;
}

}  // namespace assetlint::usda
