#include "cli/completion.h"

#include <fmt/format.h>

#include "cli/command_table.h"
#include "cli/options.h"
#include "commands/exit_status.h"
#include "rules/registry.h"

namespace assetlint::cli {
namespace {

// The words each kind of completion offers, space-separated.
struct Words {
  std::string commands, options, rules;
};

Words words() {
  Words w;
  for (const std::string& name : command_names()) w.commands += (w.commands.empty() ? "" : " ") + name;
  for (const OptionName& option : option_names()) w.options += (w.options.empty() ? "" : " ") + option.name;
  for (const RuleInfo* rule : rules::catalog()) w.rules += (w.rules.empty() ? "" : " ") + std::string(rule->id);
  return w;
}

// The options whose value is one of a few words.
constexpr const char* kRuleOptions = "--select|--ignore|--extend-select|--extend-ignore";
constexpr const char* kFormats = "text full concise json sarif github gitlab junit";

std::string bash_script() {
  const Words w = words();
  return fmt::format(R"(# bash completion for asset-lint. Load it in the current shell with
#   source <(asset-lint completion bash)
# or install it: asset-lint completion bash > ~/.local/share/bash-completion/completions/asset-lint
_asset_lint() {{
  local cur="${{COMP_WORDS[COMP_CWORD]}}" prev=""
  [ "$COMP_CWORD" -gt 0 ] && prev="${{COMP_WORDS[COMP_CWORD-1]}}"
  local commands="{0}"
  local options="{1}"
  local rules="{2}"
  case "$prev" in
    {3}) COMPREPLY=($(compgen -W "$rules" -- "$cur")); return ;;
    --output-format) COMPREPLY=($(compgen -W "{4}" -- "$cur")); return ;;
    --fail-on) COMPREPLY=($(compgen -W "info warning error" -- "$cur")); return ;;
    --color) COMPREPLY=($(compgen -W "auto always never" -- "$cur")); return ;;
  esac
  if [ "$COMP_CWORD" -eq 2 ] && [ "${{COMP_WORDS[1]}}" = rule ]; then
    COMPREPLY=($(compgen -W "$rules --all" -- "$cur")); return
  fi
  if [ "$COMP_CWORD" -eq 2 ] && [ "${{COMP_WORDS[1]}}" = completion ]; then
    COMPREPLY=($(compgen -W "bash zsh fish" -- "$cur")); return
  fi
  if [[ "$cur" == -* ]]; then
    COMPREPLY=($(compgen -W "$options" -- "$cur")); return
  fi
  if [ "$COMP_CWORD" -eq 1 ]; then
    COMPREPLY=($(compgen -W "$commands" -- "$cur") $(compgen -f -- "$cur")); return
  fi
  COMPREPLY=($(compgen -f -- "$cur"))
}}
complete -o filenames -F _asset_lint asset-lint
)",
                     w.commands, w.options, w.rules, kRuleOptions, kFormats);
}

std::string zsh_script() {
  const Words w = words();
  return fmt::format(R"(#compdef asset-lint
# zsh completion for asset-lint. Load it in the current shell with
#   source <(asset-lint completion zsh)
# or install it as _asset_lint in a directory of $fpath.
_asset_lint() {{
  local -a commands options rules
  commands=({0})
  options=({1})
  rules=({2})
  case "${{words[CURRENT-1]}}" in
    {3}) compadd -a rules; return ;;
    --output-format) compadd {4}; return ;;
    --fail-on) compadd info warning error; return ;;
    --color) compadd auto always never; return ;;
  esac
  if (( CURRENT == 3 )) && [[ "${{words[2]}}" == rule ]]; then
    compadd -a rules; compadd -- --all; return
  fi
  if (( CURRENT == 3 )) && [[ "${{words[2]}}" == completion ]]; then
    compadd bash zsh fish; return
  fi
  if [[ "${{words[CURRENT]}}" == -* ]]; then
    compadd -a options; return
  fi
  (( CURRENT == 2 )) && compadd -a commands
  _files
}}
if [ "$funcstack[1]" = "_asset_lint" ]; then
  _asset_lint "$@"
else
  compdef _asset_lint asset-lint
fi
)",
                     w.commands, w.options, w.rules, kRuleOptions, kFormats);
}

// fish quotes with single quotes; a quote inside is written \'.
std::string fish_quoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) {
    if (c == '\'' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "'";
}

std::string fish_script() {
  const Words w = words();
  std::string script =
      "# fish completion for asset-lint. Load it in the current shell with\n"
      "#   asset-lint completion fish | source\n"
      "# or install it: asset-lint completion fish > ~/.config/fish/completions/asset-lint.fish\n"
      "complete -c asset-lint -e\n";
  for (const CommandInfo& command : command_table())
    script += fmt::format("complete -c asset-lint -n __fish_use_subcommand -a {} -d {}\n", command.name,
                          fish_quoted(std::string(command.summary)));
  script += fmt::format("complete -c asset-lint -n '__fish_seen_subcommand_from rule' -x -a {}\n",
                        fish_quoted(w.rules + " --all"));
  script += "complete -c asset-lint -n '__fish_seen_subcommand_from completion' -x -a 'bash zsh fish'\n";
  for (const OptionName& option : option_names()) {
    const bool is_long = option.name.starts_with("--");
    std::string line = fmt::format("complete -c asset-lint {} {}", is_long ? "-l" : "-s",
                                   option.name.substr(is_long ? 2 : 1));
    if (option.name == "--select" || option.name == "--ignore" || option.name == "--extend-select" ||
        option.name == "--extend-ignore")
      line += " -x -a " + fish_quoted(w.rules);
    else if (option.name == "--output-format") line += fmt::format(" -x -a '{}'", kFormats);
    else if (option.name == "--fail-on") line += " -x -a 'info warning error'";
    else if (option.name == "--color") line += " -x -a 'auto always never'";
    else if (option.takes_value) line += " -r";
    script += line + " -d " + fish_quoted(option.description.substr(0, option.description.find(" ("))) + "\n";
  }
  return script;
}

}  // namespace

int run_completion_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  constexpr const char* kUsage = "usage: asset-lint completion bash|zsh|fish   print the shell's completion script\n";
  if (args.size() == 2 && (args[1] == "--help" || args[1] == "-h")) {
    out << kUsage;
    return commands::kExitClean;
  }
  if (args.size() == 2 && args[1] == "bash") out << bash_script();
  else if (args.size() == 2 && args[1] == "zsh") out << zsh_script();
  else if (args.size() == 2 && args[1] == "fish") out << fish_script();
  else {
    err << "asset-lint: error: " << kUsage;
    return commands::kExitError;
  }
  return commands::kExitClean;
}

}  // namespace assetlint::cli
