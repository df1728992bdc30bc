#include "pipeline/discovery.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "engine/file_system.h"
#include "formats/file_kind.h"
#include "formats/xacro/entry_points.h"
#include "formats/usdc/crate_file.h"
#include "pipeline/gitignore.h"

namespace assetlint {
namespace {

namespace fs = std::filesystem;

std::string head_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  char buffer[48] = {};  // enough for a crate's magic and a Git LFS pointer's first line
  in.read(buffer, sizeof buffer);
  return std::string(buffer, static_cast<std::size_t>(in.gcount()));
}

const config::FileSelection& default_selection() {
  static const config::FileSelection selection = [] {
    std::error_code ec;
    return config::effective_file_selection(std::nullopt, {}, fs::current_path(ec).string());
  }();
  return selection;
}

bool mjcf_text(const fs::path& path) {
  std::string error;
  auto text = disk().read(path.string(), error);
  return text && file_kind(path.string(), *text) == FileKind::Mjcf;
}

// What a directory walk does with a file it meets.
enum class WalkVerdict { Check, BinaryUsd, Xacro, NotAnAsset };

WalkVerdict walk_verdict(const fs::path& path) {
  switch (file_kind(path.string())) {
    case FileKind::Urdf:
    case FileKind::Usda: return WalkVerdict::Check;
    case FileKind::Usd:
    case FileKind::BinaryUsd: {
      // Text and crate layers are read, and an LFS pointer is reported as one (the gate would
      // otherwise check nothing); other binary USD (.usdz packages) is counted as skipped.
      const std::string head = head_of(path);
      const bool readable = usd_kind(head) == FileKind::Usda || usdc::is_crate(head) || is_lfs_pointer(head);
      return readable ? WalkVerdict::Check : WalkVerdict::BinaryUsd;
    }
    case FileKind::Mjcf:
      // A .xml is an asset only when its root is <mujoco> (not launch files, not URDFs named .xml).
      return extension_of(path.string()) != ".xml" || mjcf_text(path) ? WalkVerdict::Check : WalkVerdict::NotAnAsset;
    case FileKind::Xacro: return WalkVerdict::Xacro;
    case FileKind::Unsupported: break;
  }
  return WalkVerdict::NotAnAsset;
}

struct Walk {
  const fs::path& cwd;
  PathExpansion& out;
  const SelectionFor& selection_for;
  std::vector<std::string> found;
  std::vector<std::string> xacro;  // .xacro files: only the top-level ones are checked

  bool left_out(const fs::path& path, bool is_directory, const GitIgnore& gitignore) const {
    const std::string spelled_path = spelled(path, cwd);
    if (selection_for(spelled_path).excluding(spelled_path)) return true;
    return gitignore.ignored(path, is_directory);
  }

  void error(const fs::path& path, const char* what, const std::error_code& ec) {
    const std::string shown = spelled(path, cwd);
    out.errors.push_back({shown, fmt::format("cannot read {} '{}': {}", what, shown, ec.message())});
  }

  void file(const fs::path& path) {
    switch (walk_verdict(path)) {
      case WalkVerdict::Check: found.push_back(spelled(path, cwd)); break;
      case WalkVerdict::BinaryUsd: out.binary_usd.push_back(spelled(path, cwd)); break;
      case WalkVerdict::Xacro: xacro.push_back(spelled(path, cwd)); break;
      case WalkVerdict::NotAnAsset: break;
    }
  }

  // The .xacro files to check: the configured entry points, else the top-level files.
  void found_xacro(const std::vector<std::string>& entry_points) {
    if (entry_points.empty()) {
      for (auto& top : xacro::top_level_xacro_files(xacro)) found.push_back(std::move(top));
      return;
    }
    for (const std::string& file : xacro) {
      std::error_code ec;
      const std::string absolute = fs::absolute(file, ec).lexically_normal().string();
      if (std::find(entry_points.begin(), entry_points.end(), absolute) != entry_points.end()) found.push_back(file);
    }
  }

  // Directory by directory, so that one unreadable directory is named and the walk goes on.
  void directory(const fs::path& dir, const GitIgnore& gitignore) {
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
        if (!it->is_symlink(link_ec) && !left_out(path, true, gitignore)) subdirectories.push_back(path);
      } else if (fs::is_regular_file(status)) {
        if (!left_out(path, false, gitignore)) file(path);
      }
    }
    if (ec) error(dir, "directory", ec);
    std::sort(subdirectories.begin(), subdirectories.end());
    for (const auto& sub : subdirectories) directory(sub, gitignore.enter(sub));
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

PathExpansion expand_paths(const std::vector<std::string>& paths, const SelectionFor& given_selection_for) {
  PathExpansion out;
  std::error_code cwd_ec;
  const fs::path cwd = fs::current_path(cwd_ec);
  const SelectionFor selection_for =
      given_selection_for ? given_selection_for : [](const std::string&) -> const config::FileSelection& {
        return default_selection();
      };
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
    // Named paths are checked whatever the exclusions say, unless --force-exclude (as
    // pre-commit and editors name every file).
    const config::FileSelection& named_selection = selection_for(path);
    if (named_selection.force_exclude && path != "." && named_selection.excluding(path)) continue;
    if (!fs::is_directory(status)) {
      // With --force-exclude (pre-commit, editors) a named file is also held to what a walk
      // checks: a hook matching *.xml passes launch files and other XML that is no model.
      if (named_selection.force_exclude && walk_verdict(path) == WalkVerdict::NotAnAsset) continue;
      out.files.push_back(path);
      continue;
    }
    Walk walk{cwd, out, selection_for, {}, {}};
    // The selection inside the directory: its own asset-lint.toml counts.
    const config::FileSelection& inside = selection_for((fs::path(path) / "*").generic_string());
    walk.directory(path, inside.respect_gitignore.value ? GitIgnore::for_directory(path) : GitIgnore{});
    walk.found_xacro(inside.xacro_entry_points);
    std::sort(walk.found.begin(), walk.found.end());
    if (walk.found.empty()) out.without_assets.push_back(path);
    out.files.insert(out.files.end(), walk.found.begin(), walk.found.end());
  }
  return out;
}

}  // namespace assetlint
