#include "cli/report_writer.h"

#include <filesystem>

#include "report/concise_reporter.h"
#include "report/github_reporter.h"
#include "report/gitlab_reporter.h"
#include "report/json_reporter.h"
#include "report/junit_reporter.h"
#include "report/sarif_reporter.h"
#include "report/statistics.h"
#include "report/summary.h"
#include "report/text_reporter.h"

namespace assetlint::cli {

commands::WriteReport report_writer(const Options& options, bool use_color, config::SettingsResolver& resolver,
                                    std::ostream& out) {
  return [&options, use_color, &resolver, &out](const std::vector<FileReport>& reports, const RunProblems& problems) {
    const std::string& format = options.format;
    if (options.statistics && format == "json") write_statistics_json(out, reports);
    else if (options.statistics) {
      write_statistics_text(out, reports);
      const Summary s = summarize(reports);
      if (!options.quiet && s.fixable) out << "[*] fixable with `asset-lint --fix`\n";
    } else if (format == "json") write_json(out, reports, problems);
    else if (format == "concise") write_concise(out, reports);
    else if (format == "github") write_github(out, reports, problems);
    else if (format == "gitlab") write_gitlab(out, reports);
    else if (format == "sarif") {
      std::error_code ec;
      write_sarif(out, reports, SarifOptions{std::filesystem::current_path(ec).string()}, problems);
    } else if (format == "junit") {
      write_junit(
          out, reports, [&](const FileReport& r) { return rules_run_on(resolver.for_file(r.path), r.path); },
          problems);
    } else write_text(out, reports, TextOptions{use_color, !options.quiet, format == "full"}, problems);
    out.flush();
  };
}

}  // namespace assetlint::cli
