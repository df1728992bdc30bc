// The joint schemas Newton and MuJoCo read besides PhysX's: NewtonMimicAPI as a mimic,
// NewtonJointAPI's and MjcJointAPI's armature, MjcJointAPI's damping; units converted once.
#include <catch2/catch.hpp>

#include <numbers>
#include <string>

#include "formats/usda/usd_reader.h"

using namespace assetlint;
using Catch::Matchers::WithinRel;

namespace {

ReadResult read_text(const std::string& joints, const std::string& stage_units = "metersPerUnit = 1") {
  std::string text = "#usda 1.0\n(\n    " + stage_units + R"(
)

def Xform "robot" (
    prepend apiSchemas = ["NewtonArticulationRootAPI"]
)
{
    def Xform "base" (
        prepend apiSchemas = ["PhysicsRigidBodyAPI"]
    )
    {
    }

    def Xform "finger" (
        prepend apiSchemas = ["PhysicsRigidBodyAPI"]
    )
    {
    }

    def PhysicsRevoluteJoint "leader"
    {
        rel physics:body0 = </robot/base>
        rel physics:body1 = </robot/finger>
        float physics:lowerLimit = 0
        float physics:upperLimit = 45
    }

    def PhysicsPrismaticJoint "slider"
    {
        rel physics:body0 = </robot/base>
        rel physics:body1 = </robot/finger>
    }
)" + joints + "}\n";
  return usda::read_usda(std::make_shared<const SourceFile>("mem/robot.usda", std::move(text)), disk());
}

const Joint& joint(const ReadResult& r, const char* name) {
  const Joint* j = r.asset.find_joint(name);
  REQUIRE(j != nullptr);
  return *j;
}

constexpr double kDegree = std::numbers::pi / 180.0;

}  // namespace

TEST_CASE("newton schemas: NewtonMimicAPI is a mimic, joint0 = coef0 + coef1 · joint1", "[usd][reader][newton]") {
  auto r = read_text(R"(
    def PhysicsRevoluteJoint "follower" (
        prepend apiSchemas = ["NewtonMimicAPI"]
    )
    {
        rel physics:body0 = </robot/base>
        rel physics:body1 = </robot/finger>
        rel newton:mimicJoint = </robot/leader>
        float newton:mimicCoef0 = 10
        float newton:mimicCoef1 = -0.5
    }

    def PhysicsRevoluteJoint "defaults" (
        prepend apiSchemas = ["NewtonMimicAPI"]
    )
    {
        rel newton:mimicJoint = </robot/leader>
    }

    def PhysicsRevoluteJoint "disabled" (
        prepend apiSchemas = ["NewtonMimicAPI"]
    )
    {
        bool newton:mimicEnabled = false
        rel newton:mimicJoint = </robot/leader>
    }

    def PhysicsRevoluteJoint "unapplied"
    {
        rel newton:mimicJoint = </robot/leader>
    }
)");
  REQUIRE(r.usable);
  const Joint& follower = joint(r, "/robot/follower");
  REQUIRE(follower.mimic);
  CHECK(follower.mimic->reference.text == "/robot/leader");
  CHECK(follower.mimic->multiplier.value == -0.5);  // the model's convention already: no sign flip
  CHECK(follower.mimic->multiplier.unit == Unit::None);
  CHECK_THAT(follower.mimic->offset.value, WithinRel(10 * kDegree, 1e-12));  // degrees for a revolute follower
  CHECK(follower.mimic->offset.unit == Unit::Degree);
  CHECK(follower.mimic->instance.empty());
  CHECK_FALSE(follower.mimic->natural_frequency);  // a hard constraint: no compliance to judge

  const Joint& defaults = joint(r, "/robot/defaults");
  REQUIRE(defaults.mimic);
  CHECK(defaults.mimic->multiplier.value == 1.0);  // the schema's fallbacks
  CHECK(defaults.mimic->offset.value == 0.0);
  CHECK_FALSE(defaults.mimic->multiplier.is_authored());

  CHECK_FALSE(joint(r, "/robot/disabled").mimic);   // newton:mimicEnabled = false: the joint moves freely
  CHECK_FALSE(joint(r, "/robot/unapplied").mimic);  // no NewtonMimicAPI: nothing reads the relationship
  // A Newton mimic is not omni.physx's: no finite-limit requirement.
  for (const Diagnostic& d : r.diagnostics) CHECK(d.rule != "mimic-limits-required");
}

TEST_CASE("newton schemas: a prismatic Newton mimic's offset is in stage distance", "[usd][reader][newton]") {
  auto r = read_text(R"(
    def PhysicsPrismaticJoint "follower" (
        prepend apiSchemas = ["NewtonMimicAPI"]
    )
    {
        rel newton:mimicJoint = </robot/slider>
        float newton:mimicCoef0 = 2
        float newton:mimicCoef1 = 1
    }
)",
                     "metersPerUnit = 0.01");
  const Joint& follower = joint(r, "/robot/follower");
  REQUIRE(follower.mimic);
  CHECK_THAT(follower.mimic->offset.value, WithinRel(0.02, 1e-12));
  CHECK(follower.mimic->multiplier.value == 1.0);
}

TEST_CASE("newton schemas: PhysxMimicJointAPI stays the mimic PhysX builds when both are applied", "[usd][reader][newton]") {
  auto r = read_text(R"(
    def PhysicsRevoluteJoint "follower" (
        prepend apiSchemas = ["NewtonMimicAPI", "PhysxMimicJointAPI:rotX"]
    )
    {
        float physics:lowerLimit = -45
        float physics:upperLimit = 0
        rel newton:mimicJoint = </robot/leader>
        float newton:mimicCoef1 = -1
        rel physxMimicJoint:rotX:referenceJoint = </robot/leader>
        float physxMimicJoint:rotX:gearing = 1
    }
)");
  const Joint& follower = joint(r, "/robot/follower");
  REQUIRE(follower.mimic);
  CHECK(follower.mimic->instance == "rotX");
  CHECK(follower.mimic->multiplier.value == -1.0);  // gearing 1: q = −q_ref
  CHECK(follower.mimic->multiplier.unit == Unit::UsdGearing);
}

TEST_CASE("newton schemas: MjcJointAPI and NewtonJointAPI armature, MjcJointAPI damping per radian",
          "[usd][reader][newton]") {
  auto r = read_text(R"(
    def PhysicsRevoluteJoint "mjc" (
        prepend apiSchemas = ["MjcJointAPI"]
    )
    {
        uniform double mjc:armature = 0.3
        uniform double mjc:damping = 0.05
    }

    def PhysicsRevoluteJoint "newton" (
        prepend apiSchemas = ["NewtonJointAPI", "MjcJointAPI"]
    )
    {
        float newton:armature = 0.02
        uniform double mjc:armature = 0.3
    }

    def PhysicsRevoluteJoint "physx" (
        prepend apiSchemas = ["PhysxJointAPI", "MjcJointAPI"]
    )
    {
        float physxJoint:armature = 0.001
        uniform double mjc:armature = 0.3
    }

    def PhysicsPrismaticJoint "mjc_slider" (
        prepend apiSchemas = ["MjcJointAPI"]
    )
    {
        uniform double mjc:armature = 0.5
        uniform double mjc:damping = 3
    }

    def PhysicsRevoluteJoint "unapplied"
    {
        uniform double mjc:armature = 0.3
    }
)");
  const Joint& mjc = joint(r, "/robot/mjc");
  REQUIRE(mjc.armature);
  CHECK(mjc.armature->value == 0.3);
  CHECK(mjc.armature->unit == Unit::KilogramMeter2);
  REQUIRE(mjc.joint_damping);
  CHECK(mjc.joint_damping->value == 0.05);  // MuJoCo's damping is per radian already
  CHECK(mjc.joint_damping->unit == Unit::NewtonMeterSecondPerRadian);
  CHECK(joint(r, "/robot/newton").armature->value == Approx(0.02));  // Newton's own attribute first
  CHECK(joint(r, "/robot/physx").armature->value == Approx(0.001));   // what PhysX simulates first
  const Joint& slider = joint(r, "/robot/mjc_slider");
  CHECK(slider.armature->unit == Unit::Kilogram);
  CHECK(slider.joint_damping->unit == Unit::NewtonSecondPerMeter);
  CHECK(slider.joint_damping->value == 3.0);
  CHECK_FALSE(joint(r, "/robot/unapplied").armature);
}

TEST_CASE("newton schemas: stage units scale MjcJointAPI values like every USD value", "[usd][reader][newton]") {
  auto r = read_text(R"(
    def PhysicsRevoluteJoint "mjc" (
        prepend apiSchemas = ["MjcJointAPI"]
    )
    {
        uniform double mjc:armature = 100
        uniform double mjc:damping = 100
    }
)",
                     "metersPerUnit = 0.1");
  const Joint& mjc = joint(r, "/robot/mjc");
  CHECK_THAT(mjc.armature->value, WithinRel(1.0, 1e-12));  // kg·(0.1 m)²
  CHECK_THAT(mjc.joint_damping->value, WithinRel(1.0, 1e-12));
}
