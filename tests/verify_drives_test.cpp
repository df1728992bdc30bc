// `asset-lint verify` without a [gripper] spec: the drive tests of every actuated joint, on a
// one-link pendulum whose answers follow by hand. The link is 1 kg with its centre of mass
// 0.3 m from the joint and 0.01 kg·m² about it there, so the joint sees I = 0.01 + 1 × 0.3² =
// 0.1 kg·m². With the axis vertical gravity exerts no torque about it and the drive is a linear
// servo I·q̈ = k·(target − q) − d·q̇; with the axis horizontal gravity pulls m·g·l = 2.943 N·m
// when the link is horizontal (q = 0).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <numbers>

#include "test_support.h"

using assetlint::test::run_cli;
using assetlint::test::write_file;

namespace {

constexpr double kInertia = 0.1;  // kg·m² about the joint
constexpr double kG = 9.81;

std::string pendulum_urdf(const std::string& axis, const std::string& effort = "100") {
  return R"(<?xml version="1.0"?>
<robot name="pendulum">
  <link name="base">
    <inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
  </link>
  <link name="arm">
    <inertial><origin xyz="0.3 0 0"/><mass value="1"/>
      <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
  </link>
  <joint name="swing" type="revolute">
    <parent link="base"/><child link="arm"/><axis xyz=")" +
         axis + R"("/>
    <limit lower="-1" upper="1" effort=")" +
         effort + R"(" velocity="2"/>
  </joint>
</robot>
)";
}

struct Pendulum {
  assetlint::test::TempDir dir;
  Pendulum(const std::string& axis, double stiffness, double damping, const std::string& effort = "100",
           const std::string& extra = "") {
    write_file(dir.path() / "pendulum.urdf", pendulum_urdf(axis, effort));
    write_file(dir.path() / "asset-lint.toml", extra + "[drives.swing]\nstiffness = " + std::to_string(stiffness) +
                                                   "\ndamping = " + std::to_string(damping) + "\n");
  }
  assetlint::test::CommandResult text() const { return run_cli({"verify", "pendulum.urdf"}, dir.path()); }
  assetlint::test::CommandResult run(std::vector<std::string> extra = {}) const {
    std::vector<std::string> args = {"verify", "pendulum.urdf", "--output-format", "json"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_cli(args, dir.path());
  }
  // The JSON report; exit 0 or 1 (a verdict), `exit_code` when given.
  nlohmann::json report(int exit_code = -1) const {
    const auto r = run();
    INFO(r.out << r.err);
    REQUIRE(r.exit_code != 2);
    if (exit_code >= 0) REQUIRE(r.exit_code == exit_code);
    return nlohmann::json::parse(r.out);
  }
};

const nlohmann::json& test_of(const nlohmann::json& report, const std::string& kind) {
  for (const auto& s : report["scenes"])
    if (s["kind"] == kind) return s;
  FAIL("no " << kind << " test");
  static nlohmann::json none;
  return none;
}

}  // namespace

TEST_CASE("verify drives: a pendulum's step overshoots as its damping ratio says", "[verify][drives]") {
  // k = 10 N·m/rad on 0.1 kg·m²: ω = 10 rad/s; d = 0.6 N·m·s/rad gives ζ = 0.6 / (2·√(10 × 0.1)) = 0.3,
  // whose step overshoots exp(−π·0.3/√(1 − 0.09)) = 37.2 % and whose envelope e^(−ζωt)/√(1 − ζ²)
  // is inside 5 % from ln(0.05·√0.91)/(−3) = 1.01 s on.
  const double zeta = 0.3, omega = 10;
  Pendulum p("0 0 1", kInertia * omega * omega, 2 * zeta * std::sqrt(kInertia * omega * omega * kInertia));
  const auto report = p.report();
  const auto& step = test_of(report, "step");
  CHECK(step["joint"] == "swing");
  CHECK(step["ran"] == true);
  const double expected = std::exp(-std::numbers::pi * zeta / std::sqrt(1 - zeta * zeta));
  CHECK(step["metrics"]["overshoot"].get<double>() == Approx(expected).margin(0.01));
  CHECK(step["metrics"]["step_size"].get<double>() == Approx(0.5));  // a quarter of the 2 rad range < 30°
  CHECK(step["metrics"]["settle_time_s"].get<double>() < 1.02);
  CHECK(step["metrics"]["settle_time_s"].get<double>() > 0.3);
  CHECK(std::abs(step["metrics"]["steady_error"].get<double>()) < 1e-3);
  CHECK(step["passed"] == true);
  const auto& hold = test_of(report, "hold");
  CHECK(hold["metrics"]["gravity_torque_max"].get<double>() < 1e-9);  // the axis is vertical
  CHECK(hold["passed"] == true);
}

TEST_CASE("verify drives: a joint whose effort cannot hold its link horizontal fails the hold", "[verify][drives]") {
  // Axis horizontal: at q = 0 the link is horizontal and gravity pulls m·g·l = 1 × 9.81 × 0.3 = 2.943 N·m,
  // above the 2 N·m effort limit. k = 1000 with ζ = 1 (d = 2·√(1000 × 0.1) = 20).
  Pendulum p("0 1 0", 1000, 20, "2");
  const auto r = p.run();
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 1);
  const auto report = nlohmann::json::parse(r.out);
  CHECK(report["passed"] == false);
  const auto& hold = test_of(report, "hold");
  CHECK(hold["passed"] == false);
  CHECK(hold["metrics"]["gravity_torque_max"].get<double>() == Approx(1 * kG * 0.3).epsilon(0.002));
  CHECK(hold["metrics"]["gravity_torque_at"].get<double>() == Approx(0).margin(1e-9));
  CHECK(hold["metrics"]["effort_limit"].get<double>() == 2);
  CHECK(hold["metrics"]["effort_margin"].get<double>() == Approx(2 - kG * 0.3).epsilon(0.002));
  CHECK(hold["failures"][0].get<std::string>().find("> effort limit 2 N·m") != std::string::npos);
  const auto text = p.text();
  CHECK(text.out.find("max force 2.943") != std::string::npos);  // the fix raises it to gravity's pull
}

TEST_CASE("verify drives: an undamped drive rings", "[verify][drives]") {
  // kv = 0: the servo oscillates for ever at ω = √(100 / 0.1) = 31.6 rad/s (5.03 Hz), overshooting the
  // whole step and reversing twice a period: 2 × 5.03 × 6 s ≈ 60 times after the step.
  Pendulum p("0 0 1", 100, 0);
  const auto report = p.report(1);
  const auto& step = test_of(report, "step");
  CHECK(step["passed"] == false);
  CHECK(step["metrics"]["overshoot"].get<double>() == Approx(1).margin(0.03));
  const double reversals = 2 * std::sqrt(100 / kInertia) / (2 * std::numbers::pi) * 6.0;
  CHECK(step["metrics"]["sign_changes"].get<double>() == Approx(reversals).margin(3));
  CHECK(step["metrics"]["diverged"] == false);
}

TEST_CASE("verify drives: a stiff drive at a coarse step diverges", "[verify][drives]") {
  // PGS at 60 Hz steps h = 1/60 s; k = 4000 on 0.1 kg·m² is ω = 200 rad/s, ω·h = 3.3 > 2: MuJoCo
  // integrates the spring explicitly and, without damping, every step multiplies the error by the
  // root of λ² − (2 − (ω·h)²)·λ + 1, about −9. A max force would bound the state (bang-bang); this
  // one's effort is far beyond what the step needs.
  Pendulum p("0 0 1", 4000, 0, "1e6", "[simulation]\ntimesteps_per_second = 60\nsolver = \"PGS\"\n\n");
  const auto report = p.report(1);
  const auto& step = test_of(report, "step");
  CHECK(step["metrics"]["diverged"] == true);
  CHECK(step["failures"][0].get<std::string>().rfind("diverged: ", 0) == 0);
  const auto text = p.text();
  CHECK(text.out.find("h·nf = 3.33 (above 2") != std::string::npos);
}

TEST_CASE("verify drives: a joint without a drive is not run and says what would give it one", "[verify][drives]") {
  assetlint::test::TempDir dir;
  write_file(dir.path() / "pendulum.urdf", pendulum_urdf("0 1 0"));
  const auto r = run_cli({"verify", "pendulum.urdf"}, dir.path());
  INFO(r.out << r.err);
  CHECK(r.exit_code == 1);
  // The proposal: holding gravity's 2.943 N·m at q = 0 within the 0.1 rad droop limit needs 29.43 N·m/rad,
  // but the step (0 → 0.5 rad) settles within 5 % of it only if gravity's m·g·l·cos 0.5 = 2.583 N·m at
  // its target leaves less than 0.025 rad, and the proposal aims at half of that: 206.6 N·m/rad.
  // Damping for ζ = 1 on 0.1 kg·m² is 2·√(206.6 × 0.1) = 9.091 N·m·s/rad.
  CHECK(r.out.find("not run: no drive: add [drives.swing] stiffness = 206.6, damping = 9.091 in asset-lint.toml") !=
        std::string::npos);
}

TEST_CASE("verify drives: the same input gives the same bytes, in parallel or not; --plot draws a panel per joint",
          "[verify][drives]") {
  Pendulum p("0 1 0", 1000, 20);
  const auto one = p.run({"-j", "1"});
  const auto two = p.run({"-j", "2", "--plot", "drives.svg"});
  INFO(one.err << two.err);
  REQUIRE(one.exit_code != 2);
  CHECK(one.out == two.out);
  const auto svg = assetlint::test::read_file(p.dir.path() / "drives.svg");
  CHECK(svg.find("'swing' (rad)") != std::string::npos);
  const auto png = p.dir.path() / "drives.png";
  const std::string command =
      "rsvg-convert -w 800 -o '" + png.string() + "' '" + (p.dir.path() / "drives.svg").string() + "'";
  CHECK(std::system(command.c_str()) == 0);
}

TEST_CASE("verify drives: the proposed gains pass when applied, and --fine-tune confirms them", "[verify][drives]") {
  // The gains the no-drive report proposes for the horizontal pendulum (k = 206.6, d = 9.091: ζ = 1):
  // its step settles within the band and its hold is within the droop limit.
  Pendulum p("0 1 0", 206.6, 9.091);
  const auto report = p.report();
  CHECK(test_of(report, "step")["passed"] == true);
  CHECK(test_of(report, "sweep")["passed"] == true);
  CHECK(test_of(report, "hold")["passed"] == true);
  CHECK(test_of(report, "step")["metrics"]["overshoot"].get<double>() < 0.05);
  // kv = 0 rings; --fine-tune proposes critical damping on 0.1 kg·m² at the stiffness the step needs and
  // tests the pendulum again with it.
  Pendulum ringing("0 1 0", 300, 0);
  const auto r = ringing.run({"--fine-tune"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 1);  // the verdict is on the asset as it is
  const auto tuned = nlohmann::json::parse(r.out)["fine_tune"];
  CHECK(tuned["runs"] == 2);
  REQUIRE(tuned["joints"].size() == 1);
  CHECK(tuned["joints"][0]["joint"] == "swing");
  CHECK(tuned["joints"][0]["proposed"]["stiffness"].get<double>() == Approx(300));
  CHECK(tuned["joints"][0]["proposed"]["damping"].get<double>() == Approx(2 * std::sqrt(300 * kInertia)).epsilon(0.01));
  CHECK(tuned["joints"][0]["passed"] == true);
}

TEST_CASE("verify drives: an MJCF pendulum on a free base: the base is pinned, the actuator's gains are tested",
          "[verify][drives]") {
  // The same link as the URDF pendulum, hung from a floating body; <position kp="10" kv="0.6"/> is ζ = 0.3.
  assetlint::test::TempDir dir;
  write_file(dir.path() / "pendulum.xml", R"(<mujoco model="pendulum">
  <worldbody>
    <body name="base">
      <freejoint/>
      <inertial pos="0 0 0" mass="1" diaginertia="0.01 0.01 0.01"/>
      <body name="arm">
        <joint name="swing" type="hinge" axis="0 0 1" range="-1 1"/>
        <inertial pos="0.3 0 0" mass="1" diaginertia="0.001 0.01 0.01"/>
      </body>
    </body>
  </worldbody>
  <actuator><position joint="swing" kp="10" kv="0.6"/></actuator>
</mujoco>
)");
  const auto r = run_cli({"verify", "pendulum.xml", "--output-format", "json"}, dir.path());
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 1);  // MJCF has no max joint velocity: the velocity test is not run
  const auto report = nlohmann::json::parse(r.out);
  CHECK(report["base"]["pinned"] == true);
  const auto& step = test_of(report, "step");
  CHECK(step["metrics"]["overshoot"].get<double>() ==
        Approx(std::exp(-std::numbers::pi * 0.3 / std::sqrt(1 - 0.09))).margin(0.015));
  CHECK(test_of(report, "velocity")["ran"] == false);
  CHECK(test_of(report, "velocity")["failures"][0].get<std::string>().find("[drives.swing] max_velocity") !=
        std::string::npos);
}
