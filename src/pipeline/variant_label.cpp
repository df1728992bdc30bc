#include "pipeline/variant_label.h"

#include <fmt/format.h>

namespace assetlint {
namespace {

// Splits `text` at every `separator`.
std::vector<std::string_view> split(std::string_view text, std::string_view separator) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t at = text.find(separator, start);
    out.push_back(text.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start));
    if (at == std::string_view::npos) return out;
    start = at + separator.size();
  }
}

}  // namespace

std::string selection_label(const VariantSelection& selection) {
  std::string out;
  for (const auto& [set, variant] : selection) out += fmt::format("{}{}={}", out.empty() ? "" : ", ", set, variant);
  return out;
}

std::string variant_prefix(const std::vector<VariantSelection>& selections) {
  std::string joined;
  for (const auto& s : selections) joined += (joined.empty() ? "" : "; ") + selection_label(s);
  return fmt::format("in variant{} {}: ", selections.size() == 1 ? "" : "s", joined);
}

std::vector<VariantSelection> variant_selections(std::string_view message) {
  // USD's set and variant names hold no ':', ';', ',', '=' or space, so the prefix parses back.
  std::string_view rest;
  if (message.starts_with("in variant ")) rest = message.substr(11);
  else if (message.starts_with("in variants ")) rest = message.substr(12);
  else return {};
  const std::size_t end = rest.find(": ");
  if (end == std::string_view::npos) return {};
  std::vector<VariantSelection> out;
  for (std::string_view label : split(rest.substr(0, end), "; ")) {
    VariantSelection selection;
    for (std::string_view choice : split(label, ", ")) {
      const std::size_t eq = choice.find('=');
      if (eq == 0 || eq == std::string_view::npos || choice.find(' ') != std::string_view::npos) return {};
      selection.emplace_back(std::string(choice.substr(0, eq)), std::string(choice.substr(eq + 1)));
    }
    out.push_back(std::move(selection));
  }
  return out;
}

}  // namespace assetlint
