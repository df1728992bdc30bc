#pragma once
#include <string>
#include <string_view>

namespace assetlint {

// Which reader a file needs, by its extension (case-insensitive): .urdf, .usda, and
// .mjcf or .xml for MJCF.
enum class FileKind { Urdf, Usda, Mjcf, Unsupported };
FileKind file_kind(const std::string& path);
// The same, with the text to decide what a `.xml` file is: MJCF when its root element is
// <mujoco>, URDF when it is <robot>, otherwise unsupported.
FileKind file_kind(const std::string& path, std::string_view text);

// The lower-case extension of `path`, with its dot ("" when none).
std::string extension_of(const std::string& path);

}  // namespace assetlint
