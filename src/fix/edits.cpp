#include "fix/edits.h"

#include <algorithm>
#include <stdexcept>

namespace assetlint::fix {

bool edits_conflict(const Edit& a, const Edit& b) {
  if (a.file != b.file) return false;
  const std::size_t a_end = a.offset + a.length, b_end = b.offset + b.length;
  if (a.offset == b.offset) return true;
  if (a.offset < b_end && b.offset < a_end) return true;
  // An insertion touching the end of another edit: which goes first is a guess.
  if (a.length == 0 && a.offset == b_end) return true;
  if (b.length == 0 && b.offset == a_end) return true;
  return false;
}

bool edit_lists_conflict(const std::vector<Edit>& a, const std::vector<Edit>& b) {
  for (const Edit& x : a)
    for (const Edit& y : b)
      if (edits_conflict(x, y)) return true;
  return false;
}

bool edits_fit(const std::vector<Edit>& edits, std::string_view text) {
  for (std::size_t i = 0; i < edits.size(); ++i) {
    const Edit& e = edits[i];
    if (e.offset > text.size() || e.length > text.size() - e.offset) return false;
    for (std::size_t j = i + 1; j < edits.size(); ++j)
      if (e.file == edits[j].file && edits_conflict(e, edits[j])) return false;
  }
  return true;
}

std::string apply_edits(std::string_view text, std::vector<Edit> edits) {
  std::sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.offset < b.offset; });
  std::string out;
  std::size_t reserve = text.size();
  for (const Edit& e : edits) reserve += e.replacement.size();
  out.reserve(reserve);
  std::size_t pos = 0;
  for (std::size_t i = 0; i < edits.size(); ++i) {
    const Edit& e = edits[i];
    if (e.offset > text.size() || e.length > text.size() - e.offset)
      throw std::invalid_argument("edit outside the text");
    if (i > 0 && edits_conflict(edits[i - 1], e)) throw std::invalid_argument("conflicting edits");
    if (e.offset < pos) throw std::invalid_argument("conflicting edits");
    out.append(text.substr(pos, e.offset - pos));
    out.append(e.replacement);
    pos = e.offset + e.length;
  }
  out.append(text.substr(pos));
  return out;
}

}  // namespace assetlint::fix
