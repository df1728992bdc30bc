#pragma once
// Writing fixed files: atomically, only when the file still has the bytes that were
// linted, keeping its permission bits and owner.
#include <functional>
#include <optional>
#include <string>

#include "fix/fixer.h"

namespace assetlint::fix {

struct WriteOptions {
  // Test hook: called after the temporary file is complete, before the final check
  // that the original is unchanged and the rename over it.
  std::function<void(const std::string& temp_path)> before_rename;
};

// Replaces the file at `path` with `text`: writes a temporary file in the same
// directory, fsyncs it, gives it the original's mode (and owner, where permitted),
// and renames it over the original (through a symbolic link, over its target).
// Refuses, leaving everything as it was, when the file's bytes are no longer
// `expected_original`, when the file is not writable (permission bits, immutable,
// read-only file system), or when the temporary file cannot be created or written
// (directory not writable, disk full); the temporary file is removed.
// Returns nullopt on success, otherwise a message naming the file.
std::optional<std::string> write_atomically(const std::string& path, const std::string& expected_original,
                                            const std::string& text, const WriteOptions& options = {});

// Creates the file at `path` with `text`, atomically: a temporary file in the same
// directory, fsynced, then linked to `path`, which fails (leaving nothing behind) when
// `path` exists by then. Returns nullopt on success, otherwise a message naming the file.
std::optional<std::string> create_atomically(const std::string& path, const std::string& text);

inline std::optional<std::string> write_fixed_file(const FixedFile& file, const WriteOptions& options = {}) {
  return write_atomically(file.path, file.original, file.fixed, options);
}

}  // namespace assetlint::fix
