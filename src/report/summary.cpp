#include "report/summary.h"

namespace assetlint {

Summary summarize(const std::vector<FileReport>& reports) {
  Summary s;
  for (const auto& report : reports) {
    ++s.files;
    for (const auto& d : report.diagnostics) {
      switch (d.severity) {
        case Severity::Error: ++s.errors; break;
        case Severity::Warning: ++s.warnings; break;
        case Severity::Info: ++s.infos; break;
      }
      if (d.fix && d.fix->applicability == Applicability::Safe) ++s.fixable;
      if (d.fix && d.fix->applicability == Applicability::Unsafe) ++s.unsafe_fixable;
    }
  }
  return s;
}

LineColumn end_position(const FileReport& report, const Span& span) {
  if (span.file >= report.sources.size()) return {span.line, span.column};
  return report.source(span.file).position(span.offset + span.length);
}

}  // namespace assetlint
