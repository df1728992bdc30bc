#pragma once
// The joint-space mass matrix M of an articulation at its reference pose (q = 0), formed
// whole: every degree of freedom of every joint (a free joint's six, a ball joint's three,
// several joints in one body one after another), each joint's armature on its own diagonal,
// as MuJoCo builds it (mj_crb; `mjData.qM`). Where the O(n) recursions of Articulation see
// only single-DOF trees, this sees the tree MuJoCo steps, at O(nv³) for nv degrees of freedom.
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

 private:
  const Articulation& articulation_;
  std::vector<ArticulatedInertia> tree_results_;      // per Articulation tree_ entry
  std::vector<ArticulatedInertia> parallel_results_;  // per Articulation parallel_ entry
};

}  // namespace assetlint::physics
