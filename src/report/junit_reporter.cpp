#include "report/junit_reporter.h"

#include <fmt/format.h>

#include <map>

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

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
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

void write_junit(std::ostream& out, const std::vector<FileReport>& reports, const RulesRun& rules_run) {
  struct Suite {
    const FileReport* report;
    std::vector<std::string> rules;
    std::map<std::string, std::vector<const Diagnostic*>, std::less<>> failures;
  };
  std::vector<Suite> suites;
  std::size_t tests = 0, failures = 0;
  for (const auto& report : reports) {
    Suite suite{&report, rules_run(report), {}};
    for (const auto& d : report.diagnostics) suite.failures[d.rule].push_back(&d);
    // A finding of a rule outside the list still gets its testcase.
    for (const auto& [rule, list] : suite.failures)
      if (std::find(suite.rules.begin(), suite.rules.end(), rule) == suite.rules.end()) suite.rules.push_back(rule);
    tests += suite.rules.size();
    failures += report.diagnostics.size();
    suites.push_back(std::move(suite));
  }
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out << fmt::format("<testsuites name=\"asset-lint\" tests=\"{}\" failures=\"{}\" errors=\"0\">\n", tests, failures);
  for (const auto& suite : suites) {
    const FileReport& report = *suite.report;
    const std::string path = xml_escape(report.path);
    out << fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" skipped=\"0\">\n", path,
                       suite.rules.size(), report.diagnostics.size());
    for (const auto& rule : suite.rules) {
      auto it = suite.failures.find(rule);
      if (it == suite.failures.end()) {
        out << fmt::format("    <testcase classname=\"{}\" name=\"{}\"/>\n", path, xml_escape(rule));
        continue;
      }
      out << fmt::format("    <testcase classname=\"{}\" name=\"{}\">\n", path, xml_escape(rule));
      for (const Diagnostic* d : it->second) {
        const std::string& where = diagnostic_path(report, *d);
        const std::string location = where == report.path ? fmt::format("{}:{}", d->span.line, d->span.column)
                                                           : fmt::format("{}:{}:{}", where, d->span.line, d->span.column);
        const std::string notes = notes_text(report, *d);
        const std::string body = notes.empty() ? d->message : d->message + "\n" + notes;
        out << fmt::format("      <failure message=\"{}\" type=\"{}\">{} {}</failure>\n", xml_escape(d->message),
                           severity_name(d->severity), xml_escape(location), xml_escape(body));
      }
      out << "    </testcase>\n";
    }
    out << "  </testsuite>\n";
  }
  out << "</testsuites>\n";
}

}  // namespace assetlint
