#pragma once
// Fuzz inputs as files in memory: one input may hold several layers, each starting at a
// line "#usda" after the first ("root.usda", then "l1.usda", "l2.usda", ...), so that
// sublayers, references and payloads between them resolve.
#include <map>
#include <string>
#include <string_view>

#include "engine/file_system.h"
#include "pipeline/lint.h"

namespace assetlint::fuzz {

class MemoryFileSystem final : public FileSystem {
 public:
  void set(const std::string& path, std::string text) { files_[path] = std::move(text); }
  std::optional<std::string> read(const std::string& path, std::string& error) const override {
    auto it = files_.find(path);
    if (it == files_.end()) {
      error = "No such file or directory";
      return std::nullopt;
    }
    return it->second;
  }

 private:
  std::map<std::string, std::string> files_;
};

// Splits `input` into at most 8 files at each `marker` (which starts with a newline): the
// first part is `root`, the others <prefix>1<extension>, <prefix>2<extension>, ... without
// that newline. Returns the root's text.
inline std::string split_files(std::string_view input, MemoryFileSystem& files, std::string_view marker,
                               const std::string& root_name, const std::string& prefix, const std::string& extension) {
  std::string root;
  int index = 0;
  std::size_t start = 0;
  while (start <= input.size()) {
    std::size_t next = input.find(marker, start + 1);
    if (next == std::string_view::npos || index >= 8) next = input.size();
    std::string text(input.substr(start, next - start));
    if (index == 0) root = text;
    else files.set(prefix + std::to_string(index) + extension, text.substr(1));  // drop the newline
    ++index;
    start = next == input.size() ? input.size() + 1 : next;
  }
  files.set(root_name, root);
  return root;
}

// USDA layers: split at each `\n#usda` into root.usda, l1.usda, l2.usda, ...
inline std::string split_layers(std::string_view input, MemoryFileSystem& files) {
  return split_files(input, files, "\n#usda", "root.usda", "l", ".usda");
}

// MJCF files: split at each `\n<mujoco` into robot.xml, i1.xml, i2.xml, ... (for <include>).
inline std::string split_mjcf(std::string_view input, MemoryFileSystem& files) {
  return split_files(input, files, "\n<mujoco", "robot.xml", "i", ".xml");
}

// Lints `root_text` as `root_path` with the other files in `files`, every rule on. A memory
// file system has no tree to leave, so layers and includes anywhere in it are read.
inline void lint_in_memory(const std::string& root_path, std::string root_text, const MemoryFileSystem& files) {
  Settings settings;
  settings.allow_outside_root = true;
  (void)lint_text(root_path, std::move(root_text), settings, files);
}

}  // namespace assetlint::fuzz
