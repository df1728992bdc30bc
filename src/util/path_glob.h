#pragma once
#include <string_view>

namespace assetlint {

// Path glob: `**/` matches any number of whole directories, a trailing or inner `**`
// anything; `*` and `?` do not cross '/'. A pattern without '/' matches the file name
// alone as well. Time O(|pattern| · |path|), whatever the pattern.
bool path_glob_match(std::string_view pattern, std::string_view path);

}  // namespace assetlint
