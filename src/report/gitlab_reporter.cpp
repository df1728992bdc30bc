#include "report/gitlab_reporter.h"

#include <fmt/format.h>

#include <map>
#include <nlohmann/json.hpp>
#include <tuple>

#include "report/report_util.h"

namespace assetlint {
namespace {

// GitLab's scale is info, minor, major, critical, blocker.
const char* gitlab_severity(Severity s) {
  switch (s) {
    case Severity::Error: return "major";
    case Severity::Warning: return "minor";
    case Severity::Info: return "info";
  }
  return "minor";
}

std::uint64_t fnv1a(std::string_view text, std::uint64_t hash) {
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ULL;
  }
  return hash;
}

}  // namespace

std::string gitlab_fingerprint(std::string_view rule, std::string_view path, std::string_view message,
                               std::size_t occurrence) {
  // Fields separated by a byte no path or message holds, so that no two keys run together.
  const std::string key = fmt::format("{}\x1f{}\x1f{}\x1f{}", rule, path, message, occurrence);
  return fmt::format("{:016x}{:016x}", fnv1a(key, 14695981039346656037ULL), fnv1a(key, 0x9E3779B97F4A7C15ULL));
}

void write_gitlab(std::ostream& out, const std::vector<FileReport>& reports) {
  using nlohmann::ordered_json;
  ordered_json issues = ordered_json::array();
  std::map<std::tuple<std::string, std::string, std::string>, std::size_t> seen;
  for (const auto& report : reports) {
    for (const auto& d : report.diagnostics) {
      const std::string& path = diagnostic_path(report, d);
      const std::size_t occurrence = seen[{d.rule, path, d.message}]++;
      ordered_json issue;
      issue["type"] = "issue";
      const auto object = object_path(report, d.span);
      // A binary layer has no lines: line 1, with the object the finding is about in the description.
      issue["description"] = object ? "<" + *object + "> " + d.message : d.message;
      issue["check_name"] = d.rule;
      issue["fingerprint"] = gitlab_fingerprint(d.rule, path, d.message, occurrence);
      issue["severity"] = gitlab_severity(d.severity);
      issue["location"] = {{"path", path}, {"lines", {{"begin", object ? 1u : d.span.line}}}};
      issues.push_back(std::move(issue));
    }
  }
  out << issues.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
}

}  // namespace assetlint
