#pragma once
// Inline suppressions and per-file ignores, applied to a file's findings after the
// rules ran.
//
//   URDF:  <!-- asset-lint: ignore[rule-id, other-*] -->   before an element: the element,
//                                                          through its end tag
//   USDA:  # asset-lint: ignore[rule-id]                   before a prim (to its closing brace)
//                                                          or a statement (its line, plus a
//                                                          trailing ( … ) metadata block)
//   both:  asset-lint: ignore-file[rule-id]                in a comment before the first
//                                                          element or prim: the whole file
//
// A suppression that suppresses nothing in the run (for rules that ran), names no known
// rule, or is malformed is reported as `unused-suppression`.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/diagnostic.h"
#include "engine/settings.h"
#include "model/source.h"

namespace assetlint {

enum class CommentSyntax { Xml, Usda };

struct SuppressionComment {
  std::size_t comment_offset = 0;  // the whole comment, delimiters included
  std::size_t comment_length = 0;
  bool file_level = false;         // ignore-file[...]
  std::vector<std::string> patterns;
  // The byte range whose findings it suppresses; empty when nothing follows it.
  std::size_t begin = 0;
  std::size_t end = 0;
  std::string target;              // "element", "prim", "statement", "file"
  std::optional<std::string> problem;  // malformed or misplaced: suppresses nothing
};

// The suppression comments of one source text, with the range each one covers.
// Comments are found by a small scanner of the format's lexical structure, so text
// inside strings or attribute values is never taken for a comment.
std::vector<SuppressionComment> find_suppressions(std::string_view text, CommentSyntax syntax);

// The syntax of a source by its path: .urdf (and .xml) is XML, anything else a USD layer.
CommentSyntax comment_syntax_for(std::string_view path);

// Whether `path` (as the checked file was named) matches a per-file-ignores glob of
// `settings` for `rule_id`. Globs are matched against the path relative to the directory
// of the configuration file; `**` spans directories, `*` and `?` stay within one.
bool per_file_ignored(const Settings& settings, std::string_view path, std::string_view rule_id);

// Path glob: `**` matches any number of whole directories (or, at the end, anything),
// `*` and `?` do not cross '/'. A pattern without '/' matches the file name alone as well.
bool path_glob_match(std::string_view pattern, std::string_view path);

// Drops the suppressed findings of `diagnostics` (located in `sources`), then adds the
// unused-suppression findings when that rule is enabled.
void apply_suppressions(const std::vector<std::shared_ptr<const SourceFile>>& sources,
                        std::vector<Diagnostic>& diagnostics, const Settings& settings);

}  // namespace assetlint
