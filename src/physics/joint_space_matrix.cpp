#include "physics/joint_space_matrix.h"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <algorithm>
#include <map>

#include "physics/spatial.h"

namespace assetlint::physics {
namespace {

// The degrees of freedom one tree holds: its joints and their columns in M.
struct DofBlock {
  const TreeJoint* joint;
  int column;          // of its first DOF
  bool parallel;       // an Articulation parallel_ entry (else a tree_ entry)
  std::size_t index;   // in that list
};

struct TreeDofs {
  std::vector<DofBlock> joints;
  int count = 0;
  int root_columns = -1;  // a floating root without a joint: its six DOFs start here
  std::vector<std::string> unknown_links;
  std::string reason;
};

}  // namespace

JointSpaceMatrix::JointSpaceMatrix(const Articulation& a) : articulation_(a) {
  const auto& bodies = a.bodies_;
  const auto& tree = a.tree_;
  const auto& parallel = a.parallel_;
  tree_results_.assign(tree.size(), {});
  parallel_results_.assign(parallel.size(), {});
  tree_column_.assign(tree.size(), {-1, -1});
  parallel_column_.assign(parallel.size(), {-1, -1});

  // Which tree each body belongs to, and the columns of each tree's degrees of freedom.
  std::vector<int> tree_of(bodies.size(), -1);
  std::vector<TreeDofs> trees(a.roots_.size());
  for (std::size_t t = 0; t < a.roots_.size(); ++t) {
    const auto root = static_cast<std::size_t>(a.roots_[t]);
    tree_of[root] = static_cast<int>(t);
    if (a.floating_[root]) {
      trees[t].root_columns = 0;
      trees[t].count = 6;
    }
  }
  const auto add_joint = [&](const TreeJoint& j, bool is_parallel, std::size_t index) {
    TreeDofs& dofs = trees[static_cast<std::size_t>(tree_of[static_cast<std::size_t>(j.child)])];
    if (j.dof_motions.empty() && dofs.reason.empty())
      dofs.reason = fmt::format("joint '{}' is {}, not modelled", j.joint->name.text, joint_type_name(j.joint->type));
    dofs.joints.push_back({&j, dofs.count, is_parallel, index});
    dofs.count += static_cast<int>(j.dof_motions.size());
  };
  for (std::size_t k = 0; k < tree.size(); ++k) {
    tree_of[static_cast<std::size_t>(tree[k].child)] = tree_of[static_cast<std::size_t>(tree[k].parent)];
    add_joint(tree[k], false, k);
  }
  for (std::size_t k = 0; k < parallel.size(); ++k) add_joint(parallel[k], true, k);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (tree_of[b] < 0 || bodies[b].world || bodies[b].massless) continue;
    auto& unknown = trees[static_cast<std::size_t>(tree_of[b])].unknown_links;
    unknown.insert(unknown.end(), bodies[b].unknown_links.begin(), bodies[b].unknown_links.end());
  }

  // Each body's Jacobian (its velocity in its own frame per unit rate of each DOF of its
  // tree), parents first; M = Σ Jᵀ·I·J over the bodies, plus the armatures.
  std::vector<Eigen::MatrixXd> jacobian(bodies.size());
  std::vector<Eigen::MatrixXd> mass(trees.size());
  for (std::size_t t = 0; t < trees.size(); ++t) {
    const TreeDofs& dofs = trees[t];
    mass[t] = Eigen::MatrixXd::Zero(dofs.count, dofs.count);
    const auto root = static_cast<std::size_t>(a.roots_[t]);
    jacobian[root] = Eigen::MatrixXd::Zero(6, dofs.count);
    if (dofs.root_columns >= 0) jacobian[root].middleCols(dofs.root_columns, 6) = Matrix6::Identity();
  }
  // The columns each joint writes into its child's Jacobian.
  std::vector<std::vector<DofBlock>> joints_into(bodies.size());
  for (const TreeDofs& dofs : trees)
    for (const DofBlock& block : dofs.joints) joints_into[static_cast<std::size_t>(block.joint->child)].push_back(block);
  for (const TreeJoint& j : tree) {
    const auto p = static_cast<std::size_t>(j.parent), c = static_cast<std::size_t>(j.child);
    jacobian[c] = bodies[p].world ? Eigen::MatrixXd::Zero(6, jacobian[p].cols())
                                  : Eigen::MatrixXd(motion_transform(j.child_in_parent) * jacobian[p]);
    for (const DofBlock& block : joints_into[c])
      for (std::size_t k = 0; k < block.joint->dof_motions.size(); ++k)
        jacobian[c].col(block.column + static_cast<int>(k)) += block.joint->dof_motions[k];
  }
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (tree_of[b] < 0 || bodies[b].world || !bodies[b].mass_known) continue;
    const Matrix6 inertia = spatial_inertia(bodies[b].mass, bodies[b].com, bodies[b].inertia);
    mass[static_cast<std::size_t>(tree_of[b])] += jacobian[b].transpose() * inertia * jacobian[b];
  }

  for (std::size_t t = 0; t < trees.size(); ++t) {
    const TreeDofs& dofs = trees[t];
    for (const DofBlock& block : dofs.joints)
      for (int k = 0; k < static_cast<int>(block.joint->dof_motions.size()); ++k)
        mass[t](block.column + k, block.column + k) += block.joint->armature;
    factors_.push_back(TreeFactor{Eigen::LLT<Eigen::MatrixXd>(mass[t]), dofs.count, {}, mass[t]});
    const Eigen::LLT<Eigen::MatrixXd>& factor = factors_.back().factor;
    const bool singular = dofs.count > 0 && factor.info() != Eigen::Success;
    ArticulatedInertia& status = factors_.back().status;
    status.known = dofs.reason.empty() && dofs.unknown_links.empty() && !singular;
    if (!dofs.reason.empty()) status.reason = dofs.reason;
    else if (!dofs.unknown_links.empty()) status.unknown_links = dofs.unknown_links;
    else if (singular) status.reason = "its joint-space mass matrix is singular (a body the joints move has no mass or inertia)";
    for (const DofBlock& block : dofs.joints) {
      (block.parallel ? parallel_column_[block.index] : tree_column_[block.index]) = {static_cast<int>(t), block.column};
      ArticulatedInertia& result = block.parallel ? parallel_results_[block.index] : tree_results_[block.index];
      if (!dofs.reason.empty()) {
        result.reason = dofs.reason;
      } else if (!dofs.unknown_links.empty()) {
        result.unknown_links = dofs.unknown_links;
      } else if (singular) {
        result.reason = "its joint-space mass matrix is singular (a body the joints move has no mass or inertia)";
      } else if (block.joint->dof_motions.size() == 1) {
        Eigen::VectorXd unit = Eigen::VectorXd::Zero(dofs.count);
        unit(block.column) = 1;
        result.response = factor.solve(unit)(block.column);
        result.value = 1.0 / result.response;
        result.known = true;
      } else {
        result.reason = "a multi-DOF joint";
      }
    }
  }
}

ArticulatedInertia JointSpaceMatrix::operational_inertia(const Joint& joint) const {
  const Articulation& a = articulation_;
  const auto i = a.asset_->index_of(joint);
  if (i && *i < a.tree_of_joint_.size() && a.tree_of_joint_[*i] >= 0)
    return tree_results_[static_cast<std::size_t>(a.tree_of_joint_[*i])];
  if (i && *i < a.parallel_of_joint_.size() && a.parallel_of_joint_[*i] >= 0)
    return parallel_results_[static_cast<std::size_t>(a.parallel_of_joint_[*i])];
  ArticulatedInertia none;
  none.reason = "the joint is not part of the articulation's tree";
  return none;
}

}  // namespace assetlint::physics

namespace assetlint::physics {

bool JointSpaceMatrix::point_rows(const Link& link, const Eigen::Vector3d& point, const Eigen::Vector3d* root_point,
                                  bool angular, int& tree, Eigen::MatrixXd& rows, Eigen::Vector3d* in_root) const {
  const Articulation& a = articulation_;
  const int start = a.body_index(&link);
  tree = -1;
  rows.resize(0, 0);
  if (start < 0) return false;
  const Body& body = a.bodies_[static_cast<std::size_t>(start)];
  if (body.world) return true;
  // The link's place in its body, then the chain of bodies up to the tree's root.
  const auto at = std::find(body.links.begin(), body.links.end(), &link);
  const Eigen::Vector3d in_body = body.link_in_body[static_cast<std::size_t>(at - body.links.begin())] * point;
  std::vector<int> chain;  // tree_ entries from the link's body up
  for (int b = start; a.joint_into_[static_cast<std::size_t>(b)] >= 0;) {
    const int entry = a.joint_into_[static_cast<std::size_t>(b)];
    chain.push_back(entry);
    b = a.tree_[static_cast<std::size_t>(entry)].parent;
    if (a.bodies_[static_cast<std::size_t>(b)].world) break;
  }
  // Poses in the root's frame, root first.
  std::vector<Eigen::Isometry3d> pose(chain.size() + 1, Eigen::Isometry3d::Identity());
  for (std::size_t k = chain.size(); k-- > 0;)
    pose[k] = pose[k + 1] * a.tree_[static_cast<std::size_t>(chain[k])].child_in_parent;
  // pose[0]: the link's body. The point in the root frame:
  const Eigen::Vector3d p = root_point ? *root_point : Eigen::Vector3d(pose[0] * in_body);
  if (in_root) *in_root = p;
  if (chain.empty()) return false;  // a floating root's own freedoms are not tied by anything here
  const auto here = tree_column_[static_cast<std::size_t>(chain.front())];
  if (here.first < 0) return false;
  tree = here.first;
  const int count = factors_[static_cast<std::size_t>(tree)].count;
  rows = Eigen::MatrixXd::Zero(angular ? 6 : 3, count);
  // Each joint into a body of the chain (the tree joint and any parallel to it) adds its motion.
  const auto add = [&](const TreeJoint& j, const Eigen::Isometry3d& child_pose, int column) {
    for (std::size_t k = 0; k < j.dof_motions.size(); ++k) {
      const Eigen::Vector3d w = j.dof_motions[k].head<3>(), v = j.dof_motions[k].tail<3>();
      const Eigen::Vector3d p_child = child_pose.inverse() * p;
      const Eigen::Vector3d linear = child_pose.linear() * (v + w.cross(p_child));
      const int c = column + static_cast<int>(k);
      if (angular) {
        rows.block<3, 1>(0, c) += child_pose.linear() * w;
        rows.block<3, 1>(3, c) += linear;
      } else {
        rows.block<3, 1>(0, c) += linear;
      }
    }
  };
  for (std::size_t k = 0; k < chain.size(); ++k) {
    const TreeJoint& j = a.tree_[static_cast<std::size_t>(chain[k])];
    const int column = tree_column_[static_cast<std::size_t>(chain[k])].second;
    if (column < 0) return false;
    add(j, pose[k], column);
    for (std::size_t q = 0; q < a.parallel_.size(); ++q)
      if (a.parallel_[q].child == j.child && parallel_column_[q].second >= 0) add(a.parallel_[q], pose[k], parallel_column_[q].second);
  }
  return true;
}

std::pair<int, int> JointSpaceMatrix::column_of(const Joint& joint) const {
  const Articulation& a = articulation_;
  const auto i = a.asset_->index_of(joint);
  if (i && *i < a.tree_of_joint_.size() && a.tree_of_joint_[*i] >= 0)
    return tree_column_[static_cast<std::size_t>(a.tree_of_joint_[*i])];
  if (i && *i < a.parallel_of_joint_.size() && a.parallel_of_joint_[*i] >= 0)
    return parallel_column_[static_cast<std::size_t>(a.parallel_of_joint_[*i])];
  return {-1, -1};
}

ArticulatedInertia JointSpaceMatrix::operational_inertia(const std::vector<std::pair<const Joint*, double>>& moment) const {
  ArticulatedInertia out;
  // J·M⁻¹·Jᵀ: M is block diagonal over the trees, so the trees' terms add.
  std::map<int, Eigen::VectorXd> rows;
  for (const auto& [joint, value] : moment) {
    const auto [tree, column] = column_of(*joint);
    if (tree < 0 || !is_single_dof(joint->type)) {
      out.reason = fmt::format("joint '{}' is not a single-DOF joint of the articulation's tree", joint->name.text);
      return out;
    }
    const TreeFactor& f = factors_[static_cast<std::size_t>(tree)];
    if (!f.status.known) return f.status;
    auto row = rows.try_emplace(tree, Eigen::VectorXd::Zero(f.count)).first;
    row->second(column) += value;
  }
  double response = 0;
  for (const auto& [tree, row] : rows) response += row.dot(factors_[static_cast<std::size_t>(tree)].factor.solve(row));
  if (!(response > 0)) {
    out.reason = "the transmission moves no degree of freedom";
    return out;
  }
  out.response = response;
  out.value = 1.0 / response;
  out.known = true;
  return out;
}

}  // namespace assetlint::physics
