// `asset-lint verify` on the ros-industrial Robotiq 2F-85 description (the corpus's expanded
// URDF, Collada collision meshes from its package) with the guide's spec and final tuning.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "test_support.h"

using assetlint::test::read_file;
using assetlint::test::replace_once;
using assetlint::test::run_cli;
using assetlint::test::write_file;

namespace {

// The guide's spec sheet and its final tuning of the driven joint.
std::string config(const std::string& stiffness, const std::string& damping) {
  return "[simulation]\ntimesteps_per_second = 250\nposition_iterations = 64\n\n"
         "[gripper]\npayload_kg = 5\nfriction = 0.3\nlever_arm_m = 0.04\ngravity = 10\nfinger_speed_m_s = 0.15\n"
         "stroke_m = 0.085\ndriven_joint = \"finger_joint\"\n\n"
         "[drives.finger_joint]\nstiffness = " + stiffness + "\ndamping = " + damping + "\nmax_force = 24\n\n"
         "[verify]\nwindow_s = 0.3\n";
}

}  // namespace

TEST_CASE("verify: the ros-industrial 2F-85 with the guide's spec and final tuning holds 5 kg at every width",
          "[verify][corpus]") {
  const auto corpus = assetlint::test::corpus_dir();
  const auto urdf = corpus / "urdf" / "robotiq2f85__rosindustrial_arg2f_85_model.urdf";
  if (corpus.empty() || !std::filesystem::exists(urdf)) {
    WARN("../shared/corpus is absent: the 2F-85 verification is skipped");
    return;
  }
  assetlint::test::TempDir dir;
  // The final tuning's max joint velocity: the joint's 0.8 rad in the spec's close time,
  // (0.085 m / 2) / 0.15 m/s = 0.2833 s, is 2.824 rad/s (the file says 2.0).
  write_file(dir.path() / "r85.urdf", replace_once(read_file(urdf), "upper=\"0.8\" velocity=\"2.0\"",
                                                   "upper=\"0.8\" velocity=\"2.824\""));
  const auto run = [&](const std::string& stiffness, const std::string& damping) {
    write_file(dir.path() / "asset-lint.toml", config(stiffness, damping));
    auto r = run_cli({"verify", "r85.urdf", "--root", corpus.string(), "--output-format", "json"}, dir.path());
    INFO(r.out << r.err);
    REQUIRE(r.exit_code == 0);
    return nlohmann::json::parse(r.out);
  };
  const auto report = run("275", "0.06089");
  CHECK(report["passed"] == true);
  CHECK(report["engine"]["timestep_s"].get<double>() == Approx(1.0 / 16000));  // TGS h = dt/64 at 250 Hz
  const auto& scenes = report["scenes"];
  REQUIRE(scenes.size() == 8);
  // Close: the target ramps 0.8 rad at 2.824 rad/s = 0.2833 s, the spec's (0.085/2)/0.15.
  CHECK(scenes[0]["metrics"]["spec_close_time_s"].get<double>() == Approx(0.2833).epsilon(0.001));
  CHECK(scenes[0]["metrics"]["close_time_s"].get<double>() == Approx(0.2833).epsilon(0.05));
  for (std::size_t i = 1; i < 8; ++i) {
    const auto& m = scenes[i]["metrics"];
    INFO(scenes[i]["name"]);
    CHECK(scenes[i]["object"]["mass_kg"].get<double>() == 5.0);
    CHECK(m["peak_penetration_m"].get<double>() < 1e-4);
    if (m.contains("grip_force_n")) {
      // m·g/μ = 5 × 10 / 0.3 = 166.7 N; the drive's 24 N·m squeezes well past it.
      CHECK(m["required_grip_force_n"].get<double>() == Approx(166.667).epsilon(1e-4));
      CHECK(m["grip_force_n"].get<double>() > 166.667);
    }
    if (m.contains("slip_m")) CHECK(m["slip_m"].get<double>() < 0.001);
  }
  // The boxes: met at 10 % and 50 % of the 0.8 rad stroke and 5° before closed, the widest
  // within the 85 mm the spec gives between the open fingers.
  CHECK(scenes[1]["object"]["width_m"].get<double>() < 0.085);
  CHECK(scenes[1]["object"]["width_m"].get<double>() > scenes[2]["object"]["width_m"].get<double>());
  CHECK(scenes[2]["object"]["width_m"].get<double>() > scenes[3]["object"]["width_m"].get<double>());
  // The original 5700 N·m/rad: at MuJoCo's 1/16000 s step with the damping solved implicitly, the
  // drive is resolved and the squeeze is still bounded by the 24 N·m max force: the same verdicts.
  const auto original = run("5700", "0.1");
  CHECK(original["passed"] == true);
  for (std::size_t i = 1; i < 8; ++i)
    if (scenes[i]["metrics"].contains("grip_force_n"))
      CHECK(original["scenes"][i]["metrics"]["grip_force_n"].get<double>() ==
            Approx(scenes[i]["metrics"]["grip_force_n"].get<double>()).epsilon(0.01));
}
