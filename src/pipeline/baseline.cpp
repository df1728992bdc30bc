#include "pipeline/baseline.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <tuple>

#include "formats/locator.h"

namespace assetlint {
namespace {

namespace fs = std::filesystem;

using Key = std::tuple<std::string, std::string, std::string, std::string>;  // path, element, attribute, rule

Key key_of(const BaselineEntry& e) { return {e.path, e.element, e.attribute, e.rule}; }

std::string relative_path(const std::string& path, const fs::path& directory) {
  std::error_code ec;
  const fs::path file = fs::weakly_canonical(fs::absolute(path, ec), ec);
  const fs::path base = fs::weakly_canonical(fs::absolute(directory, ec), ec);
  const fs::path relative = file.lexically_relative(base);
  return (relative.empty() ? file : relative).generic_string();
}

// The key of every finding of a report, in order; each source's structure is read once.
std::vector<Key> keys_of(const FileReport& report, const fs::path& directory) {
  std::map<FileId, std::unique_ptr<SourceLocator>> locators;
  std::map<FileId, std::string> paths;
  std::vector<Key> keys;
  for (const Diagnostic& d : report.diagnostics) {
    const FileId file = d.span.file == kNoFile || d.span.file >= report.sources.size() ? kNoFile : d.span.file;
    if (file == kNoFile) {
      keys.emplace_back(relative_path(report.path, directory), "", "", d.rule);
      continue;
    }
    auto& locator = locators[file];
    if (!locator) {
      locator = std::make_unique<SourceLocator>(report.source(file));
      paths[file] = relative_path(report.source(file).path(), directory);
    }
    ElementKey key = locator->key_at(d.span.offset);
    keys.emplace_back(paths[file], std::move(key.element), std::move(key.attribute), d.rule);
  }
  return keys;
}

}  // namespace

bool BaselineEntry::same_key(const BaselineEntry& other) const { return key_of(*this) == key_of(other); }

std::string BaselineEntry::to_string() const {
  std::string where = element;
  if (!attribute.empty()) where += (where.empty() ? "" : " ") + attribute;
  return fmt::format("{}: {}[{}]{}", path, where.empty() ? "" : where + " ", rule,
                     count > 1 ? fmt::format(" ×{}", count) : "");
}

std::vector<BaselineEntry> baseline_entries(const std::vector<FileReport>& reports, const fs::path& directory) {
  std::map<Key, std::size_t> counts;
  for (const auto& report : reports)
    for (auto& key : keys_of(report, directory)) ++counts[std::move(key)];
  std::vector<BaselineEntry> entries;
  for (const auto& [key, count] : counts)
    entries.push_back(BaselineEntry{std::get<0>(key), std::get<1>(key), std::get<2>(key), std::get<3>(key), count});
  return entries;
}

std::string baseline_text(const std::vector<BaselineEntry>& entries) {
  nlohmann::ordered_json findings = nlohmann::ordered_json::array();
  for (const auto& e : entries) {
    nlohmann::ordered_json item;
    item["path"] = e.path;
    item["element"] = e.element;
    item["attribute"] = e.attribute;
    item["rule"] = e.rule;
    item["count"] = e.count;
    findings.push_back(std::move(item));
  }
  nlohmann::ordered_json document;
  document["asset-lint-baseline"] = 1;
  document["findings"] = std::move(findings);
  return document.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::optional<std::vector<BaselineEntry>> read_baseline(const std::string& path, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = fmt::format("cannot read baseline '{}'", path);
    return std::nullopt;
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  const auto document = nlohmann::json::parse(buffer.str(), nullptr, false);
  const auto bad = [&](const std::string& why) {
    error = fmt::format("'{}' is not an asset-lint baseline: {}", path, why);
    return std::nullopt;
  };
  if (document.is_discarded()) return bad("it is not JSON");
  if (!document.is_object() || document.value("asset-lint-baseline", 0) != 1 || !document.contains("findings") ||
      !document["findings"].is_array())
    return bad("expected {\"asset-lint-baseline\": 1, \"findings\": [...]}");
  std::vector<BaselineEntry> entries;
  for (const auto& item : document["findings"]) {
    const auto text = [&](const char* field) -> std::optional<std::string> {
      if (!item.is_object() || !item.contains(field) || !item[field].is_string()) return std::nullopt;
      return item[field].get<std::string>();
    };
    auto file = text("path"), element = text("element"), attribute = text("attribute"), rule = text("rule");
    if (!file || !element || !attribute || !rule || !item.contains("count") || !item["count"].is_number_unsigned())
      return bad(fmt::format("entry {} needs path, element, attribute, rule (strings) and count", entries.size() + 1));
    entries.push_back(BaselineEntry{*file, *element, *attribute, *rule, item["count"].get<std::size_t>()});
  }
  return entries;
}

BaselineMatch apply_baseline(std::vector<FileReport>& reports, const std::vector<BaselineEntry>& baseline,
                             const fs::path& directory) {
  std::map<Key, std::size_t> remaining;
  for (const auto& e : baseline) remaining[key_of(e)] += e.count;
  BaselineMatch match;
  std::set<std::string> checked;  // paths (as keys spell them) this run read
  for (auto& report : reports) {
    checked.insert(relative_path(report.path, directory));
    for (const auto& source : report.sources) checked.insert(relative_path(source->path(), directory));
    const std::vector<Key> keys = keys_of(report, directory);
    std::size_t i = 0;
    std::erase_if(report.diagnostics, [&](const Diagnostic&) {
      auto it = remaining.find(keys[i++]);
      if (it == remaining.end() || it->second == 0) return false;
      --it->second;
      ++match.matched;
      return true;
    });
  }
  for (const auto& [key, count] : remaining)
    if (count > 0 && checked.contains(std::get<0>(key)))
      match.stale.push_back(BaselineEntry{std::get<0>(key), std::get<1>(key), std::get<2>(key), std::get<3>(key), count});
  return match;
}

}  // namespace assetlint
