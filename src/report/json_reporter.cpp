#include "report/json_reporter.h"

#include <nlohmann/json.hpp>

#include "report/report_util.h"
#include "report/summary.h"
#include "report/variant_json.h"

namespace assetlint {

void write_json(std::ostream& out, const std::vector<FileReport>& reports, const RunProblems& problems) {
  using nlohmann::ordered_json;
  ordered_json diagnostics = ordered_json::array();
  for (const auto& report : reports) {
    for (const auto& d : report.diagnostics) {
      const LineColumn end = end_position(report, d.span);
      ordered_json item;
      item["file"] = d.span.file < report.sources.size() ? report.source(d.span.file).path() : report.path;
      if (auto object = object_path(report, d.span)) {
        // A binary layer has no lines: the object the finding is about instead.
        item["object_path"] = *object;
      } else {
        item["line"] = d.span.line;
        item["column"] = d.span.column;
        item["end_line"] = end.line;
        item["end_column"] = end.column;
      }
      item["rule"] = d.rule;
      item["severity"] = severity_name(d.severity);
      item["message"] = d.message;
      if (auto variants = variants_json(d.message)) item["variants"] = std::move(*variants);
      // v1 added `notes` (each with an optional location); the fields above are unchanged.
      ordered_json notes = ordered_json::array();
      for (const Note& note : d.notes) {
        ordered_json entry{{"message", note.message}};
        if (note.span.valid()) {
          entry["file"] = note_path(report, note);
          if (auto object = object_path(report, note.span)) {
            entry["object_path"] = *object;
          } else {
            entry["line"] = note.span.line;
            entry["column"] = note.span.column;
          }
        }
        notes.push_back(std::move(entry));
      }
      item["notes"] = std::move(notes);
      // Present only when set: the consumers a consumer-specific finding concerns, and the
      // requirements of other checkers (SimReady) that state the same verdict.
      if (!d.consumers.empty()) item["consumers"] = d.consumers;
      if (!d.related.empty()) item["related"] = d.related;
      if (d.fix) {
        ordered_json edits = ordered_json::array();
        for (const auto& e : d.fix->edits) {
          const LineColumn at = e.file < report.sources.size() ? report.source(e.file).position(e.offset) : LineColumn{};
          ordered_json edit;
          if (e.file != d.span.file && e.file < report.sources.size()) edit["file"] = report.source(e.file).path();
          edit["offset"] = e.offset;
          edit["length"] = e.length;
          edit["replacement"] = e.replacement;
          edit["line"] = at.line;
          edit["column"] = at.column;
          edits.push_back(std::move(edit));
        }
        item["fix"] = {{"title", d.fix->title},
                       {"applicability", applicability_name(d.fix->applicability)},
                       {"edits", std::move(edits)}};
      }
      diagnostics.push_back(std::move(item));
    }
  }
  const Summary s = summarize(reports);
  ordered_json doc;
  doc["version"] = 1;
  doc["tool"] = {{"name", "asset-lint"}, {"version", ASSET_LINT_VERSION}};
  doc["diagnostics"] = std::move(diagnostics);
  // Paths the run could not read (the run exits 2): each with its path and message.
  ordered_json errors = ordered_json::array();
  for (const auto& error : problems.errors) errors.push_back({{"path", error.path}, {"message", error.message}});
  doc["errors"] = std::move(errors);
  doc["summary"] = {{"files", s.files},     {"problems", s.total()},  {"errors", s.errors},
                    {"warnings", s.warnings}, {"infos", s.infos},      {"fixable", s.fixable},
                    {"unsafe_fixable", s.unsafe_fixable}, {"not_read", problems.errors.size()},
                    {"skipped_binary_usd", problems.binary_usd}};
  out << doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
}

}  // namespace assetlint
