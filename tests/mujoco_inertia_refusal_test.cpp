// inertia-invalid says "MuJoCo's compiler refuses the file" where MuJoCo's compiler does: the
// refusal rules of src/physics/mujoco_inertia.h on their own, and the rule's verdicts held to
// MuJoCo itself (tests/mujoco_reference/compile.mjs, MuJoCo 3.14 in WASM, npm @mujoco/mujoco; it
// refuses the same fixtures at the same bodies as 3.3 did) on every URDF fixture of the rule.
// Skipped with a message when `node` or @mujoco/mujoco is absent; a failure under CI=true.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "engine/settings.h"
#include "physics/mujoco_inertia.h"
#include "pipeline/lint.h"
#include "support/mujoco_oracle.h"
#include "test_support.h"

using namespace assetlint;
namespace fs = std::filesystem;

namespace {

Eigen::Matrix3d tensor(double ixx, double iyy, double izz, double ixy = 0, double ixz = 0, double iyz = 0) {
  Eigen::Matrix3d m;
  m << ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz;
  return m;
}

// The links inertia-invalid says MuJoCo refuses the file at, in one lint of `file`.
std::set<std::string> refused_links(const fs::path& file) {
  const FileReport report = lint_file(file.string(), Settings{});
  std::set<std::string> links;
  const std::regex named("link '([^']+)'");
  for (const Diagnostic& d : report.diagnostics) {
    if (d.rule != "inertia-invalid") continue;
    const bool refusal = std::any_of(d.notes.begin(), d.notes.end(), [](const Note& n) {
      return n.message.find("MuJoCo's compiler refuses") != std::string::npos ||
             n.message.find("MuJoCo refuses the file") != std::string::npos;
    });
    std::smatch m;
    if ((refusal || d.message.find("MuJoCo refuses") != std::string::npos) && std::regex_search(d.message, m, named))
      links.insert(m[1]);
  }
  return links;
}

}  // namespace

TEST_CASE("MuJoCo's inertia refusals: eigenvalues of a full tensor, A + B >= C exactly, bounds first", "[inertia][mujoco]") {
  using physics::MujocoInertiaInput;
  using physics::mujoco_inertia_refusal;
  const MujocoInertiaInput full;
  CHECK_FALSE(mujoco_inertia_refusal(tensor(0, 0, 0), full));  // six zeros: no tensor written
  CHECK(mujoco_inertia_refusal(tensor(-1e-20, 1e-20, 1e-20), full) == "inertia must have positive eigenvalues");
  CHECK(mujoco_inertia_refusal(tensor(1e-15, 1e-9, 1e-9), full));  // under mjEPS = 1e-14
  CHECK_FALSE(mujoco_inertia_refusal(tensor(2e-14, 2e-14, 2e-14), full));
  // A thin plate rounded up by half a unit in its last digit: refused unless balanced.
  const Eigen::Matrix3d plate = tensor(0.001437, 0.001437, 0.002875);
  CHECK(mujoco_inertia_refusal(plate, full) == "inertia must satisfy A + B >= C; use 'balanceinertia' to fix");
  MujocoInertiaInput balanced;
  balanced.balanceinertia = true;
  CHECK_FALSE(mujoco_inertia_refusal(plate, balanced));
  CHECK_FALSE(mujoco_inertia_refusal(tensor(0.001, 0.001, 0.002), full));  // an exact plate
  // A diagonal tensor is never diagonalised: only a negative moment or A + B < C refuses it.
  MujocoInertiaInput diagonal;
  diagonal.form = MujocoInertiaInput::Form::Diagonal;
  CHECK_FALSE(mujoco_inertia_refusal(tensor(1e-20, 1e-20, 1e-20), diagonal));
  // A negative diagonal moment is raised to boundinertia (0) before any check: accepted when the
  // triangle holds then, refused when it does not.
  CHECK_FALSE(mujoco_inertia_refusal(tensor(-1e-6, 1e-6, 1e-6), diagonal));
  CHECK(mujoco_inertia_refusal(tensor(-1e-6, 1e-6, 3e-6), diagonal));
  // boundinertia raises the small moments before the triangle check.
  diagonal.boundinertia = 0.002;
  CHECK_FALSE(mujoco_inertia_refusal(plate, diagonal));
}

TEST_CASE("inertia-invalid names MuJoCo's refusal of a URDF exactly where MuJoCo's compiler refuses it",
          "[inertia][mujoco][oracle]") {
  if (test::skip_without_reference("MuJoCo (@mujoco/mujoco)", test::mujoco_missing())) return;

  std::vector<fs::path> models;
  for (const auto& entry : fs::directory_iterator(test::fixtures_dir() / "rules" / "inertia-invalid"))
    if (entry.path().extension() == ".urdf") models.push_back(entry.path());
  std::sort(models.begin(), models.end());
  REQUIRE(models.size() >= 10);
  const nlohmann::json compiled = test::compile_with_mujoco(models);
  REQUIRE(compiled["models"].size() == models.size());

  // The errors of MuJoCo's compiler a link's mass properties cause, and the body they name.
  const std::regex inertia_error(
      "(inertia must|mass and inertia cannot be negative|mass and inertia of moving bodies).*Element name '([^']+)'");
  int refused = 0;
  for (std::size_t i = 0; i < models.size(); ++i) {
    const nlohmann::json& model = compiled["models"][i];
    const std::string error = model["error"].is_string() ? model["error"].get<std::string>() : "";
    const std::set<std::string> claimed = refused_links(models[i]);
    INFO("fixture " << models[i].filename().string() << "; MuJoCo: " << (error.empty() ? "compiled" : error));
    std::smatch m;
    if (std::regex_search(error, m, inertia_error) && claimed.count(m[2])) ++refused;
    // Every claim is MuJoCo's, and MuJoCo stops at the first body it refuses: one of the claimed.
    if (!claimed.empty()) CHECK((std::regex_search(error, m, inertia_error) && claimed.count(m[2]) == 1));
    // A tensor MuJoCo refuses is claimed (the massless moving body is only claimed when it is drawn
    // without a collision shape; other massless bodies get their error without that note).
    if (error.find("inertia must") != std::string::npos || error.find("cannot be negative") != std::string::npos)
      CHECK(!claimed.empty());
  }
  CHECK(refused >= 6);
}
