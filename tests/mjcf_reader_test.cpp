// The MJCF reader: units per <compiler>, default classes, frames, mimic couplings,
// actuators as drives, includes, and errors with positions.
#include <catch2/catch.hpp>

#include <numbers>

#include "engine/file_system.h"
#include "formats/mjcf/mjcf_reader.h"
#include "test_support.h"

using namespace assetlint;
using Catch::Matchers::WithinRel;

namespace {

class MemoryFiles final : public FileSystem {
 public:
  std::map<std::string, std::string> files;
  std::optional<std::string> read(const std::string& path, std::string& error) const override {
    auto it = files.find(path);
    if (it == files.end()) {
      error = "No such file or directory";
      return std::nullopt;
    }
    return it->second;
  }
};

ReadResult read(const std::string& text, const FileSystem& files = disk(), const std::string& path = "m/model.xml") {
  return mjcf::read_mjcf(std::make_shared<const SourceFile>(path, text), files);
}

std::string located(const ReadResult& r) {
  std::string out;
  for (const auto& d : r.diagnostics)
    out += d.rule + " " + std::to_string(d.span.file) + ":" + std::to_string(d.span.line) + ":" +
           std::to_string(d.span.column) + " " + d.message + "\n";
  return out;
}

}  // namespace

TEST_CASE("the guide's MJCF gripper reads like its URDF twin", "[mjcf]") {
  const auto path = test::fixtures_dir() / "mjcf" / "robotiq_2f85" / "robotiq_2f85.xml";
  const ReadResult r = read(test::read_file(path));
  INFO(located(r));
  REQUIRE(r.usable);
  CHECK(r.diagnostics.empty());
  const Asset& a = r.asset;
  CHECK(a.format == SourceFormat::Mjcf);
  CHECK(a.robot_name.text == "robotiq_2f85_guide");
  CHECK(a.links.size() == 7);
  // base_link is welded to the world; six hinges.
  const Joint* weld = a.find_joint("base_link (welded)");
  REQUIRE(weld);
  CHECK(weld->type == JointType::Fixed);
  CHECK(weld->parent.text.empty());

  const Joint* j0 = a.find_joint("finger_joint");
  REQUIRE(j0);
  CHECK(j0->type == JointType::Revolute);
  CHECK(j0->parent.text == "base_link");
  CHECK(j0->child.text == "left_outer_knuckle");
  CHECK(j0->axis.isApprox(Eigen::Vector3d::UnitX()));
  CHECK(j0->frame_in_link[0].translation().isApprox(Eigen::Vector3d(0, -0.0306, 0.0549)));
  REQUIRE(j0->upper);
  CHECK(j0->upper->unit == Unit::Degree);
  CHECK(j0->upper->authored == 47);
  CHECK_THAT(j0->upper->value, WithinRel(47 * std::numbers::pi / 180, 1e-12));
  CHECK(j0->upper->span.line == 27);
  REQUIRE(j0->drive);
  CHECK_THAT(j0->drive->stiffness->value, WithinRel(275.0, 1e-12));
  CHECK(j0->drive->stiffness->unit == Unit::NewtonMeterPerRadian);
  CHECK_THAT(j0->drive->damping->value, WithinRel(0.06073, 1e-12));
  CHECK_THAT(j0->drive->max_force->value, WithinRel(24.0, 1e-12));
  CHECK_FALSE(j0->velocity);

  // Class "inner_finger" gives the range; the mimic is q1 = c0 + c1·q2.
  const Joint* finger = a.find_joint("left_inner_finger_joint");
  REQUIRE(finger);
  REQUIRE(finger->lower);
  CHECK(finger->lower->authored == -47);
  CHECK(finger->lower->span.line == 18);  // written in the default class
  REQUIRE(finger->mimic);
  CHECK(finger->mimic->reference.text == "finger_joint");
  CHECK(finger->mimic->multiplier.value == -1);
  CHECK(finger->mimic->offset.value == 0);
  CHECK(finger->mimic->offset.unit == Unit::Radian);
  // childclass on the right outer knuckle body reaches its own joint.
  const Joint* right = a.find_joint("right_outer_knuckle_joint");
  REQUIRE(right);
  REQUIRE(right->upper);
  CHECK(right->upper->authored == 47);

  const Link* base = a.find_link("base_link");
  REQUIRE(base);
  REQUIRE(base->inertial);
  CHECK(base->inertial->mass.value == 0.636);
  CHECK(base->inertial->com.isApprox(Eigen::Vector3d(0, 0, 0.03)));
  CHECK_THAT(base->inertial->inertia(2, 2), WithinRel(0.00043, 1e-12));

  REQUIRE(a.scene.timesteps_per_second);
  CHECK_THAT(a.scene.timesteps_per_second->value, WithinRel(250.0, 1e-12));
  CHECK(a.scene.timesteps_per_second->authored == 0.004);
  CHECK(a.scene.solver == "MuJoCo");
}

TEST_CASE("MJCF: radians, euler sequences, gear and general actuators", "[mjcf]") {
  const ReadResult r = read(R"(<mujoco>
  <compiler angle="radian" eulerseq="zyx"/>
  <default>
    <general biastype="affine" gainprm="100" biasprm="0 -100 -10"/>
  </default>
  <worldbody>
    <body name="a" euler="1.5707963267948966 0 0">
      <joint name="j" range="-1 1" armature="0.01" damping="0.5" frictionloss="0.2" stiffness="3"/>
      <inertial pos="0 0 0" mass="1" fullinertia="1 2 3 0.1 0 0"/>
      <body name="b" pos="0 0 1"><joint name="s" type="slide" limited="false" range="0 1"/></body>
    </body>
  </worldbody>
  <actuator>
    <general joint="j" gear="2" forcerange="-3 5"/>
    <motor joint="s" ctrlrange="-7 7" gear="3"/>
  </actuator>
</mujoco>)");
  INFO(located(r));
  REQUIRE(r.usable);
  CHECK(r.diagnostics.empty());
  const Joint* j = r.asset.find_joint("j");
  REQUIRE(j);
  CHECK(j->upper->unit == Unit::Radian);
  CHECK(j->upper->value == 1);
  CHECK(j->armature->value == 0.01);
  CHECK(j->joint_damping->value == 0.5);
  CHECK(j->joint_friction->value == 0.2);
  CHECK(j->joint_stiffness->value == 3);
  // eulerseq zyx with only the z angle: a quarter turn about z; the joint axis (z) stays z.
  CHECK(j->frame_in_link[0].linear().isApprox(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix()));
  REQUIRE(j->drive);
  // Joint gains: −biasprm through the gear squared; max force through |gear|.
  CHECK_THAT(j->drive->stiffness->value, WithinRel(400.0, 1e-12));
  CHECK(j->drive->stiffness->authored == -100);
  CHECK(j->drive->stiffness->authored_for(800.0) == -200);
  // kv·gear² plus the joint's own damping: two literals, so no single one to rewrite.
  CHECK_THAT(j->drive->damping->value, WithinRel(40.5, 1e-12));
  CHECK_FALSE(j->drive->damping->is_authored());
  CHECK_THAT(j->drive->max_force->value, WithinRel(10.0, 1e-12));
  CHECK(j->drive->max_force->authored == 5);
  const Joint* s = r.asset.find_joint("s");
  REQUIRE(s);
  CHECK(s->type == JointType::Prismatic);
  CHECK_FALSE(s->lower);  // limited="false" wins over the range
  REQUIRE(s->effort);
  CHECK_THAT(s->effort->value, WithinRel(21.0, 1e-12));
  CHECK_FALSE(s->drive);
  const Link* a = r.asset.find_link("a");
  REQUIRE(a->inertial);
  CHECK(a->inertial->inertia(0, 1) == 0.1);
}

TEST_CASE("MJCF: degrees are the default, hinges without a range are continuous", "[mjcf]") {
  const ReadResult r = read(R"(<mujoco><worldbody><body name="a">
      <joint name="limited" range="-90 90"/><joint name="free_spin"/>
      <body name="b" axisangle="0 0 1 90"><freejoint name="float"/></body>
  </body></worldbody></mujoco>)");
  REQUIRE(r.usable);
  const Joint* limited = r.asset.find_joint("limited");
  CHECK(limited->type == JointType::Revolute);
  CHECK(limited->upper->unit == Unit::Degree);
  CHECK_THAT(limited->upper->value, WithinRel(std::numbers::pi / 2, 1e-12));
  CHECK(r.asset.find_joint("free_spin")->type == JointType::Continuous);
  CHECK(r.asset.find_joint("float")->type == JointType::Floating);
  CHECK(r.asset.scene.timesteps_per_second->value == 500);
  CHECK_FALSE(r.asset.scene.timesteps_per_second->is_authored());
  CHECK(r.asset.scene.integrator.empty());  // MuJoCo's default, Euler
  const ReadResult fast = read("<mujoco><option integrator='implicitfast'/><worldbody/></mujoco>");
  CHECK(fast.asset.scene.integrator == "implicitfast");
  CHECK(fast.asset.scene.integrator_span.column == 29);
  CHECK_FALSE(r.asset.find_link("a")->inertial);  // MuJoCo derives it from geoms
}

TEST_CASE("MJCF: includes are read relative to the model, outside ones are skipped", "[mjcf]") {
  MemoryFiles files;
  files.files["m/parts/arm.xml"] = R"(<mujoco><body name="arm"><joint name="elbow" range="0 1"/></body></mujoco>)";
  files.files["outside.xml"] = "<mujoco/>";
  const ReadResult r = read(R"(<mujoco><compiler angle="radian"/>
<worldbody><include file="parts/arm.xml"/></worldbody>
<include file="../outside.xml"/>
</mujoco>)",
                            files);
  INFO(located(r));
  REQUIRE(r.usable);
  REQUIRE(r.asset.sources.size() == 2);
  CHECK(r.asset.sources[1]->path() == "m/parts/arm.xml");
  const Joint* elbow = r.asset.find_joint("elbow");
  REQUIRE(elbow);
  CHECK(elbow->upper->span.file == 1);
  CHECK(elbow->upper->unit == Unit::Radian);
  CHECK(located(r) ==
        "layer-unresolved 0:3:16 include '../outside.xml' is outside the checked directory tree; skipped\n");
}

TEST_CASE("MJCF: a missing include is an error and nothing else in the model is judged", "[mjcf]") {
  // The include that is missing could hold <compiler angle="radian">: reading the ranges in
  // degrees without it would report every joint.
  const ReadResult r = read(R"(<mujoco><include file="missing.xml"/>
<worldbody><body name="a"><joint name="j" range="-1.57 1.57"/></body></worldbody>
</mujoco>)");
  CHECK_FALSE(r.usable);
  REQUIRE(r.diagnostics.size() == 1);
  CHECK(r.diagnostics[0].severity == Severity::Error);
  CHECK(located(r) == "layer-unresolved 0:1:24 include 'missing.xml' cannot be read: No such file or directory\n");
}

TEST_CASE("MJCF: a joint equality leads from its actuated side", "[mjcf]") {
  const std::string model = R"(<mujoco><compiler angle="radian"/><worldbody><body name="base">
      <body name="l"><joint name="left" type="slide" range="0 0.04"/></body>
      <body name="r"><joint name="right" type="slide" range="0 0.02"/></body></body></worldbody>
    <equality><joint joint1="left" joint2="right" polycoef="0.004 2 0 0 0"/></equality>
    <actuator>ACTUATORS</actuator></mujoco>)";
  const auto with = [&](const std::string& actuators) {
    std::string text = model;
    text.replace(text.find("ACTUATORS"), 9, actuators);
    return read(text);
  };
  // Only joint1 actuated: joint2 follows it, q2 = (q1 − 0.004) / 2.
  const ReadResult left_driven = with(R"(<position joint="left" kp="100"/>)");
  REQUIRE(left_driven.usable);
  CHECK_FALSE(left_driven.asset.find_joint("left")->mimic);
  const Joint* right = left_driven.asset.find_joint("right");
  REQUIRE(right->mimic);
  CHECK(right->mimic->reference.text == "left");
  CHECK_THAT(right->mimic->multiplier.value, WithinRel(0.5, 1e-12));
  CHECK_THAT(right->mimic->offset.value, WithinRel(-0.002, 1e-12));
  CHECK(right->mimic->reference.span.column == 30);
  // joint2 actuated, or both, or neither: joint1 follows joint2, as written.
  for (const std::string& actuators : {std::string(R"(<position joint="right" kp="100"/>)"),
                                       std::string(R"(<position joint="left" kp="100"/><position joint="right" kp="100"/>)"),
                                       std::string()}) {
    const ReadResult r = with(actuators);
    INFO(actuators);
    const Joint* left = r.asset.find_joint("left");
    REQUIRE(left->mimic);
    CHECK(left->mimic->reference.text == "right");
    CHECK(left->mimic->multiplier.value == 2);
    CHECK_FALSE(r.asset.find_joint("right")->mimic);
  }
}

TEST_CASE("MJCF: errors carry file, line and column", "[mjcf]") {
  CHECK(located(read("<mujoco>\n<worldbody><body name='a'><joint range='0 x'/></body></worldbody></mujoco>")) ==
        "parse-error 0:2:41 <joint range>: expected 2 numbers, found '0 x'\n");
  CHECK(located(read("<robot name='r'/>")) == "parse-error 0:1:1 not MJCF: the root element is <robot>, expected <mujoco>\n");
  CHECK(located(read("<mujoco><worldbody><body childclass='nope'/></worldbody></mujoco>")) ==
        "parse-error 0:1:38 unknown default class 'nope'\n");
  CHECK(located(read("<mujoco>\n  <option integrator='Implicit'/><worldbody/></mujoco>")) ==
        "parse-error 0:2:23 <option integrator>: expected Euler, RK4, implicit or implicitfast, found 'Implicit'\n");
  const ReadResult broken = read("<mujoco>\n  <worldbody>\n</mujoco>");
  CHECK_FALSE(broken.usable);
  REQUIRE_FALSE(broken.diagnostics.empty());
  CHECK(broken.diagnostics[0].rule == "parse-error");
  CHECK(broken.diagnostics[0].span.line == 3);
}

TEST_CASE("MJCF: every use of classes a loader would add is one error with a note per use", "[mjcf]") {
  const ReadResult r = read(
      "<mujoco><worldbody><body name='a'>\n"
      "<joint name='j1' class='large'/>\n"
      "<body name='b'><joint name='j2' class='small'/>\n"
      "<body name='c'><joint name='j3' class='large'/></body></body>\n"
      "</body></worldbody></mujoco>");
  REQUIRE(r.diagnostics.size() == 1);
  const Diagnostic& d = r.diagnostics[0];
  CHECK(d.rule == "parse-error");
  CHECK(d.span.line == 2);
  CHECK(d.message == "2 unknown default classes ('large', 'small'), used 3 times");
  REQUIRE(d.notes.size() == 3);
  CHECK(d.notes[1].message == "'small' is not defined either");
  CHECK(d.notes[1].span.line == 3);
  CHECK(d.notes[2].message == "'large' used again");
  CHECK(d.notes[2].span.line == 4);
}

TEST_CASE("MJCF: nonlinear couplings and tendon actuators are reported as not modelled", "[mjcf]") {
  const ReadResult r = read(R"(<mujoco><worldbody><body name="a"><joint name="p"/>
<body name="b"><joint name="q"/></body></body></worldbody>
<equality><joint joint1="q" joint2="p" polycoef="0.1 2 0.5 0 0"/></equality>
<actuator><position tendon="t" kp="5"/></actuator></mujoco>)");
  INFO(located(r));
  // The polynomial maps p's range elsewhere than its linear part would: no mimic to judge.
  const Joint* q = r.asset.find_joint("q");
  REQUIRE(q);
  CHECK_FALSE(q->mimic);
  CHECK_FALSE(r.asset.find_joint("p")->mimic);
  CHECK(located(r) ==
        "mjcf-unsupported 0:3:56 coupling of 'q' is nonlinear (polycoef c2 = 0.5)\n"
        "mjcf-unsupported 0:4:11 <position> actuator acts through tendon 't'\n");
}
