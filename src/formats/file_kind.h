#pragma once
#include <string>
#include <string_view>

namespace assetlint {

// Which reader a file needs, by its extension (case-insensitive). A `.usd` file may be
// text or a binary crate: `Usd` until its first bytes say which (usd_kind). `.mjcf` and
// `.xml` are MJCF (a `.xml` until its text says otherwise, see below).
enum class FileKind { Urdf, Usda, Usd, BinaryUsd, Mjcf, Xacro, Unsupported };
FileKind file_kind(const std::string& path);
// The same, with the text to decide what a `.xml` file is: MJCF when its root element is
// <mujoco>, URDF when it is <robot>, otherwise unsupported.
FileKind file_kind(const std::string& path, std::string_view text);

// A `.usd` file's kind by its first bytes: text layers start with `#usda`.
FileKind usd_kind(std::string_view head);

// A Git LFS pointer: the small text file git checks out in place of a large file when the LFS
// content was not fetched (https://github.com/git-lfs/git-lfs/blob/main/docs/spec.md).
bool is_lfs_pointer(std::string_view head);
// The message for a layer or file that is one.
std::string lfs_pointer_message();

// The lower-case extension of `path`, with its dot ("" when none).
std::string extension_of(const std::string& path);

}  // namespace assetlint
