#pragma once
// `asset-lint completion bash|zsh|fish`: a completion script with the commands, the options
// and their values, and the rule ids (for --select, --ignore and `rule`).
#include <ostream>
#include <string>
#include <vector>

namespace assetlint::cli {

int run_completion_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace assetlint::cli
