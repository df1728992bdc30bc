// The only test file compiled with the checkout's and the build's paths: every other test file
// then compiles to the same object in every worktree, and a compiler cache can share it.
#include "../test_support.h"

namespace assetlint::test {

std::filesystem::path source_dir() { return ASSET_LINT_SOURCE_DIR; }
std::filesystem::path asset_lint_binary() { return ASSET_LINT_BINARY; }

}  // namespace assetlint::test
