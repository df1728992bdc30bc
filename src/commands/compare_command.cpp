#include "commands/compare_command.h"

#include <fmt/format.h>

#include <filesystem>

#include "commands/compare_fix.h"
#include "commands/exit_status.h"

namespace assetlint::commands {

int run_compare(const std::vector<std::string>& paths, const CompareCommandOptions& command,
                const SettingsFor& settings, std::ostream& out, std::ostream& err, const WriteReport& write_report) {
  if (paths.size() < 2 || paths.size() > 3) {
    err << "asset-lint: error: usage: asset-lint compare A B [C]\n";
    return kExitError;
  }
  CompareOptions options;
  options.rtol = command.rtol;
  for (const auto& pair : command.map_pairs) {
    const auto eq = pair.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == pair.size()) {
      err << fmt::format("asset-lint: error: --map '{}': expected NAME=OTHER_NAME\n", pair);
      return kExitError;
    }
    options.map.emplace_back(pair.substr(0, eq), pair.substr(eq + 1));
  }
  if (!command.fix_side.empty()) {
    for (std::size_t i = 0; i < paths.size(); ++i)
      if (paths[i] == command.fix_side || std::filesystem::path(paths[i]).filename() == command.fix_side)
        options.fix_side = static_cast<int>(i);
    if (options.fix_side < 0) {
      err << fmt::format("asset-lint: error: --fix-side '{}' is none of the compared files\n", command.fix_side);
      return kExitError;
    }
  }
  if (command.fix && options.fix_side < 0) {
    err << "asset-lint: error: compare --fix needs --fix-side FILE (which file is right is yours to say)\n";
    return kExitError;
  }
  std::string error;
  std::vector<ComparisonSummary> summaries;
  FileReport report = compare_files(paths, settings, options, error, &summaries);
  if (error.empty() && command.fix) {
    int changed = 0;
    if (auto failure = apply_compare_fixes(report, settings, changed)) {
      err << "asset-lint: error: " << *failure << "\n";
      return kExitError;
    }
    out << fmt::format("compare: {} file{} fixed\n", changed, changed == 1 ? "" : "s");
    summaries.clear();
    report = compare_files(paths, settings, options, error, &summaries);
  }
  if (!error.empty()) {
    err << "asset-lint: error: " << error << "\n";
    return kExitError;
  }
  if (command.summary)
    for (const ComparisonSummary& summary : summaries)
      for (const std::string& line : summary_lines(summary)) out << line << "\n";
  write_report({report}, RunProblems{});
  return report.diagnostics.empty() ? kExitClean : kExitFindings;
}

}  // namespace assetlint::commands
