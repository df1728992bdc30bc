#include "cli/command_table.h"

#include <fmt/format.h>

#include <algorithm>

namespace assetlint::cli {

const std::vector<CommandInfo>& command_table() {
  static const std::vector<CommandInfo> table = {
      {"check", "asset-lint [check] [PATH...]", "check files and directories (default: .)"},
      {"compare", "asset-lint compare A B [C]", "do files in any of the formats describe the same physics?"},
      {"expand", "asset-lint expand FILE.xacro", "print the URDF a .xacro file expands to (--xacro-arg name:=value)"},
      {"tune", "asset-lint tune FILE", "derive the driven joint's drive from the spec sheet, step by step (--apply)"},
      {"simulate", "asset-lint simulate FILE", "step the driven joint from open to closed as the engine does (--plot)"},
      {"verify", "asset-lint verify FILE", "close, grasp, hold and lift a payload in MuJoCo against the spec (--plot)"},
      {"rule", "asset-lint rule RULE-ID", "print a rule's documentation and options (rule --all: every rule)"},
      {"cat", "asset-lint cat FILE.usd", "print a binary (crate) USD layer as USDA text, e.g. for git diff"},
      {"init", "asset-lint init [DIR]", "write a commented asset-lint.toml for the assets found in DIR"},
      {"completion", "asset-lint completion SHELL", "print the completion script for bash, zsh or fish"},
  };
  return table;
}

std::vector<std::string> command_names() {
  std::vector<std::string> names;
  for (const CommandInfo& command : command_table()) names.emplace_back(command.name);
  return names;
}

std::string commands_help() {
  std::size_t width = 0;
  for (const CommandInfo& command : command_table()) width = std::max(width, command.synopsis.size());
  std::string text;
  for (const CommandInfo& command : command_table())
    text += fmt::format("  {:<{}}  {}\n", command.synopsis, width, command.summary);
  return text;
}

}  // namespace assetlint::cli
