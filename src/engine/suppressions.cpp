#include "engine/suppressions.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "rules/reader_rules.h"
#include "rules/registry.h"

namespace assetlint {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
bool is_blank(char c) { return c == ' ' || c == '\t'; }

bool starts_with_at(std::string_view text, std::size_t at, std::string_view prefix) {
  return at <= text.size() && text.substr(at, prefix.size()) == prefix;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

// Parses the directive in a comment's body, if it has one. `offset`/`length` locate the
// whole comment in the file.
std::optional<SuppressionComment> parse_directive(std::string_view body, std::size_t offset, std::size_t length) {
  constexpr std::string_view kMarker = "asset-lint:";
  const std::size_t at = body.find(kMarker);
  if (at == std::string_view::npos) return std::nullopt;
  std::size_t p = at + kMarker.size();
  while (p < body.size() && is_blank(body[p])) ++p;
  SuppressionComment s;
  s.comment_offset = offset;
  s.comment_length = length;
  if (starts_with_at(body, p, "ignore-file")) {
    s.file_level = true;
    p += std::string_view("ignore-file").size();
  } else if (starts_with_at(body, p, "ignore")) {
    p += std::string_view("ignore").size();
  } else {
    return std::nullopt;  // prose that mentions the tool, not a directive
  }
  while (p < body.size() && is_blank(body[p])) ++p;
  const std::size_t close = p < body.size() && body[p] == '[' ? body.find(']', p) : std::string_view::npos;
  if (close == std::string_view::npos) {
    s.problem = fmt::format("malformed suppression: expected 'asset-lint: {}[rule-id, ...]'",
                            s.file_level ? "ignore-file" : "ignore");
    return s;
  }
  std::string_view list = body.substr(p + 1, close - p - 1);
  while (!list.empty()) {
    const std::size_t comma = list.find(',');
    const std::string_view item = trim(list.substr(0, comma));
    if (!item.empty()) s.patterns.emplace_back(item);
    if (comma == std::string_view::npos) break;
    list.remove_prefix(comma + 1);
  }
  if (s.patterns.empty()) s.problem = "malformed suppression: the list of rules is empty";
  return s;
}

// ---- XML ------------------------------------------------------------------------------

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
          if (!out.back().problem) pending.push_back(out.size() - 1);
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

// ---- USDA -----------------------------------------------------------------------------

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
      if (!s->problem) {
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

// ---- Applying -------------------------------------------------------------------------

// Matches `pattern` against `path` segment-aware; both use '/'.
bool glob_path(std::string_view pattern, std::string_view path) {
  if (pattern.empty()) return path.empty();
  if (starts_with_at(pattern, 0, "**")) {
    std::string_view rest = pattern.substr(2);
    if (rest.empty()) return true;
    if (rest.front() == '/') {
      rest.remove_prefix(1);
      // Zero or more whole directories.
      if (glob_path(rest, path)) return true;
      for (std::size_t i = 0; i < path.size(); ++i)
        if (path[i] == '/' && glob_path(rest, path.substr(i + 1))) return true;
      return false;
    }
    for (std::size_t i = 0; i <= path.size(); ++i)
      if (glob_path(rest, path.substr(i))) return true;
    return false;
  }
  if (pattern.front() == '*') {
    for (std::size_t i = 0; i <= path.size(); ++i) {
      if (glob_path(pattern.substr(1), path.substr(i))) return true;
      if (i < path.size() && path[i] == '/') break;
    }
    return false;
  }
  if (path.empty()) return false;
  if (pattern.front() == '?' ? path.front() != '/' : pattern.front() == path.front())
    return glob_path(pattern.substr(1), path.substr(1));
  return false;
}

std::string relative_to_config(const Settings& settings, std::string_view path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path file = fs::absolute(fs::path(path), ec).lexically_normal();
  if (settings.config_path.empty() || ec) return fs::path(path).lexically_normal().generic_string();
  const fs::path dir = fs::absolute(fs::path(settings.config_path), ec).parent_path().lexically_normal();
  if (ec) return fs::path(path).generic_string();
  return file.lexically_relative(dir).generic_string();
}

std::string quote_list(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

// The edit that removes a comment: its whole line when nothing else is on it, otherwise
// the comment and the blanks before it.
Edit delete_comment(FileId file, std::string_view text, std::size_t begin, std::size_t end) {
  std::size_t line_begin = begin;
  while (line_begin > 0 && text[line_begin - 1] != '\n' && text[line_begin - 1] != '\r') --line_begin;
  std::size_t line_end = end;
  while (line_end < text.size() && text[line_end] != '\n' && text[line_end] != '\r') ++line_end;
  auto blank = [&](std::size_t a, std::size_t b) {
    for (std::size_t i = a; i < b; ++i)
      if (!is_blank(text[i])) return false;
    return true;
  };
  if (blank(line_begin, begin) && blank(end, line_end)) {
    std::size_t stop = line_end;
    if (stop < text.size()) stop += text[stop] == '\r' && stop + 1 < text.size() && text[stop + 1] == '\n' ? 2 : 1;
    return Edit{file, line_begin, stop - line_begin, ""};
  }
  std::size_t from = begin;
  if (blank(end, line_end)) {
    while (from > line_begin && is_blank(text[from - 1])) --from;
    return Edit{file, from, line_end - from, ""};
  }
  return Edit{file, begin, end - begin, ""};
}

}  // namespace

CommentSyntax comment_syntax_for(std::string_view path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".urdf" || ext == ".xml" || ext == ".mjcf" ? CommentSyntax::Xml : CommentSyntax::Usda;
}

std::vector<SuppressionComment> find_suppressions(std::string_view text, CommentSyntax syntax) {
  if (text.find("asset-lint:") == std::string_view::npos) return {};
  return syntax == CommentSyntax::Xml ? scan_xml(text) : scan_usda(text);
}

bool path_glob_match(std::string_view pattern, std::string_view path) {
  if (glob_path(pattern, path)) return true;
  if (pattern.find('/') == std::string_view::npos) {
    const std::size_t slash = path.rfind('/');
    if (slash != std::string_view::npos) return glob_path(pattern, path.substr(slash + 1));
  }
  return false;
}

bool per_file_ignored(const Settings& settings, std::string_view path, std::string_view rule_id) {
  if (settings.per_file_ignores.empty()) return false;
  const std::string relative = relative_to_config(settings, path);
  for (const auto& entry : settings.per_file_ignores) {
    if (!path_glob_match(entry.glob, relative)) continue;
    for (const auto& rule : entry.rules)
      if (glob_match(rule, rule_id)) return true;
  }
  return false;
}

void apply_suppressions(const std::vector<std::shared_ptr<const SourceFile>>& sources,
                        std::vector<Diagnostic>& diagnostics, const Settings& settings) {
  struct Found {
    FileId file;
    SuppressionComment comment;
    std::vector<bool> used;
  };
  std::vector<Found> found;
  for (FileId id = 0; id < sources.size(); ++id) {
    for (auto& c : find_suppressions(sources[id]->view(), comment_syntax_for(sources[id]->path()))) {
      const std::size_t count = c.patterns.size();
      found.push_back(Found{id, std::move(c), std::vector<bool>(count, false)});
    }
  }
  if (found.empty() && settings.per_file_ignores.empty()) return;

  auto file_of = [&](const Diagnostic& d) -> FileId { return d.span.file == kNoFile ? 0 : d.span.file; };
  // Whether a finding is covered by an inline suppression; marks the patterns that cover it.
  auto suppressed = [&](const Diagnostic& d) {
    bool hit = false;
    const FileId file = file_of(d);
    for (auto& f : found) {
      if (f.file != file || f.comment.problem) continue;
      if (!f.comment.file_level && !(d.span.offset >= f.comment.begin && d.span.offset < f.comment.end)) continue;
      for (std::size_t i = 0; i < f.comment.patterns.size(); ++i) {
        if (glob_match(f.comment.patterns[i], d.rule)) {
          f.used[i] = true;
          hit = true;
        }
      }
    }
    return hit;
  };
  auto path_of = [&](FileId file) -> std::string_view {
    return file < sources.size() ? std::string_view(sources[file]->path()) : std::string_view();
  };
  std::erase_if(diagnostics, [&](const Diagnostic& d) {
    const bool inline_hit = suppressed(d);
    return inline_hit || per_file_ignored(settings, path_of(file_of(d)), d.rule);
  });

  const std::string_view unused_id = rules::kUnusedSuppression.id;
  std::vector<Diagnostic> unused;
  for (auto& f : found) {
    const std::string_view path = path_of(f.file);
    if (!settings.selection.enabled(unused_id) || per_file_ignored(settings, path, unused_id)) continue;
    const SourceFile& source = *sources[f.file];
    const SuppressionComment& c = f.comment;
    const Span span = source.span(f.file, c.comment_offset, c.comment_length);
    const Severity severity = settings.severity_for(unused_id, rules::kUnusedSuppression.default_severity);
    if (c.problem) {
      unused.push_back(Diagnostic{std::string(unused_id), severity, span, *c.problem, std::nullopt, {}});
      continue;
    }
    std::vector<std::string> unknown, idle, kept;
    for (std::size_t i = 0; i < c.patterns.size(); ++i) {
      const std::string& pattern = c.patterns[i];
      bool known = false, enabled = false;
      for (const RuleInfo* rule : rules::catalog()) {
        if (!glob_match(pattern, rule->id)) continue;
        known = true;
        // A suppression of a rule that did not run, or of unused-suppression itself,
        // cannot be judged in this run.
        enabled = enabled || (rule->id != unused_id && settings.selection.enabled(rule->id) &&
                              !per_file_ignored(settings, path, rule->id));
      }
      if (!known) unknown.push_back(pattern);
      else if (enabled && !f.used[i]) idle.push_back(pattern);
      else kept.push_back(pattern);
    }
    if (unknown.empty() && idle.empty()) continue;
    std::string message;
    if (!unknown.empty())
      message = fmt::format("suppression names unknown rule{} {}; `asset-lint --list-rules` lists them",
                            unknown.size() == 1 ? "" : "s", quote_list(unknown));
    if (!idle.empty()) {
      const std::string where = c.target == "file"   ? "in this file"
                                : c.begin == c.end   ? fmt::format("and no {} follows it", c.target == "element" ? "element" : "statement")
                                                     : fmt::format("in the {} that follows", c.target);
      message += fmt::format("{}unused suppression of {}: no such finding {}", message.empty() ? "" : "; ",
                             quote_list(idle), where);
    }
    Diagnostic d{std::string(unused_id), severity, span, std::move(message), std::nullopt, {}};
    const Applicability applicability = unknown.empty() ? Applicability::Safe : Applicability::Unsafe;
    if (kept.empty()) {
      d.fix = Fix{"remove the suppression comment", applicability,
                  {delete_comment(f.file, source.view(), c.comment_offset, c.comment_offset + c.comment_length)}};
    } else {
      // Rewrite the list inside the brackets, keeping the patterns that still work.
      const std::string_view comment = source.view().substr(c.comment_offset, c.comment_length);
      const std::size_t marker = comment.find("asset-lint:");
      const std::size_t open = comment.find('[', marker);
      const std::size_t close = comment.find(']', open);
      d.fix = Fix{fmt::format("keep only {} in the suppression", quote_list(kept)), applicability,
                  {Edit{f.file, c.comment_offset + open + 1, close - open - 1, quote_list(kept)}}};
    }
    unused.push_back(std::move(d));
  }
  // unused-suppression findings can be suppressed too (ignore-file[unused-suppression]).
  for (auto& d : unused)
    if (!suppressed(d)) diagnostics.push_back(std::move(d));
}

}  // namespace assetlint
