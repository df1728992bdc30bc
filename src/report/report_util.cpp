#include "report/report_util.h"

#include <fmt/format.h>

namespace assetlint {

std::string help_line(const Fix& fix) {
  switch (fix.applicability) {
    case Applicability::Safe: return "fix: " + fix.title;
    case Applicability::Unsafe: return "unsafe fix: " + fix.title;
    case Applicability::Display: return "suggestion: " + fix.title;
  }
  return fix.title;
}

std::string notes_text(const FileReport& report, const Diagnostic& d) {
  std::string out;
  for (const Note& note : d.notes) {
    if (!out.empty()) out += '\n';
    if (note.span.valid())
      out += fmt::format("{}:{}:{}: note: {}", note_path(report, note), note.span.line, note.span.column, note.message);
    else
      out += "note: " + note.message;
  }
  if (d.fix) {
    if (!out.empty()) out += '\n';
    out += "help: " + help_line(*d.fix);
  }
  return out;
}

}  // namespace assetlint
