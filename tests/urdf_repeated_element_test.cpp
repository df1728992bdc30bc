// urdf-repeated-element says "MuJoCo's URDF importer refuses the file" exactly where MuJoCo does:
// every URDF fixture of the rule, and the rule's other fixtures' neighbours, compiled by MuJoCo
// itself (tests/mujoco_reference/compile.mjs, MuJoCo 3.14 in WASM, npm @mujoco/mujoco).
// Skipped with a message when `node` or @mujoco/mujoco is absent; a failure under CI=true.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/settings.h"
#include "pipeline/lint.h"
#include "support/mujoco_oracle.h"
#include "test_support.h"

using namespace assetlint;
namespace fs = std::filesystem;

namespace {

bool flagged(const fs::path& file) {
  const FileReport report = lint_file(file.string(), Settings{});
  return std::any_of(report.diagnostics.begin(), report.diagnostics.end(),
                     [](const Diagnostic& d) { return d.rule == "urdf-repeated-element"; });
}

}  // namespace

TEST_CASE("urdf-repeated-element flags a URDF exactly when MuJoCo refuses it for a repeated element",
          "[urdf][mujoco][oracle]") {
  if (test::skip_without_reference("MuJoCo (@mujoco/mujoco)", test::mujoco_missing())) return;

  std::vector<fs::path> models;
  for (const char* dir : {"urdf-repeated-element", "structure-multiple-parents", "structure-joint-axis"})
    for (const auto& entry : fs::directory_iterator(test::fixtures_dir() / "rules" / dir))
      if (entry.path().extension() == ".urdf") models.push_back(entry.path());
  std::sort(models.begin(), models.end());
  REQUIRE(models.size() >= 4);
  const nlohmann::json compiled = test::compile_with_mujoco(models);
  REQUIRE(compiled["models"].size() == models.size());
  int refused = 0;
  for (std::size_t i = 0; i < models.size(); ++i) {
    const nlohmann::json& model = compiled["models"][i];
    const std::string error = model["error"].is_string() ? model["error"].get<std::string>() : "";
    INFO("fixture " << models[i].filename().string() << "; MuJoCo: " << (error.empty() ? "compiled" : error));
    const bool repeated = error.find("repeated element") != std::string::npos;
    refused += repeated ? 1 : 0;
    CHECK(flagged(models[i]) == repeated);
  }
  CHECK(refused >= 1);
}
