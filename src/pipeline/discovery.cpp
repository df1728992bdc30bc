#include "pipeline/discovery.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "engine/file_system.h"
#include "formats/file_kind.h"

namespace assetlint {
namespace {

namespace fs = std::filesystem;

std::string head_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  char buffer[8] = {};
  in.read(buffer, sizeof buffer);
  return std::string(buffer, static_cast<std::size_t>(in.gcount()));
}

bool mjcf_text(const fs::path& path) {
  std::string error;
  auto text = disk().read(path.string(), error);
  return text && file_kind(path.string(), *text) == FileKind::Mjcf;
}

struct Walk {
  const fs::path& cwd;
  PathExpansion& out;
  std::vector<std::string> found;

  void error(const fs::path& path, const char* what, const std::error_code& ec) {
    const std::string shown = spelled(path, cwd);
    out.errors.push_back({shown, fmt::format("cannot read {} '{}': {}", what, shown, ec.message())});
  }

  void file(const fs::path& path) {
    switch (file_kind(path.string())) {
      case FileKind::Urdf:
      case FileKind::Usda: found.push_back(spelled(path, cwd)); break;
      case FileKind::Usd:
        if (usd_kind(head_of(path)) == FileKind::Usda) found.push_back(spelled(path, cwd));
        else out.binary_usd.push_back(spelled(path, cwd));
        break;
      case FileKind::BinaryUsd: out.binary_usd.push_back(spelled(path, cwd)); break;
      case FileKind::Mjcf:
        // A .xml is an asset only when its root is <mujoco> (not launch files, not URDFs named .xml).
        if (extension_of(path.string()) != ".xml" || mjcf_text(path)) found.push_back(spelled(path, cwd));
        break;
      case FileKind::Unsupported: break;
    }
  }

  // Directory by directory, so that one unreadable directory is named and the walk goes on.
  void directory(const fs::path& dir) {
    std::error_code ec;
    fs::directory_iterator it(dir, ec), end;
    if (ec) return error(dir, "directory", ec);
    std::vector<fs::path> subdirectories;
    for (; it != end; it.increment(ec)) {
      const fs::path path = it->path();
      std::error_code entry_ec;
      const fs::file_status status = it->status(entry_ec);
      if (entry_ec) {
        // A dangling symlink is not an asset; anything else unreadable is named.
        std::error_code link_ec;
        if (!(it->is_symlink(link_ec) && entry_ec == std::errc::no_such_file_or_directory)) error(path, "entry", entry_ec);
        continue;
      }
      if (fs::is_directory(status)) {
        // Symlinked directories are not followed (a link to an ancestor would never end).
        std::error_code link_ec;
        if (!path.filename().string().starts_with(".") && !it->is_symlink(link_ec)) subdirectories.push_back(path);
      } else if (fs::is_regular_file(status)) {
        file(path);
      }
    }
    if (ec) error(dir, "directory", ec);
    std::sort(subdirectories.begin(), subdirectories.end());
    for (const auto& sub : subdirectories) directory(sub);
  }
};

}  // namespace

std::string spelled(const std::filesystem::path& path, const std::filesystem::path& cwd) {
  fs::path normal = path.lexically_normal();
  if (normal.is_absolute() && !cwd.empty()) {
    const fs::path relative = normal.lexically_relative(cwd);
    if (!relative.empty() && *relative.begin() != "..") normal = relative;
  }
  std::string text = normal.generic_string();
  if (text.size() > 1 && text.back() == '/') text.pop_back();
  return text.empty() ? "." : text;
}

PathExpansion expand_paths(const std::vector<std::string>& paths) {
  PathExpansion out;
  std::error_code cwd_ec;
  const fs::path cwd = fs::current_path(cwd_ec);
  for (const auto& named : paths) {
    const std::string path = spelled(named, cwd);
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (ec || !fs::exists(status)) {
      const bool missing = !ec || ec == std::errc::no_such_file_or_directory;
      out.errors.push_back({path, missing ? fmt::format("no such file or directory: '{}'", path)
                                          : fmt::format("cannot read '{}': {}", path, ec.message())});
      continue;
    }
    if (!fs::is_directory(status)) {
      out.files.push_back(path);
      continue;
    }
    Walk walk{cwd, out, {}};
    walk.directory(path);
    std::sort(walk.found.begin(), walk.found.end());
    if (walk.found.empty()) out.without_assets.push_back(path);
    out.files.insert(out.files.end(), walk.found.begin(), walk.found.end());
  }
  return out;
}

}  // namespace assetlint
