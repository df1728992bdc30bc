// `asset-lint simulate`: the stepper against closed forms, the guide's cases (PHYSICS.md
// §2–3, issue 14 §4), a stalling load, the outputs (JSON, CSV, SVG rendered by
// rsvg-convert) and bad input.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>

#include "commands/simulate_run.h"
#include "test_support.h"

using namespace assetlint;
using assetlint::test::read_file;
using assetlint::test::run_cli;
using assetlint::test::write_file;

namespace {

const std::string kUrdf = "fixtures/robotiq_2f85/robotiq_2f85.urdf";

physics::SimulationRate rate(double hz, double iterations, physics::Solver solver) {
  physics::SimulationRate r;
  r.timesteps_per_second = hz;
  r.position_iterations = iterations;
  r.solver = solver;
  return r;
}

// The URDF fixture with [drives.finger_joint] from a temporary asset-lint.toml.
struct Gripper {
  test::TempDir dir;
  explicit Gripper(const std::string& drive) {
    write_file(dir.path() / "gripper.urdf", read_file(test::fixtures_dir() / "robotiq_2f85" / "robotiq_2f85.urdf"));
    write_file(dir.path() / "asset-lint.toml", "[drives.finger_joint]\n" + drive);
  }
  nlohmann::json run(std::vector<std::string> extra) const {
    std::vector<std::string> args = {"simulate", "gripper.urdf", "--output-format", "json"};
    args.insert(args.end(), extra.begin(), extra.end());
    auto r = run_cli(args, dir.path());
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    return nlohmann::json::parse(r.out);
  }
};

}  // namespace

TEST_CASE("simulate: a critically damped, well-resolved step matches the closed form within 1 %", "[simulate]") {
  // I = 1, k = 100 (nf = 10 rad/s), d = 2·sqrt(k·I) = 20; TGS 1000 Hz × 4: h·nf = 0.0025.
  commands::SimulationSetup setup;
  setup.row = physics::drive_row(rate(1000, 4, physics::Solver::TGS), 100.0, 20.0, DriveType::Force, 1.0);
  setup.from = 0;
  setup.target = 1;
  setup.frames = 2000;
  const auto run = commands::run_simulation(setup);
  double worst = 0;
  for (const auto& s : run.implicit) {
    const double w = 10.0 * s.time;
    worst = std::max(worst, std::abs(s.position - (1.0 - (1.0 + w) * std::exp(-w))));
  }
  CHECK(worst < 0.01);
  // q(t90): 1 − (1 + ωt)e^(−ωt) = 0.9 at ωt = 3.890: t = 0.389 s.
  REQUIRE(run.implicit_metrics.time_to_90);
  CHECK(*run.implicit_metrics.time_to_90 == Approx(0.389).epsilon(0.01));
  CHECK(run.implicit_metrics.overshoot < 1e-3);
  CHECK(run.implicit_metrics.velocity_sign_changes == 0);
  CHECK_FALSE(run.explicit_metrics.diverged);
}

TEST_CASE("simulate: the guide's 5700 N·m/rad at 250 Hz × 64: the explicit spring diverges, PhysX's row converges",
          "[simulate][cli]") {
  Gripper g("stiffness = 5700\ndamping = 0.277\n");
  // On the guide's lighter link h·nf = 1/16000 × sqrt(5700 / 3.37e-6) = 2.57.
  const auto doc = g.run({"--rate", "250", "--position-iterations", "64", "--inertia", "lighter-link"});
  CHECK(doc["h_s"].get<double>() == Approx(1.0 / 16000));
  CHECK(doc["inertia"].get<double>() == Approx(3.37e-6).epsilon(1e-3));
  CHECK(doc["implicit_factor"].get<double>() == Approx(0.078).epsilon(0.01));
  CHECK(doc["explicit_stable"] == false);
  CHECK(doc["implicit"]["diverged"] == false);
  CHECK(doc["implicit"]["time_to_98_s"].is_number());
  // The max velocity (2.9 rad/s) decides the motion: 0.82 rad takes ≈ 0.283 s.
  CHECK(doc["implicit"]["velocity_clamped_s"].get<double>() > 0.2);
}

TEST_CASE("simulate: 275 N·m/rad + 5e-3 armature at 60 Hz: PGS explicit diverges (h·nf = 3.9), TGS both fine",
          "[simulate][cli]") {
  Gripper g("stiffness = 275\ndamping = 0.061\narmature = 5e-3\n");
  const auto pgs = g.run({"--rate", "60", "--position-iterations", "64", "--solver", "PGS", "--duration", "2"});
  CHECK(pgs["h_s"].get<double>() == Approx(1.0 / 60));
  CHECK(pgs["explicit_stable"] == false);
  CHECK(pgs["implicit"]["diverged"] == false);
  const auto tgs = g.run({"--rate", "60", "--position-iterations", "64", "--solver", "TGS", "--duration", "2"});
  CHECK(tgs["h_s"].get<double>() == Approx(1.0 / 3840));
  CHECK(tgs["explicit_stable"] == true);
  CHECK(tgs["explicit"]["diverged"] == false);
  CHECK(tgs["implicit"]["diverged"] == false);
  CHECK(tgs["implicit"]["time_to_98_s"].is_number());
}

TEST_CASE("simulate: a load above max force stalls the joint, and the report says so", "[simulate][cli]") {
  Gripper g("stiffness = 275\ndamping = 0.061\n");
  const std::vector<std::string> pgs = {"--rate", "250", "--position-iterations", "64", "--solver", "PGS",
                                        "--load-torque", "30"};
  std::vector<std::string> args = {"simulate", "gripper.urdf"};
  args.insert(args.end(), pgs.begin(), pgs.end());
  auto r = run_cli(args, g.dir.path());
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("The joint stalls: the load holds it 47 deg short of the target with the drive at its max force "
                   "24 N·m.") != std::string::npos);
  const auto doc = g.run(pgs);
  CHECK(doc["implicit"]["stalled"] == true);
  CHECK(doc["implicit"]["final_force"].get<double>() == Approx(24.0).epsilon(1e-6));
  CHECK(doc["implicit"]["steady_state_error"].get<double>() == Approx(0.820305).epsilon(1e-6));  // held at 0 by the limit
  // Under TGS the max joint velocity (2.9 rad/s) absorbs the load after each sub-step, as PhysX does
  // (tests/physx_reference: "load-30"): the joint closes regardless.
  const auto tgs = g.run({"--rate", "250", "--position-iterations", "64", "--load-torque", "30"});
  CHECK(tgs["implicit"]["stalled"] == false);
  CHECK(tgs["implicit"]["time_to_90_s"].is_number());
  auto t = run_cli({"simulate", "gripper.urdf", "--rate", "250", "--position-iterations", "64", "--load-torque", "30"},
                   g.dir.path());
  CHECK(t.out.find("The load (30 N·m) exceeds the max force, yet the joint moves on") != std::string::npos);
}

TEST_CASE("simulate: --csv and --plot write the series, rsvg-convert renders the SVG", "[simulate][cli]") {
  Gripper g("stiffness = 275\ndamping = 0.061\n");
  auto r = run_cli({"simulate", "gripper.urdf", "--rate", "250", "--position-iterations", "64", "--csv", "run.csv",
                    "--plot", "run.svg", "--duration", "0.5"},
                   g.dir.path());
  REQUIRE(r.exit_code == 0);
  const std::string csv = read_file(g.dir.path() / "run.csv");
  CHECK(csv.starts_with("time_s,implicit_position_rad,implicit_velocity_rad_s,implicit_force,explicit_position_rad,"));
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 127);  // header + 126 frames (t = 0 … 0.5 s)
  const std::string svg = read_file(g.dir.path() / "run.svg");
  CHECK(svg.find("position (deg)") != std::string::npos);
  CHECK(svg.find("drive force (N·m)") != std::string::npos);
  CHECK(svg.find("time (s)") != std::string::npos);
  if (std::system("command -v rsvg-convert >/dev/null 2>&1") != 0) {
    WARN("rsvg-convert not installed (Debian librsvg2-bin, scripts/bootstrap.sh): SVG rendering not checked");
    return;
  }
  const auto png = g.dir.path() / "run.png";
  const std::string command = "rsvg-convert -w 800 -o '" + png.string() + "' '" + (g.dir.path() / "run.svg").string() + "'";
  CHECK(std::system(command.c_str()) == 0);
  CHECK(std::filesystem::file_size(png) > 10000);
}

TEST_CASE("simulate: bad input is one line naming it, exit 2, work is bounded", "[simulate][cli]") {
  Gripper g("stiffness = 275\n");
  const auto error = [&](std::vector<std::string> args) {
    args.insert(args.begin(), {"simulate", "gripper.urdf"});
    auto r = run_cli(args, g.dir.path());
    CHECK(r.exit_code == 2);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    return r.err;
  };
  CHECK(error({"--duration", "0"}) == "asset-lint simulate: error: --duration must be a finite number > 0, got '0'\n");
  CHECK(error({"--duration", "nan"}) == "asset-lint simulate: error: --duration must be a finite number > 0, got 'nan'\n");
  CHECK(error({"--rate", "-60"}) == "asset-lint simulate: error: --rate must be a finite number > 0, got '-60'\n");
  CHECK(error({"--from", "inf"}) == "asset-lint simulate: error: --from must be a finite number, got 'inf'\n");
  CHECK(error({"--joint", "left_inner_finger_joint"}) ==
        "asset-lint simulate: error: gripper.urdf: --joint names 'left_inner_finger_joint', a mimic of 'finger_joint': "
        "name the joint it follows\n");
  CHECK(error({"--duration", "1000", "--rate", "250", "--position-iterations", "64"}) ==
        "asset-lint simulate: error: --duration 1000 s at 250 Hz with 64 sub-steps is 3.2e7 solver steps, above the "
        "limit of 2e7: shorten the duration\n");
  Gripper undriven("damping = 1\n");
  auto r = run_cli({"simulate", "gripper.urdf"}, undriven.dir.path());
  CHECK(r.exit_code == 2);
  CHECK(r.err == "asset-lint simulate: error: gripper.urdf: joint 'finger_joint' has no drive stiffness: author one in "
                 "the asset or set [drives.finger_joint] stiffness (`asset-lint tune --apply` derives it)\n");
}

TEST_CASE("simulate and tune on the Robotiq stack of the corpus (configuration layer over payloads)", "[simulate][corpus]") {
  const auto corpus = test::corpus_dir();
  if (corpus.empty()) {
    WARN("../shared/corpus is absent: the Robotiq stack is not checked");
    return;
  }
  const auto stack = corpus / "usda" / "robotiq_2f85";
  const std::string top = (stack / "configuration" / "Robotiq_2F_85_config_physics_parallel_grip.usda").string();
  // The payload layers sit beside the configuration directory: --root takes them in.
  auto r = run_cli({"simulate", top, "--root", stack.string(), "--output-format", "json"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto doc = nlohmann::json::parse(r.out);
  CHECK(doc["joint"] == "/Robotiq_2F_85/Robotiq_2F_85/Joints/finger_joint");
  // Three bodies author no mass (their colliders would give it): the default falls back to the
  // guide's lighter link and says why.
  CHECK(doc["inertia_origin"].get<std::string>().starts_with("the guide's lighter link: the mechanism inertia is unknown"));
  CHECK(doc["inertia"].get<double>() == Approx(1.16e-4).epsilon(0.01));
  CHECK(doc["stiffness"].get<double>() == Approx(171.9).epsilon(1e-3));
  CHECK(doc["h_s"].get<double>() == Approx(1.0 / 3840));
  CHECK(doc["implicit"]["time_to_98_s"].is_number());
  CHECK(doc["implicit"]["diverged"] == false);
  auto asked = run_cli({"simulate", top, "--root", stack.string(), "--inertia", "mechanism"});
  CHECK(asked.exit_code == 2);
  // Only the bodies the mechanism moves count: the base that carries it is no part of Jᵀ·M·J.
  CHECK(asked.err.find("the mechanism inertia of joint '/Robotiq_2F_85/Robotiq_2F_85/Joints/finger_joint' is unknown "
                       "(unauthored mass: '/Robotiq_2F_85/Robotiq_2F_85/left_outer_knuckle', "
                       "'/Robotiq_2F_85/Robotiq_2F_85/right_outer_knuckle')") != std::string::npos);
  CHECK(run_cli({"tune", top, "--root", stack.string()}).exit_code == 0);
}

TEST_CASE("simulate on MJCF steps MuJoCo's integrator, not PhysX's row", "[simulate][cli][mjcf]") {
  // The same stiff, heavily damped shoulder servo (h·nf = 2.11, kv 100) under implicitfast and Euler.
  const auto run = [](const std::string& fixture) {
    const auto r = run_cli({"simulate", fixture, "--output-format", "json"}, test::fixtures_dir() / "rules" /
                                                                              "drive-natural-frequency");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    return nlohmann::json::parse(r.out);
  };
  const auto fast = run("servo_implicitfast.xml");
  CHECK(fast["engine"] == "MuJoCo (implicitfast)");
  CHECK(fast["integrator"] == "implicitfast");
  CHECK(fast["implicit_factor"].is_null());
  CHECK(fast["h_s"].get<double>() == Approx(0.002));
  CHECK(fast["implicit"]["diverged"] == false);
  // Stepped by physics::mujoco_step (checked against libmujoco's trajectory): the force range
  // saturates the servo on the way, and it settles within 0.05 % of the 360° move.
  CHECK(fast["implicit"]["force_clamped_s"].get<double>() > 0.1);
  CHECK(fast["implicit"]["time_to_98_s"].get<double>() == Approx(0.316).margin(0.002));
  CHECK(std::abs(fast["implicit"]["steady_state_error"].get<double>()) < 1e-3);
  const std::string setup = fast["setup"].dump();
  CHECK(setup.find("Integrator: implicitfast (servo_implicitfast.xml:4): one step's spectral radius 0.96") !=
        std::string::npos);

  // Euler takes kv explicitly: MuJoCo's own step is the explicit spring, bounded only by the force range.
  const auto euler = run("servo_euler.xml");
  CHECK(euler["engine"] == "MuJoCo (Euler)");
  CHECK(euler["implicit"]["velocity_sign_changes"] == euler["explicit"]["velocity_sign_changes"]);
  CHECK(euler["implicit"]["velocity_sign_changes"].get<int>() > 100);
  const auto text = run_cli({"simulate", "servo_euler.xml"}, test::fixtures_dir() / "rules" / "drive-natural-frequency");
  CHECK(text.out.find("MuJoCo (Euler) is unstable at this step (spectral radius 115 per step); only the force range "
                      "keeps it bounded. Under implicitfast, which solves kv implicitly, it would be stable (spectral "
                      "radius 0.96).\n") != std::string::npos);
}
