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

// A sentence under a finding: an input, a threshold, a step of the derivation. It may
// point at another place (the followed joint, the configuration line, the lighter link).
struct Note {
  std::string message;
  Span span;  // invalid when the note has no place of its own
};

// A finding: a short primary message (what is wrong, where, the key number; at most
// kMaxPrimaryMessage characters), the notes with the numbers behind it, and the fix,
// whose title says what it writes.
struct Diagnostic {
  std::string rule;
  Severity severity = Severity::Warning;
  Span span;
  std::string message;
  std::optional<Fix> fix;
  std::vector<Note> notes;
  // Requirements of other checkers that state the same verdict ("SimReady DJ.004"): data for
  // a team that maps one report onto another (JSON `related`, SARIF `properties`).
  std::vector<std::string> related;
  // The consumers a consumer-specific finding concerns ("MuJoCo 3.3", "Gazebo (DART)"); empty
  // when it concerns every program that loads the file.
  std::vector<std::string> consumers;

  Diagnostic& note(std::string text);
  Diagnostic& note(const Span& at, std::string text);
};

inline constexpr std::size_t kMaxPrimaryMessage = 120;

}  // namespace assetlint
