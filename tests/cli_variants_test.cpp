// Physics kept in USD variant sets (NVIDIA's SimReady layout, fixtures/usda/variants): every
// variant that carries physics is checked, its findings name the selection in every report
// format, and --variant / [usd] variants pin one selection.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

#include "test_support.h"

using assetlint::test::run_cli;

namespace {

std::size_t occurrences(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

const std::string kGripper = "usda/variants/simready/gripper.usda";

}  // namespace

TEST_CASE("cli variants: the PhysX payload's drive is found only with PhysX=Enabled, in every format",
          "[cli][usd][variants]") {
  const auto fixtures = assetlint::test::fixtures_dir();
  auto text = run_cli({kGripper}, fixtures);
  INFO(text.out << text.err);
  CHECK(text.exit_code == 1);
  CHECK(occurrences(text.out, "error: in variants PhysX=Enabled; MuJoCo=Enabled: drive of 'finger_joint': natural "
                              "frequency 41540 rad/s") == 1);
  CHECK(occurrences(text.out, "info: in variant Newton=Enabled: ") == 1);
  CHECK(occurrences(text.out, "the stage itself selects PhysX=Disabled, MuJoCo=Disabled") == 1);
  CHECK(occurrences(text.out, "in 1 file.") == 1);

  auto concise = run_cli({"--output-format", "concise", kGripper}, fixtures);
  CHECK(occurrences(concise.out, "physx.usda:40:49: drive-natural-frequency in variants PhysX=Enabled; MuJoCo=Enabled: ") == 1);

  auto json = run_cli({"--output-format", "json", kGripper}, fixtures);
  const auto doc = nlohmann::json::parse(json.out);
  std::size_t in_variant = 0;
  const auto both = nlohmann::json::parse(R"([[{"set": "PhysX", "variant": "Enabled"}], [{"set": "MuJoCo", "variant": "Enabled"}]])");
  for (const auto& d : doc["diagnostics"]) {
    if (d["message"].get<std::string>().rfind("in variant", 0) != 0) {
      CHECK_FALSE(d.contains("variants"));
      continue;
    }
    ++in_variant;
    CHECK(d["notes"][0]["message"].get<std::string>().rfind("Found with ", 0) == 0);
    // The selections as data too, one list per selection.
    const bool shared = d["message"].get<std::string>().rfind("in variants PhysX=Enabled; MuJoCo=Enabled: ", 0) == 0;
    CHECK(d["variants"] == (shared ? both : nlohmann::json::parse(R"([[{"set": "Newton", "variant": "Enabled"}]])")));
  }
  CHECK(in_variant == 2);

  auto sarif = nlohmann::json::parse(run_cli({"--output-format", "sarif", kGripper}, fixtures).out);
  std::size_t with_variants = 0;
  for (const auto& r : sarif["runs"][0]["results"]) {
    if (!r.contains("properties") || !r["properties"].contains("variants")) continue;
    ++with_variants;
    if (r["message"]["text"].get<std::string>().rfind("in variants PhysX=Enabled; MuJoCo=Enabled: ", 0) == 0)
      CHECK(r["properties"]["variants"] == both);
  }
  CHECK(with_variants == 2);

  for (const char* format : {"sarif", "github", "gitlab", "junit"}) {
    INFO(format);
    auto r = run_cli({"--output-format", format, kGripper}, fixtures);
    CHECK(r.exit_code == 1);
    CHECK(occurrences(r.out, "in variants PhysX=Enabled; MuJoCo=Enabled: drive of") >= 1);
    CHECK(occurrences(r.out, "in variant Newton=Enabled: drive of") >= 1);
  }
}

TEST_CASE("cli variants: --variant and [usd] variants check the pinned selection only", "[cli][usd][variants]") {
  const auto fixtures = assetlint::test::fixtures_dir();
  // Pinned off: PhysX's payload is not checked; MuJoCo's (which shares it) still is.
  auto off = run_cli({"--output-format", "concise", "--variant", "PhysX=Disabled", kGripper}, fixtures);
  CHECK(occurrences(off.out, "drive-natural-frequency in variant MuJoCo=Enabled: drive of 'finger_joint'") == 1);
  CHECK(occurrences(off.out, "PhysX=Enabled") == 0);

  // Pinned on: the stage is checked with PhysX's physics, findings carry no variant of that set.
  auto on = run_cli({"--output-format", "concise", "--variant", "PhysX=Enabled", kGripper}, fixtures);
  CHECK(occurrences(on.out, "physx.usda:40:49: drive-natural-frequency drive of 'finger_joint'") == 1);
  CHECK(occurrences(on.out, "in variant") == 0);  // Newton's and MuJoCo's are weaker than PhysX's payload

  auto bad = run_cli({"--variant", "PhysX", kGripper}, fixtures);
  CHECK(bad.exit_code == 2);
  CHECK(occurrences(bad.err, "SET=NAME") == 1);

  assetlint::test::TempDir dir;
  const auto config = dir.path() / "asset-lint.toml";
  assetlint::test::write_file(config, "select = [\"drive-natural-frequency\"]\n[usd]\nvariants = { PhysX = \"Enabled\", "
                                      "Newton = \"Disabled\", MuJoCo = \"Disabled\" }\n[simulation]\n"
                                      "timesteps_per_second = 250\nposition_iterations = 64\n");
  auto configured = run_cli({"--output-format", "concise", "--config", config.string(), kGripper}, fixtures);
  CHECK(occurrences(configured.out, "physx.usda:40:49: drive-natural-frequency drive of 'finger_joint'") == 1);
  CHECK(occurrences(configured.out, "in variant") == 0);

  auto shown = run_cli({"--config", config.string(), "--variant", "Newton=Enabled", "--show-settings", kGripper}, fixtures);
  INFO(shown.out);
  CHECK(occurrences(shown.out, "[usd]\nvariants = { MuJoCo = \"Disabled\", Newton = \"Enabled\", PhysX = \"Enabled\" }") == 1);
  CHECK(occurrences(shown.out, "--variant") == 1);
  CHECK(occurrences(shown.out, "#   </gripper> PhysX = [\"Disabled\", \"Enabled\"], pinned to \"Enabled\"") == 1);
  CHECK(occurrences(shown.out, "# checked: the stage's selection\n") == 1);
}

TEST_CASE("cli variants: --show-settings lists the variant sets and the selections checked", "[cli][usd][variants]") {
  auto r = run_cli({"--show-settings", kGripper}, assetlint::test::fixtures_dir());
  INFO(r.out);
  CHECK(r.exit_code == 0);
  CHECK(occurrences(r.out, "# variants is not set: the stage's selections, and every variant that carries physics") == 1);
  CHECK(occurrences(r.out, "#   </gripper> PhysX = [\"Disabled\", \"Enabled\"], selects \"Disabled\"") == 1);
  CHECK(occurrences(r.out, "#   </gripper> Newton = [\"Disabled\", \"Enabled\"], selects \"Disabled\"") == 1);
  CHECK(occurrences(r.out, "# checked: the stage's selection; PhysX=Enabled; Newton=Enabled; MuJoCo=Enabled") == 1);
}

TEST_CASE("cli variants: a directory run judges the payload layers once, in the stage", "[cli][usd][variants]") {
  const auto dir = assetlint::test::fixtures_dir() / "usda" / "variants" / "simready";
  auto r = run_cli({"--output-format", "concise", "--select", "drive-natural-frequency", "."}, dir);
  INFO(r.out);
  CHECK(occurrences(r.out, "physx.usda:40:49:") == 1);
  CHECK(occurrences(r.out, "newton.usda:40:49:") == 1);
  CHECK(occurrences(r.out, "in 4 files") == 0);  // concise has no summary
  CHECK(r.exit_code == 1);
}

TEST_CASE("cli variants: a variant's fix edits the payload layer it lives in", "[cli][usd][variants][fix]") {
  auto r = run_cli({"--diff", "--unsafe-fixes", kGripper}, assetlint::test::fixtures_dir());
  INFO(r.out << r.err);
  CHECK(r.exit_code == 1);
  CHECK(occurrences(r.out, "+++ b/usda/variants/simready/runnables/physics/physx.usda") == 1);
  CHECK(occurrences(r.out, "-        float drive:angular:physics:stiffness = 99.48") == 1);
  CHECK(occurrences(r.out, "+        float drive:angular:physics:stiffness = 4.8") == 1);
  CHECK(occurrences(r.out, "gripper.usda\n") == 0);  // the root layer is not touched
}

TEST_CASE("cli variants: tune reads the stage in the selection --variant names", "[cli][usd][variants]") {
  const auto fixtures = assetlint::test::fixtures_dir();
  auto off = run_cli({"tune", kGripper}, fixtures);
  CHECK(off.exit_code == 2);
  CHECK(occurrences(off.err, "no driven joint") == 1);
  auto on = run_cli({"tune", "--variant", "PhysX=Enabled", kGripper}, fixtures);
  INFO(on.out << on.err);
  CHECK(occurrences(on.out, "Tuning revolute joint '/gripper/finger_joint'") == 1);
}
