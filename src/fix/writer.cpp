#include "fix/writer.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>

#include "engine/file_system.h"

namespace assetlint::fix {
namespace {

namespace fs = std::filesystem;

std::string errno_text(int error) { return std::strerror(error); }

// Closes and removes the temporary file unless released.
class TempFile {
 public:
  ~TempFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!path_.empty()) ::unlink(path_.c_str());
  }
  bool create(const fs::path& dir, const std::string& name) {
    std::string pattern = (dir / ("." + name + ".asset-lint-XXXXXX")).string();
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    fd_ = ::mkstemp(buffer.data());
    if (fd_ < 0) return false;
    path_ = buffer.data();
    return true;
  }
  int fd() const { return fd_; }
  const std::string& path() const { return path_; }
  int close() {
    const int rc = ::close(fd_);
    fd_ = -1;
    return rc;
  }
  void release() { path_.clear(); }

 private:
  int fd_ = -1;
  std::string path_;
};

bool write_all(int fd, const std::string& text) {
  const char* data = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

// nullopt when the file at `path` still holds `expected`, else why not.
std::optional<std::string> changed_on_disk(const std::string& path, const std::string& expected) {
  std::string error;
  const std::optional<std::string> now = disk().read(path, error);
  if (!now) return fmt::format("it can no longer be read ({})", error);
  if (*now != expected) return std::string("it changed on disk while it was being checked");
  return std::nullopt;
}

}  // namespace

std::optional<std::string> write_atomically(const std::string& path, const std::string& expected_original,
                                            const std::string& text, const WriteOptions& options) {
  const auto fail = [&](const std::string& why) {
    return fmt::format("cannot write fixes to '{}': {}; the file is unchanged", path, why);
  };

  // Through a symbolic link, replace the file it leads to, not the link.
  std::error_code ec;
  fs::path target = path;
  if (fs::is_symlink(target, ec)) {
    target = fs::canonical(path, ec);
    if (ec) return fail(fmt::format("cannot resolve the symbolic link ({})", ec.message()));
  }
  const std::string target_name = target.string();

  if (auto why = changed_on_disk(target_name, expected_original)) return fail(*why);

  struct stat st {};
  if (::stat(target_name.c_str(), &st) != 0) return fail(errno_text(errno));
  if (!S_ISREG(st.st_mode)) return fail("it is not a regular file");
  // Renaming over a file only needs the directory to be writable; respect the file's own
  // read-only state (mode bits, immutable flag, read-only mount) as an editor would.
  if (::faccessat(AT_FDCWD, target_name.c_str(), W_OK, AT_EACCESS) != 0)
    return fail(fmt::format("the file is read-only ({})", errno_text(errno)));

  fs::path dir = target.parent_path();
  if (dir.empty()) dir = ".";
  TempFile temp;
  if (!temp.create(dir, target.filename().string()))
    return fail(fmt::format("cannot create a temporary file in '{}' ({})", dir.string(), errno_text(errno)));
  if (!write_all(temp.fd(), text))
    return fail(fmt::format("writing the temporary file '{}' failed ({})", temp.path(), errno_text(errno)));
  // Keep the owner where we may (root, or our own file), then the permission bits
  // (after chown, which clears set-id bits).
  if (st.st_uid != ::geteuid() || st.st_gid != ::getegid()) (void)!::fchown(temp.fd(), st.st_uid, st.st_gid);
  if (::fchmod(temp.fd(), st.st_mode & 07777) != 0)
    return fail(fmt::format("cannot set the mode of the temporary file ({})", errno_text(errno)));
  if (::fsync(temp.fd()) != 0)
    return fail(fmt::format("writing the temporary file '{}' failed ({})", temp.path(), errno_text(errno)));
  if (temp.close() != 0)
    return fail(fmt::format("writing the temporary file '{}' failed ({})", temp.path(), errno_text(errno)));

  if (options.before_rename) options.before_rename(temp.path());
  // The file may have been replaced while we worked: check once more, as late as we can.
  if (auto why = changed_on_disk(target_name, expected_original)) return fail(*why);
  if (::rename(temp.path().c_str(), target_name.c_str()) != 0)
    return fail(fmt::format("cannot replace the file ({})", errno_text(errno)));
  temp.release();

  // Make the rename itself durable (best effort).
  const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd >= 0) {
    (void)::fsync(dir_fd);
    ::close(dir_fd);
  }
  return std::nullopt;
}

std::optional<std::string> create_atomically(const std::string& path, const std::string& text) {
  const auto fail = [&](const std::string& why) { return fmt::format("cannot create '{}': {}", path, why); };
  fs::path dir = fs::path(path).parent_path();
  if (dir.empty()) dir = ".";
  TempFile temp;
  if (!temp.create(dir, fs::path(path).filename().string()))
    return fail(fmt::format("cannot create a temporary file in '{}' ({})", dir.string(), errno_text(errno)));
  if (!write_all(temp.fd(), text) || ::fchmod(temp.fd(), 0644) != 0 || ::fsync(temp.fd()) != 0 || temp.close() != 0)
    return fail(fmt::format("writing the temporary file '{}' failed ({})", temp.path(), errno_text(errno)));
  // link() refuses an existing target: a file created meanwhile is never overwritten.
  if (::link(temp.path().c_str(), path.c_str()) != 0)
    return fail(errno == EEXIST ? std::string("it exists now") : errno_text(errno));
  return std::nullopt;  // the temporary name is unlinked by TempFile
}

}  // namespace assetlint::fix
