#include "formats/file_kind.h"

#include <algorithm>
#include <filesystem>

namespace assetlint {

std::string extension_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

FileKind file_kind(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == ".urdf") return FileKind::Urdf;
  if (ext == ".usda") return FileKind::Usda;
  return FileKind::Unsupported;
}

}  // namespace assetlint
