// `simulate` and `verify` on a .xacro top file: expanded in memory with --xacro-arg and
// $(find pkg) as `check` expands it (tune's xacro cases are in tune_apply_test.cpp).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "test_support.h"

using namespace assetlint;
using assetlint::test::run_cli;
using assetlint::test::write_file;

TEST_CASE("xacro: simulate reads a .xacro top file", "[xacro][simulate][cli]") {
  const auto demo = test::fixtures_dir() / "xacro" / "demo_gripper_description" / "urdf" / "demo_gripper.urdf.xacro";
  test::TempDir dir;
  write_file(dir.path() / "asset-lint.toml", "[drives.left_finger_joint]\nstiffness = 100\ndamping = 1\n");
  const auto simulate = run_cli({"simulate", demo.string(), "--joint", "left_finger_joint", "--rate", "250",
                                 "--position-iterations", "64", "--config", (dir.path() / "asset-lint.toml").string()});
  INFO(simulate.out << simulate.err);
  CHECK(simulate.exit_code == 0);
  CHECK(simulate.out.find("left_finger_joint") != std::string::npos);
}

TEST_CASE("xacro: tune and verify on the ros-industrial 2F-85 package's top xacro file", "[xacro][verify][corpus]") {
  const auto corpus = test::corpus_dir();
  const auto top = corpus / "packages" / "ros-industrial-robotiq" / "robotiq_2f_85_gripper_visualization" / "urdf" /
                   "robotiq_arg2f_85_model.xacro";
  if (corpus.empty() || !std::filesystem::exists(top)) {
    WARN("../shared/corpus is absent: the xacro package is skipped");
    return;
  }
  const auto tune = run_cli({"tune", top.string(), "--payload-kg", "5", "--friction", "0.3"});
  INFO(tune.out << tune.err);
  REQUIRE(tune.exit_code == 0);
  CHECK(tune.out.find("'finger_joint'") != std::string::npos);
  CHECK(tune.out.find("robotiq_arg2f_85_model_macro.xacro:") != std::string::npos);

  // The guide's spec and final tuning, as in the expanded URDF's verification.
  test::TempDir dir;
  write_file(dir.path() / "asset-lint.toml",
             "[simulation]\ntimesteps_per_second = 250\nposition_iterations = 64\n\n"
             "[gripper]\npayload_kg = 5\nfriction = 0.3\nlever_arm_m = 0.04\ngravity = 10\nfinger_speed_m_s = 0.15\n"
             "stroke_m = 0.085\ndriven_joint = \"finger_joint\"\n\n"
             "[drives.finger_joint]\nstiffness = 275\ndamping = 0.06089\nmax_force = 24\n\n[verify]\nwindow_s = 0.3\n");
  const auto verify = run_cli({"verify", top.string(), "--config", (dir.path() / "asset-lint.toml").string(),
                               "--output-format", "json"},
                              dir.path());
  INFO(verify.out << verify.err);
  REQUIRE(verify.exit_code != 2);  // the meshes' package:// resolved, the scenes ran
  // A run of several seconds says which scene it is at, on standard error.
  CHECK(verify.err.find(" of 8 (hold, gravity on, ") != std::string::npos);
  CHECK(verify.err.find(" engine steps so far, ") != std::string::npos);
  const auto report = nlohmann::json::parse(verify.out);
  std::size_t ran = 0;
  for (const auto& scene : report["scenes"]) ran += scene["ran"].get<bool>() ? 1 : 0;
  CHECK(ran >= 4);
}
