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
  if (ext == ".usd") return FileKind::Usd;
  if (ext == ".usdc" || ext == ".usdz") return FileKind::BinaryUsd;
  return FileKind::Unsupported;
}

FileKind usd_kind(std::string_view head) { return head.starts_with("#usda") ? FileKind::Usda : FileKind::BinaryUsd; }

}  // namespace assetlint
