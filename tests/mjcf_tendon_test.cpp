// MJCF actuators on a fixed tendon and linkages closed by a connect, held to answers derived by hand (MuJoCo 3.14 compiles the
// same numbers; the reference test re-checks them against it):
//   split_fingers.xml: two 0.1 kg slide fingers, tendon length (q_l + q_r)/2, a position servo
//     kp = 100 N/m, dampratio 1, forcerange ±40 N on the tendon. Each finger alone (the other
//     held) sees the servo through a gear of 1/2: stiffness 100 × (1/2)² = 25 N/m, force bound
//     40 × 1/2 = 20 N: each finger pushes with F/2.
//     kv on the tendon: MuJoCo 3.3 to 3.14 take m = Σ M₀ⱼ/Jⱼ² = 0.1/0.25 + 0.1/0.25 = 0.8 kg,
//     kv = 2·√(100 × 0.8) = 17.889 N·s/m; 3.15 takes m = (J·M⁻¹·Jᵀ)⁻¹ = 1/(0.25/0.1 + 0.25/0.1)
//     = 0.2 kg, kv = 2·√(100 × 0.2) = 8.944 N·s/m. On each finger × (1/2)²: 4.472 and 2.236.
//   coupled_fingers.xml: the same with right_slide = left_slide (a joint equality): the tendon
//     moves G = 1/2 + 1/2 = 1 per unit of left_slide, which carries the whole servo: stiffness
//     100 N/m, force bound 40 N, judged on the pair's 0.2 kg; kv·G² = 8.944 under 3.15 is
//     damping ratio 8.944 / (2·√(100 × 0.2)) = 1 on the pair, 3.14's 17.889 is 2.
#include <catch2/catch.hpp>

#include "commands/tune_derivation.h"
#include "engine/file_system.h"
#include "engine/settings.h"
#include "formats/mjcf/mjcf_reader.h"
#include "physics/articulation.h"
#include "physics/joint_space_matrix.h"
#include "physics/linkage.h"
#include "pipeline/lint.h"
#include "rules/drive_support.h"
#include "test_support.h"

using namespace assetlint;
using Catch::Matchers::WithinRel;

namespace {

ReadResult read_fixture(const std::string& name, MujocoVersion version) {
  const auto path = test::fixtures_dir() / "mjcf" / "tendon" / name;
  mjcf::ReadOptions options;
  options.mujoco = version;
  return mjcf::read_mjcf(std::make_shared<const SourceFile>(path.string(), test::read_file(path)), DiskFileSystem{}, options);
}

const Drive& drive_of(const Asset& asset, const char* name) {
  const Joint* joint = asset.find_joint(name);
  REQUIRE(joint);
  REQUIRE(joint->drive);
  return *joint->drive;
}

}  // namespace

TEST_CASE("a fixed tendon with coef 1/2 on two free fingers: each finger pushes with F/2", "[mjcf][tendon]") {
  const ReadResult r = read_fixture("split_fingers.xml", MujocoVersion{3, 15});
  REQUIRE(r.usable);
  for (const char* finger : {"left_slide", "right_slide"}) {
    INFO(finger);
    const Joint& joint = *r.asset.find_joint(finger);
    CHECK(joint.actuation == Actuation::Actuated);
    REQUIRE(joint.transmission);
    CHECK(joint.transmission->tendon == "fixed tendon 'split'");
    CHECK(joint.transmission->ratio == 0.5);
    REQUIRE(joint.transmission->shares.size() == 2);
    CHECK(joint.transmission->shares[0].joint == "left_slide");
    CHECK(joint.transmission->shares[0].coef == 0.5);
    CHECK(joint.transmission->length0 == 0);
    const Drive& drive = drive_of(r.asset, finger);
    CHECK_THAT(drive.stiffness->value, WithinRel(25.0, 1e-12));
    CHECK_THAT(drive.max_force->value, WithinRel(20.0, 1e-12));
    // The literal stays rewritable: the fix writes kp, not the finger's share of it.
    CHECK(drive.stiffness->is_authored());
    CHECK_THAT(drive.damping->value, WithinRel(0.25 * 2 * std::sqrt(100 * 0.2), 1e-9));
    CHECK(drive.damping_origin.find("(J·M⁻¹·Jᵀ)⁻¹") != std::string::npos);
    CHECK(drive.damping_other_release.find("MuJoCo 3.3 to 3.14") != std::string::npos);
  }
  const ReadResult old = read_fixture("split_fingers.xml", MujocoVersion{3, 14});
  CHECK_THAT(drive_of(old.asset, "left_slide").damping->value, WithinRel(0.25 * 2 * std::sqrt(100 * 0.8), 1e-9));
  // No info calls the tendon unsupported any more.
  for (const Diagnostic& d : r.diagnostics) CHECK(d.message.find("acts through") == std::string::npos);
}

TEST_CASE("a fixed tendon over fingers a joint equality ties: the leading finger carries the whole servo",
          "[mjcf][tendon]") {
  const ReadResult r = read_fixture("coupled_fingers.xml", MujocoVersion{3, 15});
  REQUIRE(r.usable);
  const Joint& leader = *r.asset.find_joint("left_slide");
  const Joint& follower = *r.asset.find_joint("right_slide");
  REQUIRE(follower.is_mimic());
  CHECK_FALSE(follower.drive);
  REQUIRE(leader.transmission);
  CHECK(leader.transmission->ratio == 1.0);
  const Drive& drive = *leader.drive;
  CHECK_THAT(drive.stiffness->value, WithinRel(100.0, 1e-12));
  CHECK_THAT(drive.max_force->value, WithinRel(40.0, 1e-12));
  CHECK_THAT(drive.damping->value, WithinRel(2 * std::sqrt(100 * 0.2), 1e-9));

  // The drive rules judge it on the pair it moves: 0.2 kg, damping ratio 1.
  Settings settings;
  const rules::DriveModel model(r.asset, settings);
  const auto driven = model.spring_drive(leader);
  REQUIRE(driven);
  CHECK(driven->judged.mechanism);
  CHECK_THAT(driven->judged.value, WithinRel(0.2, 1e-12));
  CHECK_THAT(driven->damping / (2 * std::sqrt(driven->stiffness * driven->judged.value)), WithinRel(1.0, 1e-9));

  const ReadResult old = read_fixture("coupled_fingers.xml", MujocoVersion{3, 14});
  CHECK_THAT(old.asset.find_joint("left_slide")->drive->damping->value, WithinRel(2 * std::sqrt(100 * 0.8), 1e-9));
}

// fixtures/mjcf/linkage/four_bar_finger.xml: a parallelogram closed by a connect (the numbers
// are derived in the fixture's comment).
TEST_CASE("a four-bar finger closed by a connect: the drive moves the whole linkage", "[mjcf][linkage]") {
  const auto path = test::fixtures_dir() / "mjcf" / "linkage" / "four_bar_finger.xml";
  const ReadResult r =
      mjcf::read_mjcf(std::make_shared<const SourceFile>(path.string(), test::read_file(path)), DiskFileSystem{}, {});
  REQUIRE(r.usable);
  REQUIRE(r.asset.loops.size() == 1);
  const Joint& driver = *r.asset.find_joint("driver_joint");
  const Joint& coupler = *r.asset.find_joint("coupler_joint");
  const Joint& rocker = *r.asset.find_joint("rocker_joint");
  CHECK(coupler.actuation == Actuation::Linkage);
  CHECK(rocker.actuation == Actuation::Linkage);
  CHECK_FALSE(driver.hidden_load);  // the loop is modelled: nothing it moves is left out

  const physics::Articulation articulation(r.asset);
  const physics::JointSpaceMatrix matrix(articulation);
  const physics::Mechanism mechanism = physics::drive_mechanism(matrix, r.asset, driver);
  CHECK(mechanism.freedoms == 1);
  REQUIRE(mechanism.inertia.known);
  CHECK_THAT(mechanism.inertia.value, WithinRel(2 * (1e-7 + 0.02 * 0.025 * 0.025) + 0.05 * 0.05 * 0.05 + 2e-4, 1e-9));
  // Per unit of the driver: coupler −1, rocker +1.
  REQUIRE(mechanism.rates.size() == 3);
  for (std::size_t k = 0; k < 3; ++k) {
    const Joint* joint = mechanism.joints[k];
    INFO(joint->name.text);
    CHECK_THAT(mechanism.rates[k], WithinRel(joint == &coupler ? -1.0 : 1.0, 1e-9));
  }
  // The pad (on the coupler) moves at 0.05 m/s per rad/s of the driver: by virtual work the
  // driver's force bound of 0.5 N·m pushes it with 0.5 / 0.05 = 10 N.
  int tree = -1;
  Eigen::MatrixXd rows;
  REQUIRE(matrix.point_rows(*r.asset.find_link("coupler"), Eigen::Vector3d(0, 0.01, 0), nullptr, false, tree, rows, nullptr));
  Eigen::Vector3d pad = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < 3; ++k) pad += rows.col(matrix.column_of(*mechanism.joints[k]).second) * mechanism.rates[k];
  CHECK_THAT(pad.norm(), WithinRel(0.05, 1e-9));
  CHECK_THAT(driver.drive->max_force->value / pad.norm(), WithinRel(10.0, 1e-9));

  // The drive rules judge the servo on the linkage.
  Settings settings;
  const rules::DriveModel model(r.asset, settings);
  const auto driven = model.spring_drive(driver);
  REQUIRE(driven);
  CHECK(driven->judged.mechanism);
  CHECK_THAT(driven->judged.value, WithinRel(mechanism.inertia.value, 1e-12));
  // Without the coupler's armature the linkage is 1e-4 lighter.
  const physics::Mechanism without = model.mechanism(driver, physics::Armatures{&coupler, false});
  REQUIRE(without.tied());
  CHECK_THAT(without.inertia.value, WithinRel(mechanism.inertia.value - 1e-4, 1e-9));
}

TEST_CASE("verify's message for an ambiguous driven joint names no option verify rejects", "[mjcf][verify]") {
  const auto path = test::fixtures_dir() / "mjcf" / "dampratio" / "two_link_arm.xml";
  const ReadResult r =
      mjcf::read_mjcf(std::make_shared<const SourceFile>(path.string(), test::read_file(path)), DiskFileSystem{}, {});
  REQUIRE(r.usable);
  std::string error;
  CHECK_FALSE(commands::tune_joint(r.asset, Settings{}, std::nullopt, error, nullptr));
  CHECK(error.find("2 joints could be the driven one") != std::string::npos);
  CHECK(error.find("--joint") == std::string::npos);
  CHECK(error.find("[gripper] driven_joint in asset-lint.toml") != std::string::npos);
  // tune and simulate take --joint, and say so.
  CHECK_FALSE(commands::tune_joint(r.asset, Settings{}, std::nullopt, error));
  CHECK(error.find("name it with --joint or [gripper] driven_joint") != std::string::npos);
}
