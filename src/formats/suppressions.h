#pragma once
// Inline suppression comments, found in each format's own comment syntax (applied to
// findings by pipeline/suppressions.h).
//
//   URDF:  <!-- asset-lint: ignore[rule-id, other-*] -->   before an element: the element,
//                                                          through its end tag
//   USDA:  # asset-lint: ignore[rule-id]                   before a prim (to its closing brace)
//                                                          or a statement (its line, plus a
//                                                          trailing ( … ) metadata block)
//   both:  asset-lint: ignore-file[rule-id]                in a comment before the first
//                                                          element or prim: the whole file
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

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

// The comment that suppresses `rules` (ids or globs) in the next element or statement, or
// with `file_level` in the whole file: "<!-- asset-lint: ignore[a, b] -->", "# asset-lint: ignore[a]".
std::string suppression_comment(CommentSyntax syntax, bool file_level, const std::vector<std::string>& rules);

}  // namespace assetlint
