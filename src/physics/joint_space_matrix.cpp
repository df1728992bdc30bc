#include "physics/joint_space_matrix.h"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <Eigen/Dense>

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
    const Eigen::LLT<Eigen::MatrixXd> factor(mass[t]);
    const bool singular = dofs.count > 0 && factor.info() != Eigen::Success;
    for (const DofBlock& block : dofs.joints) {
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
