#pragma once
// .gitignore rules for a directory walk: `.git/info/exclude` and every `.gitignore` from
// the git work tree's root down to the walked directory, in git's order (a later pattern
// wins; `!` re-includes; `/` anchors to the file's directory; a trailing `/` matches
// directories only; `**` spans directories). Outside a git work tree nothing is ignored.
#include <filesystem>
#include <string>
#include <vector>

namespace assetlint {

class GitIgnore {
 public:
  // The rules that apply inside `directory` (its own .gitignore included).
  static GitIgnore for_directory(const std::filesystem::path& directory);
  // The rules inside `subdirectory` of the directory these rules are for.
  GitIgnore enter(const std::filesystem::path& subdirectory) const;
  // Whether `path`, an entry of the directory these rules are for, is ignored.
  bool ignored(const std::filesystem::path& path, bool is_directory) const;

 private:
  struct Pattern {
    std::string glob;
    std::filesystem::path base;  // absolute: the directory of the file that holds it
    bool negated = false;
    bool directory_only = false;
    bool anchored = false;  // holds a '/' before its end: matched from `base`, else by name
  };
  void read(const std::filesystem::path& file, const std::filesystem::path& base);

  std::vector<Pattern> patterns_;
  bool in_work_tree_ = false;
};

}  // namespace assetlint
