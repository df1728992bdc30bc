#include "engine/file_system.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace assetlint {

std::optional<std::string> DiskFileSystem::read(const std::string& path, std::string& error) const {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    error = "is a directory";
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = std::strerror(errno);
    return std::nullopt;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) {
    error = "read failed";
    return std::nullopt;
  }
  return std::move(buffer).str();
}

std::optional<std::string> OverlayFileSystem::read(const std::string& path, std::string& error) const {
  if (auto it = files_.find(path); it != files_.end()) return it->second;
  return base_.read(path, error);
}

const FileSystem& disk() {
  static const DiskFileSystem instance;
  return instance;
}

}  // namespace assetlint
