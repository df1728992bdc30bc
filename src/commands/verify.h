#pragma once
// `asset-lint verify FILE ...`: the guide's verification scenes run headless in a physics
// engine (docs/verify.md). `args` are the words after "verify".
#include <ostream>
#include <string>
#include <vector>

namespace assetlint::commands {

// Exit status: 0 every scene passed, 1 a scene failed, 2 an error (one line on `err` naming it).
int run_verify(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace assetlint::commands
