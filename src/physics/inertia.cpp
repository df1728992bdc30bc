#include "physics/inertia.h"

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include <cmath>

#include "model/poses.h"
#include "util/numbers.h"

namespace assetlint::physics {

Eigen::Vector3d principal_moments(const Eigen::Matrix3d& inertia) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertia, Eigen::EigenvaluesOnly);
  return solver.eigenvalues();
}

double axis_distance(const Inertial& inertial, const Eigen::Isometry3d& joint_in_link, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d direction = (joint_in_link.linear() * axis).normalized();
  const Eigen::Vector3d offset = inertial.com - joint_in_link.translation();
  return (offset - offset.dot(direction) * direction).norm();
}

double inertia_about_axis(const Inertial& inertial, const Eigen::Isometry3d& joint_in_link, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d direction = (joint_in_link.linear() * axis).normalized();
  const double about_com = direction.dot(inertial.inertia * direction);
  const double distance = axis_distance(inertial, joint_in_link, axis);
  return about_com + inertial.mass.value * distance * distance;
}

bool pasted_tensor(const Eigen::Matrix3d& m) {
  return m(0, 0) != 0 && m(0, 0) == m(1, 1) && m(0, 0) == m(2, 2) && m(0, 0) == m(0, 1) && m(0, 0) == m(0, 2) &&
         m(0, 0) == m(1, 2);
}

std::vector<Eigen::Vector3d> joint_frames_on(const Asset& asset, const Link& link) {
  std::vector<Eigen::Vector3d> frames;
  for (const Joint* joint : asset.joints_at(link.name.text)) {
    if (joint->parent.text == link.name.text) frames.push_back(joint->frame_in_link[0].translation());
    if (joint->child.text == link.name.text) frames.push_back(joint->frame_in_link[1].translation());
  }
  return frames;
}

double collision_reach(const Link& link, const Eigen::Vector3d& com) {
  double reach = 0;
  for (const CollisionShape& shape : link.collisions) {
    const Eigen::Vector3d centre = shape.pose.translation();
    double radius = 0;
    switch (shape.kind) {
      case CollisionShape::Kind::Box: radius = 0.5 * shape.size.norm(); break;
      case CollisionShape::Kind::Cylinder: radius = std::hypot(shape.size[0], 0.5 * shape.size[1]); break;
      case CollisionShape::Kind::Sphere: radius = shape.size[0]; break;
      case CollisionShape::Kind::Capsule: radius = shape.size[0] + 0.5 * shape.size[1]; break;
      case CollisionShape::Kind::Mesh:
        for (const Eigen::Vector3d& p : shape.points) reach = std::max(reach, (shape.pose * p - com).norm());
        continue;
    }
    if (std::isfinite(radius) && radius > 0) reach = std::max(reach, (centre - com).norm() + radius);
  }
  return reach;
}

double gyration_scale(const Asset& asset) {
  Eigen::AlignedBox3d box;
  for (const auto& [name, pose] : link_poses(asset)) box.extend(pose.translation());
  if (box.isEmpty()) return 1.0;
  return std::max(1.0, box.diagonal().norm() / kGyrationReferenceSize);
}

namespace {

// A uniform box with principal moments I₁ ≤ I₂ ≤ I₃ has sides a² = 6(I₂ + I₃ − I₁)/m and the
// like; its density is m over a·b·c. 0 when the moments fit no box (a side of zero or less).
double box_density(const Eigen::Vector3d& moments, double mass) {
  const double i1 = moments[0], i2 = moments[1], i3 = moments[2];
  const double a2 = 6 * (i2 + i3 - i1) / mass, b2 = 6 * (i1 + i3 - i2) / mass, c2 = 6 * (i1 + i2 - i3) / mass;
  if (!(a2 > 0 && b2 > 0 && c2 > 0)) return 0;
  return mass / std::sqrt(a2 * b2 * c2);
}

}  // namespace

std::optional<Gyration> judge_gyration(const Inertial& inertial, const std::vector<Eigen::Vector3d>& joint_frames,
                                       const std::optional<Eigen::Vector3d>& sole_axis, double scale,
                                       double shape_reach) {
  const double mass = inertial.mass.value;
  if (!inertial.mass_authored || !inertial.inertia_authored || !inertial.com_authored || !(mass > 0)) return std::nullopt;
  const Eigen::Vector3d moments = principal_moments(inertial.inertia);
  if (!(moments[0] > 0)) return std::nullopt;  // not a rigid body's tensor: inertia-invalid says so
  Gyration g;
  g.largest = std::sqrt(moments[2] / mass);
  if (sole_axis && sole_axis->norm() > 0) {
    const Eigen::Vector3d axis = sole_axis->normalized();
    g.largest = std::sqrt(axis.dot(inertial.inertia * axis) / mass);
    g.about_axis = true;
  }
  g.smallest = std::sqrt(moments[0] / mass);
  if (joint_frames.size() >= 2)
    for (const Eigen::Vector3d& frame : joint_frames) g.spread = std::max(g.spread, (frame - inertial.com).norm());
  g.from_size = g.spread > 0;
  g.scale = scale;
  g.bound = g.from_size ? std::max(kGyrationSizeFactor * g.spread, kGyrationFloor * scale) : kGyrationFixedBound * scale;
  if (std::isfinite(shape_reach) && shape_reach > g.bound) {
    g.bound = shape_reach;
    g.from_shapes = true;
  }
  g.box_density = box_density(moments, mass);
  g.floor_only = g.from_size && !g.from_shapes && kGyrationSizeFactor * g.spread <= kGyrationFloor * scale;
  if (g.largest > g.bound && !(g.floor_only && g.box_density >= kGyrationMinSolidDensity))
    g.verdict = Gyration::Verdict::TooLarge;
  else if (mass >= kGyrationMinMass && g.largest < kGyrationMinRadius) g.verdict = Gyration::Verdict::TooSmall;
  return g;
}

std::string Gyration::bound_text() const {
  if (verdict == Verdict::TooSmall)
    return fmt::format("the fixed lower bound {} m for a link of {} kg or more", format_number(kGyrationMinRadius),
                       format_number(kGyrationMinMass));
  if (from_shapes)
    return fmt::format("the bound {} m, how far the link's collision shapes reach from its COM", format_number(bound, 3));
  const std::string scaled =
      scale > 1 ? fmt::format(", scaled ×{} for a robot {} m across", format_number(scale, 3),
                              format_number(scale * kGyrationReferenceSize, 3))
                : std::string();
  if (!from_size)
    return fmt::format("the fixed bound {} m{} (the link has fewer than two distinct joint frames: the model gives no size)",
                       format_number(kGyrationFixedBound * scale, 3), scaled);
  return fmt::format("the bound {} m = max({} × {} m, {} m{}), {} m being the farthest joint frame on the link from its COM",
                     format_number(bound, 3), format_number(kGyrationSizeFactor), format_number(spread, 3),
                     format_number(kGyrationFloor * scale, 3), scaled, format_number(spread, 3));
}

std::string inertia_doubt(const Asset& asset, const Link& link, const std::optional<Eigen::Vector3d>& sole_axis,
                          double scale) {
  if (!link.inertial) return {};
  const Inertial& in = *link.inertial;
  const Eigen::Matrix3d& t = in.inertia;
  if (pasted_tensor(t))
    return fmt::format("link '{}' has a pasted placeholder tensor (all six entries {})", link.name.text,
                       format_number(t(0, 0), 4));
  if (in.mass_authored && in.mass.value > 0 && t(0, 0) == in.mass.value && t(1, 1) == in.mass.value &&
      t(2, 2) == in.mass.value)
    return fmt::format("link '{}' has mass and moments all {}: placeholder values", link.name.text,
                       format_number(in.mass.value, 4));
  const auto g = judge_gyration(in, joint_frames_on(asset, link), sole_axis, scale, collision_reach(link, in.com));
  if (!g || g->verdict == Gyration::Verdict::Plausible) return {};
  if (g->verdict == Gyration::Verdict::TooSmall)
    return fmt::format("link '{}' has a radius of gyration √(I/m) of {} m, below {} m: a point mass typed in",
                       link.name.text, format_number(g->largest, 3), format_number(kGyrationMinRadius));
  return fmt::format("link '{}' has a radius of gyration √(I/m) of {} m, above the {} m the link could have",
                     link.name.text, format_number(g->largest, 3), format_number(g->bound, 3));
}

}  // namespace assetlint::physics
