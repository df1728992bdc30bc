#include <catch2/catch.hpp>

#include <numbers>

#include "physics/inertia.h"

using namespace assetlint;

namespace {
Inertial make_inertial(double mass, const Eigen::Matrix3d& inertia, const Eigen::Vector3d& com) {
  Inertial in;
  in.mass = Quantity::unauthored(mass, Unit::Kilogram);
  in.inertia = inertia;
  in.com = com;
  return in;
}
}  // namespace

TEST_CASE("the guide's lighter link: 2.1e-6 + 0.0127·0.01² = 3.37e-6 kg·m²", "[physics]") {
  const Inertial finger = make_inertial(0.0127, Eigen::Vector3d(2.1e-6, 2.1e-6, 1.3e-6).asDiagonal(),
                                        Eigen::Vector3d(0, 0, 0.01));
  const double about_axis = physics::inertia_about_axis(finger, Eigen::Isometry3d::Identity(), Eigen::Vector3d::UnitX());
  CHECK(about_axis == Approx(3.37e-6).epsilon(1e-9));
  CHECK(physics::axis_distance(finger, Eigen::Isometry3d::Identity(), Eigen::Vector3d::UnitX()) == Approx(0.01));
}

TEST_CASE("inertia about an axis with rotated principal axes and an offset joint", "[physics]") {
  // Principal moments (1, 2, 3)·1e-4 about axes rotated 90° about z: the link's x axis
  // carries the 2e-4 moment.
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Matrix3d principal = Eigen::Vector3d(1e-4, 2e-4, 3e-4).asDiagonal();
  const Inertial link = make_inertial(0.5, rotation * principal * rotation.transpose(), Eigen::Vector3d(0.1, 0.2, 0.0));
  // Joint at (0.1, 0, 0) in the link frame, its axis along the link's x.
  Eigen::Isometry3d joint = Eigen::Isometry3d::Identity();
  joint.translation() = Eigen::Vector3d(0.1, 0.0, 0.0);
  // Distance from COM (0.1, 0.2, 0) to the line x-axis through (0.1, 0, 0) is 0.2.
  CHECK(physics::inertia_about_axis(link, joint, Eigen::Vector3d::UnitX()) == Approx(2e-4 + 0.5 * 0.04));
  // A joint frame rotated so that its x axis is the link's z: moment 3e-4, distance |(0, 0.2)| in xy.
  joint.linear() = Eigen::AngleAxisd(-std::numbers::pi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  CHECK(physics::inertia_about_axis(link, joint, Eigen::Vector3d::UnitX()) == Approx(3e-4 + 0.5 * 0.04));
  const Eigen::Vector3d moments = physics::principal_moments(link.inertia);
  CHECK(moments[0] == Approx(1e-4));
  CHECK(moments[2] == Approx(3e-4));
}
