#include "report/text_reporter.h"

#include <fmt/format.h>

#include "report/grouping.h"
#include "report/report_util.h"
#include "report/summary.h"

namespace assetlint {
namespace {

const char* severity_color(Severity s) {
  switch (s) {
    case Severity::Error: return "\033[1;31m";
    case Severity::Warning: return "\033[1;35m";
    case Severity::Info: return "\033[1;36m";
  }
  return "";
}

std::string plural(std::size_t n, std::string_view word) {
  return fmt::format("{} {}{}", n, word, n == 1 ? "" : "s");
}

// "  = the same on 23 more: 'palm' (31:17), 'thumb_base' (64:17), …": the places of the
// findings a printed one stands for.
std::string same_on_more(const std::vector<Diagnostic>& diagnostics, const FindingGroup& group) {
  constexpr std::size_t kListed = 6;
  std::string places;
  for (std::size_t k = 0; k < group.others.size() && k < kListed; ++k) {
    const Diagnostic& d = diagnostics[group.others[k]];
    const std::string name = first_quoted(d.message);
    places += fmt::format("{}{}{}:{}{}", k ? ", " : "", name.empty() ? "" : "'" + name + "' (", d.span.line,
                          d.span.column, name.empty() ? "" : ")");
  }
  if (group.others.size() > kListed) places += ", …";
  return fmt::format("and the same on {} more: {}", group.others.size(), places);
}

}  // namespace

void write_text(std::ostream& out, const std::vector<FileReport>& reports, const TextOptions& options,
                const RunProblems& problems) {
  const char* bold = options.color ? "\033[1m" : "";
  const char* dim = options.color ? "\033[2m" : "";
  const char* reset = options.color ? "\033[0m" : "";
  for (const auto& report : reports) {
    for (const FindingGroup& group : group_identical(report.diagnostics)) {
      const Diagnostic& d = report.diagnostics[group.first];
      const std::string& path = d.span.file < report.sources.size() ? report.source(d.span.file).path() : report.path;
      std::string marker;
      if (d.fix && d.fix->applicability == Applicability::Safe) marker = " (fixable)";
      else if (d.fix && d.fix->applicability == Applicability::Unsafe) marker = " (unsafe fix)";
      out << fmt::format("{}{}:{}:{}:{} {}{}:{} {} {}[{}]{}{}\n", bold, one_line(path), d.span.line, d.span.column, reset,
                         options.color ? severity_color(d.severity) : "", severity_name(d.severity), reset,
                         one_line(d.message),
                         dim, d.rule, marker, reset);
      for (const Note& note : d.notes) {
        if (note.span.valid())
          out << fmt::format("  {}{}:{}:{}:{} {}note:{} {}\n", bold, one_line(note_path(report, note)),
                             note.span.line, note.span.column, reset, bold, reset, one_line(note.message));
        else
          out << fmt::format("  {}note:{} {}\n", bold, reset, one_line(note.message));
      }
      if (d.fix) out << fmt::format("  {}help:{} {}\n", bold, reset, one_line(help_line(*d.fix)));
      if (!group.others.empty())
        out << fmt::format("  {}={} {}\n", bold, reset, one_line(same_on_more(report.diagnostics, group)));
    }
  }
  if (!options.show_summary) return;
  const Summary s = summarize(reports);
  // What was not looked at comes first: a run with I/O errors is never reported as clean.
  std::string line;
  if (!problems.errors.empty())
    line = fmt::format("{} could not be read (errors above); ", plural(problems.errors.size(), "path"));
  if (s.total() == 0) {
    line += fmt::format("{}o problems found in {}.", line.empty() ? "N" : "n", plural(s.files, "file"));
  } else {
    line += fmt::format("{}ound {} ({}, {}, {}) in {}.", line.empty() ? "F" : "f", plural(s.total(), "problem"),
                        plural(s.errors, "error"), plural(s.warnings, "warning"), plural(s.infos, "info"),
                        plural(s.files, "file"));
    if (s.fixable || s.unsafe_fixable)
      line += fmt::format(" {} fixable with --fix ({} more with --unsafe-fixes).", s.fixable, s.unsafe_fixable);
  }
  if (problems.binary_usd)
    line += fmt::format(" Skipped {} (asset-lint reads text USD).", plural(problems.binary_usd, "binary USD file"));
  out << line << "\n";
}

}  // namespace assetlint
