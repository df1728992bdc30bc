#include "pipeline/suppressions.h"

#include <fmt/format.h>

#include <filesystem>

#include "formats/suppression_syntax.h"
#include "formats/suppressions.h"
#include "rules/reader_rules.h"
#include "rules/registry.h"
#include "util/path_glob.h"

namespace assetlint {
namespace {

using suppression_syntax::is_blank;

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
                        std::vector<Diagnostic>& diagnostics, const Settings& settings,
                        const std::set<FileId>& unparsable) {
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
      unused.push_back(Diagnostic{std::string(unused_id), severity, span, *c.problem, std::nullopt, {}, {}, {}});
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
    Diagnostic d{std::string(unused_id), severity, span, std::move(message), std::nullopt, {}, {}, {}};
    if (unparsable.count(f.file)) {
      d.note("No fix is offered while the file has a parse error: fix that first.");
      unused.push_back(std::move(d));
      continue;
    }
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
