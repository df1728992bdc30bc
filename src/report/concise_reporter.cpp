#include "report/concise_reporter.h"

#include <fmt/format.h>

#include "report/report_util.h"

namespace assetlint {

void write_concise(std::ostream& out, const std::vector<FileReport>& reports) {
  for (const auto& report : reports)
    for (const auto& d : report.diagnostics)
      out << fmt::format("{}: {} {}\n", one_line(location_text(report, d.span, diagnostic_path(report, d))), d.rule,
                         one_line(d.message));
}

}  // namespace assetlint
