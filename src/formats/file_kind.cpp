#include "formats/file_kind.h"

#include "formats/mjcf/mjcf_reader.h"

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
  if (ext == ".mjcf" || ext == ".xml") return FileKind::Mjcf;
  if (ext == ".xacro") return FileKind::Xacro;
  return FileKind::Unsupported;
}

FileKind file_kind(const std::string& path, std::string_view text) {
  const FileKind kind = file_kind(path);
  if (kind != FileKind::Mjcf || extension_of(path) != ".xml" || mjcf::looks_like_mjcf(text)) return kind;
  const std::string_view robot = "<robot";
  for (std::size_t at = text.find('<'); at != std::string_view::npos; at = text.find('<', at + 1)) {
    const char next = at + 1 < text.size() ? text[at + 1] : '\0';
    if (next == '?' || next == '!') continue;
    return text.substr(at, robot.size()) == robot ? FileKind::Urdf : FileKind::Unsupported;
  }
  return FileKind::Unsupported;
}

bool is_lfs_pointer(std::string_view head) { return head.starts_with("version https://git-lfs.github.com/spec/"); }

std::string lfs_pointer_message() {
  return "is a Git LFS pointer, not the layer: the checkout did not fetch the LFS content (`git lfs pull`, or "
         "`lfs: true` in actions/checkout)";
}

FileKind usd_kind(std::string_view head) { return head.starts_with("#usda") ? FileKind::Usda : FileKind::BinaryUsd; }

}  // namespace assetlint
