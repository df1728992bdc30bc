#include "verify/gripper_layout.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <deque>
#include <set>

namespace assetlint::verify {
namespace {

using Poses = std::map<std::string, Eigen::Isometry3d, std::less<>>;

Eigen::Isometry3d joint_motion(const Joint& joint, double q) {
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  if (is_angular(joint.type)) motion.linear() = Eigen::AngleAxisd(q, joint.axis.normalized()).toRotationMatrix();
  else if (joint.type == JointType::Prismatic) motion.translation() = q * joint.axis.normalized();
  return motion;
}

// The mean of a link's shape origins in the frame its pose is in.
Eigen::Vector3d shapes_centre(const Link& link, const Eigen::Isometry3d& pose) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const CollisionShape& shape : link.collisions) sum += (pose * shape.pose).translation();
  return sum / static_cast<double>(link.collisions.size());
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "'" : ", '") + name + "'";
  return text;
}

}  // namespace

double support(const CollisionShape& shape, const Eigen::Isometry3d& link_pose, const Eigen::Vector3d& u,
               const MeshPoints& meshes) {
  const Eigen::Isometry3d pose = link_pose * shape.pose;
  const Eigen::Vector3d local = pose.linear().transpose() * u;  // u in the shape's frame
  const double centre = pose.translation().dot(u);
  switch (shape.kind) {
    case CollisionShape::Kind::Box:
      return centre + 0.5 * (std::abs(local.x()) * shape.size.x() + std::abs(local.y()) * shape.size.y() +
                             std::abs(local.z()) * shape.size.z());
    case CollisionShape::Kind::Sphere:
      return centre + shape.size.x();
    case CollisionShape::Kind::Cylinder:
      return centre + shape.size.x() * std::sqrt(std::max(0.0, 1.0 - local.z() * local.z())) +
             0.5 * shape.size.y() * std::abs(local.z());
    case CollisionShape::Kind::Capsule:
      return centre + shape.size.x() + 0.5 * shape.size.y() * std::abs(local.z());
    case CollisionShape::Kind::Mesh: {
      double best = -INFINITY;
      const auto found = meshes.find(shape.mesh);
      if (found == meshes.end()) return centre;
      for (const Eigen::Vector3d& p : found->second) best = std::max(best, p.cwiseProduct(shape.mesh_scale).dot(local));
      return std::isfinite(best) ? centre + best : centre;
    }
  }
  return centre;
}

std::map<std::string, double, std::less<>> GripperLayout::positions(double q) const {
  std::map<std::string, double, std::less<>> q_of;
  q_of[driven->name.text] = q;
  for (const Joint* mimic : mimics) q_of[mimic->name.text] = mimic->mimic->multiplier.value * q + mimic->mimic->offset.value;
  return q_of;
}

Poses GripperLayout::poses(const Asset& asset, double q) const {
  const auto q_of = positions(q);
  Poses poses;
  poses.emplace(root, Eigen::Isometry3d::Identity());
  std::deque<std::string> queue{root};
  while (!queue.empty()) {
    const std::string name = std::move(queue.front());
    queue.pop_front();
    const Eigen::Isometry3d parent = poses.at(name);
    for (const Joint* joint : asset.joints_at(name)) {
      if (joint->parent.text != name || poses.count(joint->child.text)) continue;
      const auto moved = q_of.find(joint->name.text);
      const double position = moved == q_of.end() ? 0.0 : moved->second;
      poses.emplace(joint->child.text,
                    parent * joint->frame_in_link[0] * joint_motion(*joint, position) * joint->frame_in_link[1].inverse());
      queue.push_back(joint->child.text);
    }
  }
  return poses;
}

Extent GripperLayout::pad_extent(const Asset& asset, int side, const Poses& poses, const Eigen::Vector3d& u,
                                 const MeshPoints& meshes) const {
  const Link* link = asset.find_link(pads[side]);
  const Eigen::Isometry3d& pose = poses.at(pads[side]);
  Extent extent{INFINITY, -INFINITY};
  for (const CollisionShape& shape : link->collisions) {
    extent.high = std::max(extent.high, support(shape, pose, u, meshes));
    extent.low = std::min(extent.low, -support(shape, pose, -u, meshes));
  }
  return extent;
}

double GripperLayout::gap(const Asset& asset, const Poses& poses, const MeshPoints& meshes) const {
  return pad_extent(asset, 1, poses, closing, meshes).low - pad_extent(asset, 0, poses, closing, meshes).high;
}

double GripperLayout::gap_at(const Asset& asset, double q, const MeshPoints& meshes) const {
  return gap(asset, poses(asset, q), meshes);
}

std::optional<double> GripperLayout::opening_for(const Asset& asset, double width, const MeshPoints& meshes) const {
  double a = open, b = closed;
  const double gap_a = gap_at(asset, a, meshes), gap_b = gap_at(asset, b, meshes);
  if (!(width <= gap_a && width >= gap_b)) return std::nullopt;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (a + b);
    (gap_at(asset, mid, meshes) > width ? a : b) = mid;
  }
  return 0.5 * (a + b);
}

std::vector<std::string> collision_meshes(const Asset& asset, const std::vector<std::string>& links) {
  std::vector<std::string> files;
  for (const auto& name : links)
    if (const Link* link = asset.find_link(name))
      for (const CollisionShape& shape : link->collisions)
        if (shape.kind == CollisionShape::Kind::Mesh && shape.points.empty() &&
            std::find(files.begin(), files.end(), shape.mesh) == files.end())
          files.push_back(shape.mesh);
  return files;
}

std::optional<GripperLayout> gripper_layout(const Asset& asset, const Joint& driven,
                                            std::string& error) {
  GripperLayout layout;
  layout.driven = &driven;
  if (!is_single_dof(driven.type) || driven.type == JointType::Continuous || !driven.lower || !driven.upper ||
      !std::isfinite(driven.lower->value) || !std::isfinite(driven.upper->value) ||
      !(driven.upper->value > driven.lower->value)) {
    error = fmt::format("joint '{}' needs a finite range (lower < upper) to open and close the gripper",
                        driven.name.text);
    return std::nullopt;
  }
  layout.mimics = asset.mimic_followers(driven.name.text);
  std::erase_if(layout.mimics, [&](const Joint* j) { return asset.followed_joint(*j) != &driven; });

  // The base: the root of the tree the driven joint hangs in.
  std::string link = driven.parent.text;
  std::set<std::string> seen;
  for (;;) {
    const Joint* up = nullptr;
    for (const Joint* j : asset.joints_at(link))
      if (j->child.text == link && !j->parent.text.empty()) up = j;
    if (!up || !seen.insert(link).second) break;
    link = up->parent.text;
  }
  layout.root = link;

  // The moving links: subtrees of the driven joint and its mimics.
  std::set<std::string, std::less<>> moving;
  std::deque<std::string> queue{driven.child.text};
  for (const Joint* mimic : layout.mimics) queue.push_back(mimic->child.text);
  while (!queue.empty()) {
    const std::string name = std::move(queue.front());
    queue.pop_front();
    if (!moving.insert(name).second) continue;
    for (const Joint* j : asset.joints_at(name))
      if (j->parent.text == name) queue.push_back(j->child.text);
  }
  for (const Link& l : asset.links)
    if (moving.count(l.name.text)) layout.moving_links.push_back(l.name.text);

  std::vector<const Link*> shaped;
  for (const auto& name : layout.moving_links)
    if (const Link* l = asset.find_link(name); l && !l->collisions.empty()) shaped.push_back(l);
  if (shaped.empty()) {
    error = fmt::format("no collision geometry on the fingers: the links joint '{}' moves ({}) have no collision "
                        "shapes (URDF <collision>, USD prims with PhysicsCollisionAPI, MJCF geoms that collide); "
                        "verify needs the shapes the fingers grasp with",
                        driven.name.text, quoted_list(layout.moving_links));
    return std::nullopt;
  }

  // One side with shapes and links without any: the bare links are the other finger.
  std::vector<std::string> bare, with_shapes;
  for (const auto& name : layout.moving_links)
    if (const Link* l = asset.find_link(name); l && l->collisions.empty()) bare.push_back(name);
  for (const Link* l : shaped) with_shapes.push_back(l->name.text);
  const auto bare_finger = [&] {
    if (bare.empty()) return false;
    error = fmt::format("no collision geometry on a finger: {} (moved by joint '{}') {} no collision shapes, so only "
                        "{} can close on an object; verify needs the shapes both fingers grasp with",
                        quoted_list(bare), driven.name.text, bare.size() == 1 ? "has" : "have",
                        quoted_list(with_shapes));
    return true;
  };

  layout.open = driven.lower->value;
  layout.closed = driven.upper->value;
  const Poses lower = layout.poses(asset, layout.open), upper = layout.poses(asset, layout.closed);
  std::vector<Eigen::Vector3d> moves;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), centre = Eigen::Vector3d::Zero();
  for (const Link* l : shaped) {
    moves.push_back(shapes_centre(*l, upper.at(l->name.text)) - shapes_centre(*l, lower.at(l->name.text)));
    mean += moves.back();
    centre += shapes_centre(*l, lower.at(l->name.text));
  }
  mean /= static_cast<double>(shaped.size());
  centre /= static_cast<double>(shaped.size());
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (const auto& m : moves) spread += (m - mean) * (m - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(spread);
  Eigen::Vector3d axis = eigen.eigenvectors().col(2);
  if (!(eigen.eigenvalues()(2) > 1e-16)) {
    if (bare_finger()) return std::nullopt;
    error = fmt::format("the links joint '{}' moves ({}) do not move toward each other over its range: verify needs "
                        "two fingers that close on each other",
                        driven.name.text, quoted_list(layout.moving_links));
    return std::nullopt;
  }
  // A deterministic sign: the axis's largest component positive.
  Eigen::Index largest = 0;
  axis.cwiseAbs().maxCoeff(&largest);
  if (axis(largest) < 0) axis = -axis;
  std::array<std::vector<const Link*>, 2> sides;
  for (std::size_t i = 0; i < shaped.size(); ++i) sides[(moves[i] - mean).dot(axis) > 0 ? 0 : 1].push_back(shaped[i]);
  if (sides[0].empty() || sides[1].empty()) {
    if (bare_finger()) return std::nullopt;
    error = fmt::format("the links joint '{}' moves ({}) all move one way: verify needs two fingers that close on "
                        "each other",
                        driven.name.text, quoted_list(layout.moving_links));
    return std::nullopt;
  }
  Eigen::Vector3d approach = centre - centre.dot(axis) * axis;
  if (!(approach.norm() > 1e-9)) {
    error = fmt::format("the fingers of joint '{}' sit level with the base link '{}': verify cannot tell which way "
                        "the gripper approaches an object",
                        driven.name.text, layout.root);
    return std::nullopt;
  }
  layout.approach = approach.normalized();
  // The pad of each side: its most distal link along the approach.
  for (int side = 0; side < 2; ++side) {
    const Link* best = nullptr;
    double reach = -INFINITY;
    for (const Link* l : sides[side]) {
      const double r = shapes_centre(*l, lower.at(l->name.text)).dot(layout.approach);
      if (r > reach + 1e-12) reach = r, best = l;
    }
    layout.pads[side] = best->name.text;
  }
  // The gripper is open where its pads are furthest apart; there side 0 is on the low side of the axis.
  const auto pad_centre = [&](int side, const Poses& poses) {
    return shapes_centre(*asset.find_link(layout.pads[side]), poses.at(layout.pads[side])).dot(axis);
  };
  const double spread_lower = std::abs(pad_centre(1, lower) - pad_centre(0, lower));
  const double spread_upper = std::abs(pad_centre(1, upper) - pad_centre(0, upper));
  if (spread_upper > spread_lower) std::swap(layout.open, layout.closed);
  const Poses& open_poses = spread_upper > spread_lower ? upper : lower;
  if (pad_centre(0, open_poses) > pad_centre(1, open_poses)) std::swap(layout.pads[0], layout.pads[1]);
  layout.closing = axis;
  // closing × lateral = approach: a right-handed frame, which the object's orientation is written from.
  layout.lateral = layout.approach.cross(layout.closing).normalized();
  return layout;
}

}  // namespace assetlint::verify
