// The guide's worked example (PHYSICS.md §3), number by number, through the same
// functions and rules the tool uses.
#include <catch2/catch.hpp>

#include <numbers>

#include "pipeline/lint.h"
#include "formats/urdf/urdf_reader.h"
#include "physics/drive.h"
#include "physics/gripper.h"
#include "test_support.h"

using namespace assetlint;

namespace {

Settings guide_settings() {
  Settings s;
  s.simulation.timesteps_per_second = Configured<double>{250.0, "test"};
  s.simulation.position_iterations = Configured<double>{64.0, "test"};
  s.gripper.payload_kg = Configured<double>{5.0, "test"};
  s.gripper.friction = Configured<double>{0.3, "test"};
  s.gripper.lever_arm_m = Configured<double>{0.04, "test"};
  s.gripper.gravity = Configured<double>{10.0, "test"};
  s.gripper.finger_speed_m_s = Configured<double>{0.15, "test"};
  s.gripper.stroke_m = Configured<double>{0.085, "test"};
  s.gripper.driven_joint = Configured<std::string>{"finger_joint", "test"};
  return s;
}

FileReport lint_gripper(const Settings& settings) {
  const auto path = test::fixtures_dir() / "robotiq_2f85" / "robotiq_2f85.urdf";
  return lint_text("robotiq_2f85.urdf", test::read_file(path), settings);
}

const Diagnostic* find(const FileReport& report, std::string_view rule) {
  for (const auto& d : report.diagnostics)
    if (d.rule == rule) return &d;
  return nullptr;
}

}  // namespace

TEST_CASE("guide: grip force, torque per joint, max drive force", "[guide]") {
  Asset asset;
  for (const char* name : {"finger_joint", "m1", "m2", "m3", "m4", "m5"}) {
    Joint j;
    j.name.text = name;
    j.type = JointType::Revolute;
    if (std::string_view(name) != "finger_joint") j.mimic = Mimic{Name{"finger_joint", {}}, {}, {}, {}, {}, {}, {}};
    asset.joints.push_back(j);
  }
  const auto force = physics::required_force(asset, guide_settings(), asset.joints[0]);
  REQUIRE(force);
  CHECK(force->grip_force == Approx(166.667).epsilon(1e-5));  // 5·10/0.3
  CHECK(force->per_finger == Approx(83.333).epsilon(1e-5));
  CHECK(force->per_joint == Approx(3.3333).epsilon(1e-4));    // the guide rounds up to 4
  CHECK(force->joints == 6);                                  // J0 + 5 mimics
  CHECK(force->required == Approx(20.0).epsilon(1e-9));       // 6 × 3.33; with the guide's 4: 24
}

TEST_CASE("guide: close time and max joint velocity", "[guide]") {
  Joint j0;
  j0.type = JointType::Revolute;
  j0.lower = Quantity::unauthored(0.0, Unit::Radian);
  j0.upper = Quantity::from_authored(47.0, Unit::Degree, Span{});
  CHECK(j0.upper->value == Approx(0.820305).epsilon(1e-6));
  const auto velocity = physics::required_velocity(guide_settings(), j0);
  REQUIRE(velocity);
  CHECK(velocity->close_time == Approx(0.28333).epsilon(1e-4));  // 0.0425 m at 0.15 m/s
  CHECK(velocity->velocity == Approx(2.895).epsilon(1e-3));      // 2.90 rad/s
  CHECK(degrees_from_radians(velocity->velocity) == Approx(165.9).epsilon(1e-3));  // 166 deg/s
}

TEST_CASE("guide: stiffness, natural frequency, damping and armature", "[guide]") {
  const double inertia = 2.1e-6 + 0.0127 * 0.01 * 0.01;
  CHECK(inertia == Approx(3.37e-6).epsilon(1e-9));
  CHECK(physics::natural_frequency(5700, inertia) == Approx(4.11e4).epsilon(2e-3));  // ≫ 64 × 250 = 1.6e4
  const double delta = radians_from_degrees(5.0);
  CHECK(delta == Approx(0.0873).epsilon(1e-3));
  const double k = 24.0 / delta;
  CHECK(k == Approx(275.0).epsilon(1e-3));
  CHECK(from_model_units(k, Unit::NewtonMeterPerDegree) == Approx(4.8).epsilon(1e-3));  // per degree in USD
  CHECK(physics::natural_frequency(275, 3.4e-6) == Approx(9.0e3).epsilon(1e-2));
  CHECK(physics::damping_for_ratio(1.0, 275, 3.4e-6) == Approx(0.061).epsilon(1e-2));
  CHECK(physics::natural_frequency(275, 5e-3) == Approx(234).epsilon(3e-3));
  CHECK(5e-3 / (50.0 * 50.0) == Approx(2e-6));  // rotor inertia behind G = 50
  // The implicit spring: at 250 Hz the guide's tuned drive keeps (dt·nf)² ≫ 1.
  CHECK(physics::implicit_fraction(1.0 / 250, physics::natural_frequency(275, 3.4e-6)) < 1e-3);
  CHECK(physics::implicit_fraction(1.0 / 60, 0.0) == 1.0);
}

TEST_CASE("guide: the effective inertia of J0 is the lighter link, shifted to the joint", "[guide]") {
  const auto path = test::fixtures_dir() / "robotiq_2f85" / "robotiq_2f85.urdf";
  const ReadResult read = urdf::read_urdf(std::make_shared<const SourceFile>("g.urdf", test::read_file(path)));
  REQUIRE(read.usable);
  const Joint* j0 = read.asset.find_joint("finger_joint");
  REQUIRE(j0);
  const physics::EffectiveInertia inertia = physics::effective_inertia(read.asset, *j0);
  REQUIRE(inertia.known);
  CHECK(inertia.link_inertia == Approx(3.37e-6).epsilon(1e-9));  // 2.1e-6 + 0.0127 × 0.01²
  CHECK(inertia.link->name.text == "left_inner_finger");
  CHECK(inertia.armature == 0.0);
  CHECK(physics::coupled_joints(read.asset, *j0).size() == 6);
  // The guide lints clean without drive gains: URDF has none.
  CHECK(lint_gripper(Settings{}).diagnostics.empty());
}

TEST_CASE("guide: k = 5700 at 250 Hz × 64 reports nf ≈ 4.1e4 and proposes k ≈ 275, d ≈ 0.061", "[guide]") {
  Settings settings = guide_settings();
  settings.drives["finger_joint"].stiffness = Configured<double>{5700.0, "asset-lint.toml:9"};
  settings.drives["finger_joint"].damping = Configured<double>{0.1, "asset-lint.toml:10"};
  const FileReport report = lint_gripper(settings);
  const Diagnostic* nf = find(report, "drive-natural-frequency");
  REQUIRE(nf);
  CHECK(nf->severity == Severity::Error);
  CHECK(nf->message ==
        "natural frequency 41130 rad/s of the drive of revolute joint 'finger_joint' (stiffness 5700 N·m/rad, I = "
        "3.37e-6 kg·m² (link 'left_inner_finger' about 'left_inner_finger_joint')) exceeds 250 Hz (test) × 64 "
        "position iterations (test) = 16000, the guide's over-optimistic bound; stiffness 5700 N·m/rad → 275 N·m/rad "
        "(max force 24 N·m reached 5° before the target), damping → 0.06089 N·m·s/rad for damping ratio 1 (natural "
        "frequency 9030 rad/s)");
  const Diagnostic* implicit = find(report, "drive-implicit-attenuation");
  REQUIRE(implicit);
  CHECK(implicit->message.find("(dt·nf)² = (0.004 s × 41130 rad/s)² = 27060 > 1") != std::string::npos);
  // 24 N·m ≥ the payload's 20 N·m; 2.9 rad/s within 2× of the spec's 2.895: no finding.
  CHECK_FALSE(find(report, "drive-max-force"));
  CHECK_FALSE(find(report, "joint-max-velocity"));
}

TEST_CASE("guide: armature 5e-3 at 60 Hz brings nf to 234 rad/s and is reported as excessive", "[guide]") {
  Settings settings = guide_settings();
  settings.simulation.timesteps_per_second = Configured<double>{60.0, "test"};
  settings.drives["finger_joint"].stiffness = Configured<double>{275.0, "test"};
  settings.drives["finger_joint"].damping = Configured<double>{0.061, "test"};
  settings.drives["finger_joint"].armature = Configured<double>{5e-3, "test"};
  const FileReport report = lint_gripper(settings);
  CHECK_FALSE(find(report, "drive-natural-frequency"));  // 234 rad/s < 20 × 60
  const Diagnostic* armature = find(report, "armature-excessive");
  REQUIRE(armature);
  CHECK(armature->message.find("armature 0.005 kg·m² of revolute joint 'finger_joint' is 1480× the lighter link's "
                               "3.37e-6 kg·m²") != std::string::npos);
  CHECK(armature->message.find("from 9030 to 234 rad/s") != std::string::npos);
}

TEST_CASE("guide: a max force below the payload spec is reported with its derivation", "[guide]") {
  Settings settings = guide_settings();
  const auto path = test::fixtures_dir() / "robotiq_2f85" / "robotiq_2f85.urdf";
  std::string text = test::read_file(path);
  const auto at = text.find("effort=\"24\"");
  REQUIRE(at != std::string::npos);
  text.replace(at, 11, "effort=\"12\"");
  const FileReport report = lint_text("robotiq_2f85.urdf", text, settings);
  const Diagnostic* force = find(report, "drive-max-force");
  REQUIRE(force);
  CHECK(force->message ==
        "effort limit 12 N·m of revolute joint 'finger_joint' is below the 20 N·m the payload spec needs: 5 kg × 10 "
        "m/s² / μ 0.3 = 166.7 N grip, 83.33 N per finger × 0.04 m lever arm = 3.33 N·m per joint × 6 joints driven "
        "through 'finger_joint' = 20 N·m");
  REQUIRE(force->fix);
  CHECK(force->fix->edits.size() == 1);
  CHECK(force->fix->edits[0].replacement == "20");
}
