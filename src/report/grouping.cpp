#include "report/grouping.h"

#include <map>
#include <string>
#include <tuple>

namespace assetlint {
namespace {

// The text with every '…' quotation replaced by a placeholder.
std::string without_quoted_names(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto close = text[i] == '\'' ? text.find('\'', i + 1) : std::string::npos;
    if (close == std::string::npos) {
      out += text[i];
      continue;
    }
    out += "'…'";
    i = close;
  }
  return out;
}

std::string group_key(const Diagnostic& d) {
  std::string key = d.rule + '\n' + std::to_string(static_cast<int>(d.severity)) + '\n' + without_quoted_names(d.message);
  for (const Note& note : d.notes) key += '\n' + without_quoted_names(note.message);
  if (d.fix) key += "\nfix " + without_quoted_names(d.fix->title);
  return key;
}

}  // namespace

std::string first_quoted(const std::string& message) {
  const auto open = message.find('\'');
  if (open == std::string::npos) return {};
  const auto close = message.find('\'', open + 1);
  return close == std::string::npos ? std::string() : message.substr(open + 1, close - open - 1);
}

std::vector<FindingGroup> group_identical(const std::vector<Diagnostic>& diagnostics) {
  std::vector<FindingGroup> groups;
  std::map<std::string, std::size_t> by_key;
  for (std::size_t i = 0; i < diagnostics.size(); ++i) {
    const auto [it, fresh] = by_key.try_emplace(group_key(diagnostics[i]), groups.size());
    if (fresh) groups.push_back({i, {}});
    else groups[it->second].others.push_back(i);
  }
  return groups;
}

}  // namespace assetlint
