#include "formats/usda/array_scan.h"

#include <cstring>

namespace assetlint::usda {

namespace {

// Byte classes of the scanner; anything not listed ends the fast scan.
enum Class : unsigned char { kOther, kSpace, kDigit, kSign, kDot, kOpen, kClose, kComma, kComment, kSlash, kLetter };

struct ClassTable {
  unsigned char of[256] = {};
  constexpr ClassTable() {
    for (int c = '0'; c <= '9'; ++c) of[c] = kDigit;
    for (int c = 'a'; c <= 'z'; ++c) of[c] = kLetter;
    for (int c = 'A'; c <= 'Z'; ++c) of[c] = kLetter;
    for (int c = 0x80; c < 256; ++c) of[c] = kLetter;
    of[static_cast<unsigned char>('_')] = kLetter;
    of[static_cast<unsigned char>(' ')] = of[static_cast<unsigned char>('\t')] = kSpace;
    of[static_cast<unsigned char>('\n')] = of[static_cast<unsigned char>('\r')] = kSpace;
    of[static_cast<unsigned char>('-')] = of[static_cast<unsigned char>('+')] = kSign;
    of[static_cast<unsigned char>('.')] = kDot;
    of[static_cast<unsigned char>('[')] = of[static_cast<unsigned char>('(')] = kOpen;
    of[static_cast<unsigned char>(']')] = of[static_cast<unsigned char>(')')] = kClose;
    of[static_cast<unsigned char>(',')] = kComma;
    of[static_cast<unsigned char>('#')] = kComment;
    of[static_cast<unsigned char>('/')] = kSlash;
  }
};
constexpr ClassTable kClasses;

inline unsigned char class_of(const char* p) { return kClasses.of[static_cast<unsigned char>(*p)]; }
inline bool digit(const char* p, const char* end) { return p < end && class_of(p) == kDigit; }
// A name character (letters, digits, '_', UTF-8 bytes): a number must not run into one ("1abc").
inline bool name_char(const char* p, const char* end) {
  return p < end && (class_of(p) == kDigit || class_of(p) == kLetter);
}

// Skips one number at p; returns the pointer after it, or nullptr if there is none.
inline const char* skip_number(const char* p, const char* end) {
  if (*p == '-' || *p == '+') ++p;
  if (end - p >= 3 && (std::memcmp(p, "inf", 3) == 0 || std::memcmp(p, "nan", 3) == 0)) {
    p += 3;
    return name_char(p, end) ? nullptr : p;
  }
  const char* const d0 = p;
  while (digit(p, end)) ++p;
  bool have = p > d0;
  if (p < end && *p == '.') {
    const char* q = p + 1;
    while (digit(q, end)) ++q;
    if (have || q > p + 1) {
      have = true;
      p = q;
    }
  }
  if (!have) return nullptr;
  if (p < end && (*p == 'e' || *p == 'E')) {
    const char* q = p + 1;
    if (q < end && (*q == '+' || *q == '-')) ++q;
    const char* const e0 = q;
    while (digit(q, end)) ++q;
    if (q == e0) return nullptr;
    p = q;
  }
  return name_char(p, end) ? nullptr : p;
}

inline const char* skip_line(const char* p, const char* end) {
  while (p < end && *p != '\n' && *p != '\r') ++p;
  return p;
}

}  // namespace

std::optional<ArrayScan> scan_numeric_array(std::string_view text, std::size_t start, std::size_t max_depth) {
  if (start >= text.size() || text[start] != '[') return std::nullopt;
  const char* const begin = text.data();
  const char* const end = begin + text.size();
  // closers[d] is the bracket that closes nesting level d.
  char closers[64];
  const std::size_t cap = max_depth < sizeof(closers) ? max_depth : sizeof(closers);
  std::size_t depth = 0;
  std::size_t count = 0;
  bool expect_value = true;  // after an opening bracket or a comma
  bool just_opened = false;
  const char* p = begin + start;
  while (p < end) {
    switch (class_of(p)) {
      case kSpace:
        ++p;
        continue;
      case kOpen:
        if (!expect_value || depth == cap) return std::nullopt;
        if (depth == 1) ++count;
        closers[depth++] = *p == '[' ? ']' : ')';
        just_opened = true;
        ++p;
        continue;
      case kClose:
        if (depth == 0 || closers[depth - 1] != *p) return std::nullopt;
        // (expect_value && !just_opened) is a trailing comma, which USD allows.
        if (expect_value && just_opened && *p == ')') return std::nullopt;  // empty tuple
        --depth;
        ++p;
        expect_value = false;
        just_opened = false;
        if (depth == 0) return ArrayScan{static_cast<std::size_t>(p - begin), count};
        continue;
      case kComma:
        if (expect_value) return std::nullopt;
        expect_value = true;
        just_opened = false;
        ++p;
        continue;
      case kComment:
        p = skip_line(p, end);
        continue;
      case kSlash:
        if (end - p >= 2 && p[1] == '/') {
          p = skip_line(p, end);
          continue;
        }
        if (end - p >= 2 && p[1] == '*') {
          const char* close = nullptr;
          for (const char* q = p + 2; end - q >= 2; ++q) {
            if (q[0] == '*' && q[1] == '/') {
              close = q;
              break;
            }
          }
          if (close == nullptr) return std::nullopt;
          p = close + 2;
          continue;
        }
        return std::nullopt;
      case kDigit:
      case kSign:
      case kDot:
      case kLetter: {
        if (!expect_value) return std::nullopt;
        const char* const after = skip_number(p, end);
        if (after == nullptr) return std::nullopt;
        if (depth == 1) ++count;
        expect_value = false;
        just_opened = false;
        p = after;
        continue;
      }
      default:
        return std::nullopt;
    }
  }
  return std::nullopt;
}

}  // namespace assetlint::usda
