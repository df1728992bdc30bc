#pragma once
// Which files a check may read. asset-lint runs as a gate on pull requests from strangers, and
// its reports are shown to them: a reference in a checked file (a xacro include, load_yaml, an
// MJCF include, a USD layer, a mesh, a symbolic link) must not make it read, and quote, a file
// outside the tree being checked. Every reader goes through a FileSystem, so the rule lives in
// one decorator: a read is allowed only when the file's real path (symbolic links resolved) is
// inside one of the allowed roots.
#include <optional>
#include <string>
#include <vector>

#include "engine/file_system.h"

namespace assetlint {

class ReadPolicy {
 public:
  // Reads anything (--allow-outside-root).
  static ReadPolicy unconfined();
  // Reads files whose real path lies under one of `roots` (the checked tree first; then the ROS
  // package directories the user named). A root that does not exist allows nothing.
  static ReadPolicy confined_to(const std::vector<std::string>& roots);

  // Why `path` may not be read, or nothing when it may.
  std::optional<std::string> refusal(const std::string& path) const;
  bool confined() const { return confined_; }
  const std::vector<std::string>& roots() const { return roots_; }

 private:
  bool confined_ = false;
  std::vector<std::string> roots_;  // real paths, without a trailing separator
};

// `base` seen through `policy`: a refused read fails with the policy's reason as its error, so
// every reader reports it where it reports any file it cannot open, naming the reference.
class ConfinedFileSystem final : public FileSystem {
 public:
  ConfinedFileSystem(const FileSystem& base, ReadPolicy policy) : base_(base), policy_(std::move(policy)) {}
  std::optional<std::string> read(const std::string& path, std::string& error) const override;
  const ReadPolicy& policy() const { return policy_; }

 private:
  const FileSystem& base_;
  ReadPolicy policy_;
};

}  // namespace assetlint
