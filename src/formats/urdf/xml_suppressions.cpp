// The suppression comments of an XML text: `<!-- asset-lint: ignore[...] -->` before an
// element covers that element through its end tag.
#include <algorithm>
#include <string_view>
#include <vector>

#include "formats/suppression_syntax.h"

namespace assetlint::suppression_syntax {

// Comments, start tags and end tags of an XML text, tolerant of errors: anything it
// cannot make sense of is skipped as text.
std::vector<SuppressionComment> scan_xml(std::string_view text) {
  struct Element {
    std::string_view name;
    std::size_t begin, end;
  };
  std::vector<Element> elements;
  std::vector<std::size_t> open;                          // indices into elements
  std::vector<std::pair<std::size_t, std::size_t>> waiting;  // (suppression, element) once known
  std::vector<SuppressionComment> out;
  std::vector<std::size_t> pending;  // suppressions waiting for the next element
  bool seen_element = false;
  const std::size_t n = text.size();
  std::size_t p = 0;
  auto drop_pending = [&] {
    for (std::size_t i : pending) out[i].begin = out[i].end = out[i].comment_offset + out[i].comment_length;
    pending.clear();
  };
  auto find_end = [&](std::size_t from, std::string_view close) {
    const std::size_t at = text.find(close, from);
    return at == std::string_view::npos ? n : at + close.size();
  };
  // A comment after markup on its own line (`<limit .../>  <!-- asset-lint: ignore[x] -->`)
  // covers the first element that starts on that line, or else the first that ends there,
  // as ruff and clang-tidy users expect of an end-of-line comment.
  auto trailing = [&](std::size_t comment_at, std::size_t suppression) {
    std::size_t line_begin = comment_at;
    while (line_begin > 0 && text[line_begin - 1] != '\n' && text[line_begin - 1] != '\r') --line_begin;
    bool after_markup = false;
    for (std::size_t i = line_begin; i < comment_at; ++i) after_markup = after_markup || !is_space(text[i]);
    if (!after_markup) return false;
    for (std::size_t e = 0; e < elements.size(); ++e) {
      if (elements[e].begin >= line_begin && elements[e].begin < comment_at) {
        waiting.emplace_back(suppression, e);
        return true;
      }
    }
    for (std::size_t e = 0; e < elements.size(); ++e) {
      if (elements[e].end > line_begin && elements[e].end <= comment_at) {
        waiting.emplace_back(suppression, e);
        return true;
      }
    }
    return false;
  };
  while (p < n) {
    const std::size_t lt = text.find('<', p);
    const std::size_t stop = lt == std::string_view::npos ? n : lt;
    for (std::size_t i = p; i < stop; ++i) {
      if (!is_space(text[i])) {
        drop_pending();  // character data between the comment and the next element
        break;
      }
    }
    if (lt == std::string_view::npos) break;
    if (starts_with_at(text, lt, "<!--")) {
      const std::size_t end = find_end(lt + 4, "-->");
      const std::size_t body_end = end == n && !text.ends_with("-->") ? n : end - 3;
      if (auto s = parse_directive(text.substr(lt + 4, body_end - (lt + 4)), lt, end - lt)) {
        if (s->file_level) {
          s->target = "file";
          if (seen_element && !s->problem)
            s->problem = "'ignore-file' after the first element has no effect: put it at the top of the file";
          s->begin = 0;
          s->end = n;
          out.push_back(std::move(*s));
        } else {
          s->target = "element";
          out.push_back(std::move(*s));
          if (!out.back().problem && !trailing(lt, out.size() - 1)) pending.push_back(out.size() - 1);
        }
      }
      p = end;
    } else if (starts_with_at(text, lt, "<![CDATA[")) {
      drop_pending();
      p = find_end(lt + 9, "]]>");
    } else if (starts_with_at(text, lt, "<?")) {
      p = find_end(lt + 2, "?>");
    } else if (starts_with_at(text, lt, "<!")) {
      // <!DOCTYPE …> with an optional [internal subset] and quoted literals.
      std::size_t q = lt + 2;
      int depth = 0;
      while (q < n) {
        const char c = text[q];
        if (c == '"' || c == '\'') {
          const std::size_t close = text.find(c, q + 1);
          q = close == std::string_view::npos ? n : close + 1;
          continue;
        }
        if (c == '[') ++depth;
        else if (c == ']') --depth;
        else if (c == '>' && depth <= 0) break;
        ++q;
      }
      p = std::min(n, q + 1);
    } else if (starts_with_at(text, lt, "</")) {
      drop_pending();
      std::size_t q = lt + 2;
      while (q < n && !is_space(text[q]) && text[q] != '>') ++q;
      const std::string_view name = text.substr(lt + 2, q - (lt + 2));
      const std::size_t gt = text.find('>', q);
      const std::size_t end = gt == std::string_view::npos ? n : gt + 1;
      // Close the innermost open element of that name, and any left open inside it.
      for (std::size_t k = open.size(); k-- > 0;) {
        if (elements[open[k]].name != name) continue;
        for (std::size_t j = k; j < open.size(); ++j) elements[open[j]].end = end;
        open.resize(k);
        break;
      }
      p = end;
    } else if (lt + 1 < n && !is_space(text[lt + 1]) && text[lt + 1] != '>' && text[lt + 1] != '=') {
      std::size_t q = lt + 1;
      while (q < n && !is_space(text[q]) && text[q] != '>' && text[q] != '/') ++q;
      const std::string_view name = text.substr(lt + 1, q - (lt + 1));
      // Attributes: quoted values may hold '>' and "<!--".
      bool self_closing = false;
      while (q < n && text[q] != '>') {
        if (text[q] == '"' || text[q] == '\'') {
          const std::size_t close = text.find(text[q], q + 1);
          q = close == std::string_view::npos ? n : close + 1;
          continue;
        }
        if (text[q] == '<') break;  // a broken tag: stop before the next markup
        ++q;
      }
      if (q < n && text[q] == '>') self_closing = q > lt && text[q - 1] == '/';
      const std::size_t end = q < n && text[q] == '>' ? q + 1 : q;
      elements.push_back(Element{name, lt, self_closing ? end : n});
      if (!self_closing) open.push_back(elements.size() - 1);
      for (std::size_t i : pending) waiting.emplace_back(i, elements.size() - 1);
      pending.clear();
      seen_element = true;
      p = end;
    } else {
      drop_pending();
      p = lt + 1;
    }
  }
  drop_pending();
  for (auto [s, e] : waiting) {
    out[s].begin = elements[e].begin;
    out[s].end = elements[e].end;  // elements never closed reach the end of the text
  }
  return out;
}


}  // namespace assetlint::suppression_syntax
