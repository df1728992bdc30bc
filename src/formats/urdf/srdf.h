#pragma once
// MoveIt's SRDF beside a URDF: the pairs of links whose collisions a planner (and anyone who
// reuses its matrix) ignores, each with the reason MoveIt's setup assistant wrote
// ("Adjacent", "Never", "Default", "User").
#include <optional>
#include <string>
#include <vector>

#include "engine/file_system.h"

namespace assetlint::urdf {

struct DisabledCollision {
  std::string link1, link2, reason;
};

struct Srdf {
  std::string path;
  std::vector<DisabledCollision> disabled;
  // Whether the SRDF disables the pair, in either order.
  const DisabledCollision* find(const std::string& a, const std::string& b) const;
};

// The .srdf file in `directory` whose <robot name> is `robot` (the only one there when none
// names it); nullopt when there is none, or it cannot be read or parsed.
std::optional<Srdf> srdf_beside(const std::string& directory, const std::string& robot, const FileSystem& files);

}  // namespace assetlint::urdf
