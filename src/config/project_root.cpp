#include "config/project_root.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "config/config.h"
#include "util/ros_package_path.h"

namespace assetlint::config {
namespace {

namespace fs = std::filesystem;

bool inside(const fs::path& file, const fs::path& root) {
  const fs::path relative = file.lexically_relative(root);
  return !relative.empty() && *relative.begin() != "..";
}

fs::path git_work_tree(const fs::path& file) {
  std::error_code ec;
  for (fs::path dir = file.parent_path(); !dir.empty(); dir = dir.parent_path()) {
    if (fs::exists(dir / ".git", ec)) return dir;
    if (dir == dir.root_path()) break;
  }
  return {};
}

// The deepest named tree that holds the file. Lexical paths, like the composer's own
// check: a tree named through a symlink keeps the files found through that symlink inside it.
fs::path deepest_named_tree(const fs::path& file, const std::vector<std::string>& trees) {
  std::error_code ec;
  fs::path best;
  for (const auto& tree : trees) {
    const fs::path root = fs::absolute(tree, ec).lexically_normal();
    if (inside(file, root) && root.native().size() > best.native().size()) best = root;
  }
  return best;
}

std::string without_trailing_separator(fs::path path) {
  std::string text = path.lexically_normal().string();
  while (text.size() > 1 && text.back() == '/') text.pop_back();
  return text;
}

// A file no tree holds (named by path from elsewhere, outside any git work tree): the
// directory that holds its ROS package, so that `$(find pkg)` reaches the package's siblings as
// in a workspace's src/; the file's own directory when it is in no package.
fs::path outside_any_tree(const fs::path& directory) {
  std::error_code ec;
  for (fs::path dir = directory; !dir.empty(); dir = dir.parent_path()) {
    if (fs::exists(dir / "package.xml", ec)) return dir.parent_path();
    if (dir == dir.root_path()) break;
  }
  return directory;
}

}  // namespace

std::string checked_root(const std::string& path, const Settings& settings) {
  std::error_code ec;
  if (!settings.root.empty()) return without_trailing_separator(fs::absolute(settings.root, ec));
  const fs::path file = fs::absolute(path, ec).lexically_normal();
  if (fs::path git = git_work_tree(file); !git.empty()) return without_trailing_separator(git);
  if (fs::path config = discover(file); !config.empty())
    return without_trailing_separator(fs::absolute(config, ec).parent_path());
  return deepest_named_tree(file, settings.trees).string();
}

ReadPolicy read_policy(const std::string& path, const Settings& settings) {
  if (settings.allow_outside_root) return ReadPolicy::unconfined();
  std::vector<std::string> roots;
  std::error_code ec;
  const fs::path directory = fs::absolute(path, ec).lexically_normal().parent_path();
  const std::string tree = checked_root(path, settings);
  roots.push_back(tree.empty() ? outside_any_tree(directory).string() : tree);
  // The file named is the user's choice, wherever --root puts the tree (an expansion written to
  // /tmp, checked with --root at its package): its own directory is read too, unless a symbolic
  // link on the way makes that directory somewhere else.
  if (fs::weakly_canonical(directory, ec) == directory) roots.push_back(directory.string());
  // The packages a ROS workspace names are read as `$(find pkg)` and `package://` resolve
  // them; ROS_PACKAGE_PATH and --package-path are the runner's, not the checked files'.
  for (std::string& entry : ros_package_search_path()) roots.push_back(std::move(entry));
  return ReadPolicy::confined_to(roots);
}

}  // namespace assetlint::config
