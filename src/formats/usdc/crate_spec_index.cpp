#include "formats/usdc/crate_spec_index.h"

#include <array>

namespace assetlint::usdc {
namespace {

// What a path element is spelled with.
enum class Spelling : std::uint8_t { Plain, Variant, Bracketed, Other };

// Characters that delimit path elements ('/', '.', '{', '}'), and brackets.
constexpr auto kDelimiters = [] {
  std::array<std::uint8_t, 256> t{};
  for (const unsigned char c : std::string_view("/.{}")) t[c] = 1;
  t['['] = t[']'] = 2;
  return t;
}();

Spelling spelling(std::string_view name) {
  unsigned seen = 0;
  for (const char c : name) seen |= kDelimiters[static_cast<unsigned char>(c)];
  // Paths under a relationship target (`/a.rel[/b]`, `/a.rel[/b].x`) are spelled with
  // brackets, which no looked-up name holds: they cannot be mistaken for one.
  if (seen & 2) return Spelling::Bracketed;
  if (seen == 0) return name.empty() ? Spelling::Other : Spelling::Plain;
  if (name.size() < 2 || name.front() != '{' || name.back() != '}') return Spelling::Other;
  for (const char c : name.substr(1, name.size() - 2))
    if (kDelimiters[static_cast<unsigned char>(c)]) return Spelling::Other;
  return Spelling::Variant;
}

}  // namespace

bool SpecIndex::is_element(std::string_view name, bool property) {
  const Spelling s = spelling(name);
  return s == Spelling::Plain || (!property && s == Spelling::Variant);
}

std::uint64_t SpecIndex::name_hash(std::string_view name) {
  // FNV-1a: names are short.
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const char c : name) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
  return h;
}

std::size_t SpecIndex::slot(std::uint64_t name_hash, std::uint32_t parent, bool property) const {
  std::uint64_t h = (name_hash ^ (std::uint64_t{parent} << 1 | (property ? 1u : 0u))) * 0x9E3779B97F4A7C15ull;
  return static_cast<std::size_t>(h >> 32) & (slots_.size() - 1);
}

bool SpecIndex::insert(const CrateFile& file, std::uint32_t path, std::uint64_t name_hash) {
  const PathEntry& e = file.paths()[path];
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t i = slot(name_hash, e.parent, e.property);; i = (i + 1) & mask) {
    Slot& s = slots_[i];
    if (s.path == kEmpty) {
      s = {path, e.parent};
      return true;
    }
    const PathEntry& other = file.paths()[s.path];
    if (s.parent == e.parent && other.property == e.property && other.name == e.name) return false;
  }
}

std::optional<SpecIndex> SpecIndex::build(const CrateFile& file) {
  const std::vector<PathEntry>& paths = file.paths();
  SpecIndex index;
  index.file_ = &file;
  std::size_t size = 16;
  while (size < paths.size() * 2) size *= 2;
  index.slots_.resize(size);
  // Whether each path is spelled with brackets (its name or an ancestor's): 0 not yet known.
  std::vector<char> bracketed(paths.size(), 0);
  std::vector<std::uint32_t> chain;
  // A property name recurs on every prim that has it: spelled and hashed once per token.
  struct TokenFacts {
    bool known = false;
    Spelling spelling = Spelling::Other;
    std::uint64_t hash = 0;
  };
  std::vector<TokenFacts> tokens;
  for (std::uint32_t i = 0; i < paths.size(); ++i) {
    const PathEntry& e = paths[i];
    if (!e.valid) continue;
    if (e.parent == i) {
      if (index.root_ != kEmpty) return std::nullopt;  // two roots, both spelled "/"
      index.root_ = i;
      bracketed[i] = 2;
    }
  }
  for (std::uint32_t i = 0; i < paths.size(); ++i) {
    if (!paths[i].valid || bracketed[i]) continue;
    // Up to the nearest path already known (the tree has no cycles: read_paths).
    chain.clear();
    std::uint32_t p = i;
    while (!bracketed[p]) {
      chain.push_back(p);
      p = paths[p].parent;
    }
    bool under = bracketed[p] == 1;
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      const PathEntry& e = paths[*it];
      if (e.token >= tokens.size()) tokens.resize(e.token + 1);
      TokenFacts& t = tokens[e.token];
      if (!t.known) t = {true, spelling(e.name), name_hash(e.name)};
      const Spelling s = t.spelling;
      under = under || s == Spelling::Bracketed;
      bracketed[*it] = under ? 1 : 2;
      if (under) continue;
      if (s == Spelling::Other || (e.property && s != Spelling::Plain)) return std::nullopt;
      if (!index.insert(file, *it, t.hash)) return std::nullopt;  // two children spelled alike
    }
  }
  index.spec_of_path_.assign(paths.size(), kEmpty);
  for (std::size_t s = 0; s < file.specs().size(); ++s) index.spec_of_path_[file.specs()[s].path] = static_cast<std::uint32_t>(s);
  return index;
}

std::optional<SpecAt> SpecIndex::at(std::uint32_t path) const {
  if (path == kEmpty || spec_of_path_[path] == kEmpty) return std::nullopt;
  return SpecAt{path, spec_of_path_[path]};
}

std::optional<SpecAt> SpecIndex::child(std::uint32_t parent, std::string_view name, bool property) const {
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t i = slot(name_hash(name), parent, property);; i = (i + 1) & mask) {
    const Slot& s = slots_[i];
    if (s.path == kEmpty) return std::nullopt;
    const PathEntry& e = file_->paths()[s.path];
    if (s.parent == parent && e.property == property && e.name == name) return at(s.path);
  }
}

}  // namespace assetlint::usdc
