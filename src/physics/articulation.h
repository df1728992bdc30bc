#pragma once
// The articulation PhysX builds from an asset (docs/physics.md "Articulated inertia"):
// links welded by fixed joints are one rigid body, bodies welded to the world are the
// world, and each movable joint's drive row sees the articulated inertia 1/r, with
// r = (M⁻¹)ᵢᵢ of the joint-space mass matrix M (armature on its diagonal, mimic rows aside).
#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "model/asset.h"

namespace assetlint::physics {

// One rigid body: links welded together by fixed joints.
struct Body {
  std::vector<const Link*> links;
  std::vector<Eigen::Isometry3d> link_in_body;  // each link's frame in the body frame (the first link's)
  bool world = false;  // welded to the world (a fixed base, a static or kinematic body)
  // Combined mass properties in the body frame, when every link states them.
  bool mass_known = false;
  double mass = 0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about the COM
  std::vector<std::string> unknown_links;  // links whose mass, inertia or COM is not authored
  bool massless = false;                   // every link states its mass and they sum to 0 (also in unknown_links)
  std::string name() const;                // the first link's name
};

// A movable single-DOF joint of the tree, between two bodies.
struct TreeJoint {
  const Joint* joint = nullptr;
  int parent = -1;  // body index on the root side
  int child = -1;   // body index on the leaf side
  // The motion subspace S in the child body frame at q = 0 ([angular; linear]).
  Eigen::Matrix<double, 6, 1> motion = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Isometry3d child_in_parent = Eigen::Isometry3d::Identity();  // at q = 0
  double armature = 0;
  bool modelled = true;  // false for multi-DOF joints: the trees holding one stay unknown
  // Every degree of freedom's motion in the child body frame at q = 0, in MuJoCo's order: a
  // hinge or slide has one (= motion); a ball joint three rotations about the child frame's
  // axes through the joint; a free joint three translations along the parent frame's axes,
  // then three rotations about the child frame's axes. Empty for a planar or generic joint.
  std::vector<Eigen::Matrix<double, 6, 1>> dof_motions;
};

// What a joint's drive row sees.
struct ArticulatedInertia {
  bool known = false;
  double value = 0;     // 1/r, kg·m² (kg for prismatic joints)
  double response = 0;  // r
  std::vector<std::string> unknown_links;  // why not known: bodies in the articulation without mass
  std::string reason;                      // when not known and no link is to blame
};

class JointSpaceMatrix;

class Articulation {
 public:
  // How a tree whose root is not welded to the world is based. Isaac's URDF importer fixes
  // the base by default (fixBase); a USD articulation without a joint to the world floats.
  enum class FreeRoot { Fixed, Floating };
  // What a link without authored mass counts as: unknown (every inertia it takes part in is
  // unknown), or massless, which makes each articulated inertia a lower bound (adding mass to
  // any body only raises 1/r) for the links listed in assumed_massless().
  enum class MissingMass { Unknown, Massless };
  explicit Articulation(const Asset& asset);
  Articulation(const Asset& asset, FreeRoot free_root, MissingMass missing = MissingMass::Unknown);

  const std::vector<Body>& bodies() const { return bodies_; }
  const std::vector<std::string>& assumed_massless() const { return assumed_massless_; }
  const Body* body_of(std::string_view link) const;
  // The body on one side of a joint: [0] parent/body0, [1] child/body1; null for the world
  // when the side names no link.
  const Body* side(const Joint& joint, int which) const;

  // 1/(M⁻¹)ᵢᵢ for a movable single-DOF joint. All joints of the asset are computed together
  // in O(n) time and memory (n bodies): one inward pass for the articulated-body inertias,
  // one outward pass for each body's inverse inertia as the whole tree sees it; each joint's
  // r is then a 6-vector product. No joint-space matrix is formed.
  ArticulatedInertia inertia(const Joint& joint) const;

  // Mᵢᵢ, the joint-space mass matrix's diagonal at q = 0 with the joint's armature: the
  // inertia of everything distal to the joint about its axis, every other joint held. It is
  // MuJoCo's dof_M0, the inertia `dampratio` is computed on. Known when every body distal to
  // the joint has mass; a multi-DOF joint among them counts as held, a massless body (MuJoCo
  // allows one inside a chain) adds nothing. Joints that share their parent and child body
  // (several joints in one MJCF body) each get theirs. O(n) for all joints.
  ArticulatedInertia joint_space_inertia(const Joint& joint) const;

  // Jᵀ·M·J: the inertia of the motion in which each listed joint moves at its rate (per unit
  // of a driver) and every other joint, a floating root included, stays still; armatures
  // count with rate². Unknown when any listed joint's `inertia` is. O(n) from the body
  // velocities (twice the kinetic energy at those rates); no mass matrix is formed.
  ArticulatedInertia coupled_inertia(const std::vector<std::pair<const Joint*, double>>& rates) const;

  // A body's moment of inertia about a joint's axis line (parallel-axis shifted; mass for
  // prismatic joints), when its mass properties are known.
  std::optional<double> inertia_about_axis(const Body& body, const Joint& joint, int which) const;

  // The axis (in the link's frame) about which a link turns when that is all it can do: the
  // first link of a body whose one joint is revolute or continuous to a body welded to the
  // world (an arm's first link). Only its moment about that axis enters the dynamics.
  std::optional<Eigen::Vector3d> sole_rotation_axis(const Link& link) const;
  // Whether the body a link starts never turns: every joint between it and a body welded to
  // the world is prismatic (a virtual base's x, y and z slides). Its rotational inertia then
  // never enters the dynamics; only its mass does.
  bool translates_only(const Link& link) const;

 private:
  friend class JointSpaceMatrix;
  void build(const Asset& asset, FreeRoot free_root, MissingMass missing);
  void solve();

  std::vector<Body> bodies_;
  std::vector<std::string> assumed_massless_;  // links without authored mass taken as massless
  std::vector<TreeJoint> tree_;                     // parents before children
  std::vector<int> roots_;                          // body indices, one per tree
  std::vector<bool> floating_;                      // per body: a floating root
  std::vector<int> joint_into_;                     // per body: the tree_ entry whose child it is, or -1
  // Indexed by the asset's link and joint positions: no name is hashed after build().
  const Asset* asset_ = nullptr;
  std::vector<int> body_of_link_;                   // per link: its body
  std::vector<int> tree_of_joint_;                  // per joint: its tree_ entry, or -1
  int body_index(const Link* link) const;           // -1 for none
  std::vector<ArticulatedInertia> results_;         // per tree_ entry
  std::vector<ArticulatedInertia> joint_space_;     // per tree_ entry: Mᵢᵢ
  // Joints parallel to a tree joint (the same parent and child body): not in the tree, but
  // each has its own Mᵢᵢ.
  std::vector<TreeJoint> parallel_;
  std::vector<int> parallel_of_joint_;              // per joint: its parallel_ entry, or -1
  std::vector<ArticulatedInertia> parallel_space_;  // per parallel_ entry: Mᵢᵢ
  void solve_joint_space();
};

// The tree's free-root convention for an asset's format.
Articulation::FreeRoot default_free_root(const Asset& asset);

// While a scope is open on this thread, shared_articulation(asset) builds the asset's
// Articulation (default free root) once and hands the same one to every caller: the rules
// of one lint pass would otherwise build it five times. The asset must not change while
// the scope is open. Outside a scope, or for another asset, each call builds a new one.
class SharedArticulationScope {
 public:
  explicit SharedArticulationScope(const Asset& asset);
  ~SharedArticulationScope();
  SharedArticulationScope(const SharedArticulationScope&) = delete;
  SharedArticulationScope& operator=(const SharedArticulationScope&) = delete;

 private:
  friend std::shared_ptr<const Articulation> shared_articulation(const Asset& asset);
  const Asset& asset_;
  std::shared_ptr<const Articulation> articulation_;
  SharedArticulationScope* enclosing_;
};

std::shared_ptr<const Articulation> shared_articulation(const Asset& asset);

}  // namespace assetlint::physics
