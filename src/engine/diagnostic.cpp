#include "engine/diagnostic.h"

namespace assetlint {

std::string_view severity_name(Severity severity) {
  switch (severity) {
    case Severity::Info: return "info";
    case Severity::Warning: return "warning";
    case Severity::Error: return "error";
  }
  return "error";
}

std::optional<Severity> parse_severity(std::string_view text) {
  if (text == "info") return Severity::Info;
  if (text == "warning") return Severity::Warning;
  if (text == "error") return Severity::Error;
  return std::nullopt;
}

std::string_view applicability_name(Applicability applicability) {
  switch (applicability) {
    case Applicability::Safe: return "safe";
    case Applicability::Unsafe: return "unsafe";
    case Applicability::Display: return "display";
  }
  return "display";
}

Diagnostic& Diagnostic::note(std::string text) {
  notes.push_back(Note{std::move(text), Span{}});
  return *this;
}

Diagnostic& Diagnostic::note(const Span& at, std::string text) {
  notes.push_back(Note{std::move(text), at});
  return *this;
}

}  // namespace assetlint
