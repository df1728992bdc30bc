// The guide's worked example (PHYSICS.md §3), number by number, through the same
// functions and rules the tool uses.
#include <catch2/catch.hpp>

#include <numbers>

#include "pipeline/lint.h"
#include "formats/urdf/urdf_reader.h"
#include "physics/drive.h"
#include "physics/drive_row.h"
#include "physics/gripper.h"
#include "rules/drive_support.h"
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
    if (std::string_view(name) != "finger_joint") {
      // Gearing ±1, as in the guide: the driver supplies Σ|g|·τ.
      const double g = std::string_view(name) == "m2" ? -1.0 : 1.0;
      j.mimic = Mimic{Name{"finger_joint", {}}, Quantity::unauthored(g, Unit::None), {}, {}, {}, {}, {}, {}};
    }
    asset.joints.push_back(j);
  }
  const auto force = physics::required_force(asset, guide_settings(), asset.joints[0]);
  REQUIRE(force);
  CHECK(force->grip_force == Approx(166.667).epsilon(1e-5));  // 5·10/0.3
  CHECK(force->per_finger == Approx(83.333).epsilon(1e-5));
  CHECK(force->per_joint_torque == Approx(3.3333).epsilon(1e-4));  // the guide rounds up to 4
  CHECK(force->rounded_torque == Approx(3.3333).epsilon(1e-4));    // no torque_margin: no rounding
  CHECK(force->joints == 6);                                       // J0 + 5 mimics
  CHECK(force->required == Approx(20.0).epsilon(1e-9));            // 6 × 3.33; with the guide's 4: 24

  Settings margin = guide_settings();
  margin.gripper.torque_margin = Configured<double>{1.0, "asset-lint.toml:9"};
  const auto rounded = physics::required_force(asset, margin, asset.joints[0]);
  REQUIRE(rounded);
  CHECK(rounded->rounded_torque == 4.0);  // the guide: 3.33 → 4 N·m
  CHECK(rounded->required == 24.0);       // 6 × 4 N·m on J0
  CHECK(rounded->unit == Unit::NewtonMeter);
  CHECK(physics::round_up_torque(4.0, margin.gripper) == 4.0);  // already on the grid
  margin.gripper.torque_margin = Configured<double>{0.5, "--torque-margin"};
  CHECK(physics::round_up_torque(3.3333, margin.gripper) == 3.5);
}

TEST_CASE("gripper spec: a prismatic finger needs the per-finger force itself, in N", "[guide]") {
  Asset asset;
  for (const char* name : {"left", "right"}) {
    Joint j;
    j.name.text = name;
    j.type = JointType::Prismatic;
    if (std::string_view(name) == "right")
      j.mimic = Mimic{Name{"left", {}}, Quantity::unauthored(-1.0, Unit::None), {}, {}, {}, {}, {}, {}};
    asset.joints.push_back(j);
  }
  Settings settings = guide_settings();
  settings.gripper.lever_arm_m.reset();                 // not needed: no lever arm on a slide
  settings.gripper.torque_margin = Configured<double>{1.0, "asset-lint.toml:9"};  // a torque margin: N·m only
  const auto force = physics::required_force(asset, settings, asset.joints[0]);
  REQUIRE(force);
  CHECK(force->unit == Unit::Newton);
  CHECK(force->per_finger == Approx(83.333).epsilon(1e-5));
  CHECK(force->gearing_sum == 2.0);
  CHECK(force->required == Approx(166.667).epsilon(1e-5));  // 2 fingers × 83.3 N, never N·m
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
  // The implicit spring at PhysX's TGS sub-step h = 1/(250 × 64): the final tuning keeps
  // x = 0.41 of k·Δ at a stop on the lighter link, the original 0.078.
  const physics::SimulationRate rate = physics::effective_simulation(Asset{}, guide_settings());
  CHECK(rate.h() == Approx(1.0 / 16000));
  CHECK(physics::drive_row(rate, 275, 0.061, DriveType::Force, inertia).x() == Approx(0.408).margin(1e-3));
  CHECK(physics::drive_row(rate, 5700, 0.277, DriveType::Force, inertia).x() == Approx(0.078).margin(1e-3));
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

static const Diagnostic* find_note(const Diagnostic& d, std::string_view text) {
  for (const auto& note : d.notes)
    if (note.message.find(text) != std::string::npos) return &d;
  return nullptr;
}

TEST_CASE("guide: k = 5700 at 250 Hz × 64 is beyond h·nf ≤ 1 and the guide's 275, 0.061 is proposed", "[guide]") {
  Settings settings = guide_settings();
  settings.drives["finger_joint"].stiffness = Configured<double>{5700.0, "asset-lint.toml:9"};
  settings.drives["finger_joint"].damping = Configured<double>{0.277, "asset-lint.toml:10"};
  const FileReport report = lint_gripper(settings);
  const Diagnostic* nf = find(report, "drive-natural-frequency");
  REQUIRE(nf);
  CHECK(nf->severity == Severity::Error);
  CHECK(nf->message == "drive of 'finger_joint': natural frequency 41130 rad/s > TGS bound 16000 rad/s (h·nf = 2.57)");
  REQUIRE(nf->notes.size() == 3);
  CHECK(nf->notes[0].message ==
        "For revolute joint 'finger_joint': nf = sqrt(k / I) = sqrt(5700 N·m/rad / 3.37e-6 kg·m²) = 41130 rad/s on the "
        "guide's lighter-link I; inertias: lighter link 3.37e-6 kg·m² ('left_inner_finger' about "
        "'left_inner_finger_joint'), the guide's estimate; articulation 8.57e-5 kg·m². On the articulation nf = 8156 "
        "rad/s.");
  CHECK(nf->notes[1].message ==
        "The guide's bound is nf ≤ rate × position iterations = 16000 rad/s, i.e. h·nf ≤ 1 at TGS (default), h = "
        "dt/64 = 1/16000 s (250 Hz (test) / 64 position iterations (test)); here h·nf = 2.57.");
  CHECK(nf->notes[2].message ==
        "The guide's stiffness is 275 N·m/rad (max force 24 N·m reached 5° before the target), with damping 0.06089 "
        "N·m·s/rad for damping ratio 1 (natural frequency 9030 rad/s).");
  // The row on each inertia: x = 0.078 on the lighter link, 0.68 on the articulation, which
  // is what the attenuation verdict rests on (no warning: the drive holds 68 % of k·Δ).
  const ReadResult read = urdf::read_urdf(std::make_shared<const SourceFile>(
      "g.urdf", test::read_file(test::fixtures_dir() / "robotiq_2f85" / "robotiq_2f85.urdf")));
  Asset asset = read.asset;
  Joint* j0 = const_cast<Joint*>(asset.find_joint("finger_joint"));
  j0->drive = Drive{};
  j0->drive->stiffness = Quantity::unauthored(5700.0, Unit::NewtonMeterPerRadian);
  j0->drive->damping = Quantity::unauthored(0.277, Unit::NewtonMeterSecondPerRadian);
  const rules::DriveModel model(asset, settings);
  const auto driven = model.spring_drive(*j0);
  REQUIRE(driven);
  CHECK(driven->articulated.value == Approx(8.57e-5).epsilon(1e-3));
  CHECK(driven->row(driven->inertia.value).x() == Approx(0.078).margin(5e-4));
  CHECK(driven->verdict_row().x() == Approx(0.68).margin(5e-3));
  CHECK_FALSE(find(report, "drive-implicit-attenuation"));
  // 24 N·m ≥ the payload's 20 N·m; 2.9 rad/s within 2× of the spec's 2.895: no finding.
  CHECK_FALSE(find(report, "drive-max-force"));
  CHECK_FALSE(find(report, "joint-max-velocity"));
}

TEST_CASE("guide: the final tuning 275, 0.061 at 250 Hz × 64 gets no warning from any rule", "[guide]") {
  Settings settings = guide_settings();
  settings.drives["finger_joint"].stiffness = Configured<double>{275.0, "test"};
  settings.drives["finger_joint"].damping = Configured<double>{0.061, "test"};
  const FileReport report = lint_gripper(settings);
  for (const Diagnostic& d : report.diagnostics) {
    INFO(d.rule << ": " << d.message);
    CHECK(d.severity == Severity::Info);
  }
  const Diagnostic* nf = find(report, "drive-natural-frequency");
  REQUIRE(nf);
  CHECK(nf->message == "drive of 'finger_joint': natural frequency 9030 rad/s is 36.1× the rate, within the TGS bound 16000 rad/s");
  // x = 0.41 on the lighter link (0.76 without damping), 0.95 on the articulation.
  const physics::SimulationRate rate = physics::effective_simulation(Asset{}, settings);
  CHECK(physics::drive_row(rate, 275, 0.061, DriveType::Force, 3.37e-6).x() == Approx(0.41).margin(5e-3));
  CHECK(physics::drive_row(rate, 275, 0.0, DriveType::Force, 3.37e-6).x() == Approx(0.76).margin(5e-3));
  CHECK(physics::drive_row(rate, 275, 0.061, DriveType::Force, 8.57e-5).x() == Approx(0.95).margin(5e-3));
}

TEST_CASE("guide: armature 5e-3 at 60 Hz × 64 holds 23.8 of 24 N·m and is reported as excessive", "[guide]") {
  Settings settings = guide_settings();
  settings.simulation.timesteps_per_second = Configured<double>{60.0, "test"};
  settings.drives["finger_joint"].stiffness = Configured<double>{275.0, "test"};
  settings.drives["finger_joint"].damping = Configured<double>{0.061, "test"};
  settings.drives["finger_joint"].armature = Configured<double>{5e-3, "test"};
  const FileReport report = lint_gripper(settings);
  const Diagnostic* nf = find(report, "drive-natural-frequency");
  REQUIRE(nf);  // 234 rad/s: 3.9× the 60 Hz rate, far within 60 × 64
  CHECK(nf->severity == Severity::Info);
  const Diagnostic* armature = find(report, "armature-excessive");
  REQUIRE(armature);
  CHECK(armature->message == "armature 0.005 kg·m² of 'finger_joint' is 1480× the lighter link's inertia (threshold 10×)");
  CHECK(find_note(*armature, "from 9030 to 234 rad/s"));
  const physics::SimulationRate rate = physics::effective_simulation(Asset{}, settings);
  CHECK(rate.h() == Approx(1.0 / 3840));
  const physics::DriveRow row = physics::drive_row(rate, 275, 0.061, DriveType::Force, 3.37e-6 + 5e-3);
  CHECK(row.x() == Approx(0.993).margin(5e-4));
  const physics::Hold hold = physics::static_hold(row, radians_from_degrees(5.0), physics::ForceLimit{24.0, true});
  CHECK(hold.force == Approx(23.8).margin(0.05));
  CHECK(hold.spring == Approx(24.0).margin(0.01));
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
  CHECK(force->message == "effort 12 N·m of revolute joint 'finger_joint' is below the 20 N·m the payload spec needs");
  REQUIRE(force->notes.size() == 3);
  CHECK(force->notes[0].message == "Grip: 5 kg × 10 m/s² / μ 0.3 = 166.7 N, 83.33 N per finger.");
  CHECK(force->notes[1].message == "Per revolute joint: 83.33 N × 0.04 m lever arm = 3.33 N·m.");
  CHECK(force->notes[2].message ==
        "'finger_joint' drives 6 joints (itself and 5 mimics), Σ|gearing| = 6: it needs 20 N·m.");
  REQUIRE(force->fix);
  CHECK(force->fix->edits.size() == 1);
  CHECK(force->fix->edits[0].replacement == "20");

  // The guide's rounding: torque_margin 1 turns 3.33 into 4 N·m per joint, 24 N·m on J0.
  settings.gripper.torque_margin = Configured<double>{1.0, "asset-lint.toml:9"};
  const FileReport with_margin = lint_text("robotiq_2f85.urdf", text, settings);
  const Diagnostic* rounded = find(with_margin, "drive-max-force");
  REQUIRE(rounded);
  CHECK(rounded->message == "effort 12 N·m of revolute joint 'finger_joint' is below the 24 N·m the payload spec needs");
  CHECK(rounded->fix->edits[0].replacement == "24");

  // 1000 N·m, the public Robotiq URDFs' value, is 41.7× what the spec needs: reported too.
  text.replace(text.find("effort=\"12\""), 11, "effort=\"1000\"");
  const FileReport placeholder = lint_text("robotiq_2f85.urdf", text, settings);
  const Diagnostic* strong = find(placeholder, "drive-max-force");
  REQUIRE(strong);
  CHECK(strong->severity == Severity::Warning);
  CHECK(strong->message == "effort 1000 N·m of revolute joint 'finger_joint' is 41.7× the 24 N·m the payload spec needs");
  CHECK(strong->fix->edits[0].replacement == "24");
}
