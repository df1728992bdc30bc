#pragma once
// Inertia helpers (PHYSICS.md §2): principal moments, and a link's inertia about a
// joint axis shifted with the parallel-axis theorem.
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "model/asset.h"

namespace assetlint::physics {

// Eigenvalues of a symmetric inertia tensor, ascending.
Eigen::Vector3d principal_moments(const Eigen::Matrix3d& inertia);

// Moment of inertia of a link about a joint's axis line (kg·m²): the COM inertia
// projected on the axis plus m·d², d being the COM's distance from the axis line.
// `joint_in_link` places the joint frame in the link frame; `axis` is in the joint frame.
double inertia_about_axis(const Inertial& inertial, const Eigen::Isometry3d& joint_in_link, const Eigen::Vector3d& axis);

// Distance (m) from the link's COM to the joint axis line.
double axis_distance(const Inertial& inertial, const Eigen::Isometry3d& joint_in_link, const Eigen::Vector3d& axis);

// ixx = iyy = izz = ixy = ixz = iyz ≠ 0: one value typed into every field (rank one).
bool pasted_tensor(const Eigen::Matrix3d& inertia);

// Whether a link's radius of gyration √(I/m) fits the link. Every point of a body lies within
// its extent R of the COM, so √(I_max/m) ≤ R. The model gives R only as the spread of the
// joint frames on the link (two or more: it spans at least between them); the bound allows
// kGyrationSizeFactor × that spread, and never less than kGyrationFloor, because a link
// reaches past its joints. Without two joint frames apart from the COM the fixed bound kGyrationFixedBound holds.
// A radius under kGyrationMinRadius on kGyrationMinMass or more is a point mass typed in.
// The factor is 4, not 3, because frames placed the Denavit-Hartenberg way can sit together at
// one end of a link: both of Franka's Panda link5 frames are 0.06 m from the COM of a 0.38 m
// forearm whose √(I/m) is 0.173 m. The corpus's wrong tensors sit 2-10× beyond 4× their spread.
inline constexpr double kGyrationSizeFactor = 4.0;
inline constexpr double kGyrationFloor = 0.1;        // m
inline constexpr double kGyrationFixedBound = 0.5;   // m
// Where the floor is the bound (the joint frames sit within a quarter of it from the COM, as on a
// wheel whose steering and spin axes cross at its centre, so they say nothing of its size), a
// tensor that a uniform box of this density or more reproduces is a solid's, not a template's:
// rigid foam is about as light as an engineering part gets. A template's 0.1 kg·m² on 0.7 kg
// implies a box of 0.8 kg/m³.
inline constexpr double kGyrationMinSolidDensity = 50.0;  // kg/m³
inline constexpr double kGyrationMinRadius = 0.002;  // m
inline constexpr double kGyrationMinMass = 0.01;     // kg
// The floor and the fixed bound are for robots up to this size across (m): a larger one's parts
// may be proportionally larger (a mecha 18 m tall has elbow pieces of 0.4 m in gyration).
inline constexpr double kGyrationReferenceSize = 2.0;

// The asset's size across (the diagonal of the box around its links at the zero
// configuration) over kGyrationReferenceSize, and never below 1: what the floor and the fixed
// bound of judge_gyration scale by.
double gyration_scale(const Asset& asset);

struct Gyration {
  enum class Verdict { Plausible, TooLarge, TooSmall };
  Verdict verdict = Verdict::Plausible;
  double largest = 0;   // √(I_max / m), m
  double smallest = 0;  // √(I_min / m), m
  double spread = 0;    // farthest joint frame on the link from its COM, m (0: no size from two or more frames)
  double bound = 0;     // the largest plausible radius, m
  bool from_size = false;  // bound = max(factor × spread, floor); else the fixed bound
  bool about_axis = false;  // `largest` is about the one axis the link turns about
  double scale = 1;         // gyration_scale of the asset
  bool from_shapes = false;  // the shapes' reach, larger than the other bounds, is the bound
  double box_density = 0;    // kg/m³: the mass over the uniform box its principal moments imply (0: none fits)
  bool floor_only = false;   // the joint frames sit within a quarter of the floor from the COM: no size from them
  std::string bound_text() const;  // "3 × 0.114 m, the farthest joint frame on the link from its COM" / …
};

// The joint frames on a link, in the link frame: where it is a joint's parent or child.
std::vector<Eigen::Vector3d> joint_frames_on(const Asset& asset, const Link& link);

// How far the link's collision shapes reach from `com` (link frame), m: for each primitive its
// centre's distance plus the radius of the sphere around it, for a mesh written inline its
// farthest vertex; 0 when the link has no shape whose size the file gives (mesh files).
// The link is at least that large, so its radius of gyration may be that large too.
double collision_reach(const Link& link, const Eigen::Vector3d& com);

// Needs an authored, positive-definite tensor, a positive mass and an authored COM. With
// `sole_axis` (a link that only turns about that axis, in its frame) only the moment about it
// is judged: the other two never enter the dynamics, and identified parameter sets leave them
// arbitrary (Franka's Panda link1: 0.70 kg·m² across a 0.33 m link, 0.009 about its axis).
// `shape_reach` (collision_reach, 0 when unknown) raises the bound: a link is at least as large
// as its collision shapes.
std::optional<Gyration> judge_gyration(const Inertial& inertial, const std::vector<Eigen::Vector3d>& joint_frames,
                                       const std::optional<Eigen::Vector3d>& sole_axis, double scale,
                                       double shape_reach);

// Why the guide's formulas cannot trust a link's tensor, or empty: a pasted placeholder (all
// six entries equal, or mass equal to each moment) or a radius of gyration that does not fit.
std::string inertia_doubt(const Asset& asset, const Link& link, const std::optional<Eigen::Vector3d>& sole_axis,
                          double scale);

}  // namespace assetlint::physics
