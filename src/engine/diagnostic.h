#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/source.h"

namespace assetlint {

enum class Severity { Info, Warning, Error };
std::string_view severity_name(Severity severity);
std::optional<Severity> parse_severity(std::string_view text);

// How far a fix may be trusted: `safe` keeps the asset's intent (applied by --fix),
// `unsafe` changes behaviour or guesses intent (--unsafe-fixes), `display` is only shown.
enum class Applicability { Safe, Unsafe, Display };
std::string_view applicability_name(Applicability applicability);

// Replace `length` bytes at `offset` of file `file` with `replacement`.
struct Edit {
  FileId file = 0;
  std::size_t offset = 0;
  std::size_t length = 0;
  std::string replacement;
};

struct Fix {
  std::string title;
  Applicability applicability = Applicability::Unsafe;
  std::vector<Edit> edits;
};

struct Diagnostic {
  std::string rule;
  Severity severity = Severity::Warning;
  Span span;
  std::string message;
  std::optional<Fix> fix;
};

}  // namespace assetlint
