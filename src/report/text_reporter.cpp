#include "report/text_reporter.h"

#include <fmt/color.h>
#include <fmt/format.h>

#include <algorithm>

#include "report/grouping.h"
#include "report/report_util.h"
#include "report/summary.h"
#include "util/binary_data.h"

namespace assetlint {
namespace {

fmt::text_style severity_style(Severity s) {
  switch (s) {
    case Severity::Error: return fmt::emphasis::bold | fmt::fg(fmt::terminal_color::red);
    case Severity::Warning: return fmt::emphasis::bold | fmt::fg(fmt::terminal_color::magenta);
    case Severity::Info: return fmt::emphasis::bold | fmt::fg(fmt::terminal_color::cyan);
  }
  return {};
}

// Text in a style when colour is on (fmt/color.h writes the escape sequences).
struct Painter {
  bool color;
  std::string operator()(const fmt::text_style& style, std::string_view text) const {
    return color ? fmt::format(style, "{}", text) : std::string(text);
  }
};

std::size_t code_points(std::string_view text) {
  std::size_t n = 0;
  for (const char c : text) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return n;
}

// The `full` format's excerpt: the line of the finding with its span underlined.
//    |
//  9 |     <limit lower="0.82" upper="0" effort="24" velocity="2.9"/>
//    |                  ^^^^
void write_excerpt(std::ostream& out, const FileReport& report, const Diagnostic& d, const Painter& paint) {
  if (!d.span.valid() || d.span.file >= report.sources.size()) return;
  const SourceFile& source = report.source(d.span.file);
  // A binary layer has no lines of its own to show (`asset-lint cat` prints it as text).
  if (source.binary() || d.span.line > source.line_count()) return;
  const std::string_view text = source.view();
  const std::size_t begin = source.line_start(d.span.line);
  std::size_t end = text.find('\n', begin);
  if (end == std::string_view::npos) end = text.size();
  const std::string_view line = text.substr(begin, end - begin - (end > begin && text[end - 1] == '\r' ? 1 : 0));
  // A line of binary data is described by the message, not shown.
  if (first_binary_byte(line, line.size())) return;
  const std::size_t start = std::min(d.span.offset, begin + line.size()) - begin;
  const std::size_t stop = std::min(d.span.end(), begin + line.size()) - begin;
  // Tabs are shown as four spaces on both lines, so that the carets line up in any terminal.
  constexpr std::string_view kTab = "    ";
  std::string shown;
  for (const char c : line) shown += c == '\t' ? std::string(kTab) : std::string(1, c);
  std::string pad;
  for (const char c : line.substr(0, start))
    if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) pad += c == '\t' ? std::string(kTab) : std::string(1, ' ');
  const std::size_t width = std::max<std::size_t>(1, code_points(line.substr(start, stop - start)));
  const std::string number = std::to_string(d.span.line);
  const std::string gutter(number.size(), ' ');
  const fmt::text_style blue = fmt::emphasis::bold | fmt::fg(fmt::terminal_color::blue);
  out << fmt::format(" {} {}\n", gutter, paint(blue, "|"));
  out << fmt::format(" {} {} {}\n", paint(blue, number), paint(blue, "|"), one_line(shown));
  out << fmt::format(" {} {} {}{}\n", gutter, paint(blue, "|"), pad, paint(severity_style(d.severity), std::string(width, '^')));
}

std::string plural(std::size_t n, std::string_view word) {
  return fmt::format("{} {}{}", n, word, n == 1 ? "" : "s");
}

}  // namespace

void write_text(std::ostream& out, const std::vector<FileReport>& reports, const TextOptions& options,
                const RunProblems& problems) {
  const Painter paint{options.color};
  const fmt::text_style bold = fmt::emphasis::bold;
  for (const auto& report : reports) {
    for (const FindingGroup& group : group_identical(report.diagnostics)) {
      const Diagnostic& d = report.diagnostics[group.first];
      const std::string& path = d.span.file < report.sources.size() ? report.source(d.span.file).path() : report.path;
      std::string marker;
      if (d.fix && d.fix->applicability == Applicability::Safe) marker = " (fixable)";
      else if (d.fix && d.fix->applicability == Applicability::Unsafe) marker = " (unsafe fix)";
      out << fmt::format("{} {} {} {}\n",
                         paint(bold, one_line(location_text(report, d.span, path)) + ":"),
                         paint(severity_style(d.severity), fmt::format("{}:", severity_name(d.severity))),
                         one_line(d.message), paint(fmt::emphasis::faint, fmt::format("[{}]{}", d.rule, marker)));
      if (options.show_source) write_excerpt(out, report, d, paint);
      for (const Note& note : d.notes) {
        if (note.span.valid())
          out << fmt::format("  {} {} {}\n",
                             paint(bold, one_line(location_text(report, note.span, note_path(report, note))) + ":"),
                             paint(bold, "note:"), one_line(note.message));
        else
          out << fmt::format("  {} {}\n", paint(bold, "note:"), one_line(note.message));
      }
      if (d.fix) out << fmt::format("  {} {}\n", paint(bold, "help:"), one_line(help_line(*d.fix)));
      if (!group.others.empty())
        out << fmt::format("  {} {}\n", paint(bold, "="), one_line(same_on_more(report, group)));
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
    line += fmt::format(" Skipped {} (.usdz packages and files that are neither USDA nor crate layers).",
                        plural(problems.binary_usd, "binary USD file"));
  out << line << "\n";
}

}  // namespace assetlint
