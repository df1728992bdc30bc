#include "commands/check.h"

#include "commands/exit_status.h"

namespace assetlint::commands {

int run_check(const PathExpansion& expansion, const SettingsFor& settings, const CheckOptions& options,
              std::ostream& err, const WriteReport& write_report) {
  bool io_error = false;
  for (const auto& message : expansion.errors) {
    err << "asset-lint: error: " << message << "\n";
    io_error = true;
  }
  std::vector<FileReport> reports = lint_files(expansion.files, settings, options.jobs);
  drop_repeated_findings(reports);
  std::erase_if(reports, [&](const FileReport& report) {
    if (!report.error) return false;
    err << "asset-lint: error: " << *report.error << "\n";
    io_error = true;
    return true;
  });
  write_report(reports);
  if (io_error) return kExitError;
  for (const auto& report : reports)
    if (!report.diagnostics.empty()) return kExitFindings;
  return kExitClean;
}

}  // namespace assetlint::commands
