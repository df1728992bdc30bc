#include "report/report_util.h"

#include <fmt/format.h>

namespace assetlint {

std::string one_line(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (ch == '\n') out += "\\n";
    else if (ch == '\r') out += "\\r";
    else if (ch == '\t') out += "\\t";
    else if (c < 0x20 || c == 0x7F) out += fmt::format("\\x{:02X}", c);
    else out += ch;
  }
  return out;
}

std::optional<std::string> object_path(const FileReport& report, const Span& span) {
  if (span.file >= report.sources.size() || !report.source(span.file).binary()) return std::nullopt;
  const std::string_view object = report.source(span.file).object_at(span.offset);
  return object.empty() ? "/" : std::string(object);
}

std::string location_text(const FileReport& report, const Span& span, const std::string& path) {
  if (auto object = object_path(report, span)) return fmt::format("{} <{}>", path, *object);
  return fmt::format("{}:{}:{}", path, span.line, span.column);
}

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
      out += fmt::format("{}: note: {}", location_text(report, note.span, note_path(report, note)), note.message);
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
