// The articulated inertia 1/(M⁻¹)ᵢᵢ and the diagonal Mᵢᵢ against an independent computation:
// MuJoCo's joint-space mass matrix of the same URDF (mj_fullM), inverted densely here. MuJoCo 2.2 diagonalises
// each body's inertia, which is exact only to ~1e-9 relative, so the comparison is at 1e-6.
#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <filesystem>
#include <regex>

#include "engine/file_system.h"
#include "formats/mjcf/mjcf_reader.h"
#include "formats/urdf/urdf_reader.h"
#include "physics/articulation.h"
#include "physics/joint_space_matrix.h"
#include "test_support.h"

#ifdef ASSET_LINT_HAVE_MUJOCO
#include <mujoco/mujoco.h>
#endif

using namespace assetlint;

namespace {

#ifdef ASSET_LINT_HAVE_MUJOCO
struct MujocoInertias {
  double articulated = 0;  // 1/(M⁻¹)ᵢᵢ
  double diagonal = 0;     // Mᵢᵢ (MuJoCo's dof_M0 at qpos0)
};

// Both inertias per joint name (its first DOF), from MuJoCo at q = 0; URDF or MJCF.
std::map<std::string, MujocoInertias> mujoco_inertias(const std::filesystem::path& model_file) {
  char error[1000] = "";
  mjModel* model = mj_loadXML(model_file.string().c_str(), nullptr, error, sizeof error);
  INFO("MuJoCo: " << error);
  REQUIRE(model);
  mjData* data = mj_makeData(model);
  mj_forward(model, data);
  const int nv = model->nv;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> mass(nv, nv);
  mj_fullM(model, mass.data(), data->qM);
  const Eigen::MatrixXd inverse = Eigen::MatrixXd(mass).inverse();
  std::map<std::string, MujocoInertias> result;
  for (int j = 0; j < model->njnt; ++j) {
    const char* name = mj_id2name(model, mjOBJ_JOINT, j);
    const int dof = model->jnt_dofadr[j];
    if (name) result[name] = {1.0 / inverse(dof, dof), mass(dof, dof)};
  }
  mj_deleteData(data);
  mj_deleteModel(model);
  return result;
}
#endif

void compare_with_mujoco(const std::filesystem::path& urdf, std::size_t expected_joints) {
#ifndef ASSET_LINT_HAVE_MUJOCO
  (void)urdf;
  (void)expected_joints;
  WARN("libmujoco-dev is not installed (scripts/bootstrap.sh installs it): MuJoCo mass-matrix test skipped");
#else
  const ReadResult read = urdf::read_urdf(std::make_shared<const SourceFile>(urdf.string(), test::read_file(urdf)));
  REQUIRE(read.usable);
  const physics::Articulation articulation(read.asset);
  const auto reference = mujoco_inertias(urdf);
  REQUIRE(reference.size() == expected_joints);
  for (const auto& [name, value] : reference) {
    const Joint* joint = read.asset.find_joint(name);
    REQUIRE(joint);
    const physics::ArticulatedInertia ours = articulation.inertia(*joint);
    const physics::ArticulatedInertia diagonal = articulation.joint_space_inertia(*joint);
    const physics::ArticulatedInertia whole = physics::JointSpaceMatrix(articulation).operational_inertia(*joint);
    INFO(name);
    REQUIRE(ours.known);
    CHECK(ours.value == Approx(value.articulated).epsilon(1e-6));
    REQUIRE(whole.known);
    CHECK(whole.value == Approx(value.articulated).epsilon(1e-6));
    REQUIRE(diagonal.known);
    CHECK(diagonal.value == Approx(value.diagonal).epsilon(1e-6));
  }
#endif
}

}  // namespace

TEST_CASE("articulated inertia equals MuJoCo's 1/(M⁻¹)ᵢᵢ: a tree with rotated frames, a weld and a slider",
          "[physics][articulation][mujoco]") {
  compare_with_mujoco(test::fixtures_dir() / "physics" / "mass_matrix_tree.urdf", 5);
}

TEST_CASE("articulated inertia equals MuJoCo's 1/(M⁻¹)ᵢᵢ: the Robotiq 2F-85 fixture", "[physics][articulation][mujoco]") {
  compare_with_mujoco(test::fixtures_dir() / "robotiq_2f85" / "robotiq_2f85.urdf", 6);
}

TEST_CASE("joint-space inertia of MJCF fixtures equals MuJoCo's dof_M0, armature included", "[physics][articulation][mujoco]") {
#ifndef ASSET_LINT_HAVE_MUJOCO
  WARN("libmujoco-dev is not installed (scripts/bootstrap.sh installs it): MuJoCo dof_M0 test skipped");
#else
  // Models with <inertial> on every body and no meshes, so MuJoCo compiles them as they are.
  const auto dir = test::fixtures_dir() / "rules";
  std::size_t compared = 0;
  for (const auto& path : {dir / "armature-excessive" / "humanoid_ankle.xml", dir / "drive-damping-ratio" / "tiago_style_arm.xml",
                           dir / "drive-damping-ratio" / "arm_shoulder_articulated.xml",
                           dir / "armature-excessive" / "flywheel.xml"}) {
    INFO(path.string());
    const DiskFileSystem files;
    const ReadResult read = mjcf::read_mjcf(std::make_shared<const SourceFile>(path.string(), test::read_file(path)), files);
    REQUIRE(read.usable);
    const physics::Articulation articulation(read.asset);
    // The Debian libmujoco predates <position kv>, autolimits and implicitfast: actuators, joint
    // ranges and the integrator do not change dof_M0, so they go.
    std::string text = std::regex_replace(test::read_file(path), std::regex(R"( (range|integrator)="[^"]*")"), "");
    const auto begin = text.find("<actuator>"), end = text.find("</actuator>");
    REQUIRE(begin != std::string::npos);
    REQUIRE(end != std::string::npos);
    text.erase(begin, end + std::string("</actuator>").size() - begin);
    test::TempDir temp;
    const auto copy = temp.path() / "model.xml";
    test::write_file(copy, text);
    char error[1000] = "";
    mjModel* model = mj_loadXML(copy.string().c_str(), nullptr, error, sizeof error);
    INFO("MuJoCo: " << error);
    REQUIRE(model);
    for (int j = 0; j < model->njnt; ++j) {
      const char* name = mj_id2name(model, mjOBJ_JOINT, j);
      REQUIRE(name);
      const Joint* joint = read.asset.find_joint(name);
      REQUIRE(joint);
      const physics::ArticulatedInertia ours = articulation.joint_space_inertia(*joint);
      INFO(name);
      REQUIRE(ours.known);
      CHECK(ours.value == Approx(model->dof_M0[model->jnt_dofadr[j]]).epsilon(1e-6));
      ++compared;
    }
    mj_deleteModel(model);
  }
  CHECK(compared >= 6);
#endif
}

TEST_CASE("the whole joint-space matrix: 1/(M⁻¹)ᵢᵢ with a free base, a ball joint and two hinges in one body",
          "[physics][articulation][mujoco]") {
  // The tree MuJoCo 3.15 takes a dampratio servo's inertia from: every degree of freedom free,
  // armature on each one's diagonal (the free and ball joints' too).
  const std::string text = R"(<mujoco>
  <compiler angle="radian"/>
  <worldbody>
    <body name="base" pos="0 0 1" euler="0.2 0 0.3">
      <freejoint name="root"/>
      <inertial pos="0.01 0 -0.02" mass="4" diaginertia="0.05 0.04 0.03"/>
      <body name="shoulder" pos="0.1 0.05 0">
        <joint name="shoulder_ball" type="ball" armature="0.02"/>
        <inertial pos="0.05 0 0" mass="1.2" diaginertia="0.004 0.005 0.003"/>
        <body name="upper" pos="0.2 0 0" euler="0 0.4 0">
          <joint name="elbow_pitch" axis="0 1 0" armature="0.01"/>
          <joint name="elbow_roll" axis="1 0 0" pos="0.02 0 0" armature="0.005"/>
          <inertial pos="0.12 0.01 0" mass="0.9" diaginertia="0.002 0.006 0.005"/>
          <body name="slider" pos="0.25 0 0">
            <joint name="extend" type="slide" axis="1 0 0" armature="0.3"/>
            <inertial pos="0.03 0 0" mass="0.4" diaginertia="0.0004 0.0005 0.0005"/>
          </body>
        </body>
      </body>
      <body name="tail" pos="-0.2 0 0">
        <joint name="wag" axis="0 0 1"/>
        <inertial pos="-0.1 0 0" mass="0.5" diaginertia="0.001 0.002 0.002"/>
      </body>
    </body>
  </worldbody>
</mujoco>)";
  const ReadResult read =
      mjcf::read_mjcf(std::make_shared<const SourceFile>("tree.xml", text), DiskFileSystem{});
  REQUIRE(read.usable);
  const physics::Articulation articulation(read.asset);
  const physics::JointSpaceMatrix matrix(articulation);
  // What the O(n) recursion leaves unknown (a tree with multi-DOF joints), the matrix knows.
  CHECK_FALSE(articulation.inertia(*read.asset.find_joint("elbow_pitch")).known);
#ifndef ASSET_LINT_HAVE_MUJOCO
  WARN("libmujoco-dev is not installed (scripts/bootstrap.sh installs it): MuJoCo mass-matrix test skipped");
#else
  test::TempDir temp;
  test::write_file(temp.path() / "tree.xml", text);
  const auto reference = mujoco_inertias(temp.path() / "tree.xml");
  std::size_t compared = 0;
  for (const char* name : {"elbow_pitch", "elbow_roll", "extend", "wag"}) {
    INFO(name);
    const physics::ArticulatedInertia ours = matrix.operational_inertia(*read.asset.find_joint(name));
    REQUIRE(ours.known);
    CHECK(ours.value == Approx(reference.at(name).articulated).epsilon(1e-9));
    ++compared;
  }
  CHECK(compared == 4);
#endif
}

TEST_CASE("the whole joint-space matrix is unknown where a moving body's mass is", "[physics][articulation]") {
  const std::string text = R"(<mujoco>
  <asset><mesh name="shell" file="shell.stl"/></asset>
  <worldbody>
    <body name="a"><joint name="j1" axis="0 0 1"/><geom type="mesh" mesh="shell"/>
      <body name="b" pos="0.3 0 0"><joint name="j2" axis="0 0 1"/>
        <inertial pos="0.1 0 0" mass="1" diaginertia="0.001 0.001 0.001"/></body></body>
  </worldbody>
</mujoco>)";
  const ReadResult read = mjcf::read_mjcf(std::make_shared<const SourceFile>("m/model.xml", text), DiskFileSystem{});
  REQUIRE(read.usable);
  const physics::Articulation articulation(read.asset);
  const physics::JointSpaceMatrix matrix(articulation);
  // j2's M₀ needs only 'b'; its 1/(M⁻¹)ᵢᵢ needs 'a' as well, whose mass comes from a mesh.
  CHECK(articulation.joint_space_inertia(*read.asset.find_joint("j2")).known);
  const physics::ArticulatedInertia whole = matrix.operational_inertia(*read.asset.find_joint("j2"));
  CHECK_FALSE(whole.known);
  CHECK(whole.unknown_links == std::vector<std::string>{"a"});
}
