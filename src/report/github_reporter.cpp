#include "report/github_reporter.h"

#include <fmt/format.h>

#include "report/grouping.h"
#include "report/report_util.h"
#include "report/summary.h"

namespace assetlint {

std::string github_escape_data(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (c == '%') out += "%25";
    else if (c == '\r') out += "%0D";
    else if (c == '\n') out += "%0A";
    else out += c;
  }
  return out;
}

std::string github_escape_property(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : github_escape_data(text)) {
    if (c == ':') out += "%3A";
    else if (c == ',') out += "%2C";
    else out += c;
  }
  return out;
}

namespace {

// GitHub shows an annotation's message on several lines: the notes follow the primary line,
// then the places of the identical findings the annotation stands for, as text groups them.
std::string with_notes(const FileReport& report, const Diagnostic& d, const FindingGroup& group) {
  std::string text = d.message;
  if (const std::string notes = notes_text(report, d); !notes.empty()) text += "\n" + notes;
  if (!group.others.empty()) text += "\n" + same_on_more(report, group);
  return text;
}

}  // namespace

void write_github(std::ostream& out, const std::vector<FileReport>& reports, const RunProblems& problems) {
  for (const auto& error : problems.errors)
    out << fmt::format("::error file={},title={}::{}\n", github_escape_property(error.path),
                       github_escape_property("asset-lint (I/O error)"), github_escape_data(error.message));
  for (const auto& report : reports) {
    for (const FindingGroup& group : group_identical(report.diagnostics)) {
      const Diagnostic& d = report.diagnostics[group.first];
      const char* command = d.severity == Severity::Error ? "error" : d.severity == Severity::Warning ? "warning" : "notice";
      const LineColumn end = end_position(report, d.span);
      if (auto object = object_path(report, d.span)) {
        // A binary layer has no lines: line 1, with the object the finding is about in the message.
        out << fmt::format("::{} file={},line=1,title={}::{}\n", command, github_escape_property(diagnostic_path(report, d)),
                           github_escape_property(fmt::format("asset-lint ({})", d.rule)),
                           github_escape_data("<" + *object + "> " + with_notes(report, d, group)));
        continue;
      }
      out << fmt::format("::{} file={},line={},col={},endLine={},endColumn={},title={}::{}\n", command,
                         github_escape_property(diagnostic_path(report, d)), d.span.line, d.span.column, end.line,
                         end.column, github_escape_property(fmt::format("asset-lint ({})", d.rule)),
                         github_escape_data(with_notes(report, d, group)));
    }
  }
}

}  // namespace assetlint
