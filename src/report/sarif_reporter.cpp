#include "report/sarif_reporter.h"

#include <cctype>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "report/rule_docs.h"
#include "report/report_util.h"
#include "report/variant_json.h"
#include "report/summary.h"
#include "rules/registry.h"

namespace assetlint {
namespace {

using nlohmann::ordered_json;

const char* sarif_level(Severity s) {
  switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Info: return "note";
  }
  return "warning";
}

std::string percent_encode(std::string_view path) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (char ch : path) {
    const auto c = static_cast<unsigned char>(ch);
    if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '.' ||
        c == '_' || c == '~' || c == '/') {
      out += ch;
    } else {
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

std::string_view page_of(std::string_view id) {
  for (const auto& [doc_id, page] : rule_docs())
    if (doc_id == id) return page;
  return {};
}

ordered_json message(std::string text) { return ordered_json{{"text", std::move(text)}}; }

// "mimic-max-velocity" -> "MimicMaxVelocity": SARIF's Pascal-case friendly name.
std::string friendly_name(std::string_view id) {
  std::string out;
  bool upper = true;
  for (char c : id) {
    if (c == '-') {
      upper = true;
      continue;
    }
    out += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
    upper = false;
  }
  return out;
}

#ifndef ASSET_LINT_HOMEPAGE
#define ASSET_LINT_HOMEPAGE ""
#endif

}  // namespace

std::string first_paragraph(std::string_view page) {
  std::string out;
  bool in_paragraph = false;
  while (!page.empty()) {
    const std::size_t nl = page.find('\n');
    std::string_view line = page.substr(0, nl);
    page = nl == std::string_view::npos ? std::string_view() : page.substr(nl + 1);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const bool blank = line.find_first_not_of(" \t") == std::string_view::npos;
    if (!in_paragraph) {
      if (blank || line.starts_with("#")) continue;
      in_paragraph = true;
    } else if (blank || line.starts_with("#")) {
      break;
    }
    if (!out.empty()) out += ' ';
    out += line;
  }
  return out;
}

std::string sarif_uri(std::string_view path, std::string_view source_root, bool& relative) {
  namespace fs = std::filesystem;
  const fs::path p = fs::path(path).lexically_normal();
  fs::path rel = p;
  if (p.is_absolute() && !source_root.empty()) rel = p.lexically_relative(fs::path(source_root));
  relative = !rel.empty() && !rel.is_absolute() && *rel.begin() != "..";
  if (relative) return percent_encode(rel.generic_string());
  std::error_code ec;
  fs::path absolute = p.is_absolute() ? p : fs::absolute(p, ec).lexically_normal();
  return "file://" + percent_encode(absolute.generic_string());
}

void write_sarif(std::ostream& out, const std::vector<FileReport>& reports, const SarifOptions& options,
                 const RunProblems& problems) {
  ordered_json rules = ordered_json::array();
  std::map<std::string_view, std::size_t, std::less<>> rule_index;
  for (const RuleInfo* rule : rules::catalog()) {
    rule_index[rule->id] = rules.size();
    const std::string_view page = page_of(rule->id);
    ordered_json descriptor;
    descriptor["id"] = rule->id;
    descriptor["name"] = friendly_name(rule->id);
    descriptor["shortDescription"] = message(std::string(rule->summary));
    const std::string full = first_paragraph(page);
    descriptor["fullDescription"] = message(full.empty() ? std::string(rule->summary) : full);
    if (!page.empty()) descriptor["help"] = {{"text", std::string(page)}, {"markdown", std::string(page)}};
    descriptor["defaultConfiguration"] = {{"level", sarif_level(rule->default_severity)}};
    descriptor["properties"] = {{"tags", ordered_json::array({rule->origin == RuleOrigin::Reader ? "reader" : "physics"})}};
    rules.push_back(std::move(descriptor));
  }

  auto location = [&](const std::string& path) {
    bool relative = false;
    ordered_json artifact{{"uri", sarif_uri(path, options.source_root, relative)}};
    if (relative) artifact["uriBaseId"] = "%SRCROOT%";
    return artifact;
  };

  ordered_json results = ordered_json::array();
  for (const auto& report : reports) {
    for (const auto& d : report.diagnostics) {
      ordered_json result;
      result["ruleId"] = d.rule;
      if (auto it = rule_index.find(d.rule); it != rule_index.end()) result["ruleIndex"] = it->second;
      result["level"] = sarif_level(d.severity);
      if (d.notes.empty() && !d.fix) {
        result["message"] = message(d.message);
      } else {
        // Plain text keeps the primary line first; markdown lists the notes beneath it.
        const std::string body = notes_text(report, d);
        std::string markdown = d.message + "\n";
        for (std::size_t start = 0; start < body.size();) {
          const std::size_t nl = std::min(body.find('\n', start), body.size());
          markdown += "\n- " + body.substr(start, nl - start);
          start = nl + 1;
        }
        result["message"] = {{"text", d.message + "\n" + body}, {"markdown", markdown}};
      }
      ordered_json physical{{"artifactLocation", location(diagnostic_path(report, d))}};
      const auto object = object_path(report, d.span);
      if (d.span.line != 0 && !object) {
        const LineColumn end = end_position(report, d.span);
        physical["region"] = {{"startLine", d.span.line},
                              {"startColumn", d.span.column},
                              {"endLine", end.line},
                              {"endColumn", end.column}};
      }
      ordered_json where{{"physicalLocation", std::move(physical)}};
      // A binary layer has no lines: the prim or property the finding is about.
      if (object) where["logicalLocations"] = ordered_json::array({{{"fullyQualifiedName", *object}, {"kind", "object"}}});
      result["locations"] = ordered_json::array({std::move(where)});
      ordered_json related = ordered_json::array();
      for (const Note& note : d.notes) {
        if (!note.span.valid() || object_path(report, note.span)) continue;
        const LineColumn end = end_position(report, note.span);
        ordered_json region{{"startLine", note.span.line},
                            {"startColumn", note.span.column},
                            {"endLine", end.line},
                            {"endColumn", end.column}};
        related.push_back({{"id", related.size() + 1},
                           {"physicalLocation",
                            {{"artifactLocation", location(note_path(report, note))}, {"region", std::move(region)}}},
                           {"message", message(note.message)}});
      }
      if (!related.empty()) result["relatedLocations"] = std::move(related);
      if (d.fix && d.fix->applicability != Applicability::Display && !d.fix->edits.empty()) {
        // One artifactChange per file, replacements in the fix's order.
        std::vector<FileId> files;
        for (const auto& e : d.fix->edits)
          if (std::find(files.begin(), files.end(), e.file) == files.end()) files.push_back(e.file);
        ordered_json changes = ordered_json::array();
        for (FileId file : files) {
          ordered_json replacements = ordered_json::array();
          for (const auto& e : d.fix->edits) {
            if (e.file != file) continue;
            replacements.push_back({{"deletedRegion", {{"byteOffset", e.offset}, {"byteLength", e.length}}},
                                    {"insertedContent", {{"text", e.replacement}}}});
          }
          const std::string& path = file < report.sources.size() ? report.source(file).path() : report.path;
          changes.push_back({{"artifactLocation", location(path)}, {"replacements", std::move(replacements)}});
        }
        ordered_json fix{{"description", message(d.fix->title)}, {"artifactChanges", std::move(changes)}};
        result["fixes"] = ordered_json::array({std::move(fix)});
        result["properties"] = {{"applicability", applicability_name(d.fix->applicability)}};
      }
      if (auto variants = variants_json(d.message)) result["properties"]["variants"] = std::move(*variants);
      if (!d.consumers.empty()) result["properties"]["consumers"] = d.consumers;
      if (!d.related.empty()) result["properties"]["related"] = d.related;
      results.push_back(std::move(result));
    }
  }

  ordered_json run;
  run["tool"] = {{"driver",
                  {{"name", "asset-lint"}, {"semanticVersion", ASSET_LINT_VERSION}}}};
  // Only a homepage the build was given (-DASSET_LINT_HOMEPAGE=...); none is made up.
  if (std::string_view(ASSET_LINT_HOMEPAGE).size())
    run["tool"]["driver"]["informationUri"] = ASSET_LINT_HOMEPAGE;
  run["tool"]["driver"]["rules"] = std::move(rules);
  if (!options.source_root.empty()) {
    std::string root = "file://" + percent_encode(std::filesystem::path(options.source_root).generic_string());
    if (root.back() != '/') root += '/';
    run["originalUriBaseIds"] = {{"%SRCROOT%", {{"uri", root}}}};
  }
  // The invocation says whether the run looked at everything: each path it could not
  // read is a tool execution notification, and makes the execution unsuccessful.
  ordered_json notifications = ordered_json::array();
  for (const auto& error : problems.errors) {
    notifications.push_back({{"level", "error"},
                             {"message", message(error.message)},
                             {"locations", ordered_json::array({{{"physicalLocation",
                                                                  {{"artifactLocation", location(error.path)}}}}})}});
  }
  ordered_json invocation{{"executionSuccessful", problems.errors.empty()}};
  if (!notifications.empty()) invocation["toolExecutionNotifications"] = std::move(notifications);
  run["invocations"] = ordered_json::array({std::move(invocation)});
  run["columnKind"] = "unicodeCodePoints";
  run["results"] = std::move(results);

  ordered_json doc;
  doc["$schema"] = "https://json.schemastore.org/sarif-2.1.0.json";
  doc["version"] = "2.1.0";
  doc["runs"] = ordered_json::array({std::move(run)});
  out << doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
}

}  // namespace assetlint
