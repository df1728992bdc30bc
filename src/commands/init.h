#pragma once
// `asset-lint init [DIR]`: a first asset-lint.toml for the assets in DIR, every key commented,
// with what the assets tell (the rate a stage authors, the gripper's driven joint) filled in
// and the spec sheet left for the user.
#include <ostream>
#include <string>
#include <vector>

namespace assetlint::commands {

int run_init(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace assetlint::commands
