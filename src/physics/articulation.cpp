#include "physics/articulation.h"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <deque>
#include <numeric>

#include "physics/spatial.h"
#include "util/numbers.h"

namespace assetlint::physics {

namespace {

bool is_multi_dof(JointType type) {
  return type == JointType::Floating || type == JointType::Planar || type == JointType::Spherical ||
         type == JointType::Generic;
}

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

}  // namespace

std::string Body::name() const { return links.empty() ? std::string("world") : links.front()->name.text; }

Articulation::FreeRoot default_free_root(const Asset& asset) {
  return asset.format == SourceFormat::Usda ? Articulation::FreeRoot::Floating : Articulation::FreeRoot::Fixed;
}

Articulation::Articulation(const Asset& asset) : Articulation(asset, default_free_root(asset)) {}

Articulation::Articulation(const Asset& asset, FreeRoot free_root, MissingMass missing) {
  build(asset, free_root, missing);
  solve();
  solve_joint_space();
}

int Articulation::body_index(const Link* link) const {
  const auto i = link ? asset_->index_of(*link) : std::nullopt;
  return i && *i < body_of_link_.size() ? body_of_link_[*i] : -1;
}

const Body* Articulation::body_of(std::string_view link) const {
  const int b = body_index(asset_->find_link(link));
  return b < 0 ? nullptr : &bodies_[static_cast<std::size_t>(b)];
}

const Body* Articulation::side(const Joint& joint, int which) const {
  const int b = body_index(asset_->side_link(joint, which));
  return b < 0 ? nullptr : &bodies_[static_cast<std::size_t>(b)];
}

void Articulation::build(const Asset& asset, FreeRoot free_root, MissingMass missing) {
  asset_ = &asset;
  const std::size_t n = asset.links.size();
  // A link's position; the first definition of a repeated name stands for it.
  const auto link_index = [&](const Link* link) { return link ? static_cast<int>(*asset.index_of(*link)) : -1; };
  const auto side_index = [&](const Joint& joint, int which) { return link_index(asset.side_link(joint, which)); };

  // Rigid bodies: links welded by fixed joints. A fixed joint to nothing (the world, a
  // static prim) or to a link named "world" welds its component to the world.
  UnionFind welded(n);
  std::vector<bool> to_world(n, false);
  const auto world_link = [&](int i) {
    const Link& link = asset.links[static_cast<std::size_t>(i)];
    return link.kinematic || (asset.format == SourceFormat::Urdf && link.name.text == "world" && !link.inertial);
  };
  for (std::size_t i = 0; i < n; ++i)
    if (world_link(static_cast<int>(i))) to_world[i] = true;
  for (const Joint& joint : asset.joints) {
    if (joint.type != JointType::Fixed) continue;
    const int a = side_index(joint, 0), b = side_index(joint, 1);
    if (a >= 0 && b >= 0) welded.unite(a, b);
    else if (a >= 0 && joint.child.text.empty()) to_world[static_cast<std::size_t>(a)] = true;
    else if (b >= 0 && joint.parent.text.empty()) to_world[static_cast<std::size_t>(b)] = true;
  }

  // One Body per component, its frame the first link's; link frames placed by walking
  // the fixed joints.
  // The fixed joints at each link, in document order, as one array sliced by `first_fixed`.
  std::vector<std::size_t> first_fixed(n + 1, 0);
  for (const Joint& joint : asset.joints) {
    if (joint.type != JointType::Fixed) continue;
    const int a = side_index(joint, 0), b = side_index(joint, 1);
    if (a < 0 || b < 0) continue;
    ++first_fixed[static_cast<std::size_t>(a) + 1];
    ++first_fixed[static_cast<std::size_t>(b) + 1];
  }
  for (std::size_t i = 0; i < n; ++i) first_fixed[i + 1] += first_fixed[i];
  std::vector<const Joint*> fixed_at(first_fixed[n]);
  {
    std::vector<std::size_t> fill(first_fixed.begin(), first_fixed.end() - 1);
    for (const Joint& joint : asset.joints) {
      if (joint.type != JointType::Fixed) continue;
      const int a = side_index(joint, 0), b = side_index(joint, 1);
      if (a < 0 || b < 0) continue;
      fixed_at[fill[static_cast<std::size_t>(a)]++] = &joint;
      fixed_at[fill[static_cast<std::size_t>(b)]++] = &joint;
    }
  }
  std::vector<int> body_of_link(n, -1);
  std::vector<Eigen::Isometry3d> link_pose(n, Eigen::Isometry3d::Identity());
  std::vector<int> pending;  // breadth-first queue of one component, reused
  for (std::size_t start = 0; start < n; ++start) {
    if (body_of_link[start] >= 0) continue;
    const int body = static_cast<int>(bodies_.size());
    bodies_.emplace_back();
    pending.assign(1, static_cast<int>(start));
    body_of_link[start] = body;
    for (std::size_t head = 0; head < pending.size(); ++head) {
      const int at = pending[head];
      Body& b = bodies_.back();
      b.links.push_back(&asset.links[static_cast<std::size_t>(at)]);
      b.link_in_body.push_back(link_pose[static_cast<std::size_t>(at)]);
      if (to_world[static_cast<std::size_t>(at)]) b.world = true;
      for (std::size_t k = first_fixed[static_cast<std::size_t>(at)]; k < first_fixed[static_cast<std::size_t>(at) + 1]; ++k) {
        const Joint& joint = *fixed_at[k];
        const bool forward = side_index(joint, 0) == at;
        const int next = forward ? side_index(joint, 1) : side_index(joint, 0);
        if (body_of_link[static_cast<std::size_t>(next)] >= 0) continue;  // a weld loop: first path wins
        const auto& f = joint.frame_in_link;
        const Eigen::Isometry3d next_in_at = forward ? f[0] * f[1].inverse() : f[1] * f[0].inverse();
        link_pose[static_cast<std::size_t>(next)] = link_pose[static_cast<std::size_t>(at)] * next_in_at;
        body_of_link[static_cast<std::size_t>(next)] = body;
        pending.push_back(next);
      }
    }
  }
  body_of_link_ = body_of_link;

  // Combined mass properties. USD: a body without authored mass, inertia or COM gets them
  // from its colliders, which a text linter cannot see. URDF: a link without <inertial>
  // is massless.
  for (Body& body : bodies_) {
    if (body.world) continue;
    double mass = 0;
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < body.links.size(); ++i) {
      const Link& link = *body.links[i];
      const auto& in = link.inertial;
      const bool usd = asset.format == SourceFormat::Usda;
      if (!in ? usd || link.mass_from_geoms : (!in->mass_authored || !in->inertia_authored || !in->com_authored || !(in->mass.value >= 0))) {
        if (missing == MissingMass::Massless) assumed_massless_.push_back(link.name.text);
        else body.unknown_links.push_back(link.name.text);
        continue;
      }
      if (!in) continue;
      mass += in->mass.value;
      moment += in->mass.value * (body.link_in_body[i] * in->com);
    }
    if (!body.unknown_links.empty()) continue;
    if (!(mass > 0)) {
      body.massless = mass == 0;
      // Taken as massless on purpose, the body adds nothing (its joint alone has no inertia).
      if (missing == MissingMass::Massless && body.massless) continue;
      for (const Link* link : body.links) body.unknown_links.push_back(link->name.text);
      continue;
    }
    body.mass = mass;
    body.com = moment / mass;
    for (std::size_t i = 0; i < body.links.size(); ++i) {
      const auto& in = body.links[i]->inertial;
      if (!in) continue;
      const Eigen::Matrix3d r = body.link_in_body[i].linear();
      const Eigen::Vector3d d = body.link_in_body[i] * in->com - body.com;
      body.inertia += r * in->inertia * r.transpose() +
                      in->mass.value * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
    }
    body.mass_known = true;
  }

  // The tree of movable joints, found breadth-first from the world; a tree with no world
  // in it starts at a body no joint has as its child.
  const int world = static_cast<int>(bodies_.size());
  bodies_.emplace_back();
  bodies_.back().world = true;
  struct Edge {
    const Joint* joint;
    int a, b;  // body on the joint's parent/body0 side and child/body1 side
  };
  std::vector<Edge> edges;
  std::vector<std::vector<int>> incident(bodies_.size());
  std::vector<bool> has_parent(bodies_.size(), false);
  for (const Joint& joint : asset.joints) {
    if (joint.type == JointType::Fixed) continue;
    const int pa = side_index(joint, 0), pb = side_index(joint, 1);
    const int a = pa >= 0 ? body_of_link[static_cast<std::size_t>(pa)] : joint.parent.text.empty() ? world : -1;
    const int b = pb >= 0 ? body_of_link[static_cast<std::size_t>(pb)] : joint.child.text.empty() ? world : -1;
    if (a < 0 || b < 0 || a == b) continue;  // an undefined link, or a joint inside one body
    const int e = static_cast<int>(edges.size());
    edges.push_back({&joint, a, b});
    incident[static_cast<std::size_t>(a)].push_back(e);
    incident[static_cast<std::size_t>(b)].push_back(e);
    has_parent[static_cast<std::size_t>(b)] = true;
  }
  floating_.assign(bodies_.size(), false);
  joint_into_.assign(bodies_.size(), -1);
  tree_of_joint_.assign(asset.joints.size(), -1);
  std::vector<bool> visited(bodies_.size(), false);
  std::vector<bool> used(edges.size(), false);
  const auto make_tree_joint = [&](const Joint* joint, int at, int next, bool forward) {
    TreeJoint tj;
    tj.joint = joint;
    tj.parent = at;
    tj.child = next;
    tj.armature = joint->armature ? joint->armature->value : 0.0;
    tj.modelled = !is_multi_dof(joint->type);
    // The joint frame in each body; the world side needs none (it does not move).
    const auto frame_in = [&](int body, int which) {
      const int link = side_index(*joint, which);
      const Eigen::Isometry3d& f = joint->frame_in_link[static_cast<std::size_t>(which)];
      return body == world || link < 0 ? f : link_pose[static_cast<std::size_t>(link)] * f;
    };
    const Eigen::Isometry3d in_parent = frame_in(at, forward ? 0 : 1);
    const Eigen::Isometry3d in_child = frame_in(next, forward ? 1 : 0);
    tj.child_in_parent = in_parent * in_child.inverse();
    const Eigen::Vector3d axis = (in_child.linear() * joint->axis).normalized();
    if (joint->type == JointType::Prismatic) {
      tj.motion.tail<3>() = axis;
    } else {
      tj.motion.head<3>() = axis;
      tj.motion.tail<3>() = in_child.translation().cross(axis);
    }
    const auto rotation_about = [&](const Eigen::Vector3d& pivot, const Eigen::Vector3d& direction) {
      Vector6 s;
      s << direction, pivot.cross(direction);
      return s;
    };
    if (!is_multi_dof(joint->type)) {
      tj.dof_motions = {tj.motion};
    } else if (joint->type == JointType::Spherical || joint->type == JointType::Floating) {
      // The child link's own axes, in its body's frame.
      const int link = side_index(*joint, forward ? 1 : 0);
      const Eigen::Matrix3d axes =
          link < 0 ? Eigen::Matrix3d(Eigen::Matrix3d::Identity()) : Eigen::Matrix3d(link_pose[static_cast<std::size_t>(link)].linear());
      if (joint->type == JointType::Floating)
        for (int k = 0; k < 3; ++k) {
          Vector6 s = Vector6::Zero();
          s.tail<3>() = tj.child_in_parent.linear().transpose().col(k);
          tj.dof_motions.push_back(s);
        }
      for (int k = 0; k < 3; ++k) tj.dof_motions.push_back(rotation_about(in_child.translation(), axes.col(k)));
    }
    return tj;
  };
  parallel_of_joint_.assign(asset.joints.size(), -1);
  const auto grow = [&](int root) {
    roots_.push_back(root);
    visited[static_cast<std::size_t>(root)] = true;
    std::deque<int> pending{root};
    while (!pending.empty()) {
      const int at = pending.front();
      pending.pop_front();
      for (int e : incident[static_cast<std::size_t>(at)]) {
        if (used[static_cast<std::size_t>(e)]) continue;
        used[static_cast<std::size_t>(e)] = true;
        const Edge& edge = edges[static_cast<std::size_t>(e)];
        const bool forward = edge.a == at;
        const int next = forward ? edge.b : edge.a;
        TreeJoint tj = make_tree_joint(edge.joint, at, next, forward);
        if (visited[static_cast<std::size_t>(next)]) {  // a loop-closing joint: not in the tree
          const int into = joint_into_[static_cast<std::size_t>(next)];
          if (into >= 0 && tree_[static_cast<std::size_t>(into)].parent == at) {
            parallel_of_joint_[*asset.index_of(*edge.joint)] = static_cast<int>(parallel_.size());
            parallel_.push_back(tj);
          }
          continue;
        }
        visited[static_cast<std::size_t>(next)] = true;
        tree_of_joint_[*asset.index_of(*edge.joint)] = static_cast<int>(tree_.size());
        joint_into_[static_cast<std::size_t>(next)] = static_cast<int>(tree_.size());
        tree_.push_back(tj);
        pending.push_back(next);
      }
    }
  };
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    if (bodies_[b].world && !visited[b]) grow(static_cast<int>(b));
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      if (visited[b] || (pass == 0 && has_parent[b])) continue;
      if (free_root == FreeRoot::Fixed) bodies_[b].world = true;  // Isaac's URDF importer: fixBase
      else floating_[b] = true;
      grow(static_cast<int>(b));
    }
}

void Articulation::solve() {
  results_.assign(tree_.size(), {});
  // Which tree each body belongs to, what in it has unknown mass, and which multi-DOF
  // joint (not modelled) it holds.
  std::vector<int> tree_of(bodies_.size(), -1);
  for (std::size_t t = 0; t < roots_.size(); ++t) tree_of[static_cast<std::size_t>(roots_[t])] = static_cast<int>(t);
  for (const TreeJoint& j : tree_) tree_of[static_cast<std::size_t>(j.child)] = tree_of[static_cast<std::size_t>(j.parent)];
  std::vector<std::string> unsupported(roots_.size());
  for (const TreeJoint& j : tree_) {
    std::string& reason = unsupported[static_cast<std::size_t>(tree_of[static_cast<std::size_t>(j.child)])];
    if (!j.modelled && reason.empty())
      reason = fmt::format("joint '{}' is {}, not modelled", j.joint->name.text, joint_type_name(j.joint->type));
  }
  std::vector<std::vector<std::string>> unknown(roots_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    if (tree_of[b] < 0 || bodies_[b].world) continue;
    for (const auto& name : bodies_[b].unknown_links) unknown[static_cast<std::size_t>(tree_of[b])].push_back(name);
  }

  // Inward: articulated-body inertias, leaves first.
  std::vector<Matrix6> articulated(bodies_.size(), Matrix6::Zero());
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    if (bodies_[b].mass_known && !bodies_[b].world)
      articulated[b] = spatial_inertia(bodies_[b].mass, bodies_[b].com, bodies_[b].inertia);
  std::vector<Vector6> u(tree_.size());
  std::vector<double> d(tree_.size());
  std::vector<Matrix6> x(tree_.size());
  for (std::size_t k = tree_.size(); k-- > 0;) {
    const TreeJoint& j = tree_[k];
    const Matrix6& child = articulated[static_cast<std::size_t>(j.child)];
    x[k] = motion_transform(j.child_in_parent);
    u[k] = child * j.motion;
    d[k] = j.motion.dot(u[k]) + j.armature;
    if (!bodies_[static_cast<std::size_t>(j.parent)].world && d[k] > 0)
      articulated[static_cast<std::size_t>(j.parent)] += x[k].transpose() * (child - u[k] * u[k].transpose() / d[k]) * x[k];
  }
  // Outward: Φ, the inverse inertia of the whole tree at each body (0 for the world, the
  // inverse of the articulated inertia at a floating root), and each joint's r from it.
  std::vector<Matrix6> phi(bodies_.size(), Matrix6::Zero());
  std::vector<bool> singular(bodies_.size(), false);
  for (int root : roots_) {
    if (!floating_[static_cast<std::size_t>(root)]) continue;
    Eigen::FullPivLU<Matrix6> lu(articulated[static_cast<std::size_t>(root)]);
    if (lu.isInvertible()) phi[static_cast<std::size_t>(root)] = lu.inverse();
    else singular[static_cast<std::size_t>(root)] = true;
  }
  for (std::size_t k = 0; k < tree_.size(); ++k) {
    const TreeJoint& j = tree_[k];
    const std::size_t p = static_cast<std::size_t>(j.parent), c = static_cast<std::size_t>(j.child);
    ArticulatedInertia& result = results_[k];
    singular[c] = singular[p] || !(d[k] > 0);
    const auto& missing = unknown[static_cast<std::size_t>(tree_of[c])];
    if (const std::string& reason = unsupported[static_cast<std::size_t>(tree_of[c])]; !reason.empty()) {
      result.reason = reason;
      continue;
    }
    if (!missing.empty()) {
      result.unknown_links = missing;
      continue;
    }
    if (singular[c]) {
      result.reason = "the bodies it moves have no mass";
      continue;
    }
    const Matrix6 seen = x[k] * phi[p] * x[k].transpose();
    result.response = 1.0 / d[k] + u[k].dot(seen * u[k]) / (d[k] * d[k]);
    result.value = 1.0 / result.response;
    result.known = true;
    const Matrix6 project = Matrix6::Identity() - j.motion * u[k].transpose() / d[k];
    phi[c] = project * seen * project.transpose() + j.motion * j.motion.transpose() / d[k];
  }
}

void Articulation::solve_joint_space() {
  joint_space_.assign(tree_.size(), {});
  // Composite rigid-body inertias, leaves first: each body with everything distal to it held.
  // Names of massless links below a body are kept to a few, for messages.
  constexpr std::size_t kNamesKept = 8;
  std::vector<Matrix6> composite(bodies_.size(), Matrix6::Zero());
  std::vector<std::vector<std::string>> missing(bodies_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    if (bodies_[b].world) continue;
    if (bodies_[b].mass_known) composite[b] = spatial_inertia(bodies_[b].mass, bodies_[b].com, bodies_[b].inertia);
    if (bodies_[b].massless) continue;  // adds nothing
    for (const auto& name : bodies_[b].unknown_links)
      if (missing[b].size() < kNamesKept) missing[b].push_back(name);
  }
  const auto diagonal = [&](const TreeJoint& j, ArticulatedInertia& result) {
    const std::size_t c = static_cast<std::size_t>(j.child);
    if (!missing[c].empty()) {
      result.unknown_links = missing[c];
    } else if (const double value = j.motion.dot(composite[c] * j.motion) + j.armature; value > 0) {
      result.known = true;
      result.value = value;
      result.response = 1.0 / value;
    } else {
      result.reason = j.modelled ? "the bodies it moves have no mass" : "a multi-DOF joint";
    }
  };
  for (std::size_t k = tree_.size(); k-- > 0;) {
    const TreeJoint& j = tree_[k];
    const std::size_t p = static_cast<std::size_t>(j.parent), c = static_cast<std::size_t>(j.child);
    diagonal(j, joint_space_[k]);
    if (bodies_[p].world) continue;
    const Matrix6 x = motion_transform(j.child_in_parent);
    composite[p] += x.transpose() * composite[c] * x;
    for (const auto& name : missing[c])
      if (missing[p].size() < kNamesKept) missing[p].push_back(name);
  }
  // Composites are complete now: the joints parallel to a tree joint see the same child.
  parallel_space_.assign(parallel_.size(), {});
  for (std::size_t k = 0; k < parallel_.size(); ++k) diagonal(parallel_[k], parallel_space_[k]);
}

ArticulatedInertia Articulation::joint_space_inertia(const Joint& joint) const {
  const auto i = asset_->index_of(joint);
  if (i && *i < tree_of_joint_.size() && tree_of_joint_[*i] >= 0)
    return joint_space_[static_cast<std::size_t>(tree_of_joint_[*i])];
  if (i && *i < parallel_of_joint_.size() && parallel_of_joint_[*i] >= 0)
    return parallel_space_[static_cast<std::size_t>(parallel_of_joint_[*i])];
  ArticulatedInertia none;
  none.reason = "the joint is not part of the articulation's tree";
  return none;
}

std::optional<Eigen::Vector3d> Articulation::sole_rotation_axis(const Link& link) const {
  const int body = body_index(&link);
  if (body < 0) return std::nullopt;
  const auto b = static_cast<std::size_t>(body);
  if (bodies_[b].world || bodies_[b].links.empty() || bodies_[b].links.front() != &link || joint_into_[b] < 0)
    return std::nullopt;
  const TreeJoint& into = tree_[static_cast<std::size_t>(joint_into_[b])];
  if (!is_angular(into.joint->type) || !bodies_[static_cast<std::size_t>(into.parent)].world) return std::nullopt;
  return Eigen::Vector3d(into.motion.head<3>());
}

bool Articulation::translates_only(const Link& link) const {
  const int body = body_index(&link);
  if (body < 0) return false;
  auto b = static_cast<std::size_t>(body);
  if (bodies_[b].world || bodies_[b].links.empty() || bodies_[b].links.front() != &link) return false;
  while (!bodies_[b].world) {
    if (joint_into_[b] < 0) return false;  // a floating root turns
    const TreeJoint& into = tree_[static_cast<std::size_t>(joint_into_[b])];
    if (into.joint->type != JointType::Prismatic) return false;
    b = static_cast<std::size_t>(into.parent);
  }
  return true;
}

ArticulatedInertia Articulation::inertia(const Joint& joint) const {
  const auto i = asset_->index_of(joint);
  if (i && *i < tree_of_joint_.size() && tree_of_joint_[*i] >= 0)
    return results_[static_cast<std::size_t>(tree_of_joint_[*i])];
  ArticulatedInertia none;
  none.reason = "the joint is not part of the articulation's tree";
  return none;
}

ArticulatedInertia Articulation::coupled_inertia(const std::vector<std::pair<const Joint*, double>>& rates) const {
  std::unordered_map<const Joint*, double> rate_of;
  for (const auto& [joint, rate] : rates) {
    const auto i = asset_->index_of(*joint);
    if (!i || *i >= tree_of_joint_.size() || tree_of_joint_[*i] < 0) {
      ArticulatedInertia none;
      none.reason = "the joint is not part of the articulation's tree";
      return none;
    }
    rate_of[joint] = rate;
  }
  std::vector<Vector6> velocity(bodies_.size(), Vector6::Zero());
  double energy = 0;  // twice the kinetic energy: Σ vᵀ·I·v over the bodies + Σ armature·rate²
  for (const TreeJoint& j : tree_) {
    auto it = rate_of.find(j.joint);
    const double rate = it == rate_of.end() ? 0.0 : it->second;
    velocity[static_cast<std::size_t>(j.child)] =
        motion_transform(j.child_in_parent) * velocity[static_cast<std::size_t>(j.parent)] + j.motion * rate;
    energy += j.armature * rate * rate;
  }
  // Only the bodies the motion moves need their mass: one elsewhere in the tree without it
  // changes nothing here.
  ArticulatedInertia result;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const Body& body = bodies_[b];
    if (body.world || velocity[b].isZero(0.0)) continue;
    if (body.massless) continue;  // MuJoCo allows one inside a chain: it adds nothing
    if (!body.mass_known) {
      result.unknown_links.insert(result.unknown_links.end(), body.unknown_links.begin(), body.unknown_links.end());
      continue;
    }
    energy += velocity[b].dot(spatial_inertia(body.mass, body.com, body.inertia) * velocity[b]);
  }
  if (!result.unknown_links.empty()) return result;
  if (!(energy > 0)) {
    result.reason = "the coupled joints move no mass";
    return result;
  }
  result.known = true;
  result.value = energy;
  result.response = 1.0 / energy;
  return result;
}

std::optional<double> Articulation::inertia_about_axis(const Body& body, const Joint& joint, int which) const {
  if (!body.mass_known || body.world) return std::nullopt;
  if (joint.type == JointType::Prismatic) return body.mass;
  const std::string& link = which == 0 ? joint.parent.text : joint.child.text;
  Eigen::Isometry3d frame = joint.frame_in_link[static_cast<std::size_t>(which)];
  for (std::size_t i = 0; i < body.links.size(); ++i)
    if (body.links[i]->name.text == link) frame = body.link_in_body[i] * frame;
  const Eigen::Vector3d direction = (frame.linear() * joint.axis).normalized();
  const Eigen::Vector3d offset = body.com - frame.translation();
  const Eigen::Vector3d across = offset - offset.dot(direction) * direction;
  return direction.dot(body.inertia * direction) + body.mass * across.squaredNorm();
}

namespace {
thread_local SharedArticulationScope* open_scope = nullptr;
}  // namespace

SharedArticulationScope::SharedArticulationScope(const Asset& asset) : asset_(asset), enclosing_(open_scope) {
  open_scope = this;
}

SharedArticulationScope::~SharedArticulationScope() { open_scope = enclosing_; }

std::shared_ptr<const Articulation> shared_articulation(const Asset& asset) {
  SharedArticulationScope* scope = open_scope;
  if (scope == nullptr || &scope->asset_ != &asset) return std::make_shared<const Articulation>(asset);
  if (!scope->articulation_) scope->articulation_ = std::make_shared<const Articulation>(asset);
  return scope->articulation_;
}

}  // namespace assetlint::physics
