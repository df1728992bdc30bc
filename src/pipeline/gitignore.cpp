#include "pipeline/gitignore.h"

#include <fstream>

#include "util/path_glob.h"

namespace assetlint {
namespace {

namespace fs = std::filesystem;

fs::path absolute_normal(const fs::path& path) {
  std::error_code ec;
  return fs::absolute(path, ec).lexically_normal();
}

fs::path work_tree_of(const fs::path& directory) {
  std::error_code ec;
  for (fs::path dir = directory; !dir.empty(); dir = dir.parent_path()) {
    if (fs::exists(dir / ".git", ec)) return dir;
    if (dir == dir.root_path()) break;
  }
  return {};
}

}  // namespace

void GitIgnore::read(const fs::path& file, const fs::path& base) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // Trailing blanks are not part of the pattern unless escaped with a backslash.
    while (!line.empty() && line.back() == ' ' && !(line.size() > 1 && line[line.size() - 2] == '\\')) line.pop_back();
    if (line.empty() || line.front() == '#') continue;
    Pattern pattern;
    pattern.base = base;
    if (line.front() == '!') {
      pattern.negated = true;
      line.erase(0, 1);
    } else if (line.front() == '\\') {
      line.erase(0, 1);  // "\#name", "\!name"
    }
    if (!line.empty() && line.back() == '/') {
      pattern.directory_only = true;
      line.pop_back();
    }
    pattern.anchored = line.find('/') != std::string::npos;
    if (!line.empty() && line.front() == '/') line.erase(0, 1);
    if (line.empty()) continue;
    pattern.glob = std::move(line);
    patterns_.push_back(std::move(pattern));
  }
}

GitIgnore GitIgnore::for_directory(const fs::path& directory) {
  GitIgnore rules;
  const fs::path dir = absolute_normal(directory);
  const fs::path root = work_tree_of(dir);
  if (root.empty()) return rules;
  rules.in_work_tree_ = true;
  rules.read(root / ".git" / "info" / "exclude", root);
  fs::path walked = root;
  rules.read(root / ".gitignore", root);
  for (const auto& part : dir.lexically_relative(root)) {
    if (part == ".") continue;
    walked /= part;
    rules.read(walked / ".gitignore", walked);
  }
  return rules;
}

GitIgnore GitIgnore::enter(const fs::path& subdirectory) const {
  GitIgnore rules = *this;
  if (in_work_tree_) rules.read(subdirectory / ".gitignore", absolute_normal(subdirectory));
  return rules;
}

bool GitIgnore::ignored(const fs::path& path, bool is_directory) const {
  if (patterns_.empty()) return false;
  const fs::path absolute = absolute_normal(path);
  const std::string name = absolute.filename().string();
  bool ignored = false;
  for (const Pattern& pattern : patterns_) {
    if (pattern.directory_only && !is_directory) continue;
    bool match = false;
    if (pattern.anchored) {
      const fs::path relative = absolute.lexically_relative(pattern.base);
      if (relative.empty() || *relative.begin() == "..") continue;
      // Both prefixed with '/': an anchored glob such as `/local.urdf` must not match by name.
      match = path_glob_match("/" + pattern.glob, "/" + relative.generic_string());
    } else {
      match = path_glob_match(pattern.glob, name);
    }
    if (match) ignored = !pattern.negated;
  }
  return ignored;
}

}  // namespace assetlint
