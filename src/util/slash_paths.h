#pragma once
// Slash-separated hierarchical paths (USD prim paths).
#include <string_view>

namespace assetlint {

// `path` is `scope` or lies below it ("/robot/arm" is under "/robot", "/robotic" is not); every
// path is under the empty scope.
inline bool path_under(std::string_view path, std::string_view scope) {
  if (scope.empty()) return true;
  return path == scope || (path.starts_with(scope) && path.size() > scope.size() && path[scope.size()] == '/');
}

}  // namespace assetlint
