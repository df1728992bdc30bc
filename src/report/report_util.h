#pragma once
// Small helpers the report writers share.
#include <optional>
#include <string>
#include <string_view>

#include "pipeline/lint.h"

namespace assetlint {

// The path of the file a finding is in: a composed layer's path, or the checked file's.
inline const std::string& diagnostic_path(const FileReport& report, const Diagnostic& d) {
  return d.span.file < report.sources.size() ? report.source(d.span.file).path() : report.path;
}

// The path of the file a note points at.
inline const std::string& note_path(const FileReport& report, const Note& note) {
  return note.span.file < report.sources.size() ? report.source(note.span.file).path() : report.path;
}

// The object path a span points at in a binary (crate) layer, which has no lines
// ("/anymal/LF_HAA.drive:angular:physics:stiffness"); nullopt in a text file.
std::optional<std::string> object_path(const FileReport& report, const Span& span);

// Where a span is, for a reader: "path:line:column", or "path </object/path>" in a binary layer.
std::string location_text(const FileReport& report, const Span& span, const std::string& path);

// "fix: set stiffness …", "unsafe fix: …" or "suggestion: …": what the fix writes and
// how far it is trusted.
std::string help_line(const Fix& fix);

// Text from an asset (joint names, prim paths, file names) on one printable line:
// control characters become \n, \r, \t or \xNN, so that a crafted name cannot start a
// line of its own (a CI log command such as `::warning`).
std::string one_line(std::string_view text);

// The finding's notes and help as plain lines, for formats that carry one text body.
std::string notes_text(const FileReport& report, const Diagnostic& d);

}  // namespace assetlint
