#pragma once
// Fuzz inputs as files in memory: one input may hold several layers, each starting at a
// line "#usda" after the first ("root.usda", then "l1.usda", "l2.usda", ...), so that
// sublayers, references and payloads between them resolve.
#include <map>
#include <string>
#include <string_view>

#include "engine/file_system.h"

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

// Splits `input` into layers; returns the root layer's text and registers the others.
inline std::string split_layers(std::string_view input, MemoryFileSystem& files) {
  std::string root;
  int index = 0;
  std::size_t start = 0;
  while (start <= input.size()) {
    std::size_t next = input.find("\n#usda", start + 1);
    if (next == std::string_view::npos || index >= 8) next = input.size();
    std::string text(input.substr(start, next - start));
    if (index == 0) root = text;
    else files.set("l" + std::to_string(index) + ".usda", text.substr(1));  // drop the newline
    ++index;
    start = next == input.size() ? input.size() + 1 : next;
  }
  files.set("root.usda", root);
  return root;
}

}  // namespace assetlint::fuzz
