#include "physics/linkage.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <map>

namespace assetlint::physics {
namespace {

// Relative to the rows' scale, what counts as zero when the null space is taken.
constexpr double kRankTolerance = 1e-9;

const Link* link_named(const Asset& asset, const std::string& name) { return name.empty() ? nullptr : asset.find_link(name); }

// The joints between a link and its tree's root (or the world), nearest first.
std::vector<const Joint*> path_to_root(const Asset& asset, const Link* link) {
  std::vector<const Joint*> path;
  std::string at = link ? link->name.text : std::string();
  for (std::size_t guard = 0; !at.empty() && guard <= asset.joints.size(); ++guard) {
    const Joint* into = nullptr;
    for (const Joint* j : asset.joints_at(at))
      if (j->child.text == at) into = j;
    if (!into) break;
    if (into->type != JointType::Fixed) path.push_back(into);
    at = into->parent.text;
  }
  return path;
}

// The joints a loop ties: on one side's path to the root and not on the other's.
std::vector<const Joint*> loop_joints(const Asset& asset, const LoopClosure& loop) {
  const auto a = path_to_root(asset, link_named(asset, loop.link1));
  const auto b = path_to_root(asset, link_named(asset, loop.link2));
  std::vector<const Joint*> members;
  for (const Joint* j : a)
    if (std::find(b.begin(), b.end(), j) == b.end()) members.push_back(j);
  for (const Joint* j : b)
    if (std::find(a.begin(), a.end(), j) == a.end()) members.push_back(j);
  return members;
}

bool contains(const std::vector<const Joint*>& set, const Joint* joint) {
  return std::find(set.begin(), set.end(), joint) != set.end();
}

}  // namespace

std::vector<const Joint*> tied_joints(const Asset& asset, const std::vector<const Joint*>& seed) {
  std::vector<const Joint*> set = seed;
  std::vector<std::vector<const Joint*>> loops;
  for (const LoopClosure& loop : asset.loops) loops.push_back(loop_joints(asset, loop));
  for (bool changed = true; changed;) {
    changed = false;
    const auto add = [&](const Joint* j) {
      if (j && !contains(set, j)) {
        set.push_back(j);
        changed = true;
      }
    };
    for (const Joint& joint : asset.joints) {
      const Joint* followed = joint.is_mimic() ? asset.followed_joint(joint) : nullptr;
      if (!followed) continue;
      if (contains(set, &joint)) add(followed);
      if (contains(set, followed)) add(&joint);
    }
    for (const auto& members : loops)
      if (std::any_of(members.begin(), members.end(), [&](const Joint* j) { return contains(set, j); }))
        for (const Joint* j : members) add(j);
  }
  return set;
}

Mechanism drive_mechanism(const JointSpaceMatrix& matrix, const Asset& asset,
                          const std::vector<std::pair<const Joint*, double>>& moment, Armatures armatures) {
  Mechanism out;
  std::vector<const Joint*> seed;
  for (const auto& [joint, value] : moment) seed.push_back(joint);
  out.joints = tied_joints(asset, seed);
  ArticulatedInertia& result = out.inertia;
  // Every tied joint a single-DOF joint of one tree: the columns of the tree's M they take.
  int tree = -1;
  std::vector<int> columns;
  for (const Joint* joint : out.joints) {
    const auto [t, column] = matrix.column_of(*joint);
    if (t < 0 || !is_single_dof(joint->type) || (tree >= 0 && t != tree)) {
      result.reason = fmt::format("joint '{}' is not a single-DOF joint of the same tree", joint->name.text);
      return out;
    }
    tree = t;
    columns.push_back(column);
  }
  if (tree < 0) {
    result.reason = "the drive moves no joint";
    return out;
  }
  if (!matrix.tree_status(tree).known) {
    result = matrix.tree_status(tree);
    return out;
  }
  const auto n = static_cast<Eigen::Index>(out.joints.size());
  const auto index_of = [&](const Joint* j) {
    return static_cast<Eigen::Index>(std::find(out.joints.begin(), out.joints.end(), j) - out.joints.begin());
  };
  // The constraints' rows over the tied joints.
  std::vector<Eigen::RowVectorXd> rows;
  for (const Joint* joint : out.joints) {
    const Joint* followed = joint->is_mimic() ? asset.followed_joint(*joint) : nullptr;
    if (!followed || !contains(out.joints, followed)) continue;
    Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(n);
    row(index_of(joint)) = 1;
    row(index_of(followed)) -= joint->mimic->multiplier.value;
    rows.push_back(row);
  }
  for (const LoopClosure& loop : asset.loops) {
    const auto members = loop_joints(asset, loop);
    if (members.empty() || !contains(out.joints, members.front())) continue;
    const Link* first = link_named(asset, loop.link1);
    const Link* second = link_named(asset, loop.link2);
    if (!first || (!loop.link2.empty() && !second)) continue;
    // The anchor on the first link, and the point of the second that coincides with it at the
    // reference pose (its place in the root's frame).
    int tree1 = -1, tree2 = -1;
    Eigen::MatrixXd j1, j2;
    Eigen::Vector3d in_root = Eigen::Vector3d::Zero();
    if (!matrix.point_rows(*first, loop.anchor, nullptr, loop.weld, tree1, j1, &in_root) || tree1 < 0 ||
        (second && !matrix.point_rows(*second, Eigen::Vector3d::Zero(), &in_root, loop.weld, tree2, j2, nullptr))) {
      result.reason = fmt::format("{} could not be placed", loop.label);
      return out;
    }
    if ((tree1 >= 0 && tree1 != tree) || (tree2 >= 0 && tree2 != tree)) {
      result.reason = fmt::format("{} ties two kinematic trees", loop.label);
      return out;
    }
    const Eigen::Index height = loop.weld ? 6 : 3;
    Eigen::MatrixXd relative = Eigen::MatrixXd::Zero(height, matrix.mass_matrix(tree).cols());
    if (j1.size()) relative += j1;
    if (j2.size()) relative -= j2;
    for (Eigen::Index r = 0; r < height; ++r) {
      Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(n);
      for (Eigen::Index k = 0; k < n; ++k) row(k) = relative(r, columns[static_cast<std::size_t>(k)]);
      // A row a joint outside the tied set moves is that joint held: it constrains nothing here.
      rows.push_back(row);
    }
  }
  // The motions the constraints allow.
  Eigen::MatrixXd basis;
  if (rows.empty()) {
    basis = Eigen::MatrixXd::Identity(n, n);
  } else {
    Eigen::MatrixXd a(static_cast<Eigen::Index>(rows.size()), n);
    for (std::size_t r = 0; r < rows.size(); ++r) a.row(static_cast<Eigen::Index>(r)) = rows[r];
    const double scale = std::max(1.0, a.cwiseAbs().maxCoeff());
    Eigen::FullPivLU<Eigen::MatrixXd> lu(a / scale);
    lu.setThreshold(kRankTolerance);
    basis = lu.kernel();
    if (lu.rank() == 0) basis = Eigen::MatrixXd::Identity(n, n);
  }
  out.freedoms = static_cast<int>(basis.cols());
  Eigen::VectorXd moment_row = Eigen::VectorXd::Zero(n);
  for (const auto& [joint, value] : moment) moment_row(index_of(joint)) += value;
  const Eigen::VectorXd b = basis.transpose() * moment_row;
  if (out.freedoms == 0 || b.norm() <= kRankTolerance * std::max(1.0, moment_row.norm())) {
    result.reason = "the constraints hold the driven joints still";
    return out;
  }
  Eigen::MatrixXd m(n, n);
  const Eigen::MatrixXd& whole = matrix.mass_matrix(tree);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index k = 0; k < n; ++k) m(i, k) = whole(columns[static_cast<std::size_t>(i)], columns[static_cast<std::size_t>(k)]);
  for (const Joint* joint : out.joints)
    if ((armatures.none || joint == armatures.without) && joint->armature)
      m(index_of(joint), index_of(joint)) -= joint->armature->value;
  const Eigen::MatrixXd reduced = basis.transpose() * m * basis;
  const Eigen::LLT<Eigen::MatrixXd> factor(reduced);
  if (factor.info() != Eigen::Success) {
    result.reason = "the mechanism's mass matrix is singular (a body it moves has no mass or inertia)";
    return out;
  }
  if (out.freedoms == 1)
    for (Eigen::Index k = 0; k < n; ++k) out.rates.push_back(basis(k, 0) / b(0));
  result.response = b.dot(factor.solve(b));
  result.value = 1.0 / result.response;
  result.known = result.response > 0 && std::isfinite(result.value);
  if (!result.known) result.reason = "the mechanism reflects no inertia";
  return out;
}

Mechanism drive_mechanism(const JointSpaceMatrix& matrix, const Asset& asset, const Joint& joint,
                          Armatures armatures) {
  return drive_mechanism(matrix, asset, {{&joint, 1.0}}, armatures);
}

}  // namespace assetlint::physics
