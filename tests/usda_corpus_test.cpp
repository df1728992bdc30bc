// Every real .usda file in the shared corpus and the reference schemas must parse.
#include "test_support.h"
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "formats/usda/parser.h"

namespace fs = std::filesystem;
using namespace assetlint;
using namespace assetlint::usda;

namespace {

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<fs::path> usda_files_under(const fs::path& root) {
  std::vector<fs::path> out;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.is_regular_file() && entry.path().extension() == ".usda") out.push_back(entry.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

void check_all_parse(const fs::path& root) {
  if (!fs::is_directory(root)) {
    WARN("corpus directory not found, skipping: " << root.string());
    return;
  }
  const auto files = usda_files_under(root);
  REQUIRE_FALSE(files.empty());
  for (const auto& path : files) {
    SourceFile file(path.string(), read_file(path));
    const ParseResult r = parse_layer(file, 0);
    INFO(path.string());
    if (!r.ok()) {
      FAIL(path.string() << ":" << r.error().span.line << ":" << r.error().span.column << ": "
                         << r.error().message);
    }
    CHECK(r.layer().version == "1.0");
    CHECK_FALSE(r.layer().prims.empty());
  }
}

}  // namespace

TEST_CASE("usda corpus: every shared corpus file parses", "[usda][corpus]") {
  check_all_parse(assetlint::test::source_dir() / "../shared/corpus/usda");
}

TEST_CASE("usda corpus: every reference schema parses", "[usda][corpus]") {
  check_all_parse(assetlint::test::source_dir() / "../shared/reference/schemas");
}
