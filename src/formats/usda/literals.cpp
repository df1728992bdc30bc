#include "formats/usda/literals.h"

#include <cctype>
#include <charconv>
#include <limits>

namespace assetlint::usda {

double parse_number(std::string_view t) {
  bool negative = false;
  if (!t.empty() && (t[0] == '+' || t[0] == '-')) {
    negative = t[0] == '-';
    t.remove_prefix(1);
  }
  double v = 0.0;
  if (t == "inf") {
    v = std::numeric_limits<double>::infinity();
  } else if (t == "nan") {
    v = std::numeric_limits<double>::quiet_NaN();
  } else {
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (r.ec == std::errc::result_out_of_range) {
      // from_chars leaves v unchanged: decide between overflow and underflow.
      const auto e = t.find_first_of("eE");
      const bool tiny = e != std::string_view::npos && e + 1 < t.size() && t[e + 1] == '-';
      v = tiny ? 0.0 : std::numeric_limits<double>::infinity();
    }
  }
  return negative ? -v : v;
}

std::string decode_string(std::string_view t) {
  std::size_t q = (t.size() >= 6 && (t.compare(0, 3, "\"\"\"") == 0 || t.compare(0, 3, "'''") == 0)) ? 3 : 1;
  if (t.size() < 2 * q) return {};
  const std::string_view body = t.substr(q, t.size() - 2 * q);
  if (body.find('\\') == std::string_view::npos) return std::string(body);
  std::string out;
  out.reserve(body.size());
  for (std::size_t i = 0; i < body.size(); ++i) {
    const char c = body[i];
    if (c != '\\' || i + 1 >= body.size()) {
      out += c;
      continue;
    }
    const char e = body[++i];
    switch (e) {
      case 'n': out += '\n'; break;
      case 't': out += '\t'; break;
      case 'r': out += '\r'; break;
      case 'a': out += '\a'; break;
      case 'b': out += '\b'; break;
      case 'f': out += '\f'; break;
      case 'v': out += '\v'; break;
      case 'x': {
        int value = 0;
        int digits = 0;
        while (digits < 2 && i + 1 < body.size() && std::isxdigit(static_cast<unsigned char>(body[i + 1]))) {
          const char h = body[++i];
          value = value * 16 + (h <= '9' ? h - '0' : (h | 0x20) - 'a' + 10);
          ++digits;
        }
        if (digits == 0) {
          out += 'x';
        } else {
          out += static_cast<char>(value);
        }
        break;
      }
      default:
        if (e >= '0' && e <= '7') {
          int value = e - '0';
          int digits = 1;
          while (digits < 3 && i + 1 < body.size() && body[i + 1] >= '0' && body[i + 1] <= '7') {
            value = value * 8 + (body[++i] - '0');
            ++digits;
          }
          out += static_cast<char>(value & 0xFF);
        } else {
          out += e;  // \\ \" \' and unknown escapes keep the character
        }
    }
  }
  return out;
}

std::string decode_asset_path(std::string_view t) {
  if (t.size() >= 6 && t.compare(0, 3, "@@@") == 0) {
    std::string_view body = t.substr(3, t.size() - 6);
    std::string out;
    out.reserve(body.size());
    for (std::size_t i = 0; i < body.size(); ++i) {
      if (body[i] == '\\' && body.substr(i + 1, 3) == "@@@") {
        out += "@@@";
        i += 3;
      } else {
        out += body[i];
      }
    }
    return out;
  }
  if (t.size() >= 2) return std::string(t.substr(1, t.size() - 2));
  return {};
}

}  // namespace assetlint::usda
