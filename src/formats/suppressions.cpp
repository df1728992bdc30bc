#include "formats/suppressions.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "formats/suppression_syntax.h"

namespace assetlint {
namespace suppression_syntax {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

}  // namespace

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

}  // namespace suppression_syntax

CommentSyntax comment_syntax_for(std::string_view path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".urdf" || ext == ".xml" || ext == ".mjcf" || ext == ".xacro" ? CommentSyntax::Xml : CommentSyntax::Usda;
}

std::string suppression_comment(CommentSyntax syntax, bool file_level, const std::vector<std::string>& rules) {
  std::string list;
  for (const auto& rule : rules) list += (list.empty() ? "" : ", ") + rule;
  const std::string directive = fmt::format("asset-lint: {}[{}]", file_level ? "ignore-file" : "ignore", list);
  return syntax == CommentSyntax::Xml ? "<!-- " + directive + " -->" : "# " + directive;
}

std::vector<SuppressionComment> find_suppressions(std::string_view text, CommentSyntax syntax) {
  if (text.find("asset-lint:") == std::string_view::npos) return {};
  return syntax == CommentSyntax::Xml ? suppression_syntax::scan_xml(text) : suppression_syntax::scan_usda(text);
}

}  // namespace assetlint
