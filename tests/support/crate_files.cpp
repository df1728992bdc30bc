#include "crate_files.h"

#include <algorithm>

#include "formats/usdc/crate_file.h"
#include "../test_support.h"

namespace assetlint::test {

std::vector<std::filesystem::path> crate_files() {
  namespace fs = std::filesystem;
  std::vector<fs::path> out;
  std::vector<fs::path> roots{fixtures_dir() / "usdc"};
  if (!corpus_dir().empty()) roots.push_back(corpus_dir() / "usdc");
  for (const auto& root : roots) {
    if (!fs::exists(root)) continue;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
      if (!e.is_regular_file()) continue;
      const auto ext = e.path().extension().string();
      if ((ext == ".usd" || ext == ".usdc") && usdc::is_crate(read_file(e.path()).substr(0, 8))) out.push_back(e.path());
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace assetlint::test
