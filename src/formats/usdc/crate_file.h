#pragma once
// The structural sections of a binary USD "crate" layer (PXR-USDC): the table of
// contents, tokens, strings, fields, field sets, the path tree and the specs. Values are
// left as ValueReps (crate_values.h reads them).
//
// Every offset, count and size read from the file is checked against the bytes before
// it is used; a file that breaks the format throws CrateError naming the section.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace assetlint::usdc {

struct CrateError {
  std::string section;  // "bootstrap", "TOKENS", "PATHS", a value's field, ...
  std::string message;
};

[[noreturn]] void fail(std::string section, std::string message);

// The first bytes of every crate file.
inline constexpr std::string_view kCrateMagic = "PXR-USDC";
bool is_crate(std::string_view bytes);

struct Version {
  std::uint8_t major = 0, minor = 0, patch = 0;
  bool at_least(int mj, int mn) const { return major > mj || (major == mj && minor >= mn); }
  std::string text() const;
};

// The crate versions read here: 0.4.0 (compressed structural sections) up to the newest
// OpenUSD writes.
inline constexpr Version kOldestReadable{0, 4, 0};
inline constexpr Version kNewestReadable{0, 11, 0};

// A value as the file refers to it: type, array/inlined/compressed bits and a payload
// that is either the value itself or the file offset of its data.
struct ValueRep {
  std::uint64_t data = 0;
  bool is_array() const { return (data >> 63) & 1; }
  bool is_inlined() const { return (data >> 62) & 1; }
  bool is_compressed() const { return (data >> 61) & 1; }
  unsigned type() const { return static_cast<unsigned>((data >> 48) & 0xFF); }
  std::uint64_t payload() const { return data & ((std::uint64_t{1} << 48) - 1); }
};

// Spec types as Sdf numbers them.
enum class SpecType : std::uint32_t {
  Unknown = 0, Attribute, Connection, Expression, Mapper, MapperArg, Prim, PseudoRoot,
  Relationship, RelationshipTarget, Variant, VariantSet
};

struct Field {
  std::uint32_t token = 0;
  ValueRep rep;
};

struct Spec {
  std::uint32_t path = 0;
  std::uint32_t field_set = 0;
  SpecType type = SpecType::Unknown;
};

// Bounds-checked little-endian reads from the file's bytes.
class Cursor {
 public:
  Cursor(std::string_view bytes, const char* section) : bytes_(bytes), section_(section) {}
  std::size_t tell() const { return pos_; }
  void seek(std::uint64_t offset);
  std::size_t remaining() const { return bytes_.size() - pos_; }
  template <class T>
  T read() {
    T v;
    read_bytes(&v, sizeof v);
    return v;
  }
  void read_bytes(void* out, std::size_t n);
  std::string_view take(std::size_t n);
  // A count of items of `item_size` bytes each that must fit in the rest of the file.
  std::size_t count(std::uint64_t n, std::size_t item_size, const char* what);
  const char* section() const { return section_; }
  [[noreturn]] void fail(const std::string& message) const;

 private:
  std::string_view bytes_;
  const char* section_;
  std::size_t pos_ = 0;
};

// Decompresses a TfFastCompression buffer (LZ4 blocks, one or chunked) into exactly
// `expected` bytes at most; returns the bytes written.
std::size_t decompress(std::string_view compressed, char* out, std::size_t capacity, const Cursor& where);

// Reads `n` integers stored as crate compresses them (uint64 size, LZ4, delta codes).
std::vector<std::uint32_t> read_compressed_u32(Cursor& c, std::size_t n);
std::vector<std::int32_t> read_compressed_i32(Cursor& c, std::size_t n);
std::vector<std::int64_t> read_compressed_i64(Cursor& c, std::size_t n);

struct PathEntry {
  std::string text;          // "/robot/base.physics:mass", "/robot{physics=PhysX}"
  std::string_view name;     // the last element ("physics:mass", "{physics=PhysX}"); empty for the root
  std::uint32_t parent = 0;  // path index of the parent (the root is its own parent)
  std::uint32_t token = 0;   // the token `name` is
  bool property = false;     // the last element is a property name
  bool valid = false;
};

class CrateFile {
 public:
  // Reads the structure of `bytes` (which must outlive the object). Throws CrateError.
  explicit CrateFile(std::string_view bytes);

  std::string_view bytes() const { return bytes_; }
  const Version& version() const { return version_; }
  const std::string& token(std::uint32_t index, const char* what) const;
  // The token a string index names.
  const std::string& string(std::uint32_t index, const char* what) const;
  const PathEntry& path(std::uint32_t index, const char* what) const;
  const std::vector<Spec>& specs() const { return specs_; }
  const std::vector<PathEntry>& paths() const { return paths_; }
  // The fields of a spec, in file order.
  std::vector<Field> fields_of(const Spec& spec) const;
  // The same as indexes into field(): no copy.
  std::span<const std::uint32_t> field_set(const Spec& spec) const;
  const Field& field(std::uint32_t index) const { return fields_[index]; }

 private:
  struct Section {
    std::string name;
    std::uint64_t start = 0, size = 0;
  };
  const Section* section(std::string_view name) const;
  Cursor open(std::string_view name, const char* label) const;
  void read_tokens();
  void read_strings();
  void read_fields();
  void read_field_sets();
  void read_paths();
  void read_specs();

  std::string_view bytes_;
  Version version_;
  std::vector<Section> sections_;
  std::vector<std::string> tokens_;
  std::vector<std::uint32_t> strings_;
  std::vector<Field> fields_;
  std::vector<std::uint32_t> field_sets_;
  std::vector<PathEntry> paths_;
  std::vector<Spec> specs_;
};

}  // namespace assetlint::usdc
