// MJCF dampratio: the damping asset-lint derives equals the kv MuJoCo compiles for the same
// files under each release's rule: 3.3 to 3.14 on M₀ (numbers compiled by MuJoCo 3.14), 3.15
// and later on (J·M⁻¹·Jᵀ)⁻¹ (numbers tests/mujoco_reference/compile.mjs forms from MuJoCo's
// own mass matrix; the reference test re-checks both whenever Node and @mujoco/mujoco are
// there); the precedence of kv and dampratio, and an unknown inertia leaving the damping
// unknown, never 0.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/file_system.h"
#include "formats/mjcf/mjcf_reader.h"
#include "physics/dampratio.h"
#include "test_support.h"

using namespace assetlint;
using Catch::Matchers::WithinRel;

namespace {

using physics::DampRatioRule;

mjcf::ReadOptions under(DampRatioRule rule) {
  mjcf::ReadOptions options;
  options.mujoco = rule == DampRatioRule::OperationalSpace ? MujocoVersion{3, 15} : MujocoVersion{3, 14};
  return options;
}

// By default as MuJoCo 3.3 to 3.14 compile it.
ReadResult read_fixture(const std::string& name, DampRatioRule rule = DampRatioRule::JointSpaceDiagonal) {
  const auto path = test::fixtures_dir() / "mjcf" / "dampratio" / name;
  return mjcf::read_mjcf(std::make_shared<const SourceFile>(path.string(), test::read_file(path)), DiskFileSystem{},
                         under(rule));
}

ReadResult read_text(const std::string& text, DampRatioRule rule = DampRatioRule::JointSpaceDiagonal) {
  return mjcf::read_mjcf(std::make_shared<const SourceFile>("m/model.xml", text), DiskFileSystem{}, under(rule));
}

double damping(const Asset& asset, const char* joint) {
  const Joint* j = asset.find_joint(joint);
  REQUIRE(j);
  REQUIRE(j->drive);
  REQUIRE(j->drive->damping);
  CHECK_FALSE(j->drive->damping->is_authored());  // derived: no literal to rewrite
  return j->drive->damping->value;
}

}  // namespace

TEST_CASE("dampratio from a default class compiles to MuJoCo 3.14's kv (G1-style leg)", "[mjcf][dampratio]") {
  const ReadResult r = read_fixture("g1_style_leg.xml");
  REQUIRE(r.usable);
  CHECK_THAT(damping(r.asset, "hip_pitch"), WithinRel(22.685733428743276, 1e-12));
  CHECK_THAT(damping(r.asset, "knee"), WithinRel(10.924976741394007, 1e-12));
  CHECK_THAT(damping(r.asset, "ankle_roll"), WithinRel(1.2715722551235518, 1e-12));
  const Joint* hip = r.asset.find_joint("hip_pitch");
  CHECK(hip->drive->damping_origin.find("MuJoCo 3.3 to 3.14 derive kv from dampratio: kv = 2·ζ·√(kp·M₀) = 2 × 1 × "
                                        "√(150 × 0.857738 kg·m²)") != std::string::npos);
  // 3.15 derives a fifth of it: the note says so.
  CHECK(hip->drive->damping_other_release.find("MuJoCo 3.15 and later derive kv = 4.50259 instead") != std::string::npos);
}

TEST_CASE("MuJoCo 3.15's dampratio: kv on 1/(M⁻¹)ᵢᵢ, a floating base free (G1-style leg)", "[mjcf][dampratio]") {
  const ReadResult r = read_fixture("g1_style_leg.xml", DampRatioRule::OperationalSpace);
  REQUIRE(r.usable);
  // kv_operational from compile.mjs: 2·ζ·√(kp·(J·M⁻¹·Jᵀ)⁻¹) on MuJoCo 3.14's mass matrix.
  CHECK_THAT(damping(r.asset, "hip_pitch"), WithinRel(4.502592419179164, 1e-9));
  CHECK_THAT(damping(r.asset, "knee"), WithinRel(6.450430554157439, 1e-9));
  CHECK_THAT(damping(r.asset, "ankle_roll"), WithinRel(1.2571250356640757, 1e-9));
  const Joint* hip = r.asset.find_joint("hip_pitch");
  CHECK(hip->drive->damping_origin.find("MuJoCo 3.15 and later derive kv from dampratio: kv = 2·ζ·√(kp·m)") !=
        std::string::npos);
  CHECK(hip->drive->damping_other_release.find("MuJoCo 3.3 to 3.14 derive kv = 22.6857 instead (5.04× this)") !=
        std::string::npos);
  // Within 10 % the other release is not mentioned: the ankle's foot couples little.
  CHECK(r.asset.find_joint("ankle_roll")->drive->damping_other_release.empty());
}

TEST_CASE("MuJoCo 3.15's dampratio on a two-link arm: the docs' worked example", "[mjcf][dampratio]") {
  const ReadResult old_rule = read_fixture("two_link_arm.xml");
  const ReadResult new_rule = read_fixture("two_link_arm.xml", DampRatioRule::OperationalSpace);
  REQUIRE(old_rule.usable);
  REQUIRE(new_rule.usable);
  // M₀: 0.27 and 0.03 kg·m²; 1/(M⁻¹)ᵢᵢ = M₁₁ − M₁₂²/M₂₂ = 0.0825 and M₂₂ − M₁₂²/M₁₁ = 0.03 − 0.075²/0.27.
  CHECK_THAT(damping(old_rule.asset, "shoulder"), WithinRel(2 * std::sqrt(100 * 0.27), 1e-12));
  CHECK_THAT(damping(old_rule.asset, "elbow"), WithinRel(2 * std::sqrt(100 * 0.03), 1e-12));
  CHECK_THAT(damping(new_rule.asset, "shoulder"), WithinRel(2 * std::sqrt(100 * 0.0825), 1e-12));
  CHECK_THAT(damping(new_rule.asset, "elbow"), WithinRel(2 * std::sqrt(100 * (0.03 - 0.075 * 0.075 / 0.27)), 1e-12));
}

TEST_CASE("element kv beats a class dampratio, an element dampratio its own, joint damping adds (TIAGo-style arm)",
          "[mjcf][dampratio]") {
  const ReadResult r = read_fixture("tiago_style_arm.xml");
  REQUIRE(r.usable);
  CHECK_THAT(damping(r.asset, "arm_1_joint"), WithinRel(43.154347405562746 + 1, 1e-12));
  const Joint* arm2 = r.asset.find_joint("arm_2_joint");
  REQUIRE(arm2->drive->damping);
  CHECK(arm2->drive->damping->value == 40 + 1);  // its own kv, plus the joint's damping
  CHECK(arm2->drive->damping_origin.empty());
  CHECK_THAT(damping(r.asset, "arm_3_joint"), WithinRel(6.675706883918735 + 1, 1e-12));
  CHECK_THAT(damping(r.asset, "arm_6_joint"), WithinRel(1.1133732527773423 + 0.5, 1e-12));
  CHECK_THAT(damping(r.asset, "torso_lift_joint"), WithinRel(2561.2496949731394 + 1000, 1e-12));
}

TEST_CASE("dampratio through a gear, a <general> positive biasprm[2], and an unknown inertia", "[mjcf][dampratio]") {
  const ReadResult r = read_fixture("gear_and_geom_inertia.xml");
  REQUIRE(r.usable);
  // Through gear 5 the joint sees kv·25.
  CHECK_THAT(damping(r.asset, "wrist_yaw"), WithinRel(0.04007193531637822 * 25, 1e-12));
  CHECK_THAT(damping(r.asset, "wrist_pitch"), WithinRel(0.818840643837371, 1e-12));
  CHECK_THAT(damping(r.asset, "finger_joint"), WithinRel(0.010198039027185598, 1e-12));
  // The thumb's mass comes from its capsule: r 0.008 m, 0.04 m long, 1000 kg/m³ = 0.010187 kg,
  // 6.44599e-6 kg·m² about the hinge 0.02 m from its centroid; kv = 2·√(2 × 6.44599e-6).
  CHECK_THAT(damping(r.asset, "thumb_joint"), WithinRel(0.007181081731230781, 1e-9));
  // The pad's comes from a mesh: damping unknown, not 0, and said so.
  const Joint* pad = r.asset.find_joint("pad_joint");
  REQUIRE(pad->drive);
  CHECK_FALSE(pad->drive->damping);
  CHECK(pad->drive->damping_unknown.find("'pad'") != std::string::npos);
  REQUIRE(r.diagnostics.size() == 1);
  CHECK(r.diagnostics[0].rule == "mjcf-unsupported");
  CHECK(r.diagnostics[0].span.line == 40);
}

TEST_CASE("an element's dampratio replaces its class's kv; kv and dampratio on one element is an error",
          "[mjcf][dampratio]") {
  const ReadResult r = read_text(R"(<mujoco>
  <compiler angle="radian"/>
  <default><default class="servo"><position kp="100" kv="7"/></default></default>
  <worldbody><body name="b">
    <inertial pos="0 0 0" mass="1" diaginertia="0.01 0.01 0.01"/>
    <joint name="a" axis="0 0 1" armature="0.03"/>
    <body name="c" pos="0 0 0.1"><inertial pos="0 0 0" mass="1" diaginertia="0.01 0.01 0.01"/>
      <joint name="d" axis="1 0 0"/></body>
  </body></worldbody>
  <actuator>
    <position class="servo" joint="a" dampratio="0.5"/>
    <position class="servo" joint="d" kv="1" dampratio="1"/>
  </actuator>
</mujoco>)");
  REQUIRE(r.usable);
  // M₀ of 'a': armature 0.03 + izz of both bodies (0.01 + 0.01): kv = 2·0.5·√(100·0.05).
  CHECK_THAT(damping(r.asset, "a"), WithinRel(std::sqrt(100 * 0.05), 1e-12));
  bool refused = false;
  for (const auto& d : r.diagnostics)
    refused = refused || (d.message.find("kv and dampratio cannot both be defined") != std::string::npos);
  CHECK(refused);
}
