#include "report/junit_reporter.h"

#include <fmt/format.h>

#include <algorithm>

#include "formats/suppressions.h"
#include "report/report_util.h"
#include "pipeline/suppressions.h"
#include "rules/registry.h"

namespace assetlint {

std::vector<std::string> rules_run_on(const Settings& settings, std::string_view path) {
  std::vector<std::string> ids;
  for (const RuleInfo* rule : rules::catalog())
    if (settings.selection.enabled(rule->id) && !per_file_ignored(settings, path, rule->id))
      ids.emplace_back(rule->id);
  return ids;
}

namespace {

// The length of the valid UTF-8 sequence at text[i], or 0 when the bytes there are not one.
std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char c = byte(i);
  std::size_t length = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
  if (length == 0 || i + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k)
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  // Overlong forms, surrogates and code points past U+10FFFF are not UTF-8.
  if (length == 2 && c < 0xC2) return 0;
  if (length == 3 && ((c == 0xE0 && byte(i + 1) < 0xA0) || (c == 0xED && byte(i + 1) >= 0xA0))) return 0;
  if (length == 4 && ((c == 0xF0 && byte(i + 1) < 0x90) || c > 0xF4 || (c == 0xF4 && byte(i + 1) >= 0x90)))
    return 0;
  return length;
}

}  // namespace

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const char ch = text[i];
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x80) {
      // Bytes from an asset in another encoding (an ISO-8859-1 URDF) would make the
      // report ill-formed: each invalid byte becomes U+FFFD.
      const std::size_t length = utf8_length(text, i);
      if (length == 0) {
        out += "\xEF\xBF\xBD";
        ++i;
      } else {
        out.append(text.substr(i, length));
        i += length;
      }
      continue;
    }
    ++i;
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      case '\n': out += "&#10;"; break;
      case '\r': out += "&#13;"; break;
      case '\t': out += "&#9;"; break;
      default:
        // Other control characters are not allowed in XML 1.0, even as references.
        if (c < 0x20 || c == 0x7F) out += "?";
        else out += ch;
    }
  }
  return out;
}

void write_junit(std::ostream& out, const std::vector<FileReport>& reports, const RulesRun& rules_run,
                 const RunProblems& problems) {
  // GitLab and Jenkins show only the first <failure> of a testcase: each finding is its
  // own testcase (named by rule and position, so that names stay unique), and each rule
  // that ran without a finding a passing one.
  struct Suite {
    const FileReport* report;
    std::vector<std::string> passed;
  };
  std::vector<Suite> suites;
  std::size_t tests = problems.errors.size(), failures = 0;
  for (const auto& report : reports) {
    Suite suite{&report, {}};
    for (auto& rule : rules_run(report)) {
      const bool found = std::any_of(report.diagnostics.begin(), report.diagnostics.end(),
                                     [&](const Diagnostic& d) { return d.rule == rule; });
      if (!found) suite.passed.push_back(std::move(rule));
    }
    tests += suite.passed.size() + report.diagnostics.size();
    failures += report.diagnostics.size();
    suites.push_back(std::move(suite));
  }
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out << fmt::format("<testsuites name=\"asset-lint\" tests=\"{}\" failures=\"{}\" errors=\"{}\">\n", tests, failures,
                     problems.errors.size());
  if (!problems.errors.empty()) {
    // Paths the run could not read: an <error> each, so that the run never looks clean.
    out << fmt::format("  <testsuite name=\"asset-lint: paths not read\" tests=\"{0}\" failures=\"0\" errors=\"{0}\" "
                       "skipped=\"0\">\n",
                       problems.errors.size());
    for (const auto& error : problems.errors) {
      const std::string path = xml_escape(error.path);
      out << fmt::format("    <testcase classname=\"{0}\" name=\"read\" file=\"{0}\">\n", path);
      out << fmt::format("      <error message=\"{0}\" type=\"io-error\">{0}</error>\n", xml_escape(error.message));
      out << "    </testcase>\n";
    }
    out << "  </testsuite>\n";
  }
  for (const auto& suite : suites) {
    const FileReport& report = *suite.report;
    const std::string path = xml_escape(report.path);
    out << fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" skipped=\"0\">\n", path,
                       suite.passed.size() + report.diagnostics.size(), report.diagnostics.size());
    for (const Diagnostic& d : report.diagnostics) {
      const std::string& where = diagnostic_path(report, d);
      const std::string location = location_text(report, d.span, where);
      // A binary layer has no lines: line 1, with the object path in the name and the location.
      const auto object = object_path(report, d.span);
      const std::string place = object ? "<" + *object + ">" : fmt::format("{}:{}", d.span.line, d.span.column);
      const std::uint32_t line = object ? 1 : d.span.line;
      const std::string notes = notes_text(report, d);
      const std::string body = notes.empty() ? d.message : d.message + "\n" + notes;
      out << fmt::format("    <testcase classname=\"{}\" name=\"{} ({})\" file=\"{}\" line=\"{}\">\n", path,
                         xml_escape(d.rule), xml_escape(place), xml_escape(where), line);
      out << fmt::format("      <failure message=\"{}\" type=\"{}\">{}: {}</failure>\n", xml_escape(d.message),
                         severity_name(d.severity), xml_escape(location), xml_escape(body));
      out << "    </testcase>\n";
    }
    for (const auto& rule : suite.passed)
      out << fmt::format("    <testcase classname=\"{}\" name=\"{}\"/>\n", path, xml_escape(rule));
    out << "  </testsuite>\n";
  }
  out << "</testsuites>\n";
}

}  // namespace assetlint
