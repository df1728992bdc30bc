#pragma once
// Pairing the links or joints of two files by name.
#include <string>
#include <utility>
#include <vector>

namespace assetlint::commands {

struct NameMatch {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // (index in a, index in b)
  std::vector<std::size_t> only_a, only_b;                 // unmatched, in input order
};

// Pairs names of `a` with names of `b`, each stage among the names still unpaired and
// only where the key is unique on both sides:
//   1. the `map` pairs (a name or its last path component on each side);
//   2. the exact name;
//   3. the last path component ("/robot/joints/finger_joint" → "finger_joint");
//   4. that component in lower case without the prefix all names of its file share
//      ("robotiq_85_") and a usual suffix ("_joint", "_link", "_body").
NameMatch match_names(const std::vector<std::string>& a, const std::vector<std::string>& b,
                      const std::vector<std::pair<std::string, std::string>>& map);

// The key of stage 3.
std::string last_component(const std::string& name);

}  // namespace assetlint::commands
