// Replays inputs through a fuzz target's entry point without libFuzzer: the kept findings in
// fuzz/regressions/<target>/ and the fixtures run.sh seeds the target with. A crash, abort
// or sanitizer report fails the test; the exit status is 0 otherwise.
//   <target>_replay TARGET SOURCE_DIR
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void run(const std::string& bytes) {
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

// The fixtures that seed `target` in fuzz/run.sh (fix_fuzz is left out: tests/fix_test.cpp
// already applies every fix of every fixture).
bool seeds(const std::string& target, const fs::path& file) {
  const std::string name = file.filename().string();
  if (target == "urdf_fuzz") return file.extension() == ".urdf";
  if (target == "usda_fuzz") return file.extension() == ".usda";
  if (target == "usdc_fuzz") return file.extension() == ".usd";
  if (target == "mjcf_fuzz") return file.extension() == ".xml";
  if (target == "config_fuzz") return name == "asset-lint.toml";
  if (target == "xacro_fuzz") return file.extension() == ".xacro";
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s TARGET SOURCE_DIR\n", argv[0]);
    return 2;
  }
  const std::string target = argv[1];
  const fs::path root = argv[2];
  std::vector<fs::path> inputs;
  if (const fs::path kept = root / "fuzz" / "regressions" / target; fs::is_directory(kept))
    for (const auto& entry : fs::directory_iterator(kept))
      if (entry.is_regular_file()) inputs.push_back(entry.path());
  for (const auto& entry : fs::recursive_directory_iterator(root / "fixtures"))
    if (entry.is_regular_file() && seeds(target, entry.path())) inputs.push_back(entry.path());
  for (const fs::path& input : inputs) run(read(input));
  std::printf("%s: %zu inputs replayed\n", target.c_str(), inputs.size());
  return 0;
}
