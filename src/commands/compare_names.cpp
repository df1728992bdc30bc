#include "commands/compare_names.h"

#include <algorithm>
#include <cctype>
#include <functional>
#include <map>

namespace assetlint::commands {
namespace {

using Key = std::function<std::string(const std::string&)>;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// The prefix every name shares, cut after its last separator ('_', '-', '.').
std::string common_prefix(const std::vector<std::string>& names) {
  if (names.size() < 2) return {};
  std::string prefix = names.front();
  for (const auto& n : names) {
    std::size_t i = 0;
    while (i < prefix.size() && i < n.size() && prefix[i] == n[i]) ++i;
    prefix.resize(i);
  }
  const auto cut = prefix.find_last_of("_-.");
  return cut == std::string::npos ? std::string() : prefix.substr(0, cut + 1);
}

std::string stripped(const std::string& name, const std::string& prefix) {
  std::string s = lower(last_component(name));
  if (!prefix.empty() && s.starts_with(prefix) && s.size() > prefix.size()) s = s.substr(prefix.size());
  for (const char* suffix : {"_joint", "_link", "_body", "_jnt", "joint", "link"}) {
    const std::string_view sv(suffix);
    if (s.size() > sv.size() && s.ends_with(sv)) {
      s.resize(s.size() - sv.size());
      break;
    }
  }
  while (!s.empty() && (s.back() == '_' || s.back() == '-')) s.pop_back();
  return s;
}

void pair_by(const std::vector<std::string>& a, const std::vector<std::string>& b, const Key& key_a, const Key& key_b,
             std::vector<bool>& used_a, std::vector<bool>& used_b, NameMatch& out) {
  std::map<std::string, std::vector<std::size_t>> in_a, in_b;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!used_a[i]) in_a[key_a(a[i])].push_back(i);
  for (std::size_t j = 0; j < b.size(); ++j)
    if (!used_b[j]) in_b[key_b(b[j])].push_back(j);
  for (const auto& [key, list] : in_a) {
    if (key.empty() || list.size() != 1) continue;
    auto it = in_b.find(key);
    if (it == in_b.end() || it->second.size() != 1) continue;
    out.pairs.emplace_back(list.front(), it->second.front());
    used_a[list.front()] = used_b[it->second.front()] = true;
  }
}

}  // namespace

std::string last_component(const std::string& name) {
  const auto cut = name.find_last_of('/');
  return cut == std::string::npos ? name : name.substr(cut + 1);
}

NameMatch match_names(const std::vector<std::string>& a, const std::vector<std::string>& b,
                      const std::vector<std::pair<std::string, std::string>>& map) {
  NameMatch out;
  std::vector<bool> used_a(a.size(), false), used_b(b.size(), false);
  auto named = [](const std::vector<std::string>& names, const std::vector<bool>& used, const std::string& wanted) {
    for (std::size_t i = 0; i < names.size(); ++i)
      if (!used[i] && (names[i] == wanted || last_component(names[i]) == wanted)) return i;
    return names.size();
  };
  for (const auto& [from, to] : map) {
    const std::size_t i = named(a, used_a, from), j = named(b, used_b, to);
    if (i == a.size() || j == b.size()) continue;
    out.pairs.emplace_back(i, j);
    used_a[i] = used_b[j] = true;
  }
  const Key same = [](const std::string& s) { return s; };
  pair_by(a, b, same, same, used_a, used_b, out);
  const Key last = [](const std::string& s) { return last_component(s); };
  pair_by(a, b, last, last, used_a, used_b, out);
  auto lasts = [](const std::vector<std::string>& names) {
    std::vector<std::string> out;
    for (const auto& n : names) out.push_back(lower(last_component(n)));
    return out;
  };
  const std::string prefix_a = common_prefix(lasts(a)), prefix_b = common_prefix(lasts(b));
  pair_by(a, b, [&](const std::string& s) { return stripped(s, prefix_a); },
          [&](const std::string& s) { return stripped(s, prefix_b); }, used_a, used_b, out);
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!used_a[i]) out.only_a.push_back(i);
  for (std::size_t j = 0; j < b.size(); ++j)
    if (!used_b[j]) out.only_b.push_back(j);
  std::sort(out.pairs.begin(), out.pairs.end());
  return out;
}

}  // namespace assetlint::commands
