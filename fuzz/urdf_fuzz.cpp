// URDF bytes → read → every rule. Also checks the urdfdom skip: asset-lint must reject
// every document urdfdom rejects (src/formats/urdf/urdfdom_verdict.h).
#include <cstdint>
#include <cstdlib>
#include <string>

#include "pipeline/lint.h"
#include "pipeline/urdf_verdict.h"
#include "formats/urdf/urdf_reader.h"
#include "formats/urdf/urdfdom_check.h"
#include "memory_file_system.h"

using namespace assetlint;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  fuzz::MemoryFileSystem files;
  (void)lint_text("fuzz.urdf", text, Settings{}, files);
  // The reader's own verdict (the report's may be changed by inline suppressions).
  const ReadResult read = urdf::read_urdf(std::make_shared<const SourceFile>("fuzz.urdf", text));
  if (!rejects_as_urdfdom_would(read) && !urdf::urdfdom_errors(text).empty()) std::abort();  // accepted what urdfdom rejects
  return 0;
}
