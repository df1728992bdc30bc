#include "formats/usdc/crate_file.h"

#include <fmt/format.h>
#include <lz4.h>

#include <algorithm>
#include <cstring>
#include <limits>

namespace assetlint::usdc {
namespace {

// LZ4's largest block; crate splits bigger buffers into chunks of this size.
constexpr std::size_t kMaxChunk = 0x7E000000;
// LZ4 expands at most ~255 times; a claimed size beyond that is a lie (or a bomb).
constexpr std::uint64_t kMaxExpansion = 256;
constexpr std::uint64_t kMaxBuffer = std::uint64_t{1} << 30;
// Paths deeper than this are refused (the text writer and the parser nest per prim).
constexpr std::size_t kMaxPathDepth = 128;
constexpr std::uint32_t kNoField = std::numeric_limits<std::uint32_t>::max();

std::uint64_t decompressed_bound(std::uint64_t compressed) {
  return std::min<std::uint64_t>(kMaxBuffer, compressed * kMaxExpansion + 1024);
}

template <class Int>
std::vector<Int> decode_ints(std::string_view data, std::size_t n, const Cursor& where) {
  using SInt = std::make_signed_t<Int>;
  using Small = std::conditional_t<sizeof(Int) == 4, std::int8_t, std::int16_t>;
  using Medium = std::conditional_t<sizeof(Int) == 4, std::int16_t, std::int32_t>;
  std::vector<Int> out(n);
  if (n == 0) return out;
  const std::size_t codes_bytes = (n * 2 + 7) / 8;
  if (data.size() < sizeof(SInt) + codes_bytes) where.fail("compressed integers: the codes are cut short");
  SInt common;
  std::memcpy(&common, data.data(), sizeof common);
  const char* codes = data.data() + sizeof(SInt);
  std::size_t vpos = sizeof(SInt) + codes_bytes;
  auto take = [&](auto tag) {
    using T = decltype(tag);
    if (data.size() - vpos < sizeof(T)) where.fail("compressed integers: the values are cut short");
    T v;
    std::memcpy(&v, data.data() + vpos, sizeof v);
    vpos += sizeof v;
    return static_cast<SInt>(v);
  };
  // Deltas wrap as the writer's integers do.
  using U = std::make_unsigned_t<SInt>;
  U prev = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned code = (static_cast<unsigned char>(codes[i / 4]) >> (2 * (i % 4))) & 3;
    SInt delta = 0;
    switch (code) {
      case 0: delta = common; break;
      case 1: delta = take(Small{}); break;
      case 2: delta = take(Medium{}); break;
      default: delta = take(SInt{}); break;
    }
    prev += static_cast<U>(delta);
    out[i] = static_cast<Int>(prev);
  }
  return out;
}

template <class Int>
std::vector<Int> read_compressed(Cursor& c, std::size_t n) {
  const std::uint64_t size = c.read<std::uint64_t>();
  if (size > c.remaining()) c.fail(fmt::format("compressed integers: {} bytes claimed, {} left in the file", size, c.remaining()));
  const std::string_view compressed = c.take(static_cast<std::size_t>(size));
  if (n == 0) return {};
  const std::uint64_t need = sizeof(Int) + (std::uint64_t{n} * 2 + 7) / 8;
  if (need > decompressed_bound(size))
    c.fail(fmt::format("{} compressed integers claimed in {} bytes", n, size));
  const std::size_t capacity = sizeof(Int) + (n * 2 + 7) / 8 + n * sizeof(Int);
  std::string work(capacity, '\0');
  const std::size_t got = decompress(compressed, work.data(), work.size(), c);
  return decode_ints<Int>(std::string_view(work.data(), got), n, c);
}

}  // namespace

void fail(std::string section, std::string message) { throw CrateError{std::move(section), std::move(message)}; }

bool is_crate(std::string_view bytes) { return bytes.starts_with(kCrateMagic); }

std::string Version::text() const { return fmt::format("{}.{}.{}", major, minor, patch); }

void Cursor::fail(const std::string& message) const { usdc::fail(section_, message); }

void Cursor::seek(std::uint64_t offset) {
  if (offset > bytes_.size()) fail(fmt::format("offset {} is past the end of the file ({} bytes)", offset, bytes_.size()));
  pos_ = static_cast<std::size_t>(offset);
}

void Cursor::read_bytes(void* out, std::size_t n) {
  if (n > remaining()) fail(fmt::format("{} bytes needed at offset {}, the file ends after {}", n, pos_, remaining()));
  std::memcpy(out, bytes_.data() + pos_, n);
  pos_ += n;
}

std::string_view Cursor::take(std::size_t n) {
  if (n > remaining()) fail(fmt::format("{} bytes needed at offset {}, the file ends after {}", n, pos_, remaining()));
  const std::string_view s = bytes_.substr(pos_, n);
  pos_ += n;
  return s;
}

std::size_t Cursor::count(std::uint64_t n, std::size_t item_size, const char* what) {
  if (item_size != 0 && n > remaining() / item_size)
    fail(fmt::format("{} {} claimed at offset {}, only {} bytes left", n, what, pos_, remaining()));
  return static_cast<std::size_t>(n);
}

std::size_t decompress(std::string_view compressed, char* out, std::size_t capacity, const Cursor& where) {
  if (compressed.empty()) where.fail("empty compressed block");
  const unsigned chunks = static_cast<unsigned char>(compressed[0]);
  std::size_t pos = 1, written = 0;
  const auto block = [&](std::size_t size) {
    if (size > compressed.size() - pos) where.fail("compressed chunk runs past its section");
    const std::size_t room = std::min(capacity - written, kMaxChunk);
    const int n = LZ4_decompress_safe(compressed.data() + pos, out + written, static_cast<int>(size), static_cast<int>(room));
    if (n < 0) where.fail(fmt::format("LZ4 data is corrupt (error {})", n));
    pos += size;
    written += static_cast<std::size_t>(n);
  };
  if (chunks == 0) {
    if (compressed.size() - 1 > kMaxChunk) where.fail("compressed block too large");
    block(compressed.size() - 1);
    return written;
  }
  for (unsigned i = 0; i < chunks; ++i) {
    std::int32_t size = 0;
    if (compressed.size() - pos < sizeof size) where.fail("compressed chunk header cut short");
    std::memcpy(&size, compressed.data() + pos, sizeof size);
    pos += sizeof size;
    if (size < 0) where.fail("negative compressed chunk size");
    block(static_cast<std::size_t>(size));
  }
  return written;
}

std::vector<std::uint32_t> read_compressed_u32(Cursor& c, std::size_t n) { return read_compressed<std::uint32_t>(c, n); }
std::vector<std::int32_t> read_compressed_i32(Cursor& c, std::size_t n) { return read_compressed<std::int32_t>(c, n); }
std::vector<std::int64_t> read_compressed_i64(Cursor& c, std::size_t n) { return read_compressed<std::int64_t>(c, n); }

CrateFile::CrateFile(std::string_view bytes) : bytes_(bytes) {
  Cursor boot(bytes, "bootstrap");
  constexpr std::size_t kBootStrapSize = 8 + 8 + 8 + 64;
  if (bytes.size() < kBootStrapSize)
    boot.fail(fmt::format("the file has {} bytes, fewer than the {}-byte crate header", bytes.size(), kBootStrapSize));
  if (!is_crate(bytes)) boot.fail("the file does not start with 'PXR-USDC'");
  boot.seek(8);
  version_.major = boot.read<std::uint8_t>();
  version_.minor = boot.read<std::uint8_t>();
  version_.patch = boot.read<std::uint8_t>();
  const auto rank = [](const Version& v) { return v.major * 65536 + v.minor * 256 + v.patch; };
  if (rank(version_) < rank(kOldestReadable) || version_.major != kNewestReadable.major ||
      version_.minor > kNewestReadable.minor)
    boot.fail(fmt::format("crate version {} is not supported (asset-lint reads versions {} to {}.x; re-save the layer "
                          "with a newer OpenUSD, or export it as USDA)",
                          version_.text(), kOldestReadable.text(), kNewestReadable.text().substr(0, 4)));
  boot.seek(16);
  const auto toc = boot.read<std::int64_t>();
  if (toc < static_cast<std::int64_t>(kBootStrapSize) || static_cast<std::uint64_t>(toc) >= bytes.size())
    boot.fail(fmt::format("the table of contents is at offset {}, outside the file ({} bytes; truncated?)", toc,
                          bytes.size()));
  Cursor c(bytes, "table of contents");
  c.seek(static_cast<std::uint64_t>(toc));
  const std::size_t n = c.count(c.read<std::uint64_t>(), 32, "sections");
  for (std::size_t i = 0; i < n; ++i) {
    char name[16];
    c.read_bytes(name, sizeof name);
    Section s;
    s.name.assign(name, strnlen(name, sizeof name));
    const auto start = c.read<std::int64_t>(), size = c.read<std::int64_t>();
    if (start < 0 || size < 0 || static_cast<std::uint64_t>(start) > bytes.size() ||
        static_cast<std::uint64_t>(size) > bytes.size() - static_cast<std::uint64_t>(start))
      c.fail(fmt::format("section '{}' ({} bytes at offset {}) lies outside the file ({} bytes)", s.name, size, start,
                         bytes.size()));
    s.start = static_cast<std::uint64_t>(start);
    s.size = static_cast<std::uint64_t>(size);
    sections_.push_back(std::move(s));
  }
  read_tokens();
  read_strings();
  read_fields();
  read_field_sets();
  read_paths();
  read_specs();
}

const CrateFile::Section* CrateFile::section(std::string_view name) const {
  for (const Section& s : sections_)
    if (s.name == name) return &s;
  return nullptr;
}

Cursor CrateFile::open(std::string_view name, const char* label) const {
  const Section* s = section(name);
  if (!s) usdc::fail(label, "the section is missing from the table of contents");
  // Reads stay inside the section.
  Cursor c(bytes_.substr(0, s->start + s->size), label);
  c.seek(s->start);
  return c;
}

void CrateFile::read_tokens() {
  Cursor c = open("TOKENS", "TOKENS");
  const std::uint64_t count = c.read<std::uint64_t>();
  const std::uint64_t size = c.read<std::uint64_t>();
  const std::uint64_t compressed_size = c.read<std::uint64_t>();
  if (compressed_size > c.remaining()) c.fail(fmt::format("{} compressed bytes claimed, {} left", compressed_size, c.remaining()));
  if (size > decompressed_bound(compressed_size))
    c.fail(fmt::format("{} bytes of tokens claimed from {} compressed bytes", size, compressed_size));
  if (count > size) c.fail(fmt::format("{} tokens claimed in {} bytes", count, size));
  std::string chars(static_cast<std::size_t>(size), '\0');
  const std::size_t got = decompress(c.take(static_cast<std::size_t>(compressed_size)), chars.data(), chars.size(), c);
  chars.resize(got);
  tokens_.reserve(static_cast<std::size_t>(count));
  std::size_t p = 0;
  while (tokens_.size() < count && p < chars.size()) {
    const std::size_t end = chars.find('\0', p);
    const std::size_t stop = end == std::string::npos ? chars.size() : end;
    tokens_.emplace_back(chars, p, stop - p);
    p = stop + 1;
  }
  if (tokens_.size() != count) c.fail(fmt::format("{} tokens claimed, {} found", count, tokens_.size()));
}

void CrateFile::read_strings() {
  Cursor c = open("STRINGS", "STRINGS");
  const std::size_t n = c.count(c.read<std::uint64_t>(), 4, "strings");
  strings_.resize(n);
  for (auto& s : strings_) {
    s = c.read<std::uint32_t>();
    if (s >= tokens_.size()) c.fail(fmt::format("string names token {} of {}", s, tokens_.size()));
  }
}

void CrateFile::read_fields() {
  Cursor c = open("FIELDS", "FIELDS");
  const std::uint64_t n = c.read<std::uint64_t>();
  // Each field takes at least its 8-byte value rep before compression; LZ4 bounds the rest.
  if (n > decompressed_bound(c.remaining()) / 8) c.fail(fmt::format("{} fields claimed in {} bytes", n, c.remaining()));
  const auto tokens = read_compressed_u32(c, static_cast<std::size_t>(n));
  const std::uint64_t reps_size = c.read<std::uint64_t>();
  if (reps_size > c.remaining()) c.fail(fmt::format("{} bytes of value reps claimed, {} left", reps_size, c.remaining()));
  std::vector<std::uint64_t> reps(static_cast<std::size_t>(n));
  const std::size_t got = decompress(c.take(static_cast<std::size_t>(reps_size)), reinterpret_cast<char*>(reps.data()),
                                     reps.size() * sizeof(std::uint64_t), c);
  if (got != reps.size() * sizeof(std::uint64_t)) c.fail(fmt::format("{} value reps claimed, {} bytes found", n, got));
  fields_.resize(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < fields_.size(); ++i) {
    if (tokens[i] >= tokens_.size()) c.fail(fmt::format("field {} names token {} of {}", i, tokens[i], tokens_.size()));
    fields_[i] = Field{tokens[i], ValueRep{reps[i]}};
  }
}

void CrateFile::read_field_sets() {
  Cursor c = open("FIELDSETS", "FIELDSETS");
  const std::uint64_t n = c.read<std::uint64_t>();
  if (n > decompressed_bound(c.remaining()) * 4) c.fail(fmt::format("{} field set entries claimed in {} bytes", n, c.remaining()));
  field_sets_ = read_compressed_u32(c, static_cast<std::size_t>(n));
  for (std::uint32_t f : field_sets_)
    if (f != kNoField && f >= fields_.size()) c.fail(fmt::format("field set names field {} of {}", f, fields_.size()));
  if (!field_sets_.empty() && field_sets_.back() != kNoField) c.fail("the last field set is not terminated");
}

void CrateFile::read_paths() {
  Cursor c = open("PATHS", "PATHS");
  const std::uint64_t total = c.read<std::uint64_t>();
  const std::uint64_t n = c.read<std::uint64_t>();
  if (n > decompressed_bound(c.remaining()) * 4)
    c.fail(fmt::format("{} paths claimed in {} bytes", n, c.remaining()));
  // Every path but the empty one is in the tree.
  if (total > n + 1) c.fail(fmt::format("{} paths claimed, {} in the path tree", total, n));
  const auto indexes = read_compressed_u32(c, static_cast<std::size_t>(n));
  const auto elements = read_compressed_i32(c, static_cast<std::size_t>(n));
  const auto jumps = read_compressed_i32(c, static_cast<std::size_t>(n));
  paths_.resize(static_cast<std::size_t>(total));
  if (n == 0) return;
  // The tree is written depth first: a jump says whether an entry has a child (the next
  // entry) and where its next sibling is. Walked with an explicit stack; every entry is
  // visited at most once, so a jump that points back cannot loop.
  std::vector<bool> seen(static_cast<std::size_t>(n), false);
  struct Pending {
    std::size_t index;
    std::int64_t parent;  // path index, -1 for none (the root entry)
    std::size_t depth;
  };
  std::vector<Pending> stack{{0, -1, 0}};
  while (!stack.empty()) {
    Pending p = stack.back();
    stack.pop_back();
    for (;;) {
      const std::size_t i = p.index++;
      if (i >= n) c.fail(fmt::format("path entry {} is past the {} entries", i, n));
      if (seen[i]) c.fail(fmt::format("path entry {} is reached twice (the jumps table loops)", i));
      seen[i] = true;
      const std::uint32_t index = indexes[i];
      if (index >= paths_.size()) c.fail(fmt::format("path index {} of {}", index, paths_.size()));
      if (paths_[index].valid) c.fail(fmt::format("path {} is defined twice", index));
      PathEntry& entry = paths_[index];
      if (p.parent < 0) {
        entry.text = "/";
        entry.parent = index;
      } else {
        const std::int64_t element = elements[i];
        const std::uint64_t token = static_cast<std::uint64_t>(element < 0 ? -element : element);
        if (token >= tokens_.size()) c.fail(fmt::format("path element names token {} of {}", token, tokens_.size()));
        const std::string& parent = paths_[static_cast<std::size_t>(p.parent)].text;
        const std::string& name = tokens_[static_cast<std::size_t>(token)];
        if (name.empty()) c.fail("a path element is empty");
        // Built in place: a file has a path per prim and property.
        const bool joined = element >= 0 && (name[0] == '{' || name[0] == '[' || parent == "/" || parent.back() == '}');
        entry.text.reserve(parent.size() + 1 + name.size());
        entry.text.append(parent);
        if (!joined) entry.text += element < 0 ? '.' : '/';
        entry.text.append(name);
        entry.name = name;
        entry.token = static_cast<std::uint32_t>(token);
        entry.property = element < 0;
        entry.parent = static_cast<std::uint32_t>(p.parent);
      }
      entry.valid = true;
      const std::int32_t jump = jumps[i];
      const bool child = jump > 0 || jump == -1;
      const bool sibling = jump >= 0;
      if (child) {
        if (p.depth + 1 > kMaxPathDepth) c.fail(fmt::format("paths nest deeper than {} levels", kMaxPathDepth));
        if (sibling) stack.push_back({i + static_cast<std::size_t>(jump), p.parent, p.depth});
        p.parent = index;
        ++p.depth;
      }
      if (!child && !sibling) break;
    }
  }
}

void CrateFile::read_specs() {
  Cursor c = open("SPECS", "SPECS");
  const std::uint64_t n = c.read<std::uint64_t>();
  if (n > decompressed_bound(c.remaining()) * 4) c.fail(fmt::format("{} specs claimed in {} bytes", n, c.remaining()));
  const auto paths = read_compressed_u32(c, static_cast<std::size_t>(n));
  const auto sets = read_compressed_u32(c, static_cast<std::size_t>(n));
  const auto types = read_compressed_u32(c, static_cast<std::size_t>(n));
  specs_.resize(static_cast<std::size_t>(n));
  std::vector<char> seen(paths_.size(), 0);
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    if (paths[i] >= paths_.size() || !paths_[paths[i]].valid) c.fail(fmt::format("spec {} names path {} of {}", i, paths[i], paths_.size()));
    if (seen[paths[i]]++) c.fail(fmt::format("two specs for <{}>", paths_[paths[i]].text));
    if (sets[i] >= field_sets_.size() || (sets[i] > 0 && field_sets_[sets[i] - 1] != kNoField))
      c.fail(fmt::format("spec <{}> names field set {} of {}", paths_[paths[i]].text, sets[i], field_sets_.size()));
    if (types[i] == 0 || types[i] > static_cast<std::uint32_t>(SpecType::VariantSet))
      c.fail(fmt::format("spec <{}> has unknown spec type {}", paths_[paths[i]].text, types[i]));
    specs_[i] = Spec{paths[i], sets[i], static_cast<SpecType>(types[i])};
  }
}

const std::string& CrateFile::token(std::uint32_t index, const char* what) const {
  if (index >= tokens_.size()) usdc::fail(what, fmt::format("token index {} of {}", index, tokens_.size()));
  return tokens_[index];
}

const std::string& CrateFile::string(std::uint32_t index, const char* what) const {
  if (index >= strings_.size()) usdc::fail(what, fmt::format("string index {} of {}", index, strings_.size()));
  return tokens_[strings_[index]];
}

const PathEntry& CrateFile::path(std::uint32_t index, const char* what) const {
  // An index outside the tree is the empty path (a reference without a prim path).
  if (index >= paths_.size()) usdc::fail(what, fmt::format("path index {} of {}", index, paths_.size()));
  return paths_[index];
}

std::span<const std::uint32_t> CrateFile::field_set(const Spec& spec) const {
  // read_specs checked that the set starts inside the table and read_field_sets that the table ends terminated.
  std::size_t end = spec.field_set;
  while (end < field_sets_.size() && field_sets_[end] != kNoField) ++end;
  return std::span<const std::uint32_t>(field_sets_).subspan(spec.field_set, end - spec.field_set);
}

std::vector<Field> CrateFile::fields_of(const Spec& spec) const {
  std::vector<Field> out;
  for (std::size_t i = spec.field_set; i < field_sets_.size() && field_sets_[i] != kNoField; ++i)
    out.push_back(fields_[field_sets_[i]]);
  return out;
}

}  // namespace assetlint::usdc
