#include "config/toml_edit.h"

#include <fmt/format.h>

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>

#include "util/numbers.h"

namespace assetlint::config {
namespace {

// Byte offset where 1-based `line` starts (text size when past the end).
std::size_t line_start(std::string_view text, std::uint32_t line) {
  std::size_t offset = 0;
  for (std::uint32_t l = 1; l < line && offset < text.size(); ++l) {
    const auto next = text.find('\n', offset);
    if (next == std::string_view::npos) return text.size();
    offset = next + 1;
  }
  return offset;
}

std::size_t line_end(std::string_view text, std::size_t offset) {
  const auto next = text.find('\n', offset);
  std::size_t end = next == std::string_view::npos ? text.size() : next;
  if (end > offset && text[end - 1] == '\r') --end;
  return end;
}

std::string quoted_key(std::string_view key) {
  bool bare = !key.empty();
  for (char c : key) bare = bare && (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-');
  if (bare) return std::string(key);
  std::string out = "\"";
  for (char c : key) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

struct Replacement {
  std::size_t offset, length;
  std::string text;
};

}  // namespace

TomlEdit set_table_numbers(std::string_view text, std::string_view table, std::string_view name,
                           const std::vector<TomlValue>& values) {
  TomlEdit edit;
  edit.text = std::string(text);
  const std::string newline = text.find("\r\n") != std::string_view::npos ? "\r\n" : "\n";
  const std::string header = fmt::format("[{}.{}]", quoted_key(table), quoted_key(name));
  toml::table root;
  try {
    root = toml::parse(text);
  } catch (const toml::parse_error& e) {
    edit.error = fmt::format("{}:{}: {}", e.source().begin.line, e.source().begin.column, e.description());
    return edit;
  }
  const toml::node* node = root.at_path(toml::path{}.append(std::string(table)).append(std::string(name))).node();
  if (!node) {
    // A new table at the end of the file.
    std::string added;
    if (!text.empty() && text.back() != '\n') added += newline;
    if (!text.empty()) added += newline;
    added += header + newline;
    for (const TomlValue& v : values) {
      if (!v.add_when_missing) continue;
      added += fmt::format("{} = {}{}", v.key, v.text, newline);
      edit.changes.push_back(fmt::format("{} {} = {}", header, v.key, v.text));
    }
    edit.text += added;
    return edit;
  }
  const toml::table* t = node->as_table();
  const auto& where = node->source().begin;
  if (!t || t->is_inline()) {
    edit.error = fmt::format("{}:{}: {} is not a [table] of its own; change it by hand", where.line, where.column, header);
    return edit;
  }
  const std::size_t header_start = line_start(text, where.line);
  if (trim(text.substr(header_start, line_end(text, header_start) - header_start)).substr(0, 1) != "[") {
    edit.error = fmt::format("{}:{}: {} is defined by dotted keys; change it by hand", where.line, where.column, header);
    return edit;
  }
  std::uint32_t last_line = where.line;
  for (const auto& [key, value] : *t) last_line = std::max(last_line, value.source().end.line);

  std::vector<Replacement> replacements;
  std::string appended;
  for (const TomlValue& v : values) {
    const toml::node* existing = t->get(v.key);
    if (!existing) {
      if (!v.add_when_missing) continue;
      appended += fmt::format("{} = {}{}", v.key, v.text, newline);
      edit.changes.push_back(fmt::format("{} {} = {}", header, v.key, v.text));
      continue;
    }
    const std::size_t start = line_start(text, existing->source().begin.line);
    const std::size_t end = line_end(text, start);
    const std::string_view line = text.substr(start, end - start);
    const auto equals = line.find('=');
    if (equals == std::string_view::npos) {
      edit.error = fmt::format("{}:{}: cannot find the value of '{}'", existing->source().begin.line,
                               existing->source().begin.column, v.key);
      return edit;
    }
    std::size_t value_start = equals + 1;
    while (value_start < line.size() && (line[value_start] == ' ' || line[value_start] == '\t')) ++value_start;
    std::size_t value_end = line.find('#', value_start);
    if (value_end == std::string_view::npos) value_end = line.size();
    while (value_end > value_start && (line[value_end - 1] == ' ' || line[value_end - 1] == '\t')) --value_end;
    const std::string_view old_value = line.substr(value_start, value_end - value_start);
    const auto old_number = parse_double(old_value), new_number = parse_double(v.text);
    if (old_number && new_number && *old_number == *new_number) continue;
    replacements.push_back({start + value_start, value_end - value_start, v.text});
    edit.changes.push_back(fmt::format("{} {} = {} (was {})", header, v.key, v.text, old_value));
  }
  if (!appended.empty()) {
    std::size_t at = line_start(text, last_line + 1);
    if (at == text.size() && !text.empty() && text.back() != '\n') appended = newline + appended;
    replacements.push_back({at, 0, appended});
  }
  std::sort(replacements.begin(), replacements.end(),
            [](const Replacement& a, const Replacement& b) { return a.offset > b.offset; });
  for (const Replacement& r : replacements) edit.text.replace(r.offset, r.length, r.text);
  return edit;
}

}  // namespace assetlint::config
