// `asset-lint verify`: the guide's scenes stepped in MuJoCo on a gripper whose answers are
// known by hand (fixtures/verify/two_finger: two 50 g prismatic box fingers, one a mimic).
// The drive pushes the driven finger with F; the mimic constraint carries the other finger's
// reaction back, so each pad presses with F/2 and friction holds 2·μ·(F/2) = μ·F. The box of
// 0.5 kg at g = 10 with μ = 0.5 needs F ≥ m·g/μ = 10 N.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "test_support.h"
#include "verify_support.h"

using assetlint::test::read_file;
using assetlint::test::replace_once;
using assetlint::test::run_cli;
using assetlint::test::write_file;
using assetlint::test::check_two_finger_holds;
using assetlint::test::check_two_finger_slips;

namespace {

const std::filesystem::path kFixture = assetlint::test::fixtures_dir() / "verify" / "two_finger";

// The fixture in a temporary directory, its asset-lint.toml edited by `edit`.
struct TwoFinger {
  assetlint::test::TempDir dir;
  explicit TwoFinger(const std::function<std::string(std::string)>& edit = [](std::string t) { return t; },
                     const std::function<std::string(std::string)>& edit_urdf = [](std::string t) { return t; }) {
    write_file(dir.path() / "two_finger.urdf", edit_urdf(read_file(kFixture / "two_finger.urdf")));
    write_file(dir.path() / "asset-lint.toml", edit(read_file(kFixture / "asset-lint.toml")));
  }
  assetlint::test::CommandResult run(std::vector<std::string> extra = {}) const {
    std::vector<std::string> args = {"verify", "two_finger.urdf", "--output-format", "json"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_cli(args, dir.path());
  }
};

const nlohmann::json& scene(const nlohmann::json& report, const std::string& kind, int nth = 0) {
  return assetlint::test::verify_scene(report, kind, nth);
}

// The fixture's report at h = 4 ms (250 Hz, one iteration) with an undamped drive: it fails (exit 1).
nlohmann::json undamped_at_coarse_step(const std::string& stiffness, const std::string& max_force) {
  TwoFinger gripper([&](std::string t) {
    t = replace_once(t, "position_iterations = 4", "position_iterations = 1");
    t = replace_once(t, "stiffness = 4000", "stiffness = " + stiffness);
    t = replace_once(t, "damping = 40", "damping = 0");
    return replace_once(t, "max_force = 20", "max_force = " + max_force);
  });
  const auto r = gripper.run();
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 1);
  return nlohmann::json::parse(r.out);
}

}  // namespace

TEST_CASE("verify: twice the required squeeze holds at every width and the close time is stroke/(2·finger speed)",
          "[verify]") {
  TwoFinger gripper;
  const auto r = gripper.run();
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const auto report = nlohmann::json::parse(r.out);
  CHECK(report["passed"] == true);
  CHECK(report["engine"]["name"] == "mujoco");
  CHECK(report["engine"]["timestep_s"].get<double>() == Approx(0.001));  // 250 Hz / 4 position iterations
  CHECK(report["engine"]["cone"] == "elliptic");
  check_two_finger_holds(report);
}

TEST_CASE("verify: half the required squeeze slips and fails", "[verify]") {
  // 5 N: μ·F = 2.5 N of friction against the box's 5 N weight.
  TwoFinger gripper(
      [](std::string t) {
        t = replace_once(t, "stiffness = 4000", "stiffness = 1000");
        t = replace_once(t, "damping = 40", "damping = 20");
        return replace_once(t, "max_force = 20", "max_force = 5");
      });
  const auto r = gripper.run();
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 1);
  const auto report = nlohmann::json::parse(r.out);
  check_two_finger_slips(report);
}

TEST_CASE("verify: a too-stiff undamped drive at a coarse step fails", "[verify]") {
  // h = 4 ms; k = 4e6 N/m on 0.1 kg: h·nf = 0.004 × 6325 = 25, no damping.
  const auto report = undamped_at_coarse_step("4000000", "20");
  // The fingers slam into the boxes: every box scene fails, on penetration, jitter or divergence.
  for (const auto& s : report["scenes"]) {
    if (s["kind"] == "close") continue;
    INFO(s["name"]);
    CHECK(s["passed"] == false);
    const std::string failure = s["failures"][0].get<std::string>();
    CHECK((failure.find("penetration") != std::string::npos || failure.find("jitter") != std::string::npos ||
           failure.find("diverged") != std::string::npos));
  }
  CHECK(scene(report, "grasp", 1)["metrics"]["peak_penetration_m"].get<double>() > 0.002);
}

TEST_CASE("verify: the box is turned with the fingers, whichever axis they close along", "[verify]") {
  // With a max force the spring never reaches, the squeeze tells where the fingers met the box: each
  // finger travels 45 mm toward closed and meets a box of width w after (90 mm − w)/2, so the drive
  // stops w/2 short of its target and pushes k·w/2: 4000 N/m × 40.5, 22.5 and 5 mm = 162, 90 and 20 N.
  // A box turned a quarter turn would offer the fingers its 18 mm depth instead, at every width.
  const auto unsaturated = [](std::string t) { return replace_once(t, "max_force = 20", "max_force = 1000"); };
  const auto along_y = [](std::string t) {
    t = replace_once(t, "<box size=\"0.12 0.04 0.02\"/>", "<box size=\"0.04 0.12 0.02\"/>");
    for (int i = 0; i < 2; ++i) t = replace_once(t, "<box size=\"0.01 0.02 0.06\"/>", "<box size=\"0.02 0.01 0.06\"/>");
    t = replace_once(t, "<origin xyz=\"-0.05 0 0.05\"/><axis xyz=\"1 0 0\"/>", "<origin xyz=\"0 -0.05 0.05\"/><axis xyz=\"0 1 0\"/>");
    return replace_once(t, "<origin xyz=\"0.05 0 0.05\"/><axis xyz=\"-1 0 0\"/>", "<origin xyz=\"0 0.05 0.05\"/><axis xyz=\"0 -1 0\"/>");
  };
  for (const bool y : {false, true}) {
    INFO((y ? "closing along y" : "closing along x"));
    TwoFinger gripper(unsaturated, y ? along_y : [](std::string t) { return t; });
    const auto r = gripper.run();
    INFO(r.out << r.err);
    REQUIRE(r.exit_code == 0);
    const auto report = nlohmann::json::parse(r.out);
    const double widths[] = {0.081, 0.045, 0.010};
    for (int i = 0; i < 3; ++i) {
      const auto& grasp = scene(report, "grasp", i);
      CHECK(grasp["object"]["width_m"].get<double>() == Approx(widths[i]));
      CHECK(grasp["metrics"]["grip_force_n"].get<double>() == Approx(4000 * widths[i] / 2).epsilon(0.02));
    }
  }
}

TEST_CASE("verify: a drive too stiff for the step creates energy, and that is a divergence", "[verify]") {
  // h = 4 ms (250 Hz, one iteration), k = 2e5 N/m on the 0.1 kg of both fingers, no damping:
  // ω·h = √(2e5 / 0.1) × 0.004 = 5.7, past the 2 at which the step's explicit spring goes unstable
  // (the implicit integrator solves only the damping, here none). The state stays finite, clamped
  // by the 1000 N max force, but with gravity off and the mount still only the drive feeds the
  // scene, at most 2 × 1000 N × 45 mm = 90 J; the fingers reach hundreds of joules.
  const auto report = undamped_at_coarse_step("200000", "1000");
  for (const auto& s : report["scenes"]) {
    if (s["kind"] != "close" && s["kind"] != "grasp") continue;
    INFO(s["name"]);
    CHECK(s["metrics"]["diverged"] == true);
    const std::string failure = s["failures"][0].get<std::string>();
    CHECK(failure.find("diverged: kinetic energy reached") != std::string::npos);
    CHECK(failure.find("more than the 90 J the drive can supply (2 × 1000 N × the 0.045 m stroke)") != std::string::npos);
  }
}

TEST_CASE("verify: two runs give byte-identical JSON and the text names every input's origin", "[verify]") {
  TwoFinger gripper;
  const auto a = gripper.run(), b = gripper.run();
  CHECK(a.out == b.out);
  const auto text = run_cli({"verify", "two_finger.urdf"}, gripper.dir.path());
  CHECK(text.exit_code == 0);
  CHECK(text.out.find("payload 0.5 kg (asset-lint.toml:") != std::string::npos);
  CHECK(text.out.find("stiffness 4000 N/m (asset-lint.toml:") != std::string::npos);
  CHECK(text.out.find("max velocity 0.1 m/s (two_finger.urdf:") != std::string::npos);
  CHECK(text.out.find("Passed: 8 passed, 0 failed, 0 not run.") != std::string::npos);
}

TEST_CASE("verify: --plot writes an SVG that rsvg-convert renders", "[verify]") {
  TwoFinger gripper;
  const auto r = gripper.run({"--plot", "verify.svg"});
  REQUIRE(r.exit_code == 0);
  const std::string svg = read_file(gripper.dir.path() / "verify.svg");
  CHECK(svg.find("close: finger opening (mm)") != std::string::npos);
  CHECK(svg.find("grasp: penetration (mm)") != std::string::npos);
  CHECK(svg.find("hold: slip since gravity on (mm)") != std::string::npos);
  if (std::system("command -v rsvg-convert >/dev/null 2>&1") != 0) {
    if (assetlint::test::in_ci()) FAIL("rsvg-convert missing under CI=true (scripts/bootstrap.sh installs librsvg2-bin)");
    WARN("rsvg-convert not installed (Debian librsvg2-bin, scripts/bootstrap.sh): SVG rendering not checked");
    return;
  }
  const auto png = gripper.dir.path() / "verify.png";
  const std::string command =
      "rsvg-convert -w 800 -o '" + png.string() + "' '" + (gripper.dir.path() / "verify.svg").string() + "'";
  CHECK(std::system(command.c_str()) == 0);
  CHECK(std::filesystem::file_size(png) > 10000);
}

TEST_CASE("verify: scenes without a payload are not run and say why, errors exit 2 naming what is missing",
          "[verify]") {
  SECTION("no payload") {
    TwoFinger gripper([](std::string t) { return replace_once(t, "payload_kg = 0.5\n", ""); });
    const auto r = gripper.run();
    CHECK(r.exit_code == 1);
    const auto report = nlohmann::json::parse(r.out);
    CHECK(report["passed"] == false);
    CHECK(scene(report, "close")["ran"] == true);
    const auto& hold = scene(report, "hold");
    CHECK(hold["ran"] == false);
    CHECK(hold["passed"] == false);
    CHECK(hold["failures"][0].get<std::string>().find("[gripper] payload_kg") != std::string::npos);
  }
  SECTION("no collision geometry on the fingers") {
    TwoFinger gripper([](std::string t) { return t; },
                      [](std::string t) {
                        for (int i = 0; i < 2; ++i)
                          t = replace_once(t, "<collision><geometry><box size=\"0.01 0.02 0.06\"/></geometry></collision>", "");
                        return t;
                      });
    const auto r = gripper.run();
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("no collision geometry on the fingers") != std::string::npos);
    CHECK(r.err.find("'left_finger', 'right_finger'") != std::string::npos);
  }
  SECTION("no drive stiffness") {
    TwoFinger gripper([](std::string t) { return replace_once(t, "stiffness = 4000\n", ""); });
    const auto r = gripper.run();
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("[drives.finger_joint] stiffness") != std::string::npos);
  }
  SECTION("an unknown [verify] key") {
    TwoFinger gripper([](std::string t) { return t + "slip = 1\n"; });
    const auto r = gripper.run();
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("slip") != std::string::npos);
  }
}

TEST_CASE("verify --fine-tune: the lowest max force and stiffness that still hold, --apply writes them",
          "[verify]") {
  // The box needs F ≥ m·g/μ = 10 N; the fixture's drive gives 20 N. The lowest passing max force is
  // just above 10 N (the bisection stops within 2 % of 20 N); the stiffness then only needs to deliver it
  // at the 10 mm box, 5 mm before closed: k ≥ 10 N / 5 mm = 2000 N/m, also within 2 % of today's 4000.
  TwoFinger gripper;
  const auto r = gripper.run({"--fine-tune"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const auto report = nlohmann::json::parse(r.out);
  const auto& fine = report["fine_tune"];
  CHECK(fine["baseline_passed"] == true);
  CHECK(fine["today"]["max_force"].get<double>() == 20.0);
  const double force = fine["lowest"]["max_force"].get<double>();
  // MuJoCo's friction is soft: within about 10 % of the weight the box creeps past the 5 mm slip
  // threshold over the hold, so the lowest passing force sits a little above 10 N.
  CHECK(force >= 10.0);
  CHECK(force <= 1.1 * 10.0 + 0.02 * 20);
  const double stiffness = fine["lowest"]["stiffness"].get<double>();
  CHECK(stiffness >= 0.9 * force / 0.005);
  CHECK(stiffness <= force / 0.005 + 0.02 * 4000 + 200);
  // The same damping ratio: d ∝ √k.
  CHECK(fine["lowest"]["damping"].get<double>() == Approx(40.0 * std::sqrt(stiffness / 4000.0)));

  const auto applied = run_cli({"verify", "two_finger.urdf", "--fine-tune", "--apply"}, gripper.dir.path());
  INFO(applied.out << applied.err);
  CHECK(applied.exit_code == 0);
  const std::string config = read_file(gripper.dir.path() / "asset-lint.toml");
  CHECK(config.find("stiffness = 4000\n") == std::string::npos);
  CHECK(config.find("max_force = 20\n") == std::string::npos);
  CHECK(config.find("[verify]\nwindow_s = 0.3\n") != std::string::npos);  // the rest kept byte for byte
  const auto again = gripper.run();
  CHECK(again.exit_code == 0);  // the lowered drive still passes every scene
}
