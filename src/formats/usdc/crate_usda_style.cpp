#include "formats/usdc/crate_usda_style.h"

#include <algorithm>

namespace assetlint::usdc {

namespace {
// ASCII only, as in the "C" locale the program runs in (and without a call per character).
bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
}  // namespace

bool valid_name(std::string_view s, bool namespaced) {
  if (s.empty() || !(is_letter(s[0]) || s[0] == '_')) return false;
  for (char c : s)
    if (!(is_letter(c) || is_digit(c) || c == '_' || (namespaced && (c == ':' || c == '.' || c == '-')))) return false;
  return s.back() != ':';
}

bool valid_type_name(std::string_view s) {
  if (s.ends_with("[]")) s.remove_suffix(2);
  return valid_name(s, false);
}

bool is_structural_field(std::string_view key) {
  static constexpr std::string_view kStructural[] = {
      "primChildren", "properties", "variantChildren", "variantSetChildren", "targetChildren", "connectionChildren",
      "specifier",    "typeName",   "default",         "timeSamples",        "targetPaths",    "connectionPaths",
      "custom",       "variability", "primOrder",      "propertyOrder",      "subLayerOffsets"};
  for (std::string_view s : kStructural)
    if (s == key) return true;
  return false;
}

bool bare_when_single(std::string_view key) {
  return key == "references" || key == "payload" || key == "inherits" || key == "specializes" ||
         key == "variantSetNames";
}

bool dictionary_less(std::string_view a, std::string_view b) {
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  // Property names share long prefixes ("physics:", "drive:angular:physics:"): equal bytes
  // compare equal, so the comparison starts where they differ, or at the start of the
  // digit run there (compared by value).
  std::size_t i = static_cast<std::size_t>(std::mismatch(a.begin(), a.begin() + std::min(a.size(), b.size()), b.begin()).first - a.begin());
  while (i > 0 && digit(a[i - 1])) --i;
  std::size_t j = i;
  while (i < a.size() && j < b.size()) {
    const auto l = static_cast<unsigned char>(a[i]), r = static_cast<unsigned char>(b[j]);
    if (digit(a[i]) && digit(b[j])) {
      std::size_t ie = i, je = j;
      while (ie < a.size() && digit(a[ie])) ++ie;
      while (je < b.size() && digit(b[je])) ++je;
      std::string_view x = a.substr(i, ie - i), y = b.substr(j, je - j);
      while (x.size() > 1 && x[0] == '0') x.remove_prefix(1);
      while (y.size() > 1 && y[0] == '0') y.remove_prefix(1);
      if (x.size() != y.size()) return x.size() < y.size();
      if (x != y) return x < y;
      i = ie;
      j = je;
      continue;
    }
    if (l < 0x80 && r < 0x80 && l >= 0x40 && r >= 0x40 && (l & ~0x20) != (r & ~0x20))
      return ((l + 5) & 31) < ((r + 5) & 31);
    if (l != r && !(l >= 0x40 && r >= 0x40 && (l & ~0x20) == (r & ~0x20))) return l < r;
    ++i;
    ++j;
  }
  if (a.size() - i != b.size() - j) return a.size() - i < b.size() - j;
  return a < b;
}

std::string bracketed(const std::vector<std::string>& items, int indent) {
  std::string text = "[";
  const bool multiline = items.size() > 1 && items[0].find('(') != std::string::npos;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (multiline) text += "\n" + indentation(indent + 1);
    else if (i) text += " ";
    text += items[i];
    if (i + 1 < items.size()) text += ",";
  }
  if (multiline) text += "\n" + indentation(indent);
  return text + "]";
}

std::string indentation(int indent) { return std::string(static_cast<std::size_t>(indent) * 4, ' '); }

}  // namespace assetlint::usdc
