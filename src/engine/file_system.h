#pragma once
// Where readers get file contents: the disk, or the disk seen through pending edits
// (the fixer re-lints its results before writing anything).
#include <map>
#include <optional>
#include <string>

namespace assetlint {

class FileSystem {
 public:
  virtual ~FileSystem() = default;
  // The file's bytes, or nullopt with `error` set (e.g. "No such file or directory").
  virtual std::optional<std::string> read(const std::string& path, std::string& error) const = 0;
};

class DiskFileSystem final : public FileSystem {
 public:
  std::optional<std::string> read(const std::string& path, std::string& error) const override;
};

// Files replaced in memory, keyed by the path readers ask for; anything else from `base`.
class OverlayFileSystem final : public FileSystem {
 public:
  explicit OverlayFileSystem(const FileSystem& base) : base_(base) {}
  void set(const std::string& path, std::string text) { files_[path] = std::move(text); }
  std::optional<std::string> read(const std::string& path, std::string& error) const override;
  const std::map<std::string, std::string>& files() const { return files_; }

 private:
  const FileSystem& base_;
  std::map<std::string, std::string> files_;
};

const FileSystem& disk();

}  // namespace assetlint
