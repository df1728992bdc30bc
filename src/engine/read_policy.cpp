#include "engine/read_policy.h"

#include <fmt/format.h>

#include <filesystem>

namespace assetlint {
namespace {

namespace fs = std::filesystem;

// The real path: every symbolic link of the existing part resolved, `..` folded, the
// part that does not exist kept as written.
fs::path real_path(const std::string& path) {
  std::error_code ec;
  fs::path absolute = fs::absolute(path, ec);
  if (ec) return fs::path(path).lexically_normal();
  fs::path real = fs::weakly_canonical(absolute, ec);
  return ec ? absolute.lexically_normal() : real;
}

bool under(const fs::path& file, const fs::path& root) {
  const fs::path relative = file.lexically_relative(root);
  return !relative.empty() && *relative.begin() != "..";
}

std::string without_trailing_separator(std::string text) {
  while (text.size() > 1 && text.back() == '/') text.pop_back();
  return text;
}

}  // namespace

ReadPolicy ReadPolicy::unconfined() { return ReadPolicy{}; }

ReadPolicy ReadPolicy::confined_to(const std::vector<std::string>& roots) {
  ReadPolicy policy;
  policy.confined_ = true;
  for (const std::string& root : roots) {
    if (root.empty()) continue;
    policy.roots_.push_back(without_trailing_separator(real_path(root).string()));
  }
  return policy;
}

std::optional<std::string> ReadPolicy::refusal(const std::string& path) const {
  if (!confined_) return std::nullopt;
  const fs::path real = real_path(path);
  for (const std::string& root : roots_) {
    if (real == fs::path(root) || under(real, root)) return std::nullopt;
  }
  const std::string tree = roots_.empty() ? std::string("(none)") : roots_.front();
  const std::string via = real.string() == fs::path(path).lexically_normal().string() ? std::string()
                                                                                        : fmt::format(" (its real path is '{}')", real.string());
  return fmt::format("not read: outside the checked tree '{}'{}; --root DIR widens the tree, --allow-outside-root reads "
                     "anywhere",
                     tree, via);
}

std::optional<std::string> ConfinedFileSystem::read(const std::string& path, std::string& error) const {
  if (auto why = policy_.refusal(path)) {
    error = std::move(*why);
    return std::nullopt;
  }
  return base_.read(path, error);
}

}  // namespace assetlint
