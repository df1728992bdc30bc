// asset-lint.toml bytes → configuration.
#include <cstdint>
#include <string_view>

#include "config/config.h"

using namespace assetlint;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Settings settings;
  (void)config::load_text(std::string_view(reinterpret_cast<const char*>(data), size), "asset-lint.toml", settings);
  return 0;
}
