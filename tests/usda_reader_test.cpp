// USD → model mapping: joints, drives, mimic joints, mass properties, scene; reader
// diagnostics (stale-schema-attribute, mimic-axis-instance); the Robotiq corpus stack.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>

#include "pipeline/lint.h"
#include "formats/file_kind.h"
#include "formats/usda/usd_reader.h"
#include "engine/rule.h"
#include "report/text_reporter.h"
#include "rules/registry.h"
#include "test_support.h"

using namespace assetlint;
using Catch::Matchers::WithinRel;
using Catch::Matchers::WithinAbs;

namespace {

ReadResult read_text(std::string text, const std::string& path = "mem/robot.usda") {
  return usda::read_usda(std::make_shared<const SourceFile>(path, std::move(text)), disk());
}

std::string_view text_of(const ReadResult& r, const Span& s) {
  return r.asset.source(s.file).view().substr(s.offset, s.length);
}

const char* kRobot = R"(#usda 1.0
(
    defaultPrim = "robot"
    metersPerUnit = 1
)

def Xform "robot" (
    prepend apiSchemas = ["PhysicsArticulationRootAPI", "PhysxArticulationAPI"]
)
{
    int physxArticulation:solverPositionIterationCount = 64

    def Xform "base" (
        prepend apiSchemas = ["PhysicsRigidBodyAPI"]
    )
    {
    }

    def Xform "finger" (
        prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsMassAPI"]
    )
    {
        float physics:mass = 0.0127
        float3 physics:diagonalInertia = (2.1e-6, 1e-6, 1.5e-6)
        point3f physics:centerOfMass = (0, 0.01, 0)
    }

    def PhysicsRevoluteJoint "J0" (
        prepend apiSchemas = ["PhysxJointAPI", "PhysicsDriveAPI:angular"]
    )
    {
        rel physics:body0 = </robot/base>
        rel physics:body1 = </robot/finger>
        uniform token physics:axis = "Z"
        point3f physics:localPos0 = (0, 0.5, 0)
        quatf physics:localRot0 = (0.70710678, 0, 0, 0.70710678)
        float physics:lowerLimit = 0
        float physics:upperLimit = 47
        float drive:angular:physics:stiffness = 3
        float drive:angular:physics:damping = 0.0002
        float drive:angular:physics:maxForce = 26
        uniform token drive:angular:physics:type = "force"
        float physxJoint:maxJointVelocity = 146.46
        float physxJoint:armature = 0.0001
    }

    def PhysicsRevoluteJoint "J1" (
        prepend apiSchemas = ["PhysxMimicJointAPI:rotZ"]
    )
    {
        rel physics:body0 = </robot/base>
        rel physics:body1 = </robot/finger>
        uniform token physics:axis = "Z"
        float physics:lowerLimit = -inf
        float physics:upperLimit = inf
        rel physxMimicJoint:rotZ:referenceJoint = </robot/J0>
        float physxMimicJoint:rotZ:gearing = 1
        float physxMimicJoint:rotZ:offset = 10
        float physxMimicJoint:rotZ:naturalFrequency = 5000
        float physxMimicJoint:rotZ:dampingRatio = 0.5
    }

    def PhysicsPrismaticJoint "slide"
    {
        float physics:lowerLimit = -0.5
        float physics:upperLimit = 0.25
    }

    def PhysicsScene "scene" (
        prepend apiSchemas = ["PhysxSceneAPI"]
    )
    {
        uint physxScene:timeStepsPerSecond = 250
        uniform token physxScene:solverType = "TGS"
    }
}
)";

}  // namespace

TEST_CASE("usd reader: revolute joint with drive, PhysX joint values, limits", "[usd][reader]") {
  ReadResult r = read_text(kRobot);
  REQUIRE(r.usable);
  // J1's mimic has no finite limits (±inf): the only finding, from the reader.
  REQUIRE(r.diagnostics.size() == 1);
  CHECK(r.diagnostics[0].rule == "mimic-limits-required");
  const Asset& a = r.asset;
  CHECK(a.format == SourceFormat::Usda);
  CHECK(a.robot_name.text == "robot");
  REQUIRE(a.joints.size() == 3);
  const Joint* j = a.find_joint("/robot/J0");
  REQUIRE(j);
  CHECK(j->type == JointType::Revolute);
  CHECK(j->parent.text == "/robot/base");
  CHECK(j->child.text == "/robot/finger");
  CHECK(text_of(r, j->parent.span) == "</robot/base>");
  CHECK(j->axis == Eigen::Vector3d::UnitZ());
  CHECK(j->frame_in_link[0].translation().isApprox(Eigen::Vector3d(0, 0.5, 0)));
  CHECK(j->frame_in_link[0].linear().isApprox(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix(), 1e-6));
  REQUIRE(j->lower);
  REQUIRE(j->upper);
  CHECK(j->lower->value == 0);
  CHECK_THAT(j->upper->value, WithinRel(0.820305, 1e-6));
  CHECK(j->upper->unit == Unit::Degree);
  CHECK(j->upper->authored == 47);
  REQUIRE(j->drive);
  CHECK(j->drive->instance == "angular");
  CHECK(text_of(r, j->drive->span) == "\"PhysicsDriveAPI:angular\"");
  CHECK_THAT(j->drive->stiffness->value, WithinRel(171.887, 1e-5));
  CHECK(j->drive->stiffness->unit == Unit::NewtonMeterPerDegree);
  CHECK(j->drive->stiffness->authored == 3);
  CHECK(text_of(r, j->drive->stiffness->span) == "3");
  CHECK(text_of(r, j->drive->stiffness->declaration) == "        float drive:angular:physics:stiffness = 3\n");
  CHECK_THAT(j->drive->damping->value, WithinRel(0.0002 * 180 / std::numbers::pi, 1e-9));
  CHECK(j->drive->max_force->value == 26);
  CHECK(j->drive->type == DriveType::Force);
  REQUIRE(j->velocity);
  CHECK_THAT(j->velocity->value, WithinRel(2.5562, 1e-4));
  CHECK(j->velocity->unit == Unit::DegreePerSecond);
  CHECK_THAT(j->armature->value, WithinRel(1e-4, 1e-9));
  CHECK_FALSE(j->mimic);

  const Joint* slide = a.find_joint("/robot/slide");
  REQUIRE(slide);
  CHECK(slide->type == JointType::Prismatic);
  CHECK(slide->lower->value == -0.5);
  CHECK(slide->lower->unit == Unit::Meter);
  CHECK_FALSE(slide->drive);
  CHECK_FALSE(slide->velocity);
  CHECK(slide->parent.text.empty());  // world-attached
}

TEST_CASE("usd reader: mimic joint gearing, offset, compliance, infinite limits are free", "[usd][reader]") {
  ReadResult r = read_text(kRobot);
  const Joint* j = r.asset.find_joint("/robot/J1");
  REQUIRE(j);
  CHECK_FALSE(j->lower);
  CHECK_FALSE(j->upper);
  CHECK_FALSE(j->drive);
  CHECK_FALSE(j->velocity);  // unauthored maxJointVelocity stays empty
  REQUIRE(j->mimic);
  CHECK(j->mimic->instance == "rotZ");
  CHECK(j->mimic->reference.text == "/robot/J0");
  CHECK(r.asset.find_joint(j->mimic->reference.text));
  CHECK(j->mimic->multiplier.value == -1);
  CHECK(j->mimic->multiplier.authored == 1);
  CHECK(j->mimic->multiplier.unit == Unit::UsdGearing);
  CHECK_THAT(j->mimic->offset.value, WithinRel(-10 * std::numbers::pi / 180, 1e-9));
  CHECK(j->mimic->offset.unit == Unit::UsdOffsetDegree);
  CHECK(j->mimic->natural_frequency->value == 5000);
  CHECK(j->mimic->damping_ratio->value == 0.5);
  CHECK(text_of(r, j->mimic->span) == "\"PhysxMimicJointAPI:rotZ\"");
}

TEST_CASE("usd reader: links, mass properties, scene and articulation", "[usd][reader]") {
  ReadResult r = read_text(kRobot);
  const Asset& a = r.asset;
  REQUIRE(a.links.size() == 2);
  const Link* base = a.find_link("/robot/base");
  REQUIRE(base);
  CHECK_FALSE(base->inertial);  // no PhysicsMassAPI: PhysX derives it from colliders
  const Link* finger = a.find_link("/robot/finger");
  REQUIRE(finger->inertial);
  CHECK(finger->inertial->mass.value == Approx(0.0127));
  CHECK(finger->inertial->mass_authored);
  CHECK(finger->inertial->inertia_authored);
  CHECK(finger->inertial->inertia.diagonal().isApprox(Eigen::Vector3d(2.1e-6, 1e-6, 1.5e-6), 1e-6));
  CHECK(finger->inertial->com.isApprox(Eigen::Vector3d(0, 0.01, 0)));
  REQUIRE(a.scene.timesteps_per_second);
  CHECK(a.scene.timesteps_per_second->value == 250);
  CHECK(a.scene.solver == "TGS");
  REQUIRE(a.scene.position_iterations);
  CHECK(a.scene.position_iterations->value == 64);
}

TEST_CASE("usd reader: stage units scale lengths, masses and inertia", "[usd][reader]") {
  // metersPerUnit unauthored: 0.01 (centimetres); kilogramsPerUnit 0.001 (grams).
  ReadResult r = read_text(R"(#usda 1.0
(
    kilogramsPerUnit = 0.001
)
def Xform "b" (
    prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsMassAPI"]
)
{
    float physics:mass = 2000
    float3 physics:diagonalInertia = (1, 2, 3)
    quatf physics:principalAxes = (0.70710678, 0, 0, 0.70710678)
    point3f physics:centerOfMass = (10, 0, 0)
}
def Xform "c" (
    prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsMassAPI"]
)
{
    point3f physics:centerOfMass = (-inf, -inf, -inf)
    float physics:mass = 0
}
def PhysicsPrismaticJoint "p" (
    prepend apiSchemas = ["PhysicsDriveAPI:linear"]
)
{
    point3f physics:localPos1 = (0, 0, 50)
    float physics:upperLimit = 30
    float drive:linear:physics:stiffness = 100
}
)");
  REQUIRE(r.usable);
  const Link* b = r.asset.find_link("/b");
  REQUIRE(b);
  CHECK(b->inertial->mass.value == Approx(2.0));
  CHECK(b->inertial->mass.authored == 2000);
  CHECK(b->inertial->mass.authored_for(3.0) == Approx(3000));  // fixes write back in the file's units
  // R = Rz(90°): R·diag(1, 2, 3)·Rᵀ = diag(2, 1, 3), × 1e-3 kg × (0.01 m)².
  Eigen::Matrix3d expected = Eigen::Vector3d(2e-7, 1e-7, 3e-7).asDiagonal();
  CHECK(b->inertial->inertia.isApprox(expected, 1e-6));
  CHECK(b->inertial->com.isApprox(Eigen::Vector3d(0.1, 0, 0)));
  const Link* c = r.asset.find_link("/c");
  CHECK_FALSE(c->inertial->mass_authored);
  CHECK_FALSE(c->inertial->inertia_authored);
  CHECK(c->inertial->com.isZero());
  const Joint* p = r.asset.find_joint("/p");
  CHECK(p->frame_in_link[1].translation().isApprox(Eigen::Vector3d(0, 0, 0.5)));
  CHECK(p->upper->value == Approx(0.3));
  CHECK(p->upper->authored == 30);
  CHECK(p->drive->instance == "linear");
  CHECK(p->drive->stiffness->value == Approx(0.1));  // N/m: force scales with kg, the length cancels
}

TEST_CASE("usd reader: stale schema attributes and unknown mimic instances", "[usd][reader]") {
  ReadResult r = read_text(R"(#usda 1.0
(
    metersPerUnit = 1
)
def PhysicsRevoluteJoint "m" (
    delete apiSchemas = ["PhysicsDriveAPI:angular"]
    prepend apiSchemas = ["PhysxMimicJointAPI:transZ"]
)
{
    float drive:angular:physics:damping = 5000
    float drive:angular:physics:stiffness = 0
    float physxMimicJoint:transZ:gearing = 1
    float physxMimicJoint:rotZ:gearing = 1
    float physxJoint:maxJointVelocity = 10
}
)");
  REQUIRE(r.usable);
  const Joint* j = r.asset.find_joint("/m");
  REQUIRE(j);
  CHECK_FALSE(j->drive);
  CHECK_FALSE(j->mimic);
  CHECK_FALSE(j->velocity);
  REQUIRE(r.diagnostics.size() == 4);
  std::sort(r.diagnostics.begin(), r.diagnostics.end(),
            [](const Diagnostic& x, const Diagnostic& y) { return x.span.offset < y.span.offset; });
  CHECK(r.diagnostics[0].rule == "mimic-axis-instance");
  CHECK(r.diagnostics[0].severity == Severity::Warning);
  CHECK(r.diagnostics[0].span.line == 7);
  CHECK(r.diagnostics[0].message ==
        "'PhysxMimicJointAPI:transZ' on '/m': not a mimic instance, so the joint is not coupled");
  CHECK(r.diagnostics[0].notes.at(0).message ==
        "A mimic joint instance must be rotX, rotY or rotZ; PhysX silently ignores 'transZ'.");
  CHECK(r.diagnostics[1].rule == "stale-schema-attribute");
  CHECK(r.diagnostics[1].severity == Severity::Info);
  CHECK(r.diagnostics[1].span.line == 10);
  // The zeroed stiffness under `delete apiSchemas` is harmless and left out (issue 15).
  CHECK(r.diagnostics[1].message == "PhysicsDriveAPI:angular on 'm' is deleted: PhysX ignores its attribute");
  REQUIRE(r.diagnostics[1].notes.size() == 2);
  CHECK(r.diagnostics[1].notes[0].message ==
        "'drive:angular:physics:damping' is authored on '/m', but PhysicsDriveAPI:angular is removed by "
        "`delete apiSchemas`.");
  CHECK(r.diagnostics[2].span.line == 13);
  CHECK(r.diagnostics[2].message == "PhysxMimicJointAPI:rotZ on 'm' is not applied: PhysX ignores its attribute");
  // A max velocity PhysX does not get is what the author meant for the joint: a warning.
  CHECK(r.diagnostics[3].message == "PhysxJointAPI on 'm' is not applied: PhysX ignores its max velocity 10 deg/s");
  CHECK(r.diagnostics[3].severity == Severity::Warning);
  CHECK(r.diagnostics[2].severity == Severity::Info);
}

TEST_CASE("usd reader: lint_text dispatches .usda and reports parse errors", "[usd][reader]") {
  FileReport ok = lint_text("x.usda", "#usda 1.0\ndef \"a\" {}\n", Settings{});
  CHECK_FALSE(ok.error);
  CHECK(ok.diagnostics.empty());
  FileReport bad = lint_text("x.usda", "#usda 1.0\ndef \"a\" {\n", Settings{});
  REQUIRE(bad.diagnostics.size() == 1);
  CHECK(bad.diagnostics[0].rule == "parse-error");
  CHECK(file_kind("a/B.USDA") == FileKind::Usda);
}

// --- the real Robotiq 2F-85 layer stack ------------------------------------------------
namespace {
std::filesystem::path corpus_usda() { return assetlint::test::source_dir() / "../shared/corpus/usda"; }
}  // namespace

TEST_CASE("usd reader: every corpus .usda composes and lints without crashing", "[usd][reader][corpus]") {
  if (!std::filesystem::is_directory(corpus_usda())) {
    WARN("corpus absent: " << corpus_usda());
    return;
  }
  int count = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(corpus_usda())) {
    if (!e.is_regular_file() || e.path().extension() != ".usda") continue;
    INFO(e.path().string());
    usda::ComposeOptions options;
    options.root_dir = corpus_usda().string();
    ReadResult r = usda::read_usda(std::make_shared<const SourceFile>(e.path().string(), test::read_file(e.path())),
                                   disk(), options);
    CHECK(r.usable);
    FileReport report = lint_file(e.path().string(), Settings{});
    CHECK_FALSE(report.error);
    ++count;
  }
  CHECK(count >= 15);
}

TEST_CASE("usd reader: the Robotiq configuration layer composes its three layers", "[usd][reader][corpus]") {
  const auto root = corpus_usda() / "robotiq_2f85";
  const auto config = root / "configuration" / "Robotiq_2F_85_config_physics_parallel_grip.usda";
  if (!std::filesystem::exists(config)) {
    WARN("corpus absent: " << config);
    return;
  }
  usda::ComposeOptions options;
  options.root_dir = root.string();
  ReadResult r = usda::read_usda(std::make_shared<const SourceFile>(config.string(), test::read_file(config)), disk(), options);
  REQUIRE(r.usable);
  REQUIRE(r.asset.sources.size() == 3);
  const Asset& a = r.asset;
  CHECK(a.robot_name.text == "Robotiq_2F_85");

  const Joint* j = a.find_joint("/Robotiq_2F_85/Robotiq_2F_85/Joints/finger_joint");
  REQUIRE(j);
  CHECK(a.source(j->span.file).path().ends_with("Robotiq_2F_85_physics_parallel_grip.usda"));
  REQUIRE(j->drive);
  CHECK_THAT(j->drive->stiffness->value, WithinRel(171.887, 1e-4));
  CHECK_THAT(j->drive->damping->value, WithinRel(0.0002 * 180 / std::numbers::pi, 1e-6));
  CHECK(j->drive->max_force->value == 26);
  CHECK_THAT(j->armature->value, WithinRel(1e-4, 1e-6));
  CHECK_THAT(j->velocity->value, WithinRel(146.46 * std::numbers::pi / 180, 1e-6));
  CHECK(j->lower->value == 0);
  CHECK_THAT(j->upper->value, WithinRel(0.820305, 1e-5));
  REQUIRE(a.scene.position_iterations);
  CHECK(a.scene.position_iterations->value == 64);
  CHECK_FALSE(a.scene.timesteps_per_second);

  int mimics = 0;
  for (const Joint& joint : a.joints) {
    if (!joint.mimic) continue;
    ++mimics;
    CHECK_FALSE(joint.drive);  // deleted PhysicsDriveAPI:angular
    CHECK(joint.mimic->reference.text == j->name.text);
    REQUIRE(joint.velocity);
    CHECK(joint.velocity->authored == 10000);
  }
  CHECK(mimics == 5);
  // Bodies: three without mass (PhysX derives it from colliders), six with mass properties.
  int with_mass = 0;
  for (const Link& link : a.links) with_mass += link.inertial && link.inertial->mass_authored;
  CHECK(a.links.size() == 9);
  CHECK(with_mass == 6);
  const Link* finger = a.find_link("/Robotiq_2F_85/Robotiq_2F_85/left_inner_finger");
  REQUIRE(finger);
  CHECK_THAT(finger->inertial->mass.value, WithinRel(0.039254718, 1e-6));

  int stale = 0, unresolved = 0;
  for (const Diagnostic& d : r.diagnostics) {
    stale += d.rule == "stale-schema-attribute";
    unresolved += d.rule == "layer-unresolved";
  }
  CHECK(stale == 0);  // Robotiq's zeroed drive values under `delete apiSchemas` are harmless (issue 15)
  CHECK(unresolved == 6);  // the binary .usd mesh parts

  // The rules see the composed model: every mimic joint's maxJointVelocity 10000 is reported,
  // as an info (far above the 146 deg/s the gearing demands), its removal an unsafe fix.
  std::vector<Diagnostic> findings;
  for (const Rule* rule : rules::checks()) {
    Reporter reporter(rule->info(), findings);
    rule->check(a, Settings{}, reporter);
  }
  int mimic_velocity = 0;
  for (const Diagnostic& d : findings) {
    if (d.rule != "mimic-max-velocity") continue;
    ++mimic_velocity;
    CHECK(a.source(d.span.file).path().ends_with("Robotiq_2F_85_physics_parallel_grip.usda"));
    CHECK(text_of(r, d.span) == "10000");
    CHECK(d.severity == Severity::Info);
    REQUIRE(d.fix);
    CHECK(d.fix->applicability == Applicability::Unsafe);
    CHECK(d.fix->edits.size() == 1);
    CHECK(std::string(text_of(r, Span{d.fix->edits[0].file, d.fix->edits[0].offset, d.fix->edits[0].length, 1, 1}))
              .find("float physxJoint:maxJointVelocity = 10000\n") != std::string::npos);
  }
  CHECK(mimic_velocity == 5);
}

// --- the project's own Robotiq-2F-85-like fixture, single layer and layered -------------
namespace {
ReadResult read_fixture(const char* name) {
  const auto path = test::fixtures_dir() / "usda" / "robotiq_2f85" / name;
  return usda::read_usda(std::make_shared<const SourceFile>(path.string(), test::read_file(path)), disk());
}
}  // namespace

TEST_CASE("usd reader: the guide's gripper fixture carries the guide's numbers", "[usd][reader]") {
  for (const char* name : {"robotiq_2f85.usda", "robotiq_2f85_config.usda"}) {
    INFO(name);
    ReadResult r = read_fixture(name);
    REQUIRE(r.usable);
    CHECK(r.diagnostics.empty());
    const Asset& a = r.asset;
    CHECK(a.robot_name.text == "robotiq_2f85");
    REQUIRE(a.links.size() == 7);
    REQUIRE(a.joints.size() == 6);
    const Joint* j0 = a.find_joint("/robotiq_2f85/joints/finger_joint");
    REQUIRE(j0);
    REQUIRE(j0->drive);
    CHECK_THAT(j0->drive->stiffness->value, WithinRel(275.0, 0.001));
    CHECK_THAT(j0->drive->damping->value, WithinRel(0.0607, 0.001));
    CHECK(j0->drive->max_force->value == 24);
    CHECK_THAT(j0->velocity->value, WithinRel(2.9, 1e-4));
    CHECK_THAT(j0->upper->value, WithinRel(0.820305, 1e-6));
    CHECK(j0->axis == Eigen::Vector3d::UnitX());
    CHECK(j0->frame_in_link[0].translation().isApprox(Eigen::Vector3d(0, -0.0306, 0.0549)));
    int mimics = 0;
    for (const Joint& j : a.joints) {
      if (!j.mimic) continue;
      ++mimics;
      CHECK_FALSE(j.velocity);
      CHECK_FALSE(j.drive);
      CHECK(j.mimic->reference.text == j0->name.text);
      CHECK(std::fabs(j.mimic->multiplier.value) == 1);
      // USD gearing = −URDF multiplier: the finger joints follow with −1, the knuckles with +1.
      CHECK(j.mimic->multiplier.value == (j.lower->value < 0 ? -1 : 1));
    }
    CHECK(mimics == 5);
    const Link* finger = a.find_link("/robotiq_2f85/left_inner_finger");
    REQUIRE(finger);
    REQUIRE(finger->inertial);
    CHECK(finger->inertial->mass.value == Approx(0.0127));
    CHECK(finger->inertial->inertia(0, 0) == Approx(2.1e-6));
    CHECK(finger->inertial->com.isApprox(Eigen::Vector3d(0, 0, 0.01)));
    REQUIRE(a.scene.timesteps_per_second);
    CHECK(a.scene.timesteps_per_second->value == 250);
    CHECK(a.scene.position_iterations->value == 64);
    CHECK(a.scene.solver == "TGS");
  }
  // The layered stack: the winning opinions point into the layer that authored them.
  ReadResult layered = read_fixture("robotiq_2f85_config.usda");
  REQUIRE(layered.asset.sources.size() == 3);
  const Joint* j0 = layered.asset.find_joint("/robotiq_2f85/joints/finger_joint");
  CHECK(layered.asset.source(j0->drive->stiffness->span.file).path().ends_with("robotiq_2f85_physics.usda"));
  CHECK(layered.asset.source(layered.asset.scene.timesteps_per_second->span.file).path().ends_with("robotiq_2f85_config.usda"));
  const Link* base = layered.asset.find_link("/robotiq_2f85/base_link");
  CHECK(layered.asset.source(base->inertial->mass.span.file).path().ends_with("robotiq_2f85_physics.usda"));
}

namespace {

std::string joint_stage(const std::string& joints, const std::string& mpu = "1") {
  return R"(#usda 1.0
(
    metersPerUnit = )" + mpu + R"(
)

def Xform "robot" (
    prepend apiSchemas = ["PhysicsArticulationRootAPI"]
)
{
    def Xform "base" (
        prepend apiSchemas = ["PhysicsRigidBodyAPI"]
    )
    {
    }
)" + joints + "}\n";
}

}  // namespace

TEST_CASE("usd reader: a revolute joint reads only PhysicsDriveAPI:angular, a prismatic one only :linear",
          "[usd][reader][facts]") {
  ReadResult r = read_text(joint_stage(R"(
    def PhysicsRevoluteJoint "rot" (
        prepend apiSchemas = ["PhysicsDriveAPI:rotZ"]
    )
    {
        rel physics:body0 = </robot/base>
        float physics:lowerLimit = 0
        float physics:upperLimit = 47
        float drive:rotZ:physics:stiffness = 5700
    }

    def PhysicsPrismaticJoint "slide" (
        prepend apiSchemas = ["PhysicsDriveAPI:angular", "PhysicsDriveAPI:linear"]
    )
    {
        rel physics:body0 = </robot/base>
        float drive:angular:physics:stiffness = 10
        float drive:linear:physics:stiffness = 200
    }

    def PhysicsJoint "d6" (
        prepend apiSchemas = ["PhysicsDriveAPI:rotX"]
    )
    {
        rel physics:body0 = </robot/base>
        float drive:rotX:physics:stiffness = 3
    }
)"));
  REQUIRE(r.usable);
  const Joint* rot = r.asset.find_joint("/robot/rot");
  REQUIRE(rot);
  CHECK_FALSE(rot->drive);  // undriven: the rotZ drive is dead and not linted
  const Joint* slide = r.asset.find_joint("/robot/slide");
  REQUIRE(slide);
  REQUIRE(slide->drive);
  CHECK(slide->drive->instance == "linear");
  CHECK(slide->drive->stiffness->value == 200);
  const Joint* d6 = r.asset.find_joint("/robot/d6");
  REQUIRE(d6);
  REQUIRE(d6->drive);  // axis instances are what a D6 joint reads
  CHECK(d6->drive->instance == "rotX");

  REQUIRE(r.diagnostics.size() == 2);
  CHECK(r.diagnostics[0].rule == "drive-instance-ignored");
  CHECK(r.diagnostics[0].message ==
        "PhysicsDriveAPI:rotZ on revolute joint '/robot/rot' drives nothing (PhysX reads only :angular)");
  CHECK(text_of(r, r.diagnostics[0].span) == "\"PhysicsDriveAPI:rotZ\"");
  REQUIRE(r.diagnostics[0].notes.size() == 2);
  CHECK(r.diagnostics[0].notes[0].message.starts_with("The joint is undriven:"));
  CHECK(r.diagnostics[1].message ==
        "PhysicsDriveAPI:angular on prismatic joint '/robot/slide' drives nothing (PhysX reads only :linear)");
  CHECK(r.diagnostics[1].notes[0].message.starts_with("The joint is driven by PhysicsDriveAPI:linear alone:"));
}

TEST_CASE("usd reader: PhysxJointAxisAPI replaces PhysxJointAPI's armature and max velocity as a whole",
          "[usd][reader][facts]") {
  ReadResult r = read_text(joint_stage(R"(
    def PhysicsRevoluteJoint "axis_partial" (
        prepend apiSchemas = ["PhysxJointAPI", "PhysxJointAxisAPI:angular"]
    )
    {
        rel physics:body0 = </robot/base>
        float physics:lowerLimit = 0
        float physics:upperLimit = 47
        float physxJoint:maxJointVelocity = 146
        float physxJoint:armature = 0.01
        float physxJointAxis:angular:armature = 0.002
    }

    def PhysicsRevoluteJoint "joint_api_only" (
        prepend apiSchemas = ["PhysxJointAPI"]
    )
    {
        rel physics:body0 = </robot/base>
        float physics:lowerLimit = 0
        float physics:upperLimit = 47
        float physxJoint:maxJointVelocity = 146
        float physxJoint:armature = 0.01
    }
)"));
  REQUIRE(r.usable);
  const Joint* partial = r.asset.find_joint("/robot/axis_partial");
  REQUIRE(partial);
  REQUIRE(partial->armature);
  CHECK(partial->armature->value == Approx(0.002));
  CHECK_FALSE(partial->velocity);  // the axis schema's own fallback, not PhysxJointAPI's 146
  const Joint* plain = r.asset.find_joint("/robot/joint_api_only");
  REQUIRE(plain);
  CHECK(plain->armature->value == Approx(0.01));
  CHECK(plain->velocity->authored == 146);
}

TEST_CASE("usd reader: mixed angular/linear mimic gearing is converted (degrees, metersPerUnit)", "[usd][reader][facts]") {
  ReadResult r = read_text(joint_stage(R"(
    def PhysicsPrismaticJoint "slide"
    {
        rel physics:body0 = </robot/base>
        float physics:lowerLimit = 0
        float physics:upperLimit = 4
    }

    def PhysicsRevoluteJoint "wheel" (
        prepend apiSchemas = ["PhysxMimicJointAPI:rotX"]
    )
    {
        rel physics:body0 = </robot/base>
        float physics:lowerLimit = -360
        float physics:upperLimit = 360
        rel physxMimicJoint:rotX:referenceJoint = </robot/slide>
        float physxMimicJoint:rotX:gearing = -90
    }

    def PhysicsPrismaticJoint "rack" (
        prepend apiSchemas = ["PhysxMimicJointAPI:rotX"]
    )
    {
        rel physics:body0 = </robot/base>
        float physics:lowerLimit = -10
        float physics:upperLimit = 10
        rel physxMimicJoint:rotX:referenceJoint = </robot/wheel>
        float physxMimicJoint:rotX:gearing = 0.5
    }
)", "0.01"));
  REQUIRE(r.usable);
  CHECK(r.diagnostics.empty());
  const Joint* wheel = r.asset.find_joint("/robot/wheel");
  REQUIRE(wheel);
  // q_wheel = 90 deg per cm of slide = (π/2 rad) / 0.01 m = 157.08 rad/m.
  CHECK(wheel->mimic->multiplier.unit == Unit::UsdGearingDegreePerDistance);
  CHECK_THAT(wheel->mimic->multiplier.value, WithinRel(std::numbers::pi / 2 / 0.01, 1e-9));
  const Joint* rack = r.asset.find_joint("/robot/rack");
  REQUIRE(rack);
  // q_rack = −0.5 cm per degree of wheel = −0.005 m / (π/180 rad) = −0.2865 m/rad.
  CHECK(rack->mimic->multiplier.unit == Unit::UsdGearingDistancePerDegree);
  CHECK_THAT(rack->mimic->multiplier.value, WithinRel(-0.005 * 180 / std::numbers::pi, 1e-9));
}

TEST_CASE("usd reader: a mimic with a revolute reference without finite limits is refused", "[usd][reader][facts]") {
  ReadResult r = read_text(joint_stage(R"(
    def PhysicsRevoluteJoint "leader"
    {
        rel physics:body0 = </robot/base>
        float physics:upperLimit = 47
    }

    def PhysicsRevoluteJoint "follower" (
        prepend apiSchemas = ["PhysxMimicJointAPI:rotX"]
    )
    {
        rel physics:body0 = </robot/base>
        float physics:lowerLimit = 0
        float physics:upperLimit = 47
        rel physxMimicJoint:rotX:referenceJoint = </robot/leader>
    }
)"));
  REQUIRE(r.diagnostics.size() == 1);
  const Diagnostic& d = r.diagnostics[0];
  CHECK(d.rule == "mimic-limits-required");
  CHECK(d.severity == Severity::Error);
  CHECK(d.message == "mimic '/robot/follower' follows revolute joint without finite limits: omni.physx refuses it");
  CHECK(d.notes[0].message.starts_with("'/robot/leader' is a revolute joint whose physics:lowerLimit / "
                                       "physics:upperLimit are not both finite"));
  CHECK(text_of(r, d.span) == "\"PhysxMimicJointAPI:rotX\"");
}

TEST_CASE("usd reader: PhysxDrivePerformanceEnvelopeAPI is read with its drive", "[usd][reader][facts]") {
  ReadResult r = read_text(joint_stage(R"(
    def PhysicsRevoluteJoint "j" (
        prepend apiSchemas = ["PhysicsDriveAPI:angular", "PhysxDrivePerformanceEnvelopeAPI:angular"]
    )
    {
        rel physics:body0 = </robot/base>
        float physics:lowerLimit = 0
        float physics:upperLimit = 47
        float drive:angular:physics:stiffness = 3
        float drive:angular:physics:maxForce = 26
        float physxDrivePerformanceEnvelope:angular:maxActuatorVelocity = 180
        float physxDrivePerformanceEnvelope:angular:velocityDependentResistance = 0.5
    }
)"));
  REQUIRE(r.usable);
  CHECK(r.diagnostics.empty());  // its attributes are not stale: the schema is applied
  const Joint* j = r.asset.find_joint("/robot/j");
  REQUIRE(j);
  REQUIRE(j->drive);
  REQUIRE(j->drive->envelope);
  CHECK_THAT(j->drive->envelope->max_actuator_velocity->value, WithinRel(std::numbers::pi, 1e-9));
  CHECK_THAT(j->drive->envelope->velocity_dependent_resistance->value, WithinRel(0.5 * 180 / std::numbers::pi, 1e-9));
  CHECK_FALSE(j->drive->envelope->speed_effort_gradient);
  CHECK(text_of(r, j->drive->envelope->span) == "\"PhysxDrivePerformanceEnvelopeAPI:angular\"");
}
