// The suppression comments of a USDA text: `# asset-lint: ignore[...]` before a prim
// covers it to its closing brace, before a statement its line (plus a metadata block).
#include <algorithm>
#include <string_view>
#include <vector>

#include "formats/suppression_syntax.h"

namespace assetlint::suppression_syntax {
namespace {

enum class Tok { Word, Punct, Text, Comment, Newline };

struct Token {
  Tok kind;
  std::size_t begin, end;
};

// A flat token list of a USDA text: enough structure to find comments, statement starts
// and bracket nesting. Strings, asset paths and path references are single tokens.
std::vector<Token> tokenize_usda(std::string_view s) {
  std::vector<Token> out;
  const std::size_t n = s.size();
  std::size_t p = 0;
  auto to_line_end = [&](std::size_t q) {
    while (q < n && s[q] != '\n' && s[q] != '\r') ++q;
    return q;
  };
  while (p < n) {
    const char c = s[p];
    const std::size_t start = p;
    if (c == '\n' || c == '\r') {
      p += c == '\r' && p + 1 < n && s[p + 1] == '\n' ? 2 : 1;
      out.push_back({Tok::Newline, start, p});
    } else if (is_blank(c) || c == '\f' || c == '\v') {
      ++p;
    } else if (c == '#' || (c == '/' && p + 1 < n && s[p + 1] == '/')) {
      p = to_line_end(p);
      out.push_back({Tok::Comment, start, p});
    } else if (c == '/' && p + 1 < n && s[p + 1] == '*') {
      const std::size_t close = s.find("*/", p + 2);
      p = close == std::string_view::npos ? n : close + 2;
      out.push_back({Tok::Comment, start, p});
    } else if (c == '"' || c == '\'') {
      if (p + 2 < n && s[p + 1] == c && s[p + 2] == c) {
        std::size_t q = p + 3;
        while (q < n && !(s[q] == c && q + 2 < n && s[q + 1] == c && s[q + 2] == c)) q += s[q] == '\\' ? 2 : 1;
        p = std::min(n, q + 3);
      } else {
        std::size_t q = p + 1;
        while (q < n && s[q] != c && s[q] != '\n' && s[q] != '\r') q += s[q] == '\\' ? 2 : 1;
        p = std::min(n, q + 1);
      }
      out.push_back({Tok::Text, start, p});
    } else if (c == '@') {
      if (starts_with_at(s, p, "@@@")) {
        const std::size_t close = s.find("@@@", p + 3);
        p = close == std::string_view::npos ? to_line_end(p) : close + 3;
        while (p < n && s[p] == '@') ++p;
      } else {
        const std::size_t close = s.find_first_of("@\n\r", p + 1);
        p = close == std::string_view::npos ? n : s[close] == '@' ? close + 1 : close;
      }
      out.push_back({Tok::Text, start, p});
    } else if (c == '<') {
      const std::size_t close = s.find_first_of(">\n\r", p + 1);
      p = close == std::string_view::npos ? n : s[close] == '>' ? close + 1 : close;
      out.push_back({Tok::Text, start, p});
    } else if (std::string_view("()[]{}=,;").find(c) != std::string_view::npos) {
      ++p;
      out.push_back({Tok::Punct, start, p});
    } else {
      while (p < n && !is_space(s[p]) && std::string_view("()[]{}=,;\"'@<#").find(s[p]) == std::string_view::npos &&
             !(s[p] == '/' && p + 1 < n && (s[p + 1] == '/' || s[p + 1] == '*')))
        ++p;
      if (p == start) ++p;
      out.push_back({Tok::Word, start, p});
    }
  }
  return out;
}

}  // namespace

std::vector<SuppressionComment> scan_usda(std::string_view text) {
  const std::vector<Token> tokens = tokenize_usda(text);
  const std::size_t n = text.size();
  auto word = [&](const Token& t) { return text.substr(t.begin, t.end - t.begin); };
  auto is_punct = [&](const Token& t, char c) { return t.kind == Tok::Punct && text[t.begin] == c; };
  auto is_prim_start = [&](const Token& t) {
    if (t.kind != Tok::Word) return false;
    const auto w = word(t);
    return w == "def" || w == "over" || w == "class";
  };
  std::size_t first_prim = n;
  for (const Token& t : tokens) {
    if (is_prim_start(t)) {
      first_prim = t.begin;
      break;
    }
  }
  // The end offset of the statement starting at token j.
  auto statement_end = [&](std::size_t j, bool& is_prim) {
    is_prim = is_prim_start(tokens[j]);
    int depth = 0;
    std::size_t end = tokens[j].end;
    if (is_prim) {
      for (std::size_t k = j; k < tokens.size(); ++k) {
        const Token& t = tokens[k];
        if (t.kind != Tok::Punct) continue;
        const char c = text[t.begin];
        if (c == '(' || c == '[') ++depth;
        else if (c == ')' || c == ']') --depth;
        else if (c == '{') {
          int braces = 0;
          for (std::size_t m = k; m < tokens.size(); ++m) {
            if (is_punct(tokens[m], '{')) ++braces;
            else if (is_punct(tokens[m], '}') && --braces == 0) return tokens[m].end;
          }
          return n;
        } else if (c == '}' && depth <= 0) {
          return t.begin;  // the enclosing scope closes: a prim without a body
        }
      }
      return n;
    }
    std::size_t k = j;
    for (; k < tokens.size(); ++k) {
      const Token& t = tokens[k];
      if (t.kind == Tok::Newline && depth <= 0) break;
      if (t.kind == Tok::Punct) {
        const char c = text[t.begin];
        if (c == '(' || c == '[' || c == '{') ++depth;
        else if (c == ')' || c == ']' || c == '}') {
          if (--depth < 0) break;  // closes the enclosing prim
        }
      }
      if (t.kind != Tok::Newline && t.kind != Tok::Comment) end = t.end;
    }
    // A metadata block opened on the next line still belongs to the statement.
    std::size_t m = k;
    while (m < tokens.size() && (tokens[m].kind == Tok::Newline || tokens[m].kind == Tok::Comment)) ++m;
    if (k < tokens.size() && tokens[k].kind == Tok::Newline && m < tokens.size() && is_punct(tokens[m], '(')) {
      depth = 0;
      for (; m < tokens.size(); ++m) {
        if (is_punct(tokens[m], '(')) ++depth;
        else if (is_punct(tokens[m], ')') && --depth == 0) return tokens[m].end;
      }
      return n;
    }
    return end;
  };

  std::vector<SuppressionComment> out;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const Token& t = tokens[i];
    if (t.kind != Tok::Comment) continue;
    std::size_t body_begin = t.begin + (text[t.begin] == '#' ? 1 : 2);
    std::size_t body_end = text[t.begin + 1] == '*' && t.end - t.begin >= 4 && text.substr(t.end - 2, 2) == "*/" ? t.end - 2 : t.end;
    auto s = parse_directive(text.substr(body_begin, body_end - body_begin), t.begin, t.end - t.begin);
    if (!s) continue;
    if (s->file_level) {
      s->target = "file";
      if (t.begin > first_prim && !s->problem)
        s->problem = "'ignore-file' after the first prim has no effect: put it at the top of the file";
      s->begin = 0;
      s->end = n;
    } else {
      s->target = "statement";
      s->begin = s->end = t.end;
      // After a statement on its line (`float x = 1  # asset-lint: ignore[r]`): that
      // statement (or prim, after `def X {` or a prim's `}`), found by walking back over
      // brackets to the line it starts on.
      std::size_t start = i;
      for (int depth = 0; start > 0;) {
        const Token& back = tokens[start - 1];
        if (back.kind == Tok::Newline && depth <= 0) break;
        if (back.kind == Tok::Punct) {
          const char c = text[back.begin];
          if (c == ')' || c == ']' || c == '}') ++depth;
          else if (c == '(' || c == '[' || c == '{') depth = std::max(0, depth - 1);  // `{` of `def X {  # …`
        }
        --start;
      }
      while (start < i && tokens[start].kind == Tok::Comment) ++start;
      if (!s->problem && start < i && tokens[start].kind != Tok::Punct) {
        bool prim = false;
        s->begin = tokens[start].begin;
        s->end = std::max(statement_end(start, prim), t.begin);
        if (prim) s->target = "prim";
      } else if (!s->problem) {
        std::size_t j = i + 1;
        while (j < tokens.size() && (tokens[j].kind == Tok::Newline || tokens[j].kind == Tok::Comment)) ++j;
        if (j < tokens.size() && !is_punct(tokens[j], '}') && !is_punct(tokens[j], ')') && !is_punct(tokens[j], ']')) {
          bool prim = false;
          s->begin = tokens[j].begin;
          s->end = statement_end(j, prim);
          if (prim) s->target = "prim";
        }
      }
    }
    out.push_back(std::move(*s));
  }
  return out;
}

}  // namespace assetlint::suppression_syntax
