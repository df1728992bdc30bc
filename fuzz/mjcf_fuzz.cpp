// MJCF bytes, split into files at each `\n<mujoco` (robot.xml, i1.xml, ... for <include>)
// → read (defaults, includes, compiler settings) → every rule.
#include <cstdint>
#include <string>

#include "memory_file_system.h"

using namespace assetlint;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::MemoryFileSystem files;
  std::string root = fuzz::split_mjcf(std::string_view(reinterpret_cast<const char*>(data), size), files);
  fuzz::lint_in_memory("robot.xml", std::move(root), files);
  return 0;
}
