// USDA bytes → parse → compose (layers in memory) → every rule.
#include <cstdint>
#include <string>

#include "pipeline/lint.h"
#include "memory_file_system.h"

using namespace assetlint;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::MemoryFileSystem files;
  std::string root = fuzz::split_layers(std::string_view(reinterpret_cast<const char*>(data), size), files);
  Settings settings;
  settings.allow_outside_root = true;  // a memory file system has no tree to leave
  (void)lint_text("root.usda", std::move(root), settings, files);
  return 0;
}
