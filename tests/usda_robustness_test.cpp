// Mutated inputs (truncations, byte flips, deleted brackets) must never crash, hang or
// read outside the text, and every error must carry a span inside the text.
#include "test_support.h"
#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "usda_test_util.h"

namespace fs = std::filesystem;
using namespace assetlint;
using namespace assetlint::usda;
using usda_test::Parsed;

namespace {

// A small deterministic generator (xorshift64*), so failures reproduce exactly.
struct Rng {
  std::uint64_t state;
  std::uint64_t next() {
    state ^= state >> 12;
    state ^= state << 25;
    state ^= state >> 27;
    return state * 0x2545F4914F6CDD1DULL;
  }
  std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(next() % n); }
};

const char* const kFixture = R"(#usda 1.0
(
    "doc"
    customLayerData = {
        dictionary cam = {
            double3 position = (5, 0, 0)
        }
    }
    defaultPrim = "Robot"
    metersPerUnit = 0.01
    subLayers = [@./a.usda@ (offset = 1; scale = 2), @@@b@@@]
)

def Xform "Robot" (
    prepend apiSchemas = ["PhysicsArticulationRootAPI"]
    prepend references = @./parts.usd@</Meshes/base> (offset = 2)
    variants = { string mode = "rigid" }
)
{
    float3[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1), (0, 0, 2), (1, 0, 2), (1, 1, 2), (0, 1, 2), (0, 0, 3), (1, 0, 3), (1, 1, 3), (0, 1, 3), (0, 0, 4), (1, 0, 4)]
    def PhysicsRevoluteJoint "finger_joint" (
        delete apiSchemas = ["PhysicsDriveAPI:angular"]
    )
    {
        float drive:angular:physics:stiffness = 3 (doc = '''multi
line''')
        float physics:lowerLimit = -inf
        rel physics:body0 = </Robot/base>
        prepend rel physics:body1 = [</Robot/a>, </Robot/b>,]
        float x.timeSamples = { 0: 1, 1.5: None, }
        token outputs:surface.connect = </Looks/M.outputs:surface>
        /* block comment */ string s = "esc \" \n" // end
    }
    variantSet "mode" = {
        "rigid" ( doc = "r" ) { float k = 1 }
    }
    reorder nameChildren = ["finger_joint"]
}
)";

void check_result(const Parsed& p, std::size_t size) {
  if (p.ok()) return;
  const Span& s = p.error().span;
  CHECK(s.file == 7);
  CHECK(s.line >= 1);
  CHECK(s.column >= 1);
  CHECK(s.offset <= size);
  CHECK(s.end() <= size);
  CHECK_FALSE(p.error().message.empty());
}

void mutate_and_parse(const std::string& original, std::uint64_t seed, std::size_t rounds) {
  Rng rng{seed};
  static const char kInteresting[] = "{}[]()<>@\"'#=:,;.\n\r-+e0a \\/*\x00\xff";
  const std::size_t n = original.size();
  // Truncations at every Nth byte (at most ~200 cut points per text).
  const std::size_t step = n / 200 + 1;
  for (std::size_t cut = 0; cut <= n; cut += step) {
    const std::string t = original.substr(0, cut);
    check_result(usda_test::parse(t), t.size());
  }
  for (std::size_t round = 0; round < rounds; ++round) {
    std::string t = original;
    const std::size_t edits = 1 + rng.below(4);
    for (std::size_t e = 0; e < edits && !t.empty(); ++e) {
      const std::size_t pos = rng.below(t.size());
      switch (rng.below(4)) {
        case 0: t[pos] = kInteresting[rng.below(sizeof(kInteresting) - 1)]; break;  // byte flip
        case 1: t[pos] = static_cast<char>(rng.next() & 0xFF); break;               // random byte
        case 2: {                                                                     // delete a bracket
          const std::size_t b = t.find_first_of("{}[]()<>", pos);
          if (b != std::string::npos) t.erase(b, 1);
          break;
        }
        default: t.insert(pos, 1, kInteresting[rng.below(sizeof(kInteresting) - 1)]); break;
      }
    }
    check_result(usda_test::parse(t), t.size());
    ParseOptions eager;
    eager.lazy_arrays = false;
    check_result(usda_test::parse(t, eager), t.size());
  }
}

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST_CASE("usda robustness: the fixture parses unmutated", "[usda][robustness]") {
  const auto p = usda_test::parse(kFixture);
  if (!p.ok()) FAIL(p.error().span.line << ":" << p.error().span.column << ": " << p.error().message);
  CHECK(p.layer().prims.size() == 1);
  CHECK(p.layer().prims[0].find_attribute("points")->default_value->lazy);
}

TEST_CASE("usda robustness: mutated fixture never crashes", "[usda][robustness]") {
  mutate_and_parse(kFixture, 0x5EED1234ABCDULL, 3000);
}

TEST_CASE("usda robustness: mutated corpus files never crash", "[usda][robustness]") {
  const fs::path root = assetlint::test::source_dir() / "../shared/corpus/usda";
  if (!fs::is_directory(root)) {
    WARN("corpus directory not found, skipping: " << root.string());
    return;
  }
  std::uint64_t seed = 42;
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    // Small files only: keeps the test fast while covering every construct they use.
    if (!entry.is_regular_file() || entry.path().extension() != ".usda" || entry.file_size() > 60000) continue;
    mutate_and_parse(read_file(entry.path()), seed++, 150);
    ++files;
  }
  CHECK(files > 0);
}

TEST_CASE("usda robustness: pathological inputs", "[usda][robustness]") {
  const std::vector<std::string> inputs = {
      "#usda 1.0\n" + std::string(100000, '('),
      "#usda 1.0\n(x = " + std::string(100000, '[') ,
      "#usda 1.0\n(x = {" + std::string(5000, '{'),
      "#usda 1.0\ndef \"a\" { float[] x = [" + std::string(20000, ',') + "] }",
      "#usda 1.0\ndef \"a\" { float[] x = [1" + std::string(20000, ')') + "] }",
      "#usda 1.0\n" + std::string(100000, '}'),
      "#usda 1.0\ndef \"a\" { rel r = [" + std::string(10000, '<') + "] }",
      std::string("#usda 1.0\n\0\0\0", 13),
      "#usda 1.0\n/*",
      "#usda 1.0\n@@@",
      "#usda 1.0\n'''",
      "#usda 1.0\n\"\\",
      "#usda 1.0\ndef \"a\" { double x.spline = { " + std::string(1000, '{') + " } }",
  };
  for (const auto& t : inputs) {
    const auto p = usda_test::parse(t);
    CHECK_FALSE(p.ok());
    check_result(p, t.size());
  }
}
