#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "config/project_root.h"
#include "engine/collision.h"
#include "formats/mjcf/mjcf_contact_filter.h"
#include "formats/urdf/srdf.h"
#include "model/poses.h"
#include "rules/all_rules.h"
#include "rules/collider_points.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

constexpr std::size_t kWorld = static_cast<std::size_t>(-1);
constexpr std::size_t kNoParent = static_cast<std::size_t>(-2);

// How the links move together: links joined by fixed joints form one rigid body (MuJoCo's URDF
// import fuses them, MuJoCo welds an MJCF body without joints to its parent, Isaac Sim's
// importer merges them with merge_fixed_joints); `body[i]` is the body of link i, kWorld for a
// link welded to the world (MJCF: a body with no joint up to the world).
struct Bodies {
  std::vector<std::size_t> body;
  // By body: the body of the link its moving joint hangs from (kWorld: one welded to the world);
  // kNoParent for a body hanging from the world itself.
  std::vector<std::size_t> parent;

  // Whether a moving joint joins the two bodies.
  bool joined(std::size_t a, std::size_t b) const {
    return (a != kWorld && parent[a] == b) || (b != kWorld && parent[b] == a);
  }
};

Bodies rigid_bodies(const Asset& asset) {
  const std::size_t n = asset.links.size();
  std::vector<std::size_t> up(n);
  std::iota(up.begin(), up.end(), 0);
  std::vector<bool> welded_to_world(n, false);
  const auto find = [&](std::size_t i) {
    while (up[i] != i) i = up[i] = up[up[i]];
    return i;
  };
  for (const Joint& joint : asset.joints) {
    if (joint.type != JointType::Fixed) continue;
    const Link* parent = asset.side_link(joint, 0);
    const Link* child = asset.side_link(joint, 1);
    if (!child) continue;
    const std::size_t c = find(*asset.index_of(*child));
    if (!parent) {
      if (joint.parent.text.empty()) welded_to_world[c] = true;
      continue;
    }
    const std::size_t p = find(*asset.index_of(*parent));
    if (p == c) continue;
    up[c] = p;
    welded_to_world[p] = welded_to_world[p] || welded_to_world[c];
  }
  Bodies out{std::vector<std::size_t>(n), std::vector<std::size_t>(n, kNoParent)};
  for (std::size_t i = 0; i < n; ++i) out.body[i] = welded_to_world[find(i)] ? kWorld : find(i);
  for (const Joint& joint : asset.joints) {
    if (joint.type == JointType::Fixed) continue;
    const Link* parent = asset.side_link(joint, 0);
    const Link* child = asset.side_link(joint, 1);
    if (!child || !parent) continue;
    const std::size_t c = out.body[*asset.index_of(*child)];
    if (c != kWorld) out.parent[c] = out.body[*asset.index_of(*parent)];
  }
  return out;
}

// Links that a joint at 0 would place outside its range (Kinova's Jaco folds into itself at
// 0; a gripper's finger whose range starts at 21 mm): the joint cannot be there, PhysX clamps it
// into range and a user starts from a keyframe, so the zero pose says nothing about their shapes.
std::vector<bool> off_range(const Asset& asset) {
  std::vector<bool> off(asset.links.size(), false);
  std::multimap<std::string_view, const Joint*> by_parent;
  for (const Joint& joint : asset.joints) by_parent.emplace(joint.parent.text, &joint);
  std::vector<std::string_view> queue;
  for (const Joint& joint : asset.joints)
    if (joint.lower && joint.upper && joint.type != JointType::Fixed &&
        (joint.lower->value > 0 || joint.upper->value < 0))
      queue.push_back(joint.child.text);
  while (!queue.empty()) {
    const std::string_view name = queue.back();
    queue.pop_back();
    const Link* link = asset.find_link(name);
    if (!link || off[*asset.index_of(*link)]) continue;
    off[*asset.index_of(*link)] = true;
    auto [begin, end] = by_parent.equal_range(name);
    for (auto it = begin; it != end; ++it) queue.push_back(it->second->child.text);
  }
  return off;
}

std::string shape_label(const CollisionShape& shape) {
  switch (shape.kind) {
    case CollisionShape::Kind::Box: return "box";
    case CollisionShape::Kind::Cylinder: return "cylinder";
    case CollisionShape::Kind::Sphere: return "sphere";
    case CollisionShape::Kind::Capsule: return "capsule";
    case CollisionShape::Kind::Mesh:
      return fmt::format("mesh '{}'", std::filesystem::path(shape.mesh).filename().string());
  }
  return "shape";
}

std::string millimetres(double metres) { return format_number(metres * 1000, 3) + " mm"; }

struct Placed {
  std::size_t link;
  const CollisionShape* shape;
};

// The consumer's filters of one file, read when the engine first finds an overlap.
struct Filters {
  std::optional<urdf::Srdf> srdf;                  // URDF: MoveIt's SRDF beside the file
  std::optional<mjcf::ContactFilter> mjcf;         // MJCF: contype/conaffinity, exclude, flags
};

class SelfCollision final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    // USD is left out: PhysX's FilteredPairsAPI and collision groups, which decide its pairs,
    // are not read yet, and a pair they filter would be reported.
    if (asset.format != SourceFormat::Urdf && asset.format != SourceFormat::Mjcf) return;
    if (asset.links.size() < 2) return;
    const collision::Engine* engine = collision::installed_engine();
    if (!engine) return;
    const double tolerance = rule_option(info_, settings, "tolerance");

    const auto poses = link_poses(asset);
    const Bodies bodies = rigid_bodies(asset);
    const std::vector<bool> unreachable = off_range(asset);
    ColliderPoints meshes(asset, settings);
    std::vector<collision::PlacedShape> all_shapes;
    std::vector<Placed> all_placed;
    std::vector<Eigen::AlignedBox3d> boxes;  // in the world
    for (std::size_t i = 0; i < asset.links.size(); ++i) {
      const auto pose = poses.find(asset.links[i].name.text);
      if (pose == poses.end() || unreachable[i]) continue;
      for (const CollisionShape& shape : asset.links[i].collisions) {
        collision::PlacedShape s{bodies.body[i], shape.kind, pose->second * shape.pose, shape.size, nullptr};
        if (shape.kind == CollisionShape::Kind::Mesh && !(s.points = meshes.of(shape))) continue;
        const auto box = meshes.box_in_link(shape);
        if (!box) continue;
        Eigen::AlignedBox3d world;
        for (int c = 0; c < 8; ++c) world.extend(pose->second * box->corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
        all_shapes.push_back(std::move(s));
        all_placed.push_back({i, &shape});
        boxes.push_back(world);
      }
    }
    // Only shapes whose boxes reach into a shape of another body that no joint joins go to the
    // engine: building hulls is what costs, and most shapes of a robot at rest touch only their
    // neighbours.
    std::vector<bool> candidate(all_shapes.size(), false);
    for (std::size_t a = 0; a < all_shapes.size(); ++a)
      for (std::size_t b = a + 1; b < all_shapes.size(); ++b) {
        const std::size_t body_a = all_shapes[a].body, body_b = all_shapes[b].body;
        if (body_a == body_b || (asset.format == SourceFormat::Urdf && bodies.joined(body_a, body_b))) continue;
        const Eigen::AlignedBox3d common = boxes[a].intersection(boxes[b]);
        if (common.isEmpty() || !(common.sizes().minCoeff() > tolerance)) continue;
        candidate[a] = candidate[b] = true;
      }
    std::vector<collision::PlacedShape> shapes;
    std::vector<Placed> placed;
    for (std::size_t i = 0; i < all_shapes.size(); ++i)
      if (candidate[i]) {
        shapes.push_back(std::move(all_shapes[i]));
        placed.push_back(all_placed[i]);
      }
    std::string error;
    const auto found = engine->overlaps(shapes, error);
    if (!found) return;

    std::optional<Filters> filters;
    // The deepest overlap of each pair of rigid bodies that nothing filters, one finding each.
    std::map<std::pair<std::size_t, std::size_t>, collision::Overlap> pairs;
    for (const collision::Overlap& o : found->overlaps) {
      if (o.depth <= tolerance) continue;
      if (!filters) filters = read_filters(asset, settings);
      if (filtered(asset, bodies, *filters, placed[o.shape_a], placed[o.shape_b])) continue;
      const std::size_t a = placed[o.shape_a].link, b = placed[o.shape_b].link;
      const auto key = std::minmax(bodies.body[a], bodies.body[b]);
      auto [it, added] = pairs.emplace(key, o);
      if (!added && o.depth > it->second.depth) it->second = o;
    }
    for (const auto& [key, overlap] : pairs)
      report(asset, engine->name(), bodies, overlap, placed, *filters, meshes.unread(), out);
  }

 private:
  static Filters read_filters(const Asset& asset, const Settings& settings) {
    Filters filters;
    const std::string path = asset.source(0).path();
    const ConfinedFileSystem files(disk(), config::read_policy(path, settings));
    if (asset.format == SourceFormat::Urdf)
      filters.srdf = urdf::srdf_beside(std::filesystem::path(path).parent_path().string(), asset.robot_name.text, files);
    else
      filters.mjcf = mjcf::read_contact_filter(
          asset.sources[0], files,
          mjcf::ReadOptions{config::checked_root(path, settings), settings.allow_outside_root, settings.mujoco.parsed()});
    return filters;
  }

  // Whether the consumer the format is written for leaves the two shapes' contact out.
  static bool filtered(const Asset& asset, const Bodies& bodies, const Filters& filters, const Placed& a,
                       const Placed& b) {
    const std::size_t body_a = bodies.body[a.link], body_b = bodies.body[b.link];
    const std::string& name_a = asset.links[a.link].name.text;
    const std::string& name_b = asset.links[b.link].name.text;
    if (asset.format == SourceFormat::Urdf) {
      // PhysX filters the two links of every articulation joint, MoveIt's setup assistant marks
      // them "Adjacent"; MuJoCo's URDF import filters them too unless the parent is welded to the world.
      if (bodies.joined(body_a, body_b)) return true;
      return filters.srdf && filters.srdf->find(name_a, name_b);
    }
    const mjcf::ContactFilter& mjcf = *filters.mjcf;
    if (!mjcf.contacts) return true;
    // mj_collision's parent filter pairs a body with its parent only when neither is welded to the world.
    if (mjcf.filter_parent && body_a != kWorld && body_b != kWorld && bodies.joined(body_a, body_b)) return true;
    const auto bits_a = mjcf.bits_of(a.shape->span), bits_b = mjcf.bits_of(b.shape->span);
    if ((bits_a[0] & bits_b[1]) == 0 && (bits_b[0] & bits_a[1]) == 0) return true;
    return mjcf.find_excluded(name_a, name_b) != nullptr;
  }

  static void report(const Asset& asset, const std::string& engine, const Bodies& bodies,
                     const collision::Overlap& overlap, const std::vector<Placed>& placed, const Filters& filters,
                     const std::map<std::string, std::string>& unread, Reporter& out) {
    Placed first = placed[overlap.shape_a], second = placed[overlap.shape_b];
    if (first.link > second.link) std::swap(first, second);
    const Link& a = asset.links[first.link];
    const Link& b = asset.links[second.link];
    const CollisionShape& shape_a = *first.shape;
    const CollisionShape& shape_b = *second.shape;
    Diagnostic& d = out.report(shape_b.span.valid() ? shape_b.span : b.span,
                               fmt::format("links '{}' and '{}' overlap by {} at the default pose", a.name.text,
                                           b.name.text, millimetres(overlap.depth)));
    d.note(shape_a.span.valid() ? shape_a.span : a.span,
           fmt::format("{} finds {}'s {} and {}'s {} {} deep at ({}, {}, {}) m, every joint at 0 (the pose the "
                       "simulation starts in).",
                       engine, a.name.text, shape_label(shape_a), b.name.text, shape_label(shape_b),
                       millimetres(overlap.depth), format_number(overlap.point.x(), 4),
                       format_number(overlap.point.y(), 4), format_number(overlap.point.z(), 4)));
    if (asset.format == SourceFormat::Urdf) {
      d.note("No joint joins the two links (links welded by fixed joints count as one body, as MuJoCo's URDF import "
             "fuses them). MuJoCo collides every such pair of a URDF (each geom gets contype and conaffinity 1), and "
             "PhysX does once the articulation's self-collision is on: the solver pushes them apart from the first "
             "step, which kicks or jitters the robot at rest.");
      d.note(fmt::format("If the parts are meant to touch, filter the pair where the robot is simulated (MoveIt: "
                         "<disable_collisions link1=\"{0}\" link2=\"{1}\" reason=\"Never\"/> in an SRDF beside the "
                         "file; MuJoCo: <contact><exclude body1=\"{0}\" body2=\"{1}\"/>; PhysX: "
                         "UsdPhysicsFilteredPairsAPI); otherwise shrink or move a collision shape.",
                         a.name.text, b.name.text));
      if (filters.srdf) d.note(fmt::format("{} does not disable this pair.", filters.srdf->path));
    } else {
      const std::size_t body_a = bodies.body[first.link], body_b = bodies.body[second.link];
      const bool parent_pair = bodies.joined(body_a, body_b);
      if (parent_pair && filters.mjcf->filter_parent)
        d.note("A joint joins the two bodies, but MuJoCo's parent filter does not apply: one of them is welded to "
               "the world (no joint up to it), and mj_collision filters a parent and child only when both move.");
      else if (parent_pair)
        d.note(filters.mjcf->flag_span, "A joint joins the two bodies, but <flag filterparent=\"disable\"/> turns "
                                        "MuJoCo's parent filter off.");
      else
        d.note("No joint joins the two bodies, their geoms' contype and conaffinity meet, and no <contact><exclude> "
               "names the pair: MuJoCo's solver pushes them apart from the first step.");
      d.note(fmt::format("If the parts are meant to touch, add <contact><exclude body1=\"{}\" body2=\"{}\"/></contact>"
                         " (or give the geoms contype/conaffinity bits that do not meet); otherwise shrink or move a "
                         "geom.",
                         a.name.text, b.name.text));
    }
    if (!unread.empty())
      d.note(fmt::format("{} mesh file{} could not be read and {} left out, first '{}': {}.", unread.size(),
                         unread.size() == 1 ? "" : "s", unread.size() == 1 ? "is" : "are", unread.begin()->first,
                         unread.begin()->second));
  }

  RuleInfo info_{"self-collision",
                 "Collision shapes of two links the consumer does not filter overlap at the default pose",
                 // An info until its precision on real packages is known: a hand's safety box or a
                 // walker attached by its user with a free joint overlap by design.
                 Severity::Info,
                 false,
                 RuleOrigin::Check,
                 {{"tolerance", 0.001,
                   "Depth (m) up to which an overlap counts as touching (mesh hulls of parts that meet at a seam)"}}};
};

}  // namespace

const Rule& self_collision() {
  static const SelfCollision rule;
  return rule;
}

}  // namespace assetlint::rules
