// Crate (binary USD) bytes → the crate reader → the USDA it reads as (`cat`); and lint, which
// builds the layer from the crate's specs (or reads what it leaves through that text) →
// compose + every rule. The reader must end every input with text or an error naming the
// section.
#include <cstdint>
#include <string>
#include <variant>

#include "formats/usdc/crate_usda.h"
#include "memory_file_system.h"

using namespace assetlint;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const auto result = usdc::crate_to_usda(bytes);
  if (std::holds_alternative<usdc::CrateText>(result)) {
    fuzz::MemoryFileSystem files;
    files.set("root.usd", bytes);
    fuzz::lint_in_memory("root.usd", bytes, files);
  }
  return 0;
}
