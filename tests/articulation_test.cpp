// Articulated inertia 1/(M⁻¹)ᵢᵢ against closed forms (docs/physics.md "Articulated inertia").
#include <catch2/catch.hpp>

#include "physics/articulation.h"

using namespace assetlint;
using namespace assetlint::physics;

namespace {

Link link(const std::string& name, double mass, const Eigen::Vector3d& com, const Eigen::Vector3d& diagonal) {
  Link l;
  l.name.text = name;
  Inertial in;
  in.mass = Quantity::unauthored(mass, Unit::Kilogram);
  in.com = com;
  in.inertia = diagonal.asDiagonal();
  l.inertial = in;
  return l;
}

Link massless(const std::string& name) {
  Link l;
  l.name.text = name;
  return l;
}

Joint joint(const std::string& name, JointType type, const std::string& parent, const std::string& child,
            const Eigen::Vector3d& origin = Eigen::Vector3d::Zero(), const Eigen::Vector3d& axis = Eigen::Vector3d::UnitZ()) {
  Joint j;
  j.name.text = name;
  j.type = type;
  j.parent.text = parent;
  j.child.text = child;
  j.frame_in_link[0].translation() = origin;
  j.axis = axis;
  return j;
}

// A planar two-link arm about z on a fixed base: link 1 (m1, COM c1 along x, Izz1) with
// joint 2 at l1 along x; link 2 (m2, COM c2, Izz2).
struct TwoLink {
  double m1 = 1.0, c1 = 0.3, i1 = 0.02, l1 = 0.6, m2 = 0.5, c2 = 0.2, i2 = 0.01;
  Asset asset() const {
    Asset a;
    a.links = {massless("base"), link("l1", m1, {c1, 0, 0}, {0.001, 0.03, i1}), link("l2", m2, {c2, 0, 0}, {0.002, 0.02, i2})};
    a.joints = {joint("j1", JointType::Revolute, "base", "l1"),
                joint("j2", JointType::Revolute, "l1", "l2", {l1, 0, 0})};
    return a;
  }
  double m11() const { return i1 + m1 * c1 * c1 + i2 + m2 * (l1 * l1 + c2 * c2 + 2 * l1 * c2); }
  double m12() const { return i2 + m2 * (c2 * c2 + l1 * c2); }
  double m22() const { return i2 + m2 * c2 * c2; }
};

}  // namespace

TEST_CASE("articulated inertia of one link on a fixed base: its inertia about the axis plus armature", "[physics][articulation]") {
  Asset a;
  a.links = {massless("base"), link("l1", 2.0, {0.5, 0, 0}, {0.01, 0.02, 0.03})};
  a.joints = {joint("j1", JointType::Revolute, "base", "l1")};
  const ArticulatedInertia plain = Articulation(a).inertia(a.joints[0]);
  REQUIRE(plain.known);
  CHECK(plain.value == Approx(0.03 + 2.0 * 0.25).epsilon(1e-12));
  a.joints[0].armature = Quantity::unauthored(0.1, Unit::KilogramMeter2);
  CHECK(Articulation(a).inertia(a.joints[0]).value == Approx(0.63).epsilon(1e-12));
  // Prismatic: the mass.
  a.joints[0].type = JointType::Prismatic;
  a.joints[0].armature.reset();
  CHECK(Articulation(a).inertia(a.joints[0]).value == Approx(2.0).epsilon(1e-12));
}

TEST_CASE("articulated inertia of a two-link chain: 1/(M⁻¹)₁₁ = M₁₁ − M₁₂²/M₂₂", "[physics][articulation]") {
  TwoLink arm;
  Asset a = arm.asset();
  Articulation articulation(a);
  const ArticulatedInertia root = articulation.inertia(a.joints[0]);
  const ArticulatedInertia elbow = articulation.inertia(a.joints[1]);
  REQUIRE(root.known);
  REQUIRE(elbow.known);
  CHECK(root.value == Approx(arm.m11() - arm.m12() * arm.m12() / arm.m22()).epsilon(1e-12));
  // The elbow's parent moves: its 1/r is below its own M₂₂.
  CHECK(elbow.value == Approx(arm.m22() - arm.m12() * arm.m12() / arm.m11()).epsilon(1e-12));
  CHECK(elbow.value < arm.m22());
  // Armature on the elbow changes the shoulder's r through M.
  a.joints[1].armature = Quantity::unauthored(0.05, Unit::KilogramMeter2);
  const double m22 = arm.m22() + 0.05;
  CHECK(Articulation(a).inertia(a.joints[0]).value == Approx(arm.m11() - arm.m12() * arm.m12() / m22).epsilon(1e-12));
}

TEST_CASE("a coupled motion's inertia is Jᵀ·M·J, the other joints held", "[physics][articulation]") {
  TwoLink arm;
  Asset a = arm.asset();
  a.joints[1].armature = Quantity::unauthored(0.05, Unit::KilogramMeter2);
  Articulation articulation(a);
  const double m22 = arm.m22() + 0.05;
  // The elbow alone with the shoulder held: M₂₂ (armature included), not 1/r.
  const auto elbow = articulation.coupled_inertia({{&a.joints[1], 1.0}});
  REQUIRE(elbow.known);
  CHECK(elbow.value == Approx(m22).epsilon(1e-12));
  // The elbow following the shoulder at gearing g: M₁₁ + 2g·M₁₂ + g²·M₂₂.
  for (double g : {1.0, -0.5, 2.0}) {
    const auto coupled = articulation.coupled_inertia({{&a.joints[0], 1.0}, {&a.joints[1], g}});
    REQUIRE(coupled.known);
    CHECK(coupled.value == Approx(arm.m11() + 2 * g * arm.m12() + g * g * m22).epsilon(1e-12));
  }
}

TEST_CASE("links joined by a fixed joint are one rigid body", "[physics][articulation]") {
  Asset a;
  a.links = {massless("base"), link("l1a", 1.0, {0.3, 0, 0}, {0.001, 0.03, 0.02}), link("l1b", 0.5, {0.1, 0, 0}, {0.002, 0.004, 0.01})};
  Joint weld = joint("weld", JointType::Fixed, "l1a", "l1b", {0.6, 0, 0});
  weld.frame_in_link[0].linear() = Eigen::AngleAxisd(EIGEN_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  a.joints = {joint("j1", JointType::Revolute, "base", "l1a"), weld};
  Articulation articulation(a);
  const Body* body = articulation.body_of("l1b");
  REQUIRE(body);
  CHECK(body == articulation.body_of("l1a"));
  CHECK(body->links.size() == 2);
  REQUIRE(body->mass_known);
  CHECK(body->mass == Approx(1.5));
  // l1b's COM (0.1, 0, 0) in its frame, rotated 90° about z at (0.6, 0, 0): (0.6, 0.1, 0).
  CHECK(body->com.isApprox(Eigen::Vector3d(1.0 * 0.3 + 0.5 * 0.6, 0.5 * 0.1, 0) / 1.5, 1e-12));
  const double expected = 0.02 + 1.0 * 0.09 + 0.01 + 0.5 * (0.36 + 0.01);
  CHECK(articulation.inertia(a.joints[0]).value == Approx(expected).epsilon(1e-12));
  // The base, fixed to the world (Isaac's importer fixes a URDF base by default), is the world.
  CHECK(articulation.body_of("base")->world);
  CHECK(articulation.inertia_about_axis(*body, a.joints[0], 1) == Approx(expected).epsilon(1e-12));
  CHECK_FALSE(articulation.inertia_about_axis(*articulation.body_of("base"), a.joints[0], 0));
}

TEST_CASE("a floating base: two bodies on one axis share the motion, I₁·I₂/(I₁ + I₂)", "[physics][articulation]") {
  Asset a;
  a.format = SourceFormat::Usda;
  a.links = {link("/r/base", 3.0, {0, 0, 0}, {0.1, 0.1, 0.2}), link("/r/arm", 1.0, {0, 0, 0.1}, {0.05, 0.05, 0.05})};
  a.joints = {joint("/r/j", JointType::Revolute, "/r/base", "/r/arm")};
  Articulation floating(a);
  CHECK_FALSE(floating.body_of("/r/base")->world);
  CHECK(floating.inertia(a.joints[0]).value == Approx(0.2 * 0.05 / 0.25).epsilon(1e-12));
  // Welded to the world instead (a fixed joint from nothing): the arm alone.
  a.joints.push_back(joint("/r/anchor", JointType::Fixed, "", "/r/base"));
  Articulation anchored(a);
  CHECK(anchored.body_of("/r/base")->world);
  CHECK(anchored.inertia(a.joints[0]).value == Approx(0.05).epsilon(1e-12));
}

TEST_CASE("unknown when a moving body has no authored mass or COM, world-welded bodies do not count", "[physics][articulation]") {
  Asset a;
  a.format = SourceFormat::Usda;
  a.links = {massless("/r/base"), link("/r/knuckle", 0.03, {0, 0.03, 0.01}, {1e-5, 1e-5, 1e-5}), massless("/r/pad"),
             link("/r/finger", 0.0127, {0, 0, 0.01}, {2.1e-6, 2.1e-6, 1.3e-6})};
  a.links[1].inertial->com_authored = false;  // USD computes it from colliders
  a.joints = {joint("/r/j0", JointType::Revolute, "/r/base", "/r/knuckle", Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()),
              joint("/r/j1", JointType::Revolute, "/r/knuckle", "/r/finger", {0, 0.04, 0.04}, Eigen::Vector3d::UnitX()),
              joint("/r/weld", JointType::Fixed, "/r/finger", "/r/pad")};
  Articulation articulation(a);
  const ArticulatedInertia j0 = articulation.inertia(a.joints[0]);
  CHECK_FALSE(j0.known);
  CHECK(j0.unknown_links == std::vector<std::string>{"/r/base", "/r/knuckle", "/r/pad"});
  // Welding the base to the world takes it out of the list.
  a.joints.push_back(joint("/r/anchor", JointType::Fixed, "", "/r/base"));
  CHECK(Articulation(a).inertia(a.joints[0]).unknown_links == std::vector<std::string>{"/r/knuckle", "/r/pad"});
  // The finger's own inertia about its joint is still known (for the guide's estimate).
  const Body* finger = articulation.body_of("/r/finger");
  CHECK_FALSE(finger->mass_known);  // welded to the massless pad
}

TEST_CASE("shared_articulation: one build per asset while a scope is open, a fresh one otherwise", "[physics][articulation]") {
  Asset asset;
  asset.links = {massless("base"), link("arm", 2.0, Eigen::Vector3d(0.1, 0, 0), Eigen::Vector3d(0.01, 0.01, 0.01))};
  asset.joints = {joint("shoulder", JointType::Revolute, "base", "arm")};
  Asset other = asset;
  const auto outside = shared_articulation(asset);
  CHECK(shared_articulation(asset) != outside);
  {
    const SharedArticulationScope scope(asset);
    const auto first = shared_articulation(asset);
    CHECK(shared_articulation(asset) == first);
    CHECK(shared_articulation(other) != first);
    CHECK(first->bodies().size() == outside->bodies().size());
    CHECK(first->body_of("arm")->links.front() == &asset.links[1]);
  }
  CHECK(shared_articulation(asset) != outside);
}
