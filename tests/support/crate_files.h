#pragma once
// The binary USD (crate) layers the tests read: the project's fixtures/usdc and, when present,
// the shared corpus's usdc folder, sorted.
#include <filesystem>
#include <vector>

namespace assetlint::test {

std::vector<std::filesystem::path> crate_files();

}  // namespace assetlint::test
