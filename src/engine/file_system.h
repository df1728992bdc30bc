#pragma once
// Where readers get file contents: the disk, or the disk seen through pending edits
// (the fixer re-lints its results before writing anything).
#include <cstdint>
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

// What the disk reader refuses to read, so that hostile or accidental input (a huge
// generated file, /dev/zero, a FIFO) costs bounded time and memory.
struct ReadLimits {
  static constexpr std::uint64_t kDefaultMaxFileBytes = 512ull << 20;  // 512 MiB
  std::uint64_t max_file_bytes = kDefaultMaxFileBytes;
};

// Regular files only (no FIFO, device or socket: they could block or never end), up to
// the size limit; a file that shrinks or grows while it is read yields what was read up
// to its end or the limit (the readers then report what is wrong with those bytes).
class DiskFileSystem final : public FileSystem {
 public:
  explicit DiskFileSystem(ReadLimits limits = {}) : limits_(limits) {}
  std::optional<std::string> read(const std::string& path, std::string& error) const override;
  const ReadLimits& limits() const { return limits_; }

 private:
  ReadLimits limits_;
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

// The process's disk reader. Its limits are set once, before any file is read
// (the CLI's --max-file-size); later calls do not affect reads already running.
const FileSystem& disk();
void set_disk_limits(const ReadLimits& limits);

}  // namespace assetlint
