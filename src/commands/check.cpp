#include "commands/check.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>

#include "commands/exit_status.h"
#include "pipeline/baseline.h"

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

namespace {

std::filesystem::path directory_of(const std::string& file) {
  const std::filesystem::path parent = std::filesystem::path(file).parent_path();
  return parent.empty() ? "." : parent;
}

int write_baseline_file(const std::vector<FileReport>& reports, const RunProblems& problems, const std::string& path,
                        std::ostream& err) {
  const std::vector<BaselineEntry> entries = baseline_entries(reports, directory_of(path));
  std::size_t findings = 0;
  for (const auto& e : entries) findings += e.count;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << baseline_text(entries);
  out.close();
  if (!out) {
    err << fmt::format("asset-lint: error: cannot write baseline '{}'\n", path);
    return kExitError;
  }
  err << fmt::format("asset-lint: wrote {} finding{} ({} entr{}) to baseline '{}'\n", findings,
                     findings == 1 ? "" : "s", entries.size(), entries.size() == 1 ? "y" : "ies", path);
  return problems.errors.empty() ? kExitClean : kExitError;
}

void announce_baseline(const BaselineMatch& match, const std::string& path, std::ostream& err) {
  if (match.matched > 0)
    err << fmt::format("asset-lint: {} finding{} recorded in baseline '{}' not reported\n", match.matched,
                       match.matched == 1 ? "" : "s", path);
  if (match.stale.empty()) return;
  err << fmt::format("asset-lint: warning: {} baseline entr{} no longer occur{} (`--write-baseline {}` drops {}):\n",
                     match.stale.size(), match.stale.size() == 1 ? "y" : "ies", match.stale.size() == 1 ? "s" : "",
                     path, match.stale.size() == 1 ? "it" : "them");
  for (const auto& entry : match.stale) err << "  " << entry.to_string() << "\n";
}

}  // namespace

int run_check(const PathExpansion& expansion, const SettingsFor& settings, const CheckOptions& options,
              std::ostream& err, const WriteReport& write_report) {
  std::optional<std::vector<BaselineEntry>> baseline;
  if (!options.baseline.empty()) {
    std::string error;
    baseline = read_baseline(options.baseline, error);
    if (!baseline) {
      err << "asset-lint: error: " << error << "\n";
      return kExitError;
    }
  }
  RunProblems problems = announce_expansion(expansion, err);
  std::vector<FileReport> reports = lint_files(expansion.files, settings, options.jobs);
  drop_repeated_findings(reports);
  std::erase_if(reports, [&](const FileReport& report) {
    if (!report.error) return false;
    err << "asset-lint: error: " << *report.error << "\n";
    problems.errors.push_back({report.path, *report.error});
    return true;
  });
  if (!options.write_baseline.empty()) return write_baseline_file(reports, problems, options.write_baseline, err);
  if (baseline) announce_baseline(apply_baseline(reports, *baseline, directory_of(options.baseline)), options.baseline, err);
  write_report(reports, problems);
  if (!problems.errors.empty()) return kExitError;
  return findings_status(reports, options.fail_on);
}

}  // namespace assetlint::commands
