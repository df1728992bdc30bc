#include "formats/usda/usd_reader.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_set>

#include "formats/usda/skipped_layers.h"
#include "formats/usda/usd_colliders.h"
#include "rules/reader_rules.h"
#include "util/numbers.h"

namespace assetlint::usda {
namespace {

constexpr std::size_t kNone = static_cast<std::size_t>(-1);

bool is_rot_instance(std::string_view inst) { return inst == "rotX" || inst == "rotY" || inst == "rotZ"; }

// The schema whose namespace an attribute belongs to (only the physics schemas the
// model reads); empty for anything else.
std::string schema_of(std::string_view name) {
  auto instance_after = [&](std::string_view prefix) -> std::string_view {
    if (!name.starts_with(prefix)) return {};
    const std::string_view rest = name.substr(prefix.size());
    const auto colon = rest.find(':');
    return colon == std::string_view::npos || colon == 0 ? std::string_view() : rest.substr(0, colon);
  };
  if (auto inst = instance_after("drive:"); !inst.empty() && name.substr(6 + inst.size()).starts_with(":physics:"))
    return "PhysicsDriveAPI:" + std::string(inst);
  if (auto inst = instance_after("physxMimicJoint:"); !inst.empty()) return "PhysxMimicJointAPI:" + std::string(inst);
  if (auto inst = instance_after("physxJointAxis:"); !inst.empty()) return "PhysxJointAxisAPI:" + std::string(inst);
  if (auto inst = instance_after("physxDrivePerformanceEnvelope:"); !inst.empty())
    return "PhysxDrivePerformanceEnvelopeAPI:" + std::string(inst);
  if (name.starts_with("physxJoint:")) return "PhysxJointAPI";
  if (name.starts_with("physxArticulation:")) return "PhysxArticulationAPI";
  if (name.starts_with("physxScene:")) return "PhysxSceneAPI";
  if (name == "physics:mass" || name == "physics:diagonalInertia" || name == "physics:principalAxes" ||
      name == "physics:centerOfMass" || name == "physics:density")
    return "PhysicsMassAPI";
  return {};
}

std::optional<JointType> joint_type(std::string_view type) {
  if (type == "PhysicsRevoluteJoint") return JointType::Revolute;
  if (type == "PhysicsPrismaticJoint") return JointType::Prismatic;
  if (type == "PhysicsFixedJoint") return JointType::Fixed;
  if (type == "PhysicsSphericalJoint") return JointType::Spherical;
  if (type == "PhysicsJoint") return JointType::Generic;
  return std::nullopt;
}

Eigen::Quaterniond quaternion(const std::vector<double>& v) {
  // USD writes quaternions real part first: (w, x, y, z).
  Eigen::Quaterniond q(v[0], v[1], v[2], v[3]);
  if (!(q.norm() > 1e-12) || !std::isfinite(q.norm())) return Eigen::Quaterniond::Identity();
  return q.normalized();
}

class Reader {
 public:
  explicit Reader(Stage stage) : stage_(std::move(stage)) {}

  ReadResult run() {
    result_.asset.format = SourceFormat::Usda;
    result_.asset.sources = stage_.sources;
    result_.diagnostics = std::move(stage_.diagnostics);
    if (!stage_.usable || !stage_.root_layer()) {
      result_.usable = false;
      return std::move(result_);
    }
    const Layer& root = *stage_.root_layer();
    mpu_ = root.meters_per_unit().value_or(0.01);
    kpu_ = root.kilograms_per_unit().value_or(1.0);
    if (!(mpu_ > 0) || !std::isfinite(mpu_)) mpu_ = 0.01;
    if (!(kpu_ > 0) || !std::isfinite(kpu_)) kpu_ = 1.0;
    read_robot_name(root);

    std::vector<bool> on_stage(stage_.prims.size(), false);
    for (std::size_t i = 0; i < stage_.prims.size(); ++i) {
      const ComposedPrim& prim = stage_.prims[i];
      const bool parent_ok = prim.parent == kNone || on_stage[prim.parent];
      on_stage[i] = parent_ok && prim.defined && is_active(prim);
      if (!on_stage[i]) continue;
      check_stale(prim);
      if (prim.has_api_schema("PhysicsRigidBodyAPI")) read_link(prim);
      if (auto type = joint_type(prim.type_name)) read_joint(prim, *type);
      if (prim.type_name == "PhysicsScene") read_scene(prim);
      if (prim.has_api_schema("PhysxArticulationAPI")) {
        Scene& scene = result_.asset.scene;
        if (!scene.position_iterations)
          scene.position_iterations = positive_setting(prim, "physxArticulation:solverPositionIterationCount", Unit::None);
        if (!scene.velocity_iterations)
          scene.velocity_iterations = velocity_iteration_setting(prim, "physxArticulation:solverVelocityIterationCount");
      }
    }
    read_colliders(stage_, on_stage, mpu_, result_.asset);
    result_.asset.index_names();
    for (Joint& joint : result_.asset.joints) {
      if (!joint.mimic) continue;
      const Joint* reference = result_.asset.find_joint(joint.mimic->reference.text);
      convert_mixed_gearing(joint, reference);
      check_mimic_limits(joint, reference);
    }
    weigh_skipped_arcs(stage_, result_);
    return std::move(result_);
  }

 private:
  static bool is_active(const ComposedPrim& prim) {
    for (const SpecRef& s : prim.specs)
      if (const Metadata* m = s.prim->find_metadata("active")) return m->value.as_bool().value_or(true);
    return true;
  }

  void read_robot_name(const Layer& root) {
    if (const Metadata* m = root.find_metadata("defaultPrim")) {
      if (auto name = m->value.as_string()) {
        result_.asset.robot_name = Name{std::string(*name), m->value.span};
        const ComposedPrim* prim = stage_.find("/" + std::string(*name));
        result_.asset.robot_span = prim ? prim->span() : m->value.span;
        return;
      }
    }
    for (std::size_t index : stage_.roots) {
      const ComposedPrim& prim = stage_.prims[index];
      if (!prim.defined) continue;
      result_.asset.robot_name = Name{prim.name, prim.span()};
      result_.asset.robot_span = prim.span();
      return;
    }
  }

  void report(const RuleInfo& rule, const Span& span, std::string message, std::vector<std::string> notes = {}) {
    Diagnostic d{std::string(rule.id), rule.default_severity, span, std::move(message), std::nullopt, {}, {}, {}};
    for (std::string& note : notes) d.note(std::move(note));
    result_.diagnostics.push_back(std::move(d));
  }

  // The declaration widened to whole lines when it stands alone on them, so that
  // removing it leaves no blank line behind.
  Span declaration_span(FileId file, const Span& decl) const {
    const SourceFile& src = *stage_.sources[file];
    const std::string_view text = src.view();
    std::size_t begin = decl.offset, end = decl.end();
    while (begin > 0 && (text[begin - 1] == ' ' || text[begin - 1] == '\t')) --begin;
    if (begin > 0 && text[begin - 1] != '\n') return decl;
    std::size_t after = end;
    while (after < text.size() && (text[after] == ' ' || text[after] == '\t')) ++after;
    if (after < text.size() && text[after] == '\r') ++after;
    if (after < text.size() && text[after] != '\n') return decl;
    if (after < text.size()) ++after;
    return src.span(file, begin, after - begin);
  }

  OptQuantity number(const ComposedPrim& prim, std::string_view name, Unit unit, double scale = 1.0) {
    auto opinion = prim.attribute(name);
    if (!opinion) return std::nullopt;
    const Value& v = *opinion->attribute->default_value;
    auto d = v.as_double();
    if (!d) return std::nullopt;
    Quantity q = Quantity::from_authored(*d, unit, v.span, scale);
    q.declaration = declaration_span(opinion->file, opinion->attribute->default_declaration_span);
    return q;
  }

  // A solver setting (a rate, an iteration count) that every formula divides by or
  // multiplies with: a value that is not a finite positive number is reported and left out,
  // and the run falls back to the configuration or PhysX's default.
  OptQuantity positive_setting(const ComposedPrim& prim, std::string_view name, Unit unit) {
    OptQuantity q = number(prim, name, unit);
    if (!q || (std::isfinite(q->authored) && q->authored > 0)) return q;
    report(rules::kParseError, q->span,
           fmt::format("{} = {} is not a positive number; asset-lint ignores it", name, format_number(q->authored)),
           {"PhysX needs a positive rate and positive iteration counts; the configuration's value or PhysX's default "
            "is used instead."});
    return std::nullopt;
  }

  // The velocity iteration count may be 0: PhysX checks only that the position count is above
  // zero (NpArticulationReducedCoordinate::setSolverIterationCounts), and Isaac Lab's robot
  // configurations often run articulations with no velocity iterations.
  OptQuantity velocity_iteration_setting(const ComposedPrim& prim, std::string_view name) {
    OptQuantity q = number(prim, name, Unit::None);
    if (!q || (std::isfinite(q->authored) && q->authored >= 0)) return q;
    report(rules::kParseError, q->span,
           fmt::format("{} = {} is not a count of zero or more; asset-lint ignores it", name, format_number(q->authored)),
           {"PhysX takes 0 to 255 velocity iterations; the configuration's value or PhysX's default is used instead."});
    return std::nullopt;
  }

  std::optional<std::vector<double>> numbers(const ComposedPrim& prim, std::string_view name, std::size_t count,
                                             Span* span = nullptr) {
    auto opinion = prim.attribute(name);
    if (!opinion) return std::nullopt;
    auto v = opinion->attribute->default_value->as_numbers();
    if (!v || v->size() != count) return std::nullopt;
    if (span) *span = opinion->attribute->default_value->span;
    return v;
  }

  // A value left at zero: what a tool writes when it switches a drive off (Robotiq's mimic
  // joints keep stiffness/damping/maxForce = 0 under `delete apiSchemas`).
  static bool zeroed(const AttributeOpinion& a) {
    if (!a.attribute->default_value) return false;
    auto values = a.attribute->default_value->as_numbers();
    if (!values) {
      auto single = a.attribute->default_value->as_double();
      if (!single) return false;
      values = std::vector<double>{*single};
    }
    return std::all_of(values->begin(), values->end(), [](double v) { return v == 0.0; });
  }

  // Attributes authored for schemas the prim does not apply: one finding per schema. Zeroed
  // leftovers of a deleted schema are harmless and not reported.
  void check_stale(const ComposedPrim& prim) {
    std::map<std::string, std::vector<AttributeOpinion>> by_schema;
    std::vector<std::string> order;
    for (const AttributeOpinion& a : prim.attributes()) {
      std::string schema = schema_of(a.attribute->name);
      if (schema.empty() || prim.has_api_schema(schema)) continue;
      if (prim.schema_deleted(schema) && zeroed(a)) continue;
      auto& list = by_schema[schema];
      if (list.empty()) order.push_back(schema);
      list.push_back(a);
    }
    for (const std::string& schema : order) {
      const auto& attrs = by_schema[schema];
      std::string names;
      for (const AttributeOpinion& a : attrs) names += (names.empty() ? "'" : ", '") + a.attribute->name + "'";
      const bool deleted = prim.schema_deleted(schema);
      report(rules::kStaleSchemaAttribute, attrs.front().attribute->name_span,
             fmt::format("{} on '{}' is {}: PhysX ignores {}", schema, leaf_name(prim.path),
                         deleted ? "deleted" : "not applied",
                         attrs.size() == 1 ? "its attribute" : fmt::format("its {} attributes", attrs.size())));
      Diagnostic& d = result_.diagnostics.back();
      d.note(fmt::format("{} {} authored on '{}', but {} {}.", names, attrs.size() == 1 ? "is" : "are", prim.path,
                         schema, deleted ? "is removed by `delete apiSchemas`" : "is not applied"));
      if (schema == "PhysxJointAPI" && !deleted) unsimulated_joint_values(prim, attrs, d);
      d.note(deleted ? "They record what someone meant before switching the schema off; delete them, or apply the "
                       "schema again if they should act."
                     : "Apply the schema if they should act, or delete them.");
    }
  }

  // An armature or joint speed limit written without PhysxJointAPI is a value someone chose
  // for the joint's dynamics (a rotor's inertia, a motor's top speed) that PhysX never gets:
  // a warning, unless it equals what PhysX uses anyway (armature 0, no speed limit).
  void unsimulated_joint_values(const ComposedPrim& prim, const std::vector<AttributeOpinion>& attrs, Diagnostic& d) {
    std::vector<std::string> meant;
    for (const AttributeOpinion& a : attrs) {
      const std::string& name = a.attribute->name;
      if (name != "physxJoint:armature" && name != "physxJoint:maxJointVelocity") continue;
      auto value = a.attribute->default_value ? a.attribute->default_value->as_double() : std::nullopt;
      if (!value) continue;
      const bool armature = name == "physxJoint:armature";
      if (armature ? *value == 0.0 : !(std::isfinite(*value) && *value < 1e6)) continue;
      meant.push_back(armature ? fmt::format("armature {}", format_number(*value))
                               : fmt::format("max velocity {}{}", format_number(*value),
                                             prim.type_name == "PhysicsPrismaticJoint" ? "" : " deg/s"));
    }
    if (meant.empty()) return;
    d.severity = Severity::Warning;
    d.message = fmt::format("PhysxJointAPI on '{}' is not applied: PhysX ignores its {}", leaf_name(prim.path),
                            meant.size() == 1 ? meant[0] : meant[0] + " and " + meant[1]);
    d.note("PhysX reads a joint's armature and maximum joint velocity from PhysxJointAPI only; without it the joint "
           "has no armature and no speed limit (omni.physx's unlimited velocity), whatever the file says. Newton's "
           "importer, when told to read PhysX's namespace, takes physxJoint:* by name, applied or not: the joint "
           "moves differently in the two engines.");
  }

  static std::string_view leaf_name(std::string_view path) {
    const auto slash = path.rfind('/');
    return slash == std::string_view::npos ? path : path.substr(slash + 1);
  }

  void read_link(const ComposedPrim& prim) {
    Link link;
    link.name = Name{prim.path, prim.span()};
    link.span = prim.span();
    if (prim.has_api_schema("PhysicsMassAPI")) {
      Inertial in;
      in.span = prim.schema_span("PhysicsMassAPI");
      const double inertia_scale = kpu_ * mpu_ * mpu_;
      if (auto mass = number(prim, "physics:mass", Unit::Kilogram, kpu_)) {
        in.mass = *mass;
        in.mass_authored = mass->authored != 0.0;
      } else {
        in.mass = Quantity::unauthored(0.0, Unit::Kilogram);
        in.mass.span = in.span;
        in.mass_authored = false;
      }
      Span diag_span = in.span;
      auto diag = numbers(prim, "physics:diagonalInertia", 3, &diag_span);
      in.inertia_span = diag_span;
      in.inertia_authored = diag && ((*diag)[0] != 0 || (*diag)[1] != 0 || (*diag)[2] != 0);
      if (in.inertia_authored) {
        Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
        if (auto axes = numbers(prim, "physics:principalAxes", 4)) rotation = quaternion(*axes).toRotationMatrix();
        const Eigen::Vector3d d((*diag)[0], (*diag)[1], (*diag)[2]);
        in.inertia = rotation * d.asDiagonal() * rotation.transpose() * inertia_scale;
      }
      Span com_span = in.span;
      if (auto com = numbers(prim, "physics:centerOfMass", 3, &com_span);
          com && std::isfinite((*com)[0]) && std::isfinite((*com)[1]) && std::isfinite((*com)[2])) {
        in.com = Eigen::Vector3d((*com)[0], (*com)[1], (*com)[2]) * mpu_;
        in.com_span = com_span;
      } else {
        in.com_span = in.span;  // (-inf, -inf, -inf) or unauthored: PhysX computes it; the origin stands in
        in.com_authored = false;
      }
      link.inertial = in;
    }
    if (auto opinion = prim.attribute("physics:kinematicEnabled"); opinion && opinion->attribute->default_value)
      link.kinematic = opinion->attribute->default_value->as_bool().value_or(false);
    result_.asset.links.push_back(std::move(link));
  }

  // The first target of a relationship, as a name with the span of its path literal.
  Name target(const ComposedPrim& prim, std::string_view rel, const Span& fallback) {
    auto opinion = prim.relationship(rel);
    if (!opinion || opinion->targets.empty()) return Name{std::string(), fallback};
    return Name{opinion->targets.front(), opinion->target_values.front()->span};
  }

  Name body(const ComposedPrim& prim, std::string_view rel, const Span& fallback) {
    Name name = target(prim, rel, fallback);
    if (name.text.empty()) return name;
    const std::string& target = name.text;
    const Span span = name.span;
    // A prim that is on the stage but no rigid body is static, like the world: the
    // joint anchors there (empty name). A target that is not on the stage keeps its
    // name, and structure-undefined-link reports it.
    if (const ComposedPrim* target_prim = stage_.find(target); target_prim && !target_prim->has_api_schema("PhysicsRigidBodyAPI"))
      return Name{std::string(), span};
    return Name{target, span};
  }

  void read_joint(const ComposedPrim& prim, JointType type) {
    Joint joint;
    joint.type = type;
    joint.name = Name{prim.path, prim.span()};
    joint.span = prim.span();
    joint.type_span = joint.span;
    for (const SpecRef& s : prim.specs)
      if (s.prim->type_name == prim.type_name) {
        joint.type_span = s.prim->type_span;
        break;
      }
    joint.parent = body(prim, "physics:body0", joint.span);
    joint.child = body(prim, "physics:body1", joint.span);
    if (auto excluded = prim.attribute("physics:excludeFromArticulation"); excluded && excluded->attribute->default_value)
      joint.excluded_from_articulation = excluded->attribute->default_value->as_bool().value_or(false);
    for (int i = 0; i < 2; ++i) {
      Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
      if (auto pos = numbers(prim, i == 0 ? "physics:localPos0" : "physics:localPos1", 3))
        frame.translation() = Eigen::Vector3d((*pos)[0], (*pos)[1], (*pos)[2]) * mpu_;
      if (auto rot = numbers(prim, i == 0 ? "physics:localRot0" : "physics:localRot1", 4))
        frame.linear() = quaternion(*rot).toRotationMatrix();
      joint.frame_in_link[i] = frame;
    }
    char axis = 'X';
    joint.axis_span = joint.span;
    if (auto opinion = prim.attribute("physics:axis")) {
      if (auto token = opinion->attribute->default_value->as_string(); token && token->size() == 1) {
        axis = (*token)[0];
        joint.axis_span = opinion->attribute->default_value->span;
      }
    }
    joint.axis = axis == 'Y' ? Eigen::Vector3d::UnitY() : axis == 'Z' ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();

    const bool prismatic = type == JointType::Prismatic;
    const bool single = type == JointType::Revolute || prismatic;
    joint.limit_span = joint.span;
    if (single) {
      auto limit = [&](std::string_view name) -> OptQuantity {
        auto q = prismatic ? number(prim, name, Unit::Meter, mpu_) : number(prim, name, Unit::Degree);
        if (q && std::isinf(q->authored)) return std::nullopt;  // ±inf: free
        return q;
      };
      joint.lower = limit("physics:lowerLimit");
      joint.upper = limit("physics:upperLimit");
    }

    // The drive instances PhysX reads for this joint type (PHYSICS.md §2 item 9): a revolute
    // joint only :angular, a prismatic one only :linear; rotX…transZ are D6 axes.
    std::vector<std::string> instances;
    const char axes[] = {'X', 'Y', 'Z'};
    if (type == JointType::Revolute) instances = {"angular"};
    else if (prismatic) instances = {"linear"};
    else if (type == JointType::Generic || type == JointType::Spherical)
      for (const char* kind : {"rot", "trans"})
        for (char a : axes) instances.push_back(kind + std::string(1, a));
    auto angular_instance = [&](const std::string& inst) { return inst == "angular" || inst.starts_with("rot"); };
    auto read_by_joint = [&](const std::string& inst) {
      return std::find(instances.begin(), instances.end(), inst) != instances.end();
    };

    const double torque_scale = kpu_ * mpu_ * mpu_;  // stage mass·length² → kg·m²
    auto read_drive = [&](const std::string& inst) {
      const bool angular = angular_instance(inst);
      const std::string ns = "drive:" + inst + ":physics:";
      Drive drive;
      drive.instance = inst;
      drive.span = prim.schema_span("PhysicsDriveAPI:" + inst);
      drive.type_span = drive.span;
      drive.stiffness = angular ? number(prim, ns + "stiffness", Unit::NewtonMeterPerDegree, torque_scale)
                                : number(prim, ns + "stiffness", Unit::NewtonPerMeter, kpu_);
      drive.damping = angular ? number(prim, ns + "damping", Unit::NewtonMeterSecondPerDegree, torque_scale)
                              : number(prim, ns + "damping", Unit::NewtonSecondPerMeter, kpu_);
      drive.max_force = angular ? number(prim, ns + "maxForce", Unit::NewtonMeter, torque_scale)
                                : number(prim, ns + "maxForce", Unit::Newton, kpu_ * mpu_);
      drive.target_position = angular ? number(prim, ns + "targetPosition", Unit::Degree)
                                      : number(prim, ns + "targetPosition", Unit::Meter, mpu_);
      if (auto opinion = prim.attribute(ns + "type")) {
        if (auto token = opinion->attribute->default_value->as_string()) {
          drive.type = *token == "acceleration" ? DriveType::Acceleration : DriveType::Force;
          drive.type_span = opinion->attribute->default_value->span;
        }
      }
      if (prim.has_api_schema("PhysxDrivePerformanceEnvelopeAPI:" + inst)) {
        const std::string env = "physxDrivePerformanceEnvelope:" + inst + ":";
        PerformanceEnvelope envelope;
        envelope.span = prim.schema_span("PhysxDrivePerformanceEnvelopeAPI:" + inst);
        envelope.max_actuator_velocity = angular ? number(prim, env + "maxActuatorVelocity", Unit::DegreePerSecond)
                                                 : number(prim, env + "maxActuatorVelocity", Unit::MeterPerSecond, mpu_);
        envelope.velocity_dependent_resistance =
            angular ? number(prim, env + "velocityDependentResistance", Unit::NewtonMeterSecondPerDegree, torque_scale)
                    : number(prim, env + "velocityDependentResistance", Unit::NewtonSecondPerMeter, kpu_);
        envelope.speed_effort_gradient = number(prim, env + "speedEffortGradient", Unit::None);
        drive.envelope = std::move(envelope);
      }
      return drive;
    };
    for (const std::string& inst : instances) {
      if (!prim.has_api_schema("PhysicsDriveAPI:" + inst)) continue;
      joint.drive = read_drive(inst);
      break;
    }
    // A drive instance this joint type does not read moves nothing; it is not linted.
    if (single) {
      constexpr std::string_view kDrive = "PhysicsDriveAPI:";
      for (const std::string& schema : prim.api_schemas) {
        if (!std::string_view(schema).starts_with(kDrive) || read_by_joint(schema.substr(kDrive.size()))) continue;
        const char* wanted = prismatic ? "PhysicsDriveAPI:linear" : "PhysicsDriveAPI:angular";
        report(rules::kDriveInstanceIgnored, prim.schema_span(schema),
               fmt::format("{} on {} joint '{}' drives nothing (PhysX reads only :{})", schema,
                           prismatic ? "prismatic" : "revolute", prim.path, prismatic ? "linear" : "angular"),
               {fmt::format("The joint is {}: omni.physx builds a revolute joint's drive from the :angular instance and "
                            "a prismatic joint's from :linear only; rotX…transZ instances are for D6 joints (PhysicsJoint).",
                            joint.drive ? "driven by " + std::string(wanted) + " alone" : "undriven"),
                fmt::format("Rename the instance to {} (in apiSchemas and in its drive:… attribute names) if it is meant "
                            "to drive the joint.",
                            wanted)});
      }
    }
    // Gains left behind by a removed drive schema: inactive, but evidence of what was
    // copied where (mimic-copied-drive-gains).
    for (const std::string& inst : instances) {
      if (prim.has_api_schema("PhysicsDriveAPI:" + inst)) continue;
      Drive stale = read_drive(inst);
      if (!stale.stiffness && !stale.damping) continue;
      if (!stale.span.valid()) stale.span = prim.span();
      joint.inactive_drive = std::move(stale);
      break;
    }

    const bool angular_joint = !prismatic;
    if (prim.has_api_schema("PhysxJointAPI")) {
      joint.velocity = angular_joint ? number(prim, "physxJoint:maxJointVelocity", Unit::DegreePerSecond)
                                     : number(prim, "physxJoint:maxJointVelocity", Unit::MeterPerSecond, mpu_);
      joint.armature = angular_joint ? number(prim, "physxJoint:armature", Unit::KilogramMeter2, torque_scale)
                                     : number(prim, "physxJoint:armature", Unit::Kilogram, kpu_);
      joint.joint_friction = number(prim, "physxJoint:jointFriction", Unit::None);
    }
    // PhysxJointAxisAPI:<axis>, when applied, replaces PhysxJointAPI's armature and max
    // velocity as a whole: what it leaves unauthored takes its own fallback (1e6, 0).
    std::vector<std::string> axis_instances = instances;
    if (type == JointType::Revolute) axis_instances.push_back(std::string("rot") + axis);
    if (prismatic) axis_instances.push_back(std::string("trans") + axis);
    for (const std::string& inst : axis_instances) {
      if (!prim.has_api_schema("PhysxJointAxisAPI:" + inst)) continue;
      const std::string ns = "physxJointAxis:" + inst + ":";
      const bool angular = angular_instance(inst);
      joint.velocity = angular ? number(prim, ns + "maxJointVelocity", Unit::DegreePerSecond)
                               : number(prim, ns + "maxJointVelocity", Unit::MeterPerSecond, mpu_);
      joint.armature = angular ? number(prim, ns + "armature", Unit::KilogramMeter2, torque_scale)
                               : number(prim, ns + "armature", Unit::Kilogram, kpu_);
      break;
    }

    read_other_engine_joint_values(prim, joint, angular_joint, torque_scale);
    read_mimic(prim, joint);
    read_newton_mimic(prim, joint);
    result_.asset.joints.push_back(std::move(joint));
  }

  // What Newton and MuJoCo read where PhysX's schemas leave a value unauthored: Newton's own
  // NewtonJointAPI armature, then MuJoCo's MjcJointAPI (whose mjc:armature and mjc:damping
  // Newton's importer still reads). mjc:damping is per radian: MuJoCo states damping in SI
  // units, unlike UsdPhysics' per-degree drive gains. Stage units apply as to every USD value.
  void read_other_engine_joint_values(const ComposedPrim& prim, Joint& joint, bool angular, double torque_scale) {
    auto armature = [&](std::string_view name) {
      return angular ? number(prim, name, Unit::KilogramMeter2, torque_scale) : number(prim, name, Unit::Kilogram, kpu_);
    };
    if (!joint.armature && prim.has_api_schema("NewtonJointAPI")) joint.armature = armature("newton:armature");
    if (!prim.has_api_schema("MjcJointAPI")) return;
    if (!joint.armature) joint.armature = armature("mjc:armature");
    if (!joint.joint_damping)
      joint.joint_damping = angular ? number(prim, "mjc:damping", Unit::NewtonMeterSecondPerRadian, torque_scale)
                                    : number(prim, "mjc:damping", Unit::NewtonSecondPerMeter, kpu_);
  }

  // NewtonMimicAPI (what Isaac Sim's importers write for Newton): joint0 = coef0 + coef1·joint1,
  // the model's own convention, with coef0 in the follower's position unit (degrees or stage
  // distance) and coef1 dimensionless. A PhysxMimicJointAPI on the same joint is what PhysX
  // reads and stays the model's mimic. newton:mimicEnabled = false leaves the joint free.
  void read_newton_mimic(const ComposedPrim& prim, Joint& joint) {
    if (joint.mimic || !prim.has_api_schema("NewtonMimicAPI")) return;
    if (auto enabled = prim.attribute("newton:mimicEnabled"); enabled && enabled->attribute->default_value)
      if (!enabled->attribute->default_value->as_bool().value_or(true)) return;
    const bool prismatic = joint.type == JointType::Prismatic;
    Mimic mimic;
    mimic.span = prim.schema_span("NewtonMimicAPI");
    mimic.reference = target(prim, "newton:mimicJoint", mimic.span);
    auto coef1 = number(prim, "newton:mimicCoef1", Unit::None);
    mimic.multiplier = coef1 ? *coef1 : Quantity::unauthored(1.0, Unit::None);
    auto coef0 = prismatic ? number(prim, "newton:mimicCoef0", Unit::Meter, mpu_)
                           : number(prim, "newton:mimicCoef0", Unit::Degree);
    mimic.offset = coef0 ? *coef0 : Quantity::unauthored(0.0, prismatic ? Unit::Meter : Unit::Degree);
    joint.mimic = std::move(mimic);
  }

  void read_mimic(const ComposedPrim& prim, Joint& joint) {
    constexpr std::string_view kPrefix = "PhysxMimicJointAPI:";
    for (const std::string& schema : prim.api_schemas) {
      if (!std::string_view(schema).starts_with(kPrefix)) continue;
      const std::string inst = schema.substr(kPrefix.size());
      const Span span = prim.schema_span(schema);
      if (!is_rot_instance(inst)) {
        report(rules::kMimicAxisInstance, span,
               fmt::format("'{}' on '{}': not a mimic instance, so the joint is not coupled", schema, prim.path),
               {fmt::format("A mimic joint instance must be rotX, rotY or rotZ; PhysX silently ignores '{}'.", inst)});
        continue;
      }
      if (joint.mimic) continue;
      const std::string ns = "physxMimicJoint:" + inst + ":";
      const bool prismatic = joint.type == JointType::Prismatic;
      Mimic mimic;
      mimic.span = span;
      mimic.instance = inst;
      mimic.reference = target(prim, ns + "referenceJoint", span);
      if (auto opinion = prim.relationship(ns + "referenceJoint"))
        for (std::size_t i = 1; i < opinion->targets.size(); ++i)
          mimic.extra_references.push_back(Name{opinion->targets[i], opinion->target_values[i]->span});
      auto gearing = number(prim, ns + "gearing", Unit::UsdGearing);
      mimic.multiplier = gearing ? *gearing : Quantity::unauthored(-1.0, Unit::UsdGearing);
      auto offset = prismatic ? number(prim, ns + "offset", Unit::UsdOffsetMeter, mpu_)
                              : number(prim, ns + "offset", Unit::UsdOffsetDegree);
      mimic.offset = offset ? *offset : Quantity::unauthored(0.0, prismatic ? Unit::UsdOffsetMeter : Unit::UsdOffsetDegree);
      mimic.natural_frequency = number(prim, ns + "naturalFrequency", Unit::PerSecond);
      mimic.damping_ratio = number(prim, ns + "dampingRatio", Unit::None);
      joint.mimic = std::move(mimic);
    }
  }

  // An angular mimic of a linear joint writes its gearing in deg per distance, a linear
  // mimic of an angular joint in distance per deg: omni.physx converts degrees, and the
  // model's metres need the stage's metersPerUnit on top.
  void convert_mixed_gearing(Joint& joint, const Joint* reference) {
    if (!reference || !is_single_dof(joint.type) || !is_single_dof(reference->type)) return;
    if (is_angular(joint.type) == is_angular(reference->type)) return;
    Quantity& gearing = joint.mimic->multiplier;
    if (gearing.unit != Unit::UsdGearing) return;  // NewtonMimicAPI: across types it has no unit
    const bool angular_mimic = is_angular(joint.type);
    const Unit unit = angular_mimic ? Unit::UsdGearingDegreePerDistance : Unit::UsdGearingDistancePerDegree;
    const double scale = angular_mimic ? 1.0 / mpu_ : mpu_;
    Quantity converted = Quantity::from_authored(gearing.authored, unit, gearing.span, scale);
    converted.declaration = gearing.declaration;
    if (!gearing.span.valid()) converted.span = Span{};
    gearing = converted;
  }

  // omni.physx refuses a mimic on a revolute joint, or with a revolute reference, that
  // has no finite limits (USD only: Isaac's URDF importer gives URDF mimics limits).
  void check_mimic_limits(const Joint& joint, const Joint* reference) {
    if (joint.mimic->instance.empty()) return;  // not a PhysxMimicJointAPI: omni.physx does not build it
    auto unlimited_revolute = [](const Joint& j) { return j.type == JointType::Revolute && (!j.lower || !j.upper); };
    const bool own = unlimited_revolute(joint);
    const bool ref = reference && unlimited_revolute(*reference);
    if (!own && !ref) return;
    const Joint& culprit = own ? joint : *reference;
    std::vector<std::string> notes{
        fmt::format("'{}' is a revolute joint whose physics:lowerLimit / physics:upperLimit are {}: omni.physx does not "
                    "create a mimic joint on (or following) a revolute joint without finite limits, so the joints are "
                    "not coupled.",
                    culprit.name.text, !culprit.lower && !culprit.upper ? "both unauthored or infinite" : "not both finite"),
        "Author finite limits in degrees on that joint (its mechanical range)."};
    report(rules::kMimicLimitsRequired, joint.mimic->span,
           own ? fmt::format("mimic on revolute joint '{}' without finite limits: omni.physx refuses it", joint.name.text)
               : fmt::format("mimic '{}' follows revolute joint without finite limits: omni.physx refuses it",
                             joint.name.text),
           std::move(notes));
  }

  void read_scene(const ComposedPrim& prim) {
    Scene& scene = result_.asset.scene;
    if (!prim.has_api_schema("PhysxSceneAPI")) return;
    if (!scene.timesteps_per_second)
      scene.timesteps_per_second = positive_setting(prim, "physxScene:timeStepsPerSecond", Unit::PerSecond);
    if (!scene.min_position_iterations)
      scene.min_position_iterations = positive_setting(prim, "physxScene:minPositionIterationCount", Unit::None);
    if (!scene.max_position_iterations)
      scene.max_position_iterations = positive_setting(prim, "physxScene:maxPositionIterationCount", Unit::None);
    if (scene.solver.empty()) {
      if (auto opinion = prim.attribute("physxScene:solverType")) {
        if (auto token = opinion->attribute->default_value->as_string()) {
          scene.solver = std::string(*token);
          scene.solver_span = opinion->attribute->default_value->span;
        }
      }
    }
  }

  Stage stage_;
  ReadResult result_;
  double mpu_ = 0.01;
  double kpu_ = 1.0;
};

}  // namespace

ReadResult read_stage(Stage stage) { return Reader(std::move(stage)).run(); }

ReadResult read_usda(std::shared_ptr<const SourceFile> file, const FileSystem& files, const ComposeOptions& options) {
  return read_stage(compose_stage(std::move(file), files, options));
}

}  // namespace assetlint::usda
