#pragma once
#include <string>

namespace assetlint {

// Which reader a file needs, by its extension (case-insensitive).
enum class FileKind { Urdf, Usda, Unsupported };
FileKind file_kind(const std::string& path);

// The lower-case extension of `path`, with its dot ("" when none).
std::string extension_of(const std::string& path);

}  // namespace assetlint
