#pragma once
// The specs of a crate layer found by parent path and name ("LF_HAA" under </anymal>)
// instead of by the text of the whole path: a lookup hashes one name, not a path that grows
// with the depth of the prim.
//
// Both lookups find the same spec when no two paths of the tree are spelled alike. That is
// checked when the index is built: every name outside relationship targets (`[...]`) must be
// a plain name, or `{set=variant}` for a variant, and no parent may have two children of the
// same name and kind. A tree that breaks this gets no index; its layer is then read through
// its text, which finds specs by their whole path.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "formats/usdc/crate_file.h"

namespace assetlint::usdc {

struct SpecAt {
  std::uint32_t path = 0;  // path index (the parent of further lookups)
  std::size_t spec = 0;    // index into CrateFile::specs()
};

class SpecIndex {
 public:
  static std::optional<SpecIndex> build(const CrateFile& file);

  // The spec of the root path "/".
  std::optional<SpecAt> root() const { return at(root_); }
  // Whether `name` is one element of a path: a plain name, or (not for a property)
  // `{set=variant}`. Another name may spell a path of several elements: such a name is
  // looked up by its whole path instead.
  static bool is_element(std::string_view name, bool property);
  // The spec of child `name` (an element) of path `parent`: a prim or variant, or a
  // property. Nullopt when the path has no spec.
  std::optional<SpecAt> child(std::uint32_t parent, std::string_view name, bool property) const;

 private:
  struct Slot {
    std::uint32_t path = kEmpty;
    std::uint32_t parent = 0;
  };
  static constexpr std::uint32_t kEmpty = 0xFFFFFFFF;
  static std::uint64_t name_hash(std::string_view name);
  std::size_t slot(std::uint64_t name_hash, std::uint32_t parent, bool property) const;
  bool insert(const CrateFile& file, std::uint32_t path, std::uint64_t name_hash);
  std::optional<SpecAt> at(std::uint32_t path) const;

  const CrateFile* file_ = nullptr;
  std::uint32_t root_ = kEmpty;
  std::vector<Slot> slots_;                 // open addressing, a power of two
  std::vector<std::uint32_t> spec_of_path_;  // kEmpty where a path has no spec
};

}  // namespace assetlint::usdc
