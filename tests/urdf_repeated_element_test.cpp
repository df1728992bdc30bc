// urdf-repeated-element says "MuJoCo's URDF importer refuses the file" exactly where MuJoCo does:
// every URDF fixture of the rule, and the rule's other fixtures' neighbours, compiled by MuJoCo
// itself (tests/mujoco_reference/compile.mjs, MuJoCo 3.14 in WASM, npm @mujoco/mujoco).
// Skipped with a message when `node` or @mujoco/mujoco is absent; a failure under CI=true.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/settings.h"
#include "pipeline/lint.h"
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
  const auto package = test::source_dir() / "tools" / "node_modules" / "@mujoco" / "mujoco";
  std::string missing;
  if (!test::on_path("node")) missing = "node not found on PATH";
  else if (!fs::exists(package / "mujoco.js"))
    missing = "@mujoco/mujoco is not installed in tools/node_modules: scripts/bootstrap.sh was not run";
  if (test::skip_without_reference("MuJoCo (@mujoco/mujoco)", missing)) return;

  std::vector<fs::path> models;
  for (const char* dir : {"urdf-repeated-element", "structure-multiple-parents", "structure-joint-axis"})
    for (const auto& entry : fs::directory_iterator(test::fixtures_dir() / "rules" / dir))
      if (entry.path().extension() == ".urdf") models.push_back(entry.path());
  std::sort(models.begin(), models.end());
  REQUIRE(models.size() >= 4);
  test::TempDir dir;
  const auto out = dir.path() / "out.json", err = dir.path() / "err.txt";
  std::string command = "timeout 300 node " +
                        test::shell_quote((test::source_dir() / "tests" / "mujoco_reference" / "compile.mjs").string()) +
                        " " + test::shell_quote(package.string());
  for (const auto& model : models) command += " " + test::shell_quote(model.string());
  command += " >" + test::shell_quote(out.string()) + " 2>" + test::shell_quote(err.string()) + " </dev/null";
  REQUIRE(std::system(command.c_str()) == 0);
  const nlohmann::json compiled = nlohmann::json::parse(test::read_file(out));
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
