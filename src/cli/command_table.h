#pragma once
// Every command of asset-lint, once: the help, the "did you mean" answer to a mistyped
// command and the shell completions are written from this table.
#include <string>
#include <string_view>
#include <vector>

namespace assetlint::cli {

struct CommandInfo {
  std::string_view name;      // the first word: "tune"
  std::string_view synopsis;  // "asset-lint tune FILE"
  std::string_view summary;   // what it does, one line
};

const std::vector<CommandInfo>& command_table();
std::vector<std::string> command_names();

// The help's list of commands: one line each, synopses aligned.
std::string commands_help();

}  // namespace assetlint::cli
