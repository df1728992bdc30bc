#pragma once
// `asset-lint tune ASSET ...`: the guide's derivation of a drive from the spec sheet
// (docs/tune.md). `args` are the words after "tune".
#include <ostream>
#include <string>
#include <vector>

namespace assetlint::commands {

// Exit status: 0 printed (or applied), 1 with --diff when there is a change to show,
// 2 bad input (one line on `err` naming it).
int run_tune(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace assetlint::commands
