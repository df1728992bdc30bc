#include <fmt/format.h>

#include <algorithm>
#include <unordered_map>

#include "model/topology.h"
#include "physics/articulation.h"
#include "physics/inertia.h"
#include "physics/mujoco_inertia.h"
#include "rules/all_rules.h"
#include "rules/support.h"
#include "util/numbers.h"

namespace assetlint::rules {
namespace {

constexpr double kPointMassGyration = 1e-6;  // m

std::string moments_text(const Eigen::Vector3d& m) {
  return fmt::format("[{}, {}, {}] kg·m²", format_number(m[0], 4), format_number(m[1], 4), format_number(m[2], 4));
}

// Where a link sits in the simulated model decides how much a bad tensor matters.
enum class Role {
  BodyStart,  // the child of a movable joint: its tensor is the body's own
  Welded,     // welded by fixed joints to a body or to the root: merged into that body
  Root,       // a link no joint moves and no joint welds to anything (the base)
};

struct Placement {
  Role role = Role::Root;
  const Joint* joint = nullptr;  // BodyStart: the movable joint; Welded: the fixed joint
  bool moves = false;            // part of a body moved by a joint (not welded to the root)
  bool welded_inertia = false;   // BodyStart: a link welded to it carries a non-zero tensor
};

// Per link (by position in asset.links): where it sits; a link no joint has as its child is a root.
std::vector<Placement> placements(const Asset& asset, const std::vector<RigidBody>& bodies) {
  std::vector<Placement> out(asset.links.size());
  const auto at = [&](const Link* link) -> Placement& { return out[*asset.index_of(*link)]; };
  for (const Joint& joint : asset.joints)
    if (const Link* child = asset.side_link(joint, 1))
      at(child) = {joint.type == JointType::Fixed ? Role::Welded : Role::BodyStart, &joint};
  for (const RigidBody& body : bodies) {
    if (body.links.empty()) continue;
    Placement& start = at(body.links.front()) = {Role::BodyStart, body.joint, true};
    for (const Link* link : body.links) {
      at(link).moves = true;
      if (link != body.links.front() && link->inertial && link->inertial->inertia_authored &&
          !link->inertial->inertia.isZero(0.0))
        start.welded_inertia = true;
    }
  }
  return out;
}

class InertiaInvalid final : public Rule {
 public:
  const RuleInfo& info() const override { return info_; }

  void check(const Asset& asset, const Settings& settings, Reporter& out) const override {
    const bool urdf = asset.format == SourceFormat::Urdf;
    const std::vector<RigidBody> bodies = moving_bodies(asset);
    if (urdf && !bodies.empty() && kinematic_description(asset)) {
      report_kinematic_description(asset, bodies, out);
      return;
    }
    if (urdf) check_bodies(asset, bodies, out);
    const auto where = placements(asset, bodies);
    const auto articulation = physics::shared_articulation(asset);
    const std::optional<physics::MujocoInertiaInput> mujoco = mujoco_input(asset);
    for (std::size_t i = 0; i < asset.links.size(); ++i)
      if (!from_geometry(asset.links[i]))
        check_link(asset.links[i], where[i], *articulation, mujoco, settings, out);
    const auto equal = report_mass_equals_inertia(asset, out);
    report_gyration(asset, where, equal, settings, out);
  }

 private:
  // Moments this small for the mass (a radius of gyration under a micrometre, entries of 1e-20
  // on a kilogram link) are a zero tensor written with rounding noise, not a shape.
  static bool point_mass(const Inertial& inertial) {
    const Eigen::Vector3d moments = physics::principal_moments(inertial.inertia);
    const double scale = std::max(std::abs(moments[0]), std::abs(moments[2]));
    return inertial.mass.value > 0 && scale <= inertial.mass.value * kPointMassGyration * kPointMassGyration;
  }

  // How far rounding the six entries to the digits they are written with can move I₃ − (I₁ + I₂):
  // a thin plate's izz = ixx + iyy written as 0.001437, 0.001437, 0.002875 breaks the triangle
  // inequality by 1e-6, half a unit in the last digit of each. Values the reader converted
  // (other units) show no short form and allow next to nothing.
  static double written_rounding(const Eigen::Matrix3d& inertia) {
    double slack = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j)
        // Off-diagonal entries move the principal moments too, twice as much at most.
        slack += (i == j ? 1.0 : 2.0) * half_unit_in_last_digit(inertia(i, j));
    return slack;
  }

  // How MuJoCo's compiler receives the file's tensors: a URDF's <inertia> is a full tensor (its
  // importer reads the file's <mujoco><compiler> section); an MJCF's values are those the reader
  // already bounded and balanced as the compiler does, whose eigenvalue check it cannot repeat
  // (it does not keep whether a tensor was written full or diagonal). USD: MuJoCo does not read it.
  static std::optional<physics::MujocoInertiaInput> mujoco_input(const Asset& asset) {
    if (asset.format == SourceFormat::Urdf) {
      physics::MujocoInertiaInput input;
      input.boundinertia = asset.urdf_mujoco_compiler.boundinertia;
      input.balanceinertia = asset.urdf_mujoco_compiler.balanceinertia;
      return input;
    }
    if (asset.format == SourceFormat::Mjcf) return physics::MujocoInertiaInput{physics::MujocoInertiaInput::Form::Unknown};
    return std::nullopt;
  }

  // The note on a finding whose tensor MuJoCo's compiler refuses: the file does not load there.
  static void refusal_note(Diagnostic& d, const std::string& refusal, const Placement& placement, bool urdf) {
    d.note(fmt::format("MuJoCo's compiler refuses the file at this link: \"{}\" (mjCBody::Compile){}.", refusal,
                       urdf && placement.role == Role::Welded
                           ? "; its URDF import fuses links welded by fixed joints (fusestatic) only after "
                             "checking each link's own tensor"
                           : ""));
  }

  // Mass properties MuJoCo computes from a body's geoms describe that geometry exactly: nothing
  // typed by hand to judge.
  static bool from_geometry(const Link& link) { return link.inertial && link.inertial->from_geoms; }

  // Mass and every principal moment typed as the same number (Drake's Atlas Robotiq 3F:
  // 1e-5 kg and 1e-5 kg·m² on 21 four-bar links): a placeholder, one info per file. Its
  // radius of gyration √(I/m) = 1 m is far larger than any finger link. 1 kg with 1 kg·m² is the
  // unit default of test scenes and exporters.
  static std::vector<const Link*> report_mass_equals_inertia(const Asset& asset, Reporter& out) {
    std::vector<const Link*> found;
    for (const Link& link : asset.links) {
      if (!link.inertial || !link.inertial->mass_authored || !link.inertial->inertia_authored) continue;
      const Inertial& in = *link.inertial;
      const double m = in.mass.value;
      if (m <= 0 || m > 1.0) continue;
      if (in.inertia(0, 0) == m && in.inertia(1, 1) == m && in.inertia(2, 2) == m) found.push_back(&link);
    }
    if (found.empty()) return found;
    const Inertial& first = *found.front()->inertial;
    Diagnostic& d = out.report(first.inertia_span, Severity::Info,
                               found.size() == 1
                                   ? fmt::format("link '{}' has mass {} kg and inertia {} kg·m²: placeholder values",
                                                 found.front()->name.text, format_number(first.mass.value),
                                                 format_number(first.mass.value))
                                   : fmt::format("{} links have a mass equal to each moment of inertia (first: {}): "
                                                 "placeholder values",
                                                 found.size(), format_number(first.mass.value)));
    d.note(fmt::format("The radius of gyration √(I/m) is then 1 m whatever the mass, far larger than the link; every "
                       "natural-frequency estimate √(k/I) that uses it is wrong."));
    if (found.size() > 1) {
      std::string names;
      for (std::size_t i = 0; i < found.size() && i < 5; ++i) names += fmt::format("{}'{}'", i ? ", " : "", found[i]->name.text);
      d.note(fmt::format("They include {}{}.", names, found.size() > 5 ? fmt::format(" and {} more", found.size() - 5) : ""));
    }
    d.note("Take mass and inertia from CAD, or leave the links out of tuning until they are measured.");
    return found;
  }

  struct FoundGyration {
    const Link* link;
    physics::Gyration g;
    double excess;  // how far outside its bound, as a factor
    double share;   // the tensor's moment over what the link's joint turns (Mᵢᵢ); 1 when unknown
    double moved;   // that Mᵢᵢ, kg·m² (0 when unknown)
  };

  // What a revolute joint turns (Mᵢᵢ, everything distal to it about its axis), kg·m²; 0 when
  // that is unknown or the joint slides.
  static double moved_by_joint(const Placement& placement, const physics::Articulation& articulation) {
    if (!placement.joint || !is_angular(placement.joint->type)) return 0.0;
    const physics::ArticulatedInertia moved = articulation.joint_space_inertia(*placement.joint);
    return moved.known && moved.value > 0 ? moved.value : 0.0;
  }

  // A tensor too large (or too small) for the link that carries it: 0.02 kg fingers with
  // 0.01 kg·m² (Rethink's electric gripper), every Minitaur link. One warning per file at the
  // worst link; the others are notes. Only a body's own link is judged: a welded frame's tensor
  // is merged into a heavier body. Placeholders already reported above are not repeated. A
  // too-large moment that is a sliver of what its joint turns (the 0.1 g bodies between the
  // coincident hinges of a converted OpenSim hip) changes no drive: one info, not a warning.
  void report_gyration(const Asset& asset, const std::vector<Placement>& where, const std::vector<const Link*>& already,
                       const Settings& settings, Reporter& out) const {
    std::vector<FoundGyration> found, harmless;
    const auto articulation = physics::shared_articulation(asset);
    const double scale = physics::gyration_scale(asset);
    const double harmless_share = rule_option(info_, settings, "harmless_share");
    std::vector<bool> reported(asset.links.size(), false);
    for (const Link* link : already)
      if (const auto i = asset.index_of(*link)) reported[*i] = true;
    for (std::size_t i = 0; i < asset.links.size(); ++i) {
      const Link& link = asset.links[i];
      if (where[i].role != Role::BodyStart || !link.inertial || from_geometry(link)) continue;
      // A zero tensor is reported as a point mass (check_link), not a second time as a radius.
      if (physics::pasted_tensor(link.inertial->inertia) || reported[i] || point_mass(*link.inertial))
        continue;
      const auto g = physics::judge_gyration(*link.inertial, physics::joint_frames_on(asset, link),
                                             articulation->sole_rotation_axis(link), scale,
                                             physics::collision_reach(link, link.inertial->com));
      if (!g || g->verdict == physics::Gyration::Verdict::Plausible) continue;
      const bool large = g->verdict == physics::Gyration::Verdict::TooLarge;
      const double moved = large ? moved_by_joint(where[i], *articulation) : 0.0;
      const double share = moved > 0 ? std::min(1.0, g->largest * g->largest * link.inertial->mass.value / moved) : 1.0;
      (share < harmless_share ? harmless : found)
          .push_back({&link, *g, large ? g->largest / g->bound : physics::kGyrationMinRadius / g->largest, share, moved});
    }
    const auto by_excess = [](const FoundGyration& a, const FoundGyration& b) { return a.excess > b.excess; };
    std::stable_sort(found.begin(), found.end(), by_excess);
    std::stable_sort(harmless.begin(), harmless.end(), by_excess);
    if (!found.empty()) {
      Diagnostic& d = report_gyration_list(found, Severity::Warning, out);
      if (!harmless.empty())
        d.note(harmless.front().link->inertial->inertia_span,
               fmt::format("{} more link{} ('{}' first) {} outside the bound by a moment under {} % of what {} joint "
                           "turns: harmless.",
                           harmless.size(), harmless.size() == 1 ? "" : "s", harmless.front().link->name.text,
                           harmless.size() == 1 ? "is" : "are", format_number(harmless_share * 100),
                           harmless.size() == 1 ? "its" : "each"));
      d.note("Take mass and inertia from CAD (or compute them from the link's geometry).");
    } else if (!harmless.empty()) {
      const FoundGyration& worst = harmless.front();
      const Joint& joint = *where[*asset.index_of(*worst.link)].joint;
      Diagnostic& d = report_gyration_list(harmless, Severity::Info, out);
      d.note(joint.name.span,
             fmt::format("Harmless: its {} kg·m² is {} % of Mᵢᵢ = {} kg·m², all that {} turns (under harmless_share, {} "
                         "%): the drives see almost none of it.",
                         format_number(worst.g.largest * worst.g.largest * worst.link->inertial->mass.value, 4),
                         format_number(worst.share * 100, 2), format_number(worst.moved, 4), joint_label(joint),
                         format_number(harmless_share * 100)));
    }
  }

  static Diagnostic& report_gyration_list(const std::vector<FoundGyration>& found, Severity severity, Reporter& out) {
    const FoundGyration& worst = found.front();
    const Inertial& in = *worst.link->inertial;
    const bool large = worst.g.verdict == physics::Gyration::Verdict::TooLarge;
    const std::string more =
        found.size() > 1 ? fmt::format(" (and {} more link{})", found.size() - 1, found.size() == 2 ? "" : "s") : "";
    Diagnostic& d = out.report(
        in.inertia_span, severity,
        fmt::format("link '{}': radius of gyration {} m is {} than the link could be{}", short_path(worst.link->name.text),
                    format_number(worst.g.largest, 3), large ? "larger" : "smaller", more));
    d.note(fmt::format("√(I/m) = √({} kg·m² / {} kg) = {} m{}, {} {}.",
                       format_number(worst.g.largest * worst.g.largest * in.mass.value, 4),
                       format_number(in.mass.value, 4), format_number(worst.g.largest, 3),
                       worst.g.about_axis ? " about the one axis the link turns about" : "",
                       large ? "above" : "under", worst.g.bound_text()));
    if (large)
      d.note("All of a body's mass lies within its extent R of the COM, so √(I/m) ≤ R: this tensor (or this mass) "
             "is not the part's, often a template's 0.01 or 0.001 kg·m² left on a light link.");
    else
      d.note("A link this heavy with so small a tensor is a point mass typed in: its rotation reacts to torques as if "
             "it weighed nothing.");
    if (large && worst.g.floor_only && worst.g.box_density > 0)
      d.note(fmt::format("Its joint frames give no size, but read as a uniform box the tensor spreads {} kg at {} "
                         "kg/m³, lighter than any solid part ({} kg/m³, rigid foam).",
                         format_number(in.mass.value, 4), format_number(worst.g.box_density, 2),
                         format_number(physics::kGyrationMinSolidDensity)));
    if (severity != Severity::Info)
      d.note("Natural frequencies √(k/I) and damping ratios computed on it are wrong; the drive rules offer no fix from it.");
    for (std::size_t i = 1; i < found.size() && i <= 5; ++i)
      d.note(found[i].link->inertial->inertia_span,
             fmt::format("Also '{}': √(I/m) = {} m, bound {} m.", found[i].link->name.text,
                         format_number(found[i].g.largest, 3),
                         format_number(found[i].g.verdict == physics::Gyration::Verdict::TooLarge ? found[i].g.bound
                                                                                                   : physics::kGyrationMinRadius,
                                       3)));
    if (found.size() > 6) d.note(fmt::format("And {} more links like these.", found.size() - 6));
    return d;
  }

  // No link has an <inertial>: a description for RViz and MoveIt, not for simulation. One
  // finding for the file says so; an error per link would say the same thing many times.
  static bool kinematic_description(const Asset& asset) {
    return std::none_of(asset.links.begin(), asset.links.end(), [](const Link& link) { return link.inertial.has_value(); });
  }

  static void report_kinematic_description(const Asset& asset, const std::vector<RigidBody>& bodies, Reporter& out) {
    const Span at = asset.robot_name.span.valid() ? asset.robot_name.span : asset.robot_span;
    out.report(at, Severity::Warning,
               fmt::format("no link of '{}' has an <inertial>: a kinematic description, not a simulation model",
                           asset.robot_name.text))
        .note(fmt::format("{} bodies move ({} first), and none carries mass or inertia.", bodies.size(),
                          joint_label(*bodies.front().joint)))
        .note("Planning and visualisation (RViz, MoveIt) need none, but a simulator must invent them: Isaac Sim's "
              "importer and PhysX compute them from the collision shapes at a default density, Gazebo drops "
              "links without mass, MuJoCo infers them from geoms. The dynamics then belong to the importer, not "
              "to the robot.")
        .note("For simulation, add each link's <inertial> from CAD or the manufacturer's data.");
  }

  // Bodies with mass below them, and, per body, the body its joint's parent link belongs to.
  struct BodyTree {
    std::vector<int> parent;           // -1: hangs from the fixed base
    std::vector<bool> massive_below;   // a body further out carries mass
  };

  static double body_mass(const RigidBody& body) {
    double mass = 0.0;
    for (const Link* link : body.links)
      if (link->inertial && link->inertial->mass_authored && link->inertial->mass.value > 0)
        mass += link->inertial->mass.value;
    return mass;
  }

  static BodyTree body_tree(const Asset& asset, const std::vector<RigidBody>& bodies) {
    std::vector<int> body_of_link(asset.links.size(), -1);
    for (std::size_t b = 0; b < bodies.size(); ++b)
      for (const Link* link : bodies[b].links)
        if (const auto i = asset.index_of(*link)) body_of_link[*i] = static_cast<int>(b);
    BodyTree tree{std::vector<int>(bodies.size(), -1), std::vector<bool>(bodies.size(), false)};
    for (std::size_t b = 0; b < bodies.size(); ++b)
      if (const Link* parent = asset.side_link(*bodies[b].joint, 0))
        if (const auto i = asset.index_of(*parent)) tree.parent[b] = body_of_link[*i];
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (body_mass(bodies[b]) <= 0) continue;
      // Bounded by the body count: a cyclic file must not loop here.
      std::size_t steps = 0;
      for (int up = tree.parent[b]; up >= 0 && !tree.massive_below[up] && steps < bodies.size(); up = tree.parent[up], ++steps)
        tree.massive_below[up] = true;
    }
    return tree;
  }

  // A massless body between the fixed base and the first massive body, with only massless
  // bodies above it: the x/y/z/roll/pitch/yaw joints of a virtual floating base. The
  // simulator sees the chain as one floating body carried by the first link with mass.
  static bool virtual_base_body(const Asset& asset, const BodyTree& tree, const std::vector<RigidBody>& bodies,
                                std::size_t b) {
    if (!tree.massive_below[b]) return false;
    std::size_t top = b, steps = 0;
    for (int up = tree.parent[b]; up >= 0; up = tree.parent[up]) {
      if (body_mass(bodies[up]) > 0 || ++steps > bodies.size()) return false;
      top = static_cast<std::size_t>(up);
    }
    // The chain must hang from a massless base (the world frame), not from a robot's base link.
    const Link* base = asset.side_link(*bodies[top].joint, 0);
    return base && !(base->inertial && base->inertial->mass_authored && base->inertial->mass.value > 0);
  }

  // What a body's links carry that the simulators see: collision shapes (which PhysX and MuJoCo
  // weigh when no mass is written) and visual ones (which neither weighs).
  struct Shapes {
    bool collision = false;
    bool visual = false;
    bool any() const { return collision || visual; }
  };
  static Shapes shapes_of(const RigidBody& body) {
    Shapes shapes;
    for (const Link* link : body.links) {
      shapes.collision = shapes.collision || !link->collisions.empty();
      shapes.visual = shapes.visual || link->visual;
    }
    return shapes;
  }

  // MuJoCo's compiler rejects a moving body without mass (mjCModel::TryCompile), unless a link
  // welded to it brings some; its URDF import weighs collision geoms only.
  static void massless_refusal_note(Diagnostic& d) {
    d.note("MuJoCo refuses the file: its compiler rejects a moving body without mass (\"mass and inertia of moving "
           "bodies must be larger than mjMINVAL\"), and its URDF import gives visual geoms no mass.");
  }

  // What each simulator makes of a moving body without <inertial>, by the shapes it carries.
  static void consumers_note(Diagnostic& d, const Shapes& shapes, bool virtual_base) {
    if (shapes.collision) {
      d.note("PhysX (Isaac Sim's URDF importer) computes its mass and inertia from its collision shapes at the default "
             "density of 1000 kg/m³, and MuJoCo's compiler from its collision geoms at the same density (its URDF "
             "default inertiafromgeom=\"auto\" fills every link without <inertial>; visual geoms weigh nothing): a "
             "solid of water the part's shape, not the part.");
      return;
    }
    if (virtual_base)
      d.note("It is a frame of a virtual base: a massless body without shapes between the fixed base and the first link "
             "with mass, which kinematics and control libraries read as one floating body.");
    else if (shapes.visual)
      d.note("It is drawn but collides with nothing: PhysX has no collision shape to compute a mass from, so the "
             "importer invents one.");
    else
      d.note("Without one, the importer or simulator invents a mass and inertia unrelated to the part.");
    massless_refusal_note(d);
    if (virtual_base)
      d.note("For MuJoCo, give each such link a token <inertial> (1e-6 kg, 1e-9 kg·m²) or replace the chain by a "
             "floating joint.");
  }

  // A body that moves needs mass: without an inertial the importer invents one.
  static void check_bodies(const Asset& asset, const std::vector<RigidBody>& bodies, Reporter& out) {
    const BodyTree tree = body_tree(asset, bodies);
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const RigidBody& body = bodies[b];
      if (body.links.empty()) continue;  // undefined child: structure-undefined-link reports it
      // A link with a shape is a part, whatever carries the mass above it: never a virtual base.
      const Shapes shapes = shapes_of(body);
      const bool virtual_base = !shapes.any() && virtual_base_body(asset, tree, bodies, b);
      const Link& child = *body.links.front();
      const Link* first_inertial = nullptr;
      bool any_negative = false;
      double total_mass = 0.0;
      for (const Link* link : body.links) {
        if (!link->inertial) continue;
        if (!first_inertial) first_inertial = link;
        if (!link->inertial->mass_authored) continue;
        if (link->inertial->mass.value > 0) total_mass += link->inertial->mass.value;
        any_negative = any_negative || link->inertial->mass.value < 0;
      }
      if (any_negative) continue;  // reported once, as a negative mass
      if (!first_inertial) {
        Diagnostic& d = out.report(child.name.span, fmt::format("link '{}' moves but has no <inertial>", child.name.text));
        d.note(body.joint->name.span, fmt::format("It is the child of {}; no link welded to it has an <inertial> "
                                                  "either.",
                                                  joint_label(*body.joint)));
        consumers_note(d, shapes, virtual_base);
      } else if (total_mass <= 0) {
        Diagnostic& d = out.report(first_inertial->inertial->mass.span,
                                   fmt::format("link '{}' moves but its mass is {} kg", first_inertial->name.text,
                                               format_number(first_inertial->inertial->mass.value)));
        d.note(body.joint->name.span,
               fmt::format("It is part of the body moved by {}, and no link of that body has a positive mass.",
                           joint_label(*body.joint)));
        // A welded link without <inertial> but with collision shapes is weighed by MuJoCo.
        if (std::none_of(body.links.begin(), body.links.end(),
                         [](const Link* link) { return !link->inertial && !link->collisions.empty(); }))
          massless_refusal_note(d);
      }
    }
  }

  void check_link(const Link& link, const Placement& placement, const physics::Articulation& articulation,
                  const std::optional<physics::MujocoInertiaInput>& mujoco, const Settings& settings,
                  Reporter& out) const {
    if (!link.inertial || !link.inertial->mass_authored) return;
    const Inertial& inertial = *link.inertial;
    const double mass = inertial.mass.value;
    if (mass < 0) {
      out.report(inertial.mass.span, fmt::format("link '{}' has negative mass {} kg", link.name.text, format_number(mass)));
      return;
    }
    if (!inertial.inertia_authored) return;
    // Whatever a simulator that merges welded links would make of it, a tensor MuJoCo's
    // compiler refuses keeps the file from loading there: an error wherever the link sits.
    const std::optional<std::string> refusal =
        mujoco ? physics::mujoco_inertia_refusal(inertial.inertia, *mujoco) : std::nullopt;
    const bool urdf = mujoco && mujoco->form == physics::MujocoInertiaInput::Form::Full;
    const auto refused = [&](Diagnostic& d) {
      if (refusal) refusal_note(d, *refusal, placement, urdf);
    };
    const double dummy_mass = rule_option(info_, settings, "dummy_mass");
    if ((mass == 0 || (placement.role == Role::Root && mass <= dummy_mass)) && !refusal) return;  // a frame

    const Eigen::Vector3d moments = physics::principal_moments(inertial.inertia);
    const double scale = std::max(std::abs(moments[0]), std::abs(moments[2]));
    if (point_mass(inertial)) {
      // A point mass: welded to another body it only adds m·d² to that body (PhysX and the
      // URDF importers merge welded links), so only a body of its own is a problem to them.
      if (placement.role == Role::BodyStart && !placement.welded_inertia)
        report_point_mass(link, placement, articulation.translates_only(link), refusal, urdf, out);
      else if (refusal)
        report_refused(link, placement, moments, *refusal, urdf, out);
      return;
    }
    const double relative = rule_option(info_, settings, "definiteness_tolerance");
    const double triangle = rule_option(info_, settings, "triangle_tolerance");
    // Welded to the root, the link moves only when the base floats: risky, not certainly wrong.
    // A frame-light link welded to another body is merged into it: its tensor changes that
    // body's by a negligible amount, wrong or not.
    const bool negligible = placement.role == Role::Welded && mass <= dummy_mass;
    const Severity impossible = refusal                                              ? Severity::Error
                                : negligible                                         ? Severity::Info
                                : placement.role == Role::Welded && !placement.moves ? Severity::Warning
                                                                                     : Severity::Error;
    const auto merged_note = [&](Diagnostic& d) {
      if (negligible)
        d.note(fmt::format("It weighs {} kg (at most dummy_mass {} kg) and is welded by {}: merged into the body it is "
                           "welded to, it changes that body's inertia by at most {} kg·m². Wrong, but harmless{}.",
                           format_number(mass), format_number(dummy_mass), joint_label(*placement.joint),
                           format_number(scale, 3), refusal ? " to PhysX" : ""));
    };
    const double excess = moments[2] - (moments[0] + moments[1]);
    if (moments[0] < -relative * scale) {
      Diagnostic& d = out.report(inertial.inertia_span, impossible,
                                 fmt::format("inertia of link '{}' has a negative principal moment {} kg·m²",
                                             link.name.text, format_number(moments[0], 4)));
      d.note(fmt::format("Principal moments {} (mass {} kg); every moment of a real body is positive.",
                         moments_text(moments), format_number(mass)));
      d.note("The usual cause is a product of inertia with the wrong sign, or products copied from another frame.");
      merged_note(d);
      refused(d);
    } else if (moments[0] <= relative * scale) {
      report_singular(link, placement, moments, relative, refusal, urdf, out);
    } else if (moments[2] > (moments[0] + moments[1]) * (1 + triangle) && excess > written_rounding(inertial.inertia)) {
      Diagnostic& d = out.report(inertial.inertia_span, impossible,
                                 fmt::format("inertia of link '{}' violates the triangle inequality", link.name.text));
      d.note(fmt::format("Principal moments {}: {} > {} + {}.", moments_text(moments), format_number(moments[2], 4),
                         format_number(moments[0], 4), format_number(moments[1], 4)));
      d.note("No distribution of positive mass has a largest moment above the sum of the other two.");
      merged_note(d);
      refused(d);
    } else if (excess > 0 && excess <= written_rounding(inertial.inertia) && refusal) {
      // Within the written rounding: a plate or rod whose I₃ = I₁ + I₂ was rounded up. No motion
      // changes, but MuJoCo checks A + B ≥ C exactly.
      Diagnostic& d = out.report(inertial.inertia_span, Severity::Error,
                                 fmt::format("inertia of link '{}' breaks the triangle inequality by its rounding, and "
                                             "MuJoCo refuses it",
                                             link.name.text));
      d.note(fmt::format("Principal moments {}: {} exceeds {} + {} by {} kg·m², within half a unit in the last written "
                         "digit of each entry: a thin plate or rod (I₃ = I₁ + I₂) written rounded, the same body to "
                         "PhysX and to any simulator that takes the moments as they are.",
                         moments_text(moments), format_number(moments[2], 4), format_number(moments[0], 4),
                         format_number(moments[1], 4), format_number(excess, 3)));
      refused(d);
      d.note(fmt::format("Write the largest moment as the sum of the other two ({} kg·m²), or, for MuJoCo, set "
                         "balanceinertia=\"true\" in the <compiler>{}.",
                         format_number(moments[0] + moments[1], 6), urdf ? " of a <mujoco> section under <robot>" : ""));
    } else if (refusal && moments[0] < physics::kMujocoMinEigenvalue) {
      report_refused(link, placement, moments, *refusal, urdf, out);  // moments too small to be a shape
    }
  }

  // A tensor too small for MuJoCo that no other finding names: a point mass written as rounding
  // noise, or a frame's token tensor, which the simulators that merge welded links never mind
  // (six zeros would be accepted: MuJoCo reads them as no tensor).
  static void report_refused(const Link& link, const Placement& placement, const Eigen::Vector3d& moments,
                             const std::string& refusal, bool urdf, Reporter& out) {
    const Inertial& inertial = *link.inertial;
    Diagnostic& d = out.report(inertial.inertia_span, Severity::Error,
                               fmt::format("MuJoCo refuses the inertia of link '{}': smallest principal moment {} kg·m²",
                                           link.name.text, format_number(moments[0], 4)));
    d.note(fmt::format("Principal moments {} on {} kg{}.", moments_text(moments), format_number(inertial.mass.value),
                       point_mass(inertial) ? ": a zero tensor written with rounding noise" : ""));
    if (placement.joint && placement.role == Role::Welded)
      d.note(placement.joint->name.span,
             fmt::format("Welded by {}, it is merged as a point mass into the body it is welded to by PhysX and "
                         "Isaac Sim's importer: harmless there.",
                         joint_label(*placement.joint)));
    refusal_note(d, refusal, placement, urdf);
    d.note(urdf ? "Write all six entries as 0 (MuJoCo then reads no tensor and takes the link as a point mass), or "
                  "the part's tensor from CAD."
                : "Write the part's tensor from CAD.");
  }

  static void report_point_mass(const Link& link, const Placement& placement, bool translates_only,
                                const std::optional<std::string>& refusal, bool urdf, Reporter& out) {
    const Inertial& inertial = *link.inertial;
    if (translates_only && !refusal) {
      out.report(inertial.inertia_span, Severity::Info,
                 fmt::format("link '{}' has mass {} kg and a zero inertia tensor, but it only slides",
                             link.name.text, format_number(inertial.mass.value)))
          .note(placement.joint->name.span,
                fmt::format("It is the child of {}, and every joint between it and the fixed base is prismatic (a "
                            "virtual base's slides): it never turns, so its rotational inertia never enters the "
                            "dynamics, and PhysX's reading of a zero moment as infinite inertia locks nothing that "
                            "could move. Only its mass is simulated.",
                            joint_label(*placement.joint)))
          .note("If the base is meant to float, give the link a tensor: a floating chain turns as a whole.");
      return;
    }
    Diagnostic& d = out.report(inertial.inertia_span, refusal ? Severity::Error : Severity::Warning,
                               fmt::format("link '{}' moves with mass {} kg but a zero inertia tensor", link.name.text,
                                           format_number(inertial.mass.value)));
    d.note(placement.joint->name.span,
           fmt::format("It is the child of {}, a body of its own, and nothing welded to it carries inertia.",
                       joint_label(*placement.joint)));
    d.note("PhysX reads a zero moment as infinite inertia about that axis (the rotation is locked); other "
           "simulators reject the body or substitute a default.");
    if (refusal) refusal_note(d, *refusal, placement, urdf);
  }

  static void report_singular(const Link& link, const Placement& placement, const Eigen::Vector3d& moments,
                              double relative, const std::optional<std::string>& refusal, bool urdf, Reporter& out) {
    const Inertial& inertial = *link.inertial;
    const bool pasted = physics::pasted_tensor(inertial.inertia);
    // Welded to another body a rank-deficient tensor is merged harmlessly; say so only when
    // it is the tell-tale pasted value, or when MuJoCo refuses it.
    if (placement.role != Role::BodyStart && !pasted && !refusal) return;
    const Severity severity = refusal                                ? Severity::Error
                              : placement.role == Role::BodyStart ? Severity::Warning
                                                                  : Severity::Info;
    Diagnostic& d = out.report(
        inertial.inertia_span, severity,
        pasted ? fmt::format("inertia of link '{}' has all six entries equal to {}: a pasted placeholder",
                             link.name.text, format_number(inertial.inertia(0, 0), 4))
               : fmt::format("inertia of link '{}' is singular: smallest principal moment {} kg·m²", link.name.text,
                             format_number(moments[0], 4)));
    d.note(fmt::format("Principal moments {}; the smallest is within {} of zero relative to the largest, so the "
                       "body has no inertia about one axis.",
                       moments_text(moments), format_number(relative)));
    if (pasted) d.note("A tensor with ixx = iyy = izz = ixy = ixz = iyz has rank one: one value typed into every field.");
    if (placement.role != Role::BodyStart)
      d.note(placement.joint ? placement.joint->name.span : link.name.span,
             fmt::format("The link is welded by fixed joints, so the simulator merges it into another body; harmless "
                         "there{}.",
                         refusal ? " (PhysX, Isaac Sim's importer)" : ""));
    if (refusal) refusal_note(d, *refusal, placement, urdf);
  }

  RuleInfo info_{"inertia-invalid",
                 "A moving link without mass or inertia, or with an inertia tensor no rigid body can have",
                 Severity::Error,
                 false,
                 RuleOrigin::Check,
                 {{"triangle_tolerance", 1e-6,
                   "relative slack allowed on the triangle inequality I_max ≤ (I_a + I_b)·(1 + tolerance)"},
                  {"definiteness_tolerance", 1e-9,
                   "a principal moment within this fraction of the largest one counts as zero, not negative"},
                  {"dummy_mass", 1e-4, "a root link this light (kg) is a frame, not a body: its tensor is not checked; a welded link this light gets infos only"},
                  {"harmless_share", 0.01,
                   "a radius of gyration out of bound whose moment is under this fraction of what the link's joint turns is an info"}}};
};

}  // namespace

const Rule& inertia_invalid() {
  static const InertiaInvalid rule;
  return rule;
}

}  // namespace assetlint::rules
