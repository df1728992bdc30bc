#pragma once
// A drive's mechanism: the joints that mimics (joint equalities) and loop closures (MJCF
// connect and weld equalities) tie to the joint it drives, and the inertia the drive sees
// when those constraints hold rigidly and every other joint is held (docs/physics.md
// "Closed linkages").
//
// The constraints' velocity rows A·q̇ = 0 over the tied joints: a mimic q̇_f − m·q̇_l = 0; a
// loop closure the velocity of its anchor on one body minus that of the same point on the
// other (3 rows; a weld also their angular velocities, 3 more), each joint contributing its
// motion at the reference pose. N, a basis of A's null space, spans the motions the
// mechanism can make; along them the mass matrix is Nᵀ·M·N, and a drive whose moment on the
// tied joints is J (a unit on its joint, or a fixed tendon's gear·coefs) reflects
//   m = 1 / (b ᵀ·(Nᵀ·M·N)⁻¹·b),  b = Nᵀ·Jᵀ.
// With one freedom this is Jᵀ·M·J along the mechanism's one motion (per unit of the drive);
// with more (Robotiq 2F-85's fingers are five-bar linkages that adapt to an object) it is
// the inertia with the other freedoms free. Without constraints it is Mᵢᵢ (MuJoCo's M₀).
#include <string>
#include <utility>
#include <vector>

#include "model/asset.h"
#include "physics/articulation.h"
#include "physics/joint_space_matrix.h"

namespace assetlint::physics {

struct Mechanism {
  std::vector<const Joint*> joints;  // the driven joint (or the moment's joints) first, then those tied to it
  int freedoms = 0;                  // dimension of the constraints' null space
  ArticulatedInertia inertia;        // m above, armature included
  // With one freedom: each tied joint's rate per unit rate of the drive (b = 1), in `joints`' order.
  std::vector<double> rates;
  bool tied() const { return joints.size() > 1; }
};

// The joints the model's mimics and loop closures tie to `seed` (transitively), seed first.
std::vector<const Joint*> tied_joints(const Asset& asset, const std::vector<const Joint*>& seed);

// Which armatures the mechanism's inertia counts.
struct Armatures {
  const Joint* without = nullptr;  // this joint's is left out (what the drive would see without it)
  bool none = false;               // every tied joint's is left out: the bodies alone
};

// The mechanism a drive with moment `moment` (joint, moment) moves.
Mechanism drive_mechanism(const JointSpaceMatrix& matrix, const Asset& asset,
                          const std::vector<std::pair<const Joint*, double>>& moment, Armatures armatures = {});

// The moment of the drive on `joint`: a unit on it.
Mechanism drive_mechanism(const JointSpaceMatrix& matrix, const Asset& asset, const Joint& joint,
                          Armatures armatures = {});

}  // namespace assetlint::physics
