#pragma once
// What MuJoCo leaves out of collision detection, read from an MJCF model on demand (the
// geometry rules ask only when two shapes overlap): each geom's contype and conaffinity,
// <option><flag filterparent> and <flag contact>, and the body pairs of <contact><exclude>.
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "engine/file_system.h"
#include "formats/mjcf/mjcf_sources.h"
#include "model/source.h"

namespace assetlint::mjcf {

struct ContactFilter {
  struct Excluded {
    std::string body1, body2;
    Span span;
  };
  // contype and conaffinity of each geom, by where its element starts (file, offset): the
  // span the reader gives the geom's CollisionShape.
  std::map<std::pair<FileId, std::size_t>, std::array<std::uint32_t, 2>> bits;
  std::vector<Excluded> excluded;
  bool filter_parent = true;  // <flag filterparent>; MuJoCo's default is enabled
  bool contacts = true;       // <flag contact="disable"> turns every contact off
  Span flag_span;             // the <flag> that writes either, when one does

  // The geom's bits; MuJoCo's defaults (1 and 1) for a geom not found.
  std::array<std::uint32_t, 2> bits_of(const Span& geom) const;
  const Excluded* find_excluded(const std::string& a, const std::string& b) const;
};

// The filter of the model in `file`, its includes read as the reader read them.
ContactFilter read_contact_filter(std::shared_ptr<const SourceFile> file, const FileSystem& files,
                                  const ReadOptions& options);

}  // namespace assetlint::mjcf
