#include "commands/check.h"

#include <fmt/format.h>

#include "commands/exit_status.h"

namespace assetlint::commands {

RunProblems announce_expansion(const PathExpansion& expansion, std::ostream& err) {
  RunProblems problems;
  for (const auto& error : expansion.errors) {
    err << "asset-lint: error: " << error.message << "\n";
    problems.errors.push_back(error);
  }
  for (const auto& dir : expansion.without_assets)
    err << fmt::format("asset-lint: warning: no asset files found under '{}'\n", dir);
  problems.binary_usd = expansion.binary_usd.size();
  return problems;
}

int run_check(const PathExpansion& expansion, const SettingsFor& settings, const CheckOptions& options,
              std::ostream& err, const WriteReport& write_report) {
  RunProblems problems = announce_expansion(expansion, err);
  std::vector<FileReport> reports = lint_files(expansion.files, settings, options.jobs);
  drop_repeated_findings(reports);
  std::erase_if(reports, [&](const FileReport& report) {
    if (!report.error) return false;
    err << "asset-lint: error: " << *report.error << "\n";
    problems.errors.push_back({report.path, *report.error});
    return true;
  });
  write_report(reports, problems);
  if (!problems.errors.empty()) return kExitError;
  return findings_status(reports, options.fail_on);
}

}  // namespace assetlint::commands
