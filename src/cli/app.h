#pragma once
#include <ostream>
#include <string>
#include <vector>

namespace assetlint::cli {

// Runs the command line `args` (without the program name); returns the exit code:
// 0 nothing reported, 1 findings remain, 2 usage, configuration or I/O error.
// Standard input (for `check - --stdin-filename PATH`) is `in`.
int run(const std::vector<std::string>& args, std::istream& in, std::ostream& out, std::ostream& err,
        bool out_is_terminal);
int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, bool out_is_terminal);

}  // namespace assetlint::cli
