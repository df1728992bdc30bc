#include "engine/file_system.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace assetlint {
namespace {

// Closes the descriptor on every path out of read().
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

// "512 MiB", "2.0 MiB (2097153 bytes)", "300 bytes".
std::string describe_size(std::uint64_t bytes) {
  constexpr std::uint64_t kMiB = 1ull << 20;
  if (bytes >= kMiB && bytes % kMiB == 0) return fmt::format("{} MiB", bytes / kMiB);
  if (bytes >= kMiB) return fmt::format("{:.1f} MiB ({} bytes)", static_cast<double>(bytes) / kMiB, bytes);
  return fmt::format("{} bytes", bytes);
}

DiskFileSystem& instance() {
  static DiskFileSystem disk_instance;
  return disk_instance;
}

}  // namespace

std::optional<std::string> DiskFileSystem::read(const std::string& path, std::string& error) const {
  // O_NONBLOCK: opening a FIFO for reading must not wait for a writer.
  Descriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY)};
  if (file.fd < 0) {
    error = std::strerror(errno);
    return std::nullopt;
  }
  struct stat st {};
  if (::fstat(file.fd, &st) != 0) {
    error = std::strerror(errno);
    return std::nullopt;
  }
  if (S_ISDIR(st.st_mode)) {
    error = "is a directory";
    return std::nullopt;
  }
  if (!S_ISREG(st.st_mode)) {
    error = S_ISFIFO(st.st_mode)   ? "is a FIFO, not a regular file"
            : S_ISCHR(st.st_mode)  ? "is a character device, not a regular file"
            : S_ISBLK(st.st_mode)  ? "is a block device, not a regular file"
            : S_ISSOCK(st.st_mode) ? "is a socket, not a regular file"
                                   : "is not a regular file";
    return std::nullopt;
  }
  const auto size = static_cast<std::uint64_t>(st.st_size);
  if (size > limits_.max_file_bytes) {
    error = fmt::format("is {}, over the {} limit (--max-file-size)", describe_size(size),
                        describe_size(limits_.max_file_bytes));
    return std::nullopt;
  }
  // Exactly the size fstat gave: growing the string afterwards would copy it, and a 200 MB
  // file would then cost 400 MB at its peak.
  std::string text;
  text.resize(static_cast<std::size_t>(size));
  std::size_t done = 0;
  auto read_some = [&](char* into, std::size_t want) -> ssize_t {
    for (;;) {
      const ssize_t n = ::read(file.fd, into, want);
      if (n >= 0 || errno != EINTR) return n;
    }
  };
  while (done < text.size()) {
    const ssize_t n = read_some(text.data() + done, text.size() - done);
    if (n < 0) {
      error = std::strerror(errno);
      return std::nullopt;
    }
    if (n == 0) break;  // end of file (earlier than fstat said when it was truncated)
    done += static_cast<std::size_t>(n);
  }
  if (done == text.size()) {
    // The file may have grown since fstat: read on, up to the limit.
    char chunk[16384];
    for (;;) {
      const ssize_t n = read_some(chunk, sizeof chunk);
      if (n < 0) {
        error = std::strerror(errno);
        return std::nullopt;
      }
      if (n == 0) break;
      if (text.size() + static_cast<std::size_t>(n) > limits_.max_file_bytes) {
        error = fmt::format("grew past the {} limit while it was read (--max-file-size)",
                            describe_size(limits_.max_file_bytes));
        return std::nullopt;
      }
      text.append(chunk, static_cast<std::size_t>(n));
    }
    done = text.size();
  }
  text.resize(done);
  return text;
}

std::optional<std::string> OverlayFileSystem::read(const std::string& path, std::string& error) const {
  if (auto it = files_.find(path); it != files_.end()) return it->second;
  return base_.read(path, error);
}

const FileSystem& disk() { return instance(); }

void set_disk_limits(const ReadLimits& limits) { instance() = DiskFileSystem(limits); }

}  // namespace assetlint
