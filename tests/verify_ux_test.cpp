// What `asset-lint verify` tells a person while and after it runs: where the plot went, a
// plot whose scenes do not hide each other with failures and thresholds marked, and a
// --fine-tune that stops at once when today's drive fails, saying what to change first.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "test_support.h"

using assetlint::test::read_file;
using assetlint::test::replace_once;
using assetlint::test::run_cli;
using assetlint::test::write_file;

namespace {

const std::filesystem::path kFixture = assetlint::test::fixtures_dir() / "verify" / "two_finger";

// The fixture in a temporary directory; `weak`: half the squeeze the box needs (it slips).
struct Gripper {
  assetlint::test::TempDir dir;
  explicit Gripper(bool weak) {
    std::string config = read_file(kFixture / "asset-lint.toml");
    if (weak) {
      config = replace_once(config, "stiffness = 4000", "stiffness = 1000");
      config = replace_once(config, "damping = 40", "damping = 20");
      config = replace_once(config, "max_force = 20", "max_force = 5");
    }
    write_file(dir.path() / "two_finger.urdf", read_file(kFixture / "two_finger.urdf"));
    write_file(dir.path() / "asset-lint.toml", config);
  }
  assetlint::test::CommandResult run(std::vector<std::string> extra) const {
    std::vector<std::string> args = {"verify", "two_finger.urdf"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_cli(args, dir.path());
  }
};

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("verify --plot: says where the SVG went; one panel per scene kind, verdicts and thresholds marked",
          "[verify][plot]") {
  const Gripper passing(false);
  const auto r = passing.run({"--plot", "verify.svg", "--output-format", "json"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("asset-lint verify: wrote the plot to verify.svg\n") != std::string::npos);
  const std::string svg = read_file(passing.dir.path() / "verify.svg");
  const auto report = nlohmann::json::parse(r.out);
  // Each kind that ran has its panel, and each scene its line, in the panel of its kind only.
  for (const char* panel : {"close: finger opening (mm)", "grasp: penetration (mm)", "hold: slip since gravity on (mm)"})
    CHECK(count(svg, panel) == 1);
  std::size_t ran = 0;
  for (const auto& scene : report["scenes"]) {
    if (!scene["ran"].get<bool>()) continue;
    ++ran;
    CHECK(count(svg, scene["name"].get<std::string>() + ": pass") == 1);
  }
  CHECK(ran >= 4);
  CHECK(svg.find("peak penetration limit") != std::string::npos);
  CHECK(svg.find("slip limit") != std::string::npos);
  CHECK(svg.find("close time the spec allows") != std::string::npos);
  CHECK(svg.find("FAIL") == std::string::npos);

  const Gripper weak(true);
  const auto failed = weak.run({"--plot", "weak.svg"});
  REQUIRE(failed.exit_code == 1);
  const std::string weak_svg = read_file(weak.dir.path() / "weak.svg");
  CHECK(weak_svg.find(": FAIL (grip force)") != std::string::npos);
  CHECK(weak_svg.find("stroke-dasharray") != std::string::npos);  // failing scenes are dashed
}

TEST_CASE("verify --fine-tune: a failing drive is not re-run; the report says what to change first", "[verify]") {
  const Gripper weak(true);
  const auto json = weak.run({"--fine-tune", "--output-format", "json"});
  INFO(json.out << json.err);
  REQUIRE(json.exit_code == 1);
  const auto fine = nlohmann::json::parse(json.out)["fine_tune"];
  CHECK(fine["baseline_passed"] == false);
  CHECK(fine["runs"] == 1);  // the verification's own run, nothing more
  REQUIRE(fine["notes"].size() == 2);
  CHECK(fine["notes"][0].get<std::string>().find("today's drive already fails '") == 0);
  CHECK(fine["notes"][1].get<std::string>().find("change first: raise the max force: the grip ") == 0);

  const auto text = weak.run({"--fine-tune"});
  CHECK(text.out.find("Fine-tuning: not run, today's drive must pass every scene first.\n"
                      "  today's drive already fails '") != std::string::npos);
  CHECK(text.out.find("  change first: raise the max force") != std::string::npos);
}
