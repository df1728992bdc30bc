#pragma once
// The format-neutral robot model every rule reads. All values are in SI/PhysX units
// (radians, N·m/rad, kg·m², seconds); each keeps the span and unit it was written in.
#include <Eigen/Geometry>
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "model/quantity.h"
#include "model/source.h"
#include "util/boxed.h"

namespace assetlint {

// Lets unordered maps keyed by std::string be searched with a std::string_view.
struct TransparentHash {
  using is_transparent = void;
  std::size_t operator()(std::string_view text) const { return std::hash<std::string_view>{}(text); }
};

enum class SourceFormat { Urdf, Usda, Mjcf };

struct Name {
  std::string text;
  Span span;
};

struct Inertial {
  Quantity mass;                                    // kg
  Eigen::Vector3d com = Eigen::Vector3d::Zero();    // centre of mass in the link frame, m
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about the COM, in the link frame, kg·m²
  Span com_span;
  Span inertia_span;  // the element or attribute holding the tensor
  Span span;          // the whole <inertial> element / mass API block
  // USD: physics:mass = 0 or an all-zero diagonalInertia means "let PhysX derive it".
  bool mass_authored = true;
  bool inertia_authored = true;
  // USD without physics:centerOfMass: PhysX computes the COM from colliders; `com` is then
  // the body origin standing in, not a fact.
  bool com_authored = true;
  // MJCF body without <inertial>: computed by the reader from the body's geoms as MuJoCo's
  // compiler does; a fact of the geometry, not a value someone typed.
  bool from_geoms = false;
};

// A collision shape of a link, as the asset authors it (URDF <collision>; USD collider prims;
// MJCF geoms). Visual geometry is not modelled.
struct CollisionShape {
  enum class Kind { Box, Cylinder, Sphere, Capsule, Mesh };
  Kind kind = Kind::Box;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // in the link frame
  // Box: full edge lengths; cylinder and capsule: (radius, length along z, 0); sphere: (radius, 0, 0).
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  // Kind::Mesh: the file as written (URDF filename; MJCF file with meshdir applied), or, for
  // a mesh the asset writes inline (USD `points`, MJCF `vertex`), a name unique in the asset
  // (the prim path, the mesh asset's name) with the vertices in `points`.
  std::string mesh;
  Eigen::Vector3d mesh_scale = Eigen::Vector3d::Ones();
  std::vector<Eigen::Vector3d> points;  // inline vertices in the shape frame, m (scale applied); empty for a file
  Span span;
};

struct Link {
  Name name;
  Span span;  // the element or prim
  std::optional<Inertial> inertial;
  bool kinematic = false;  // USD physics:kinematicEnabled: moved by the user, not the solver
  // MJCF body without <inertial> (or <compiler inertiafromgeom="true">) whose geoms give
  // MuJoCo a mass asset-lint cannot compute (a mesh, a height field): mass and inertia unknown.
  bool mass_from_geoms = false;
  // The link is drawn (URDF <visual>): a part of the robot, not a frame, even where no
  // simulator weighs the shape.
  bool visual = false;
  std::vector<CollisionShape> collisions{};
};

enum class JointType { Revolute, Continuous, Prismatic, Fixed, Floating, Planar, Spherical, Generic };

inline bool is_angular(JointType t) { return t == JointType::Revolute || t == JointType::Continuous; }
inline bool is_single_dof(JointType t) {
  return t == JointType::Revolute || t == JointType::Continuous || t == JointType::Prismatic;
}

enum class DriveType { Force, Acceleration };

// USD PhysxDrivePerformanceEnvelopeAPI:<instance>: the drive's effort limit falls with
// speed, |F| ≤ maxForce − velocityDependentResistance·|v|, and is 0 at maxActuatorVelocity.
struct PerformanceEnvelope {
  OptQuantity max_actuator_velocity;          // rad/s or m/s; unset = inf
  OptQuantity velocity_dependent_resistance;  // N·m·s/rad or N·s/m; unset = 0
  OptQuantity speed_effort_gradient;          // as written (deg/s per N·m); unset = 0
  Span span;                                  // the schema application
};

struct Drive {
  OptQuantity stiffness;   // N·m/rad (angular) or N/m (linear)
  OptQuantity damping;     // N·m·s/rad or N·s/m
  // Why the damping cannot be computed from the file (MJCF `dampratio` when the reader cannot
  // derive kv); empty when it is known or unauthored. Rules skip the verdicts that need it.
  std::string damping_unknown;
  // A damping the file does not write but the engine derives (MJCF dampratio): how, with numbers.
  std::string damping_origin;
  // What another release of the engine derives instead, when that differs by more than 10 %
  // (MJCF dampratio before and after MuJoCo 3.15); empty otherwise.
  std::string damping_other_release;
  OptQuantity max_force;   // N·m or N; unset = unlimited
  OptQuantity target_position;  // rad or m: where the drive pulls the joint; unset = not authored
  DriveType type = DriveType::Force;
  Span type_span;
  Span span;               // where the drive is declared (schema application or config table)
  std::string instance;    // USD multiple-apply instance ("angular", "linear", "rotX", ...)
  std::string origin;      // where a drive the file does not hold came from ("asset-lint.toml:14")
  std::optional<PerformanceEnvelope> envelope;
};

struct Mimic {
  Name reference;          // the joint it follows
  // Model convention (URDF's): q = multiplier · q_ref + offset.
  Quantity multiplier;     // USD gearing is stored negated (Unit::UsdGearing)
  Quantity offset;         // rad or m
  OptQuantity natural_frequency;  // rad/s; ≤ 0 = hard constraint
  OptQuantity damping_ratio;      // ≤ 0 = hard constraint
  Span span;               // the <mimic> element / the mimic schema application
  std::string instance;    // USD: rotX / rotY / rotZ
  // Further targets of the reference relationship (USD): a mimic follows one joint, and
  // PhysX reads only the first of these.
  std::vector<Name> extra_references;
};

// The motor behind a joint, when the asset or configuration names it: what justifies
// an armature (reflected inertia G²·I_rotor).
struct Motor {
  Quantity rotor_inertia;  // kg·m²
  double gear_ratio = 1.0;
  std::string origin;      // where it was declared, for messages
};

// What a joint also moves that its own inertia at rest (Mᵢᵢ, every other joint held) leaves
// out: a body hung on a spatial tendon it winds, the joints a loop closure or a coupling tendon
// ties to it (MJCF). Rules that compare with that inertia know it is incomplete.
struct HiddenLoad {
  std::string what;   // "it also turns joint 'neck_pitch' through the weld at line 403"
  Span span;          // the element that carries the load
  bool rope = false;  // a hanging body: the inertia is then a lower bound
};

// Whether an actuator moves a joint. MJCF says so for every joint (an actuator's joint or
// fixed-tendon transmission, a coupling tendon, a mocap weld); URDF and USD do not, so their
// joints stay Unknown. A passive joint is a Linkage when a loop closure or a coupling ties it
// to the driven mechanism, so the actuators move it; Passive ones move only under gravity,
// contact and the reaction of their links.
enum class Actuation { Unknown, Actuated, Passive, Linkage };

// One joint of an MJCF fixed tendon: the tendon's length is Σ coef·q over its joints.
struct TendonShare {
  std::string joint;
  double coef = 1.0;  // the tendon's coef times the actuator's gear: the joint's share of the force
  Span span;          // the tendon's <joint> element
};

// The actuator's transmission ratio where the asset declares one (MJCF actuator `gear`, or the
// fixed tendon an actuator pulls): joint torque = ratio · actuator force, so an armature
// implies I_rotor = armature / ratio². On a fixed tendon the ratio is d(length)/dq along the
// joint carrying the drive, the joints that mimic it moving with it: Σ coefᵢ·multiplierᵢ.
struct Transmission {
  double ratio = 1.0;
  Span span;
  // A fixed-tendon transmission (MJCF): empty for a joint transmission.
  std::string tendon;               // "fixed tendon 'split'"
  std::string actuator;             // "actuator 'fingers_actuator'"
  std::vector<TendonShare> shares;  // every joint the tendon moves, in the tendon's order
  double length0 = 0;               // the actuator's length at the reference pose: Σ coef·q₀
  bool through_tendon() const { return !shares.empty(); }
};

struct Joint {
  Name name;
  Span span;               // the element or prim
  JointType type = JointType::Fixed;
  Span type_span;
  Name parent;             // URDF parent / USD body0
  Name child;              // URDF child / USD body1
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();  // unit vector in the joint frame
  Span axis_span;
  // The joint frame expressed in each link's frame: [0] parent/body0, [1] child/body1.
  std::array<Eigen::Isometry3d, 2> frame_in_link{Eigen::Isometry3d::Identity(), Eigen::Isometry3d::Identity()};

  OptQuantity lower;       // rad or m
  OptQuantity upper;
  Span limit_span;         // the <limit> element (URDF) or the joint prim (USD)
  bool bounds_unreadable = false;  // URDF: lower or upper written but not a number (parse-error says so)
  OptQuantity effort;      // URDF <limit effort>: N·m or N
  OptQuantity velocity;    // max joint velocity: rad/s or m/s
  OptQuantity joint_damping;   // URDF <dynamics damping>
  OptQuantity joint_friction;
  OptQuantity joint_stiffness;  // MJCF passive spring toward springref: N·m/rad or N/m
  OptQuantity armature;    // kg·m² or kg
  // The parts most joints lack are boxed: a joint record stays small (issue 10: 100 000
  // joints of 3.8 kB each were 381 MB faulted in and zeroed, and missed the cache).
  Boxed<Motor> motor;
  Actuation actuation = Actuation::Unknown;
  Boxed<Transmission> transmission;
  Boxed<Drive> drive;
  // Values of a drive schema that is authored but not applied (USD `delete apiSchemas`):
  // PhysX ignores them, but they show what someone meant, e.g. gains copied elsewhere.
  Boxed<Drive> inactive_drive;
  Boxed<Mimic> mimic;
  Boxed<HiddenLoad> hidden_load;
  // USD physics:excludeFromArticulation = true: PhysX builds the joint as a maximal-coordinate
  // joint outside the articulation, where articulation features (mimic) do not reach it.
  bool excluded_from_articulation = false;

  bool is_mimic() const { return mimic.has_value(); }
};

struct Scene {
  OptQuantity timesteps_per_second;  // 1/s
  OptQuantity position_iterations;   // count: the articulation's solverPositionIterationCount
  OptQuantity velocity_iterations;   // count: the articulation's solverVelocityIterationCount
  OptQuantity min_position_iterations;  // the scene's clamps on every actor's position iterations
  OptQuantity max_position_iterations;
  std::string solver;                // "TGS" / "PGS"; empty = unknown
  Span solver_span;
  std::string integrator;            // MJCF <option integrator> keyword; empty = MuJoCo's default (Euler)
  Span integrator_span;
  // MJCF <option> contact settings as written; empty / unset = MuJoCo's defaults
  // (cone pyramidal, impratio 1, noslip_iterations 0).
  std::string cone;
  Span cone_span;
  std::optional<double> impratio;
  Span impratio_span;
  std::optional<double> noslip_iterations;
  Span noslip_span;
};

// A constraint that closes a kinematic loop between two links of the robot (MJCF
// <equality><connect> or <weld>): the anchor point of link1 is held to the point of link2
// that coincides with it at the reference pose; a weld holds their orientations too.
struct LoopClosure {
  std::string link1, link2;                          // link2 empty: the world
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero();  // in link1's frame, m
  bool weld = false;
  Span span;
  std::string label;  // "the connect at line 173"
};

// A literal that several elements inherit (a value in an MJCF default class): an edit to it
// changes every one of them.
struct InheritedLiteral {
  Span span;
  std::string owner;      // "default class 'small_actuator'"
  std::size_t uses = 0;   // how many model values the reader took from it
};

// A URDF's <robot><mujoco><compiler> section, which MuJoCo's URDF importer applies to the
// file's <inertia> tensors.
struct UrdfMujocoCompiler {
  double boundinertia = 0;
  bool balanceinertia = false;
};

// One parsed asset: the files it was read from and the robot they describe.
struct Asset {
  SourceFormat format = SourceFormat::Urdf;
  std::vector<std::shared_ptr<const SourceFile>> sources;  // indexed by FileId; [0] is the file checked
  Name robot_name;
  Span robot_span;
  UrdfMujocoCompiler urdf_mujoco_compiler;  // URDF only; defaults when the file has no section
  std::vector<Link> links;
  std::vector<Joint> joints;
  Scene scene;
  std::vector<InheritedLiteral> inherited_literals;  // in (file, offset) order
  std::vector<LoopClosure> loops;                     // MJCF connect and weld equalities between the robot's links
  // USD: prim paths whose opinions a layer that could not be read would have brought ("" for a
  // sublayer: the whole stage). A body named under one may be defined there, so no rule may
  // call it undefined.
  std::vector<std::string> unread_scopes;

  // The literal of more than one use that `span` overlaps, if any.
  const InheritedLiteral* shared_literal_at(const Span& span) const;

  // Lookups by name: through the index once index_names() has run on the current links
  // and joints, a linear scan otherwise (assets built by hand in tests). The first
  // definition wins when a name repeats.
  const Link* find_link(std::string_view name) const;
  const Joint* find_joint(std::string_view name) const;
  // The joints whose mimic names `name`, in document order.
  std::vector<const Joint*> mimic_followers(std::string_view name) const;
  // The joints whose parent or child is the link `name`, in document order (each once).
  std::vector<const Joint*> joints_at(std::string_view link) const;
  // The joint a mimic follows when structure-mimic-reference accepts the pair (defined,
  // not itself, not a mimic, both single-DOF); nullptr otherwise, and for non-mimics.
  // Rules derive values and fixes only through an accepted pair.
  const Joint* followed_joint(const Joint& mimic) const;
  // The position of a link or joint of this asset in `links` / `joints`; nullopt for one
  // that is not an element of them.
  std::optional<std::size_t> index_of(const Link& link) const;
  std::optional<std::size_t> index_of(const Joint& joint) const;
  // The link a joint names as parent (side 0) or child (side 1); nullptr when none is
  // defined. Resolved once per joint by index_names(), a lookup by name otherwise.
  const Link* side_link(const Joint& joint, int side) const;
  // Whether a prim at `path` may be defined in a layer that could not be read.
  bool may_be_unread(std::string_view path) const;
  // Builds the name index; call again after adding, removing or renaming links or joints.
  void index_names();
  const SourceFile& source(FileId id) const { return *sources.at(id); }

 private:
  struct NameIndex {
    std::size_t link_count = 0, joint_count = 0;
    std::unordered_map<std::string, std::size_t, TransparentHash, std::equal_to<>> links, joints;
    std::unordered_map<std::string, std::vector<std::size_t>, TransparentHash, std::equal_to<>> followers;
    std::unordered_map<std::string, std::vector<std::size_t>, TransparentHash, std::equal_to<>> link_joints;
    // Per joint: the positions of its parent and child link, kNoLink when undefined
    // (positions, not pointers: a copied Asset shares the index).
    static constexpr std::size_t kNoLink = static_cast<std::size_t>(-1);
    std::vector<std::array<std::size_t, 2>> joint_links;
  };
  bool indexed() const { return index_ && index_->link_count == links.size() && index_->joint_count == joints.size(); }
  std::shared_ptr<const NameIndex> index_;
};

std::string_view joint_type_name(JointType type);

}  // namespace assetlint
