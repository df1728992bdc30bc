#include "report/grouping.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <tuple>

#include "report/report_util.h"

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

// The text with every place written as file:line:column ("called at arm.xacro:36:5") masked.
std::string without_places(const std::string& text) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t word_end = std::min(text.find_first_of(" \t\n,;()", i), text.size());
    const std::string word = text.substr(i, word_end - i);
    const auto last = word.rfind(':');
    const auto middle = last == std::string::npos || last == 0 ? std::string::npos : word.rfind(':', last - 1);
    const auto digits = [&](std::size_t from, std::size_t to) {
      return from < to && word.find_first_not_of("0123456789", from) >= to;
    };
    const bool place = middle != std::string::npos && middle > 0 && digits(middle + 1, last) &&
                       digits(last + 1, word.size() - (word.ends_with('.') ? 1 : 0));
    out += place ? "…" : word;
    if (word_end < text.size()) out += text[word_end];
    i = word_end + 1;
  }
  return out;
}

// Notes that say only where a finding was written (a xacro macro's call chain), or that its
// fix travels with another finding's (one xacro literal for both), tell nothing new.
constexpr std::string_view kFixElsewhere = "The fix of this finding rewrites the same xacro literal.";
bool place_only(const Note& note) {
  return (note.message.starts_with("in macro '") && note.message.find("' called at ") != std::string::npos) ||
         note.message == kFixElsewhere;
}

// The finding whose fix this one's travels with (the note points at it), if any.
const Note* fix_elsewhere(const Diagnostic& d) {
  for (const Note& note : d.notes)
    if (note.message == kFixElsewhere) return &note;
  return nullptr;
}

// Rule, severity, words and notes, places and quoted names left out; the fix is not in it.
std::string base_key(const Diagnostic& d) {
  std::string key = d.rule + '\n' + std::to_string(static_cast<int>(d.severity)) + '\n' + without_quoted_names(d.message);
  for (const Note& note : d.notes)
    if (!place_only(note)) key += '\n' + without_places(without_quoted_names(note.message));
  return key;
}

}  // namespace

std::string same_on_more(const FileReport& report, const FindingGroup& group) {
  const std::vector<Diagnostic>& diagnostics = report.diagnostics;
  constexpr std::size_t kListed = 6;
  const FileId first_file = diagnostics[group.first].span.file;
  std::string places;
  for (std::size_t k = 0; k < group.others.size() && k < kListed; ++k) {
    const Diagnostic& d = diagnostics[group.others[k]];
    const std::string name = first_quoted(d.message);
    const auto object = object_path(report, d.span);
    std::string at = object ? "<" + *object + ">" : fmt::format("{}:{}", d.span.line, d.span.column);
    if (!object && d.span.file != first_file)
      at = fmt::format("{}:{}", std::filesystem::path(diagnostic_path(report, d)).filename().string(), at);
    places += fmt::format("{}{}{}{}", k ? ", " : "", name.empty() ? "" : "'" + name + "' (", at, name.empty() ? "" : ")");
  }
  if (group.others.size() > kListed) places += ", …";
  return fmt::format("and the same on {} more: {}", group.others.size(), places);
}

std::string first_quoted(const std::string& message) {
  const auto open = message.find('\'');
  if (open == std::string::npos) return {};
  const auto close = message.find('\'', open + 1);
  return close == std::string::npos ? std::string() : message.substr(open + 1, close - open - 1);
}

std::vector<FindingGroup> group_identical(const std::vector<Diagnostic>& diagnostics) {
  std::vector<FindingGroup> groups;
  std::vector<std::string> bases;  // each group's first's base key
  std::map<std::string, std::size_t> by_key;
  for (std::size_t i = 0; i < diagnostics.size(); ++i) {
    const Diagnostic& d = diagnostics[i];
    const std::string base = base_key(d);
    // A finding whose fix another carries (one xacro literal for both) joins that one's group.
    if (const Note* carrier = fix_elsewhere(d)) {
      const auto group = std::find_if(groups.begin(), groups.end(), [&](const FindingGroup& g) {
        const Span& at = diagnostics[g.first].span;
        return bases[&g - groups.data()] == base && at.file == carrier->span.file && at.offset == carrier->span.offset;
      });
      if (group != groups.end()) {
        group->others.push_back(i);
        continue;
      }
    }
    const std::string key = base + (d.fix ? "\nfix " + without_quoted_names(d.fix->title) : std::string());
    const auto [it, fresh] = by_key.try_emplace(key, groups.size());
    if (fresh) {
      groups.push_back({i, {}});
      bases.push_back(base);
    } else {
      groups[it->second].others.push_back(i);
    }
  }
  return groups;
}

}  // namespace assetlint
