#include "pipeline/discovery.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "formats/file_kind.h"

namespace assetlint {

PathExpansion expand_paths(const std::vector<std::string>& paths) {
  namespace fs = std::filesystem;
  PathExpansion out;
  for (const auto& path : paths) {
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (ec || !fs::exists(status)) {
      out.errors.push_back(fmt::format("no such file or directory: '{}'", path));
      continue;
    }
    if (!fs::is_directory(status)) {
      out.files.push_back(path);
      continue;
    }
    std::vector<std::string> found;
    fs::recursive_directory_iterator it(path, fs::directory_options::skip_permission_denied, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
      const auto name = it->path().filename().string();
      // Its own error code: an entry that cannot be stat'ed (a symlink loop, a dangling
      // link) is skipped, not the end of the walk.
      std::error_code entry_ec;
      if (it->is_directory(entry_ec)) {
        if (name.starts_with(".")) it.disable_recursion_pending();
        continue;
      }
      if (it->is_regular_file(entry_ec) && file_kind(it->path().string()) != FileKind::Unsupported)
        found.push_back(it->path().string());
    }
    std::sort(found.begin(), found.end());
    out.files.insert(out.files.end(), found.begin(), found.end());
  }
  return out;
}

}  // namespace assetlint
