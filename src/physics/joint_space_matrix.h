#pragma once
// The joint-space mass matrix M of an articulation at its reference pose (q = 0), formed
// whole: every degree of freedom of every joint (a free joint's six, a ball joint's three,
// several joints in one body one after another), each joint's armature on its own diagonal,
// as MuJoCo builds it (mj_crb; `mjData.qM`). Where the O(n) recursions of Articulation see
// only single-DOF trees, this sees the tree MuJoCo steps, at O(nv³) for nv degrees of freedom.
#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <utility>
#include <vector>

#include "physics/articulation.h"

namespace assetlint::physics {

class JointSpaceMatrix {
 public:
  explicit JointSpaceMatrix(const Articulation& articulation);

  // 1/(M⁻¹)ᵢᵢ for a single-DOF joint: the inertia its axis feels when every other degree of
  // freedom of its tree (a floating base included) moves freely, armature included. It is
  // the operational-space inertia (J·M⁻¹·Jᵀ)⁻¹ of a unit transmission on the joint. Unknown
  // when any moving body of the tree has no known mass, a joint of it is planar or generic,
  // or M is singular.
  ArticulatedInertia operational_inertia(const Joint& joint) const;

  // (J·M⁻¹·Jᵀ)⁻¹ for a transmission whose moment J is `moment` on single-DOF joints (a fixed
  // tendon: gear·coef on each of its joints): the inertia it reflects with every degree of
  // freedom free. Unknown as above for any tree it reaches.
  ArticulatedInertia operational_inertia(const std::vector<std::pair<const Joint*, double>>& moment) const;

  // The tree and column of a single-DOF joint; tree < 0 when it is not in the articulation.
  std::pair<int, int> column_of(const Joint& joint) const;
  // A tree's whole mass matrix (armatures on the diagonal) and whether it is known (else why not).
  const Eigen::MatrixXd& mass_matrix(int tree) const { return factors_[static_cast<std::size_t>(tree)].mass; }
  const ArticulatedInertia& tree_status(int tree) const { return factors_[static_cast<std::size_t>(tree)].status; }

  // The velocity of a point fixed in a link, per unit rate of each degree of freedom of the
  // link's tree, at the reference pose, in the frame of the tree's root body: 3 rows (linear),
  // or 6 with `angular` (angular first). The point is `point` in the link's frame, or
  // `root_point` in the root's frame when given; `in_root` receives where it is in the root's
  // frame. `tree` is set to the link's tree, -1 for a link welded to the world (its rows are
  // zero, and `rows` is left empty). False when the link cannot be placed.
  bool point_rows(const Link& link, const Eigen::Vector3d& point, const Eigen::Vector3d* root_point, bool angular,
                  int& tree, Eigen::MatrixXd& rows, Eigen::Vector3d* in_root) const;

 private:
  // One tree's matrix and its factor: M⁻¹·v for the transmissions that reach it.
  struct TreeFactor {
    Eigen::LLT<Eigen::MatrixXd> factor;
    int count = 0;
    ArticulatedInertia status;  // known = false with the reason when M cannot be solved
    Eigen::MatrixXd mass;
  };

  const Articulation& articulation_;
  std::vector<TreeFactor> factors_;
  std::vector<std::pair<int, int>> tree_column_;      // per Articulation tree_ entry
  std::vector<std::pair<int, int>> parallel_column_;  // per Articulation parallel_ entry
  std::vector<ArticulatedInertia> tree_results_;      // per Articulation tree_ entry
  std::vector<ArticulatedInertia> parallel_results_;  // per Articulation parallel_ entry
};

}  // namespace assetlint::physics
