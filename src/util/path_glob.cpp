#include "util/path_glob.h"

#include <vector>

namespace assetlint {
namespace {

// Dynamic programming over (pattern position, path position), filled from the ends:
// each cell is decided from cells already known in O(1), so no pattern can make the
// match exponential (a backtracking matcher is with many `*`).
bool glob_path(std::string_view pattern, std::string_view path) {
  const std::size_t m = pattern.size(), n = path.size();
  const std::size_t width = n + 1;
  // matches[i][j]: pattern[i..] matches path[j..].
  std::vector<char> matches((m + 1) * width, 0);
  // in_dirs[i][j]: inside a `**/` at i, path[j..] reaches a '/' after which pattern[i+3..] matches.
  std::vector<char> in_dirs((m + 1) * width, 0);
  auto at = [&](std::vector<char>& table, std::size_t i, std::size_t j) -> char& { return table[i * width + j]; };
  at(matches, m, n) = 1;
  for (std::size_t i = m; i-- > 0;) {
    const bool double_star = pattern[i] == '*' && i + 1 < m && pattern[i + 1] == '*';
    const bool dir_star = double_star && i + 2 < m && pattern[i + 2] == '/';
    for (std::size_t j = n + 1; j-- > 0;) {
      const bool more = j < n;
      bool result = false;
      if (dir_star) {
        at(in_dirs, i, j) = more && ((path[j] == '/' && at(matches, i + 3, j + 1)) || at(in_dirs, i, j + 1));
        result = at(matches, i + 3, j) || at(in_dirs, i, j);
      } else if (double_star) {
        result = at(matches, i + 2, j) || (more && at(matches, i, j + 1));
      } else if (pattern[i] == '*') {
        result = at(matches, i + 1, j) || (more && path[j] != '/' && at(matches, i, j + 1));
      } else if (pattern[i] == '?') {
        result = more && path[j] != '/' && at(matches, i + 1, j + 1);
      } else {
        result = more && path[j] == pattern[i] && at(matches, i + 1, j + 1);
      }
      at(matches, i, j) = result;
    }
  }
  return at(matches, 0, 0);
}

}  // namespace

bool path_glob_match(std::string_view pattern, std::string_view path) {
  if (glob_path(pattern, path)) return true;
  if (pattern.find('/') == std::string_view::npos) {
    const std::size_t slash = path.rfind('/');
    if (slash != std::string_view::npos) return glob_path(pattern, path.substr(slash + 1));
  }
  return false;
}

}  // namespace assetlint
