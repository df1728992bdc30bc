#include "formats/mjcf/mjcf_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "formats/mjcf/mjcf_actuators.h"
#include "formats/mjcf/mjcf_collisions.h"
#include "formats/mjcf/mjcf_couplings.h"
#include "formats/mjcf/mjcf_dampratio.h"
#include "formats/mjcf/mjcf_defaults.h"
#include "formats/mjcf/mjcf_geom_inertia.h"
#include "formats/mjcf/mjcf_inertia_bounds.h"
#include "formats/mjcf/mjcf_values.h"
#include "formats/xml/xml_scanner.h"
#include "physics/servo_step.h"
#include "util/numbers.h"

namespace assetlint::mjcf {
namespace {

using tinyxml2::XMLElement;

// MuJoCo's <option timestep> default, seconds.
constexpr double kDefaultTimestep = 0.002;

Attr own(const XMLElement* el, const char* name) { return Attr{el, el->Attribute(name)}; }

class Reader {
 public:
  Reader(std::shared_ptr<const SourceFile> file, const FileSystem& files, const ReadOptions& options)
      : sources_(std::move(file), files, options), values_(sources_, result_.diagnostics),
        mujoco_(options.mujoco), dampratio_rule_(physics::dampratio_rule(options.mujoco)) {}

  ReadResult run() {
    result_.asset.format = SourceFormat::Mjcf;
    result_.asset.sources = sources_.sources;
    for (auto& d : sources_.diagnostics) result_.diagnostics.push_back(std::move(d));
    const XMLElement* root = sources_.root();
    if (!root || !sources_.usable) {
      result_.usable = false;
      return std::move(result_);
    }
    const char* model = root->Attribute("model");
    result_.asset.robot_name = Name{model ? model : "MuJoCo Model",
                                    model ? sources_.document_of(root).value_span(root, "model") : values_.element_span(root)};
    result_.asset.robot_span = values_.element_span(root);

    // MuJoCo reads <compiler> and <default> before the rest, wherever they are written.
    const auto sections = sources_.children(root);
    if (std::none_of(sections.begin(), sections.end(),
                     [](const XMLElement* el) { return std::string_view(el->Name()) == "worldbody"; })) {
      values_.unsupported(result_.asset.robot_span, "no <worldbody>: an <include> fragment, not a model")
          .note("It is checked as part of the model that includes it.");
      result_.usable = false;
      return std::move(result_);
    }
    for (const XMLElement* el : sections)
      if (std::string_view(el->Name()) == "compiler") read_compiler(el);
    for (const XMLElement* el : sections)
      if (std::string_view(el->Name()) == "default") defaults_.read(sources_, el, result_.diagnostics);
    read_options(sections);
    meshes_ = read_mesh_assets(sources_, sections, defaults_, compiler_, values_);
    for (const XMLElement* el : sections)
      if (std::string_view(el->Name()) == "worldbody") read_bodies(el, "", "main");
    if (compiler_.settotalmass > 0) scale_to_total_mass(compiler_.settotalmass);
    report_removed_attributes(root);
    const Couplings couplings = read_couplings(sources_, defaults_, compiler_, sections, values_, result_.asset);
    const FixedTendons& tendons = couplings.fixed;
    result_.asset.loops = loop_closures(couplings);
    std::vector<const XMLElement*> joint_equalities;
    // An actuator on a spatial tendon, a site or a body moves joints the model does not name
    // (a tendon-driven hand's finger joints): then no joint can be called passive.
    bool unnamed_transmission = false;
    // A model without any actuator is a mechanism that another model actuates (dm_control's
    // composer, MuJoCo's attach): none of its joints can be called passive either.
    bool any_actuator = false;
    std::vector<DampRatio> damp_ratios;
    std::vector<Damper> dampers;
    std::vector<const XMLElement*> on_tendons;
    for (const XMLElement* el : sections) {
      const std::string_view tag = el->Name();
      if (tag == "equality") {
        for (const XMLElement* c : sources_.children(el))
          if (std::string_view(c->Name()) == "joint") joint_equalities.push_back(c);
      } else if (tag == "actuator") {
        for (const XMLElement* c : sources_.children(el)) {
          read_actuator(c, defaults_, compiler_, tendons, values_, result_.asset, damp_ratios, dampers, on_tendons);
          any_actuator = any_actuator || default_kind(c->Name()) == "actuator";
          const char* tendon = c->Attribute("tendon");
          if ((tendon && !tendons.contains(tendon)) || c->Attribute("site") || c->Attribute("body") ||
              c->Attribute("cranksite"))
            unnamed_transmission = true;
        }
      }
    }
    drive_through_couplings(couplings, result_.asset);
    note_rope_loads(couplings, result_.asset);
    // MJCF lists every actuator: a joint none of them reaches is moved only by its links.
    if (any_actuator && !unnamed_transmission) {
      for (Joint& joint : result_.asset.joints)
        if (joint.actuation == Actuation::Unknown) joint.actuation = Actuation::Passive;
      mark_linkages(couplings, result_.asset);
    }
    // After the actuators: which side of a coupling is driven decides which one follows.
    for (const XMLElement* el : joint_equalities) read_equality_joint(el);
    note_coupled_loads(couplings, result_.asset);
    result_.asset.index_names();  // after the equalities: they make the mimics
    // A fixed tendon's drive sits on the joint its mimics follow: after the equalities.
    for (const XMLElement* el : on_tendons)
      read_tendon_actuator(el, defaults_, compiler_, tendons, qpos0_, values_, result_.asset, damp_ratios, dampers);
    // Once the whole tree is known: MuJoCo derives kv from dampratio and the inertia at qpos0.
    derive_dampratio_damping(damp_ratios, dampratio_rule_, values_, result_.asset);
    add_dampers(dampers, result_.asset);
    result_.asset.inherited_literals = values_.inherited_literals();
    // Equalities are read after the actuators; report in document order all the same.
    std::stable_sort(result_.diagnostics.begin(), result_.diagnostics.end(), [](const auto& a, const auto& b) {
      return std::tie(a.span.file, a.span.offset) < std::tie(b.span.file, b.span.offset);
    });
    return std::move(result_);
  }

 private:
  void read_compiler(const XMLElement* el) {
    if (const char* angle = el->Attribute("angle")) {
      const std::string_view a = trim(angle);
      if (a != "degree" && a != "radian")
        values_.error(values_.value_span(own(el, "angle"), "angle"),
                      fmt::format("<compiler angle>: expected degree or radian, found '{}'", angle));
      compiler_.degree = a != "radian";
      compiler_.angle_span = values_.value_span(own(el, "angle"), "angle");
    }
    if (const char* seq = el->Attribute("eulerseq")) {
      const std::string s(trim(seq));
      const bool valid = s.size() == 3 && s.find_first_not_of("xyzXYZ") == std::string::npos;
      if (!valid) values_.error(values_.value_span(own(el, "eulerseq"), "eulerseq"),
                                fmt::format("<compiler eulerseq>: expected three of x, y, z, X, Y, Z, found '{}'", seq));
      else compiler_.eulerseq = s;
    }
    if (auto f = values_.flag(own(el, "autolimits"), "autolimits")) compiler_.autolimits = *f;
    if (const char* g = el->Attribute("inertiafromgeom")) compiler_.inertiafromgeom = std::string(trim(g));
    if (auto r = values_.numbers(own(el, "inertiagrouprange"), "inertiagrouprange", 2)) {
      compiler_.inertia_group_low = static_cast<int>((*r)[0]);
      compiler_.inertia_group_high = static_cast<int>((*r)[1]);
    }
    if (auto m = values_.numbers(own(el, "settotalmass"), "settotalmass", 1)) compiler_.settotalmass = (*m)[0];
    if (auto m = values_.numbers(own(el, "boundmass"), "boundmass", 1)) compiler_.boundmass = (*m)[0];
    if (auto i = values_.numbers(own(el, "boundinertia"), "boundinertia", 1)) compiler_.boundinertia = (*i)[0];
    if (auto b = values_.flag(own(el, "balanceinertia"), "balanceinertia")) compiler_.balanceinertia = *b;
    if (const char* dir = el->Attribute("meshdir")) compiler_.meshdir = std::string(trim(dir));
    else if (const char* assets = el->Attribute("assetdir"); assets && compiler_.meshdir.empty())
      compiler_.meshdir = std::string(trim(assets));
  }

  void read_options(const std::vector<const XMLElement*>& sections) {
    Scene& scene = result_.asset.scene;
    scene.solver = "MuJoCo";
    for (const XMLElement* el : sections) {
      if (std::string_view(el->Name()) != "option") continue;
      scene.solver_span = values_.element_span(el);
      if (auto q = values_.quantity(own(el, "timestep"), "timestep", Unit::SecondsPerStep)) {
        if (!(q->authored > 0) || !std::isfinite(q->authored)) {
          values_.error(q->span, fmt::format("<option timestep>: must be a positive number of seconds, found '{}'",
                                             format_number(q->authored)));
          continue;
        }
        scene.timesteps_per_second = q;
      }
      if (const char* integrator = el->Attribute("integrator")) {
        const Span span = values_.value_span(own(el, "integrator"), "integrator");
        if (!physics::parse_integrator(integrator))
          values_.error(span, fmt::format("<option integrator>: expected Euler, RK4, implicit or implicitfast, found '{}'",
                                          integrator));
        else {
          scene.integrator = integrator;
          scene.integrator_span = span;
        }
      }
      read_contact_options(el, scene);
    }
    if (!scene.timesteps_per_second)
      scene.timesteps_per_second = Quantity::unauthored(to_model_units(kDefaultTimestep, Unit::SecondsPerStep), Unit::SecondsPerStep);
  }

  // cone, impratio and noslip_iterations: what a squeezed object's friction depends on.
  void read_contact_options(const XMLElement* el, Scene& scene) {
    if (const char* cone = el->Attribute("cone")) {
      scene.cone = std::string(trim(cone));
      scene.cone_span = values_.value_span(own(el, "cone"), "cone");
    }
    if (auto r = values_.numbers(own(el, "impratio"), "impratio", 1)) {
      scene.impratio = (*r)[0];
      scene.impratio_span = values_.value_span(own(el, "impratio"), "impratio");
    }
    if (auto n = values_.numbers(own(el, "noslip_iterations"), "noslip_iterations", 1)) {
      scene.noslip_iterations = (*n)[0];
      scene.noslip_span = values_.value_span(own(el, "noslip_iterations"), "noslip_iterations");
    }
  }

  // The class an element inside a body takes its defaults from.
  std::optional<std::string> class_of(const XMLElement* el, const std::string& childclass) {
    const char* cls = el->Attribute("class");
    if (!cls) return childclass;
    if (!defaults_.has_class(cls)) {
      values_.unknown_class(values_.value_span(own(el, "class"), "class"), "class", cls);
      return std::nullopt;
    }
    return std::string(cls);
  }

  std::string body_name(const XMLElement* el) {
    if (const char* name = el->Attribute("name")) return name;
    return fmt::format("(unnamed body at line {})", values_.element_span(el).line);
  }

  // The class an element's children default to: its `childclass`, else the one around it.
  std::string child_class(const XMLElement* el, const std::string& around) {
    const char* c = el->Attribute("childclass");
    if (!c) return around;
    if (defaults_.has_class(c)) return c;
    values_.unknown_class(values_.value_span(own(el, "childclass"), "childclass"), "childclass", c);
    return around;
  }

  // The bodies under `parent_el`, directly or through <frame>s: a frame only places what it
  // holds (its pose composes onto theirs, its childclass becomes their default class) and
  // leaves no body of its own (MuJoCo's compiler folds it away).
  void read_bodies(const XMLElement* parent_el, const std::string& parent, const std::string& childclass,
                   const Eigen::Isometry3d& frame = Eigen::Isometry3d::Identity()) {
    for (const XMLElement* el : sources_.children(parent_el)) {
      const std::string_view tag = el->Name();
      if (tag == "body") read_body(el, parent, child_class(el, childclass), frame);
      else if (tag == "frame") read_bodies(el, parent, child_class(el, childclass), frame * pose(el, compiler_, values_));
    }
  }

  // A geom and where it sits: the class it defaults to and the frames between it and its body.
  struct PlacedGeom {
    const XMLElement* element;
    std::string cls;
    Eigen::Isometry3d frame;
  };

  void collect_geoms(const XMLElement* parent_el, const std::string& cls, const Eigen::Isometry3d& frame,
                     std::vector<PlacedGeom>& out) {
    for (const XMLElement* c : sources_.children(parent_el)) {
      const std::string_view tag = c->Name();
      if (tag == "geom") out.push_back({c, cls, frame});
      else if (tag == "frame") collect_geoms(c, child_class(c, cls), frame * pose(c, compiler_, values_), out);
    }
  }

  void read_body(const XMLElement* el, const std::string& parent, const std::string& cls, const Eigen::Isometry3d& frame) {
    Link link;
    link.name = Name{body_name(el), el->Attribute("name") ? values_.value_span(own(el, "name"), "name") : values_.element_span(el)};
    link.span = values_.element_span(el);
    const Eigen::Isometry3d body_pose = frame * pose(el, compiler_, values_);
    std::size_t joints = 0;
    for (const XMLElement* c : sources_.children(el)) {
      const std::string_view tag = c->Name();
      if (tag == "inertial") read_inertial(c, link);
      else if (tag == "joint" || tag == "freejoint") joints += read_joint(c, link.name.text, parent, body_pose, cls);
    }
    std::vector<PlacedGeom> placed;
    collect_geoms(el, cls, Eigen::Isometry3d::Identity(), placed);
    std::vector<Geom> geoms;
    bool unknown_class = false;
    for (const auto& [g, geom_cls, held_in] : placed) {
      const auto geom_class = class_of(g, geom_cls);
      if (!geom_class) {
        unknown_class = true;
        continue;
      }
      const auto& defs = defaults_.elements(*geom_class, "geom");
      GeomShape shape = geom_shape(g, defs, compiler_, values_);
      shape.pose = held_in * shape.pose;  // from the <frame> that holds the geom to the body
      geoms.push_back(Geom{g, &defs, std::move(shape)});
      if (geom_collides(g, defs, values_))
        if (auto collision = collision_shape(g, geoms.back().shape, meshes_, values_))
          link.collisions.push_back(std::move(*collision));
    }
    // Without <inertial> (or when the compiler ignores it) MuJoCo sums the geoms' mass and inertia.
    if (!link.inertial && compiler_.inertiafromgeom != "false" && !unknown_class) inertia_from_geoms(link, geoms);
    if (link.inertial) report_compiler_change(link, apply_compiler_bounds(compiler_, *link.inertial));
    if (joints == 0) {
      Joint weld;
      weld.name = Name{link.name.text + " (welded)", link.name.span};
      weld.span = link.span;
      weld.type = JointType::Fixed;
      weld.type_span = link.span;
      weld.parent = Name{parent, link.span};
      weld.child = link.name;
      weld.frame_in_link[0] = body_pose;
      weld.axis_span = weld.limit_span = link.span;
      result_.asset.joints.push_back(std::move(weld));
    }
    const std::string name = link.name.text;  // links grows below: no reference into it
    result_.asset.links.push_back(std::move(link));
    read_bodies(el, name, cls);
  }

  // <compiler settotalmass>: MuJoCo scales every body's mass and inertia by one factor so that
  // they add up to the total (engine_setconst.c, mj_setTotalmass). A body of unknown mass
  // leaves the factor, and so every mass, unknown.
  void scale_to_total_mass(double total) {
    auto& links = result_.asset.links;
    double mass = 0;
    bool unknown = false;
    for (const Link& link : links) {
      unknown = unknown || link.mass_from_geoms;
      if (link.inertial) mass += link.inertial->mass.value;
    }
    if (unknown || !(mass > 0)) {
      for (Link& link : links) {
        link.mass_from_geoms = link.mass_from_geoms || link.inertial.has_value();
        link.inertial.reset();
      }
      return;
    }
    const double factor = total / mass;
    for (Link& link : links) {
      if (!link.inertial) continue;
      link.inertial->mass.value *= factor;
      link.inertial->mass.scale *= factor;
      link.inertial->inertia *= factor;
    }
  }

  // A geom of a body, its default class's geom elements and its shape in the body frame.
  struct Geom {
    const XMLElement* element;
    const std::vector<const XMLElement*>* defaults;
    GeomShape shape;
  };

  // The rules judge the mass properties MuJoCo simulates; this says they are not the ones written.
  void report_compiler_change(const Link& link, const std::string& change) {
    if (change.empty()) return;
    const Inertial& in = *link.inertial;
    result_.diagnostics.push_back({"inertia-invalid", Severity::Info, in.inertia_span.valid() ? in.inertia_span : link.span,
                                   fmt::format("MuJoCo simulates other mass properties for body '{}' than the file writes",
                                               link.name.text),
                                   std::nullopt, {}, {}, {}});
    result_.diagnostics.back()
        .note(fmt::format("Its <compiler> settings change them: {}.", change))
        .note("The checks judge the compiled values. If the part's real inertia matters, write it as measured.");
  }

  void inertia_from_geoms(Link& link, const std::vector<Geom>& geoms) {
    std::vector<physics::MassPart> parts;
    bool unknown = false;
    for (const Geom& geom : geoms) {
      const XMLElement* g = geom.element;
      const auto& defs = *geom.defaults;
      int group = 0;
      if (auto v = values_.numbers(Defaults::lookup(g, defs, "group"), "group", 1)) group = static_cast<int>((*v)[0]);
      if (group < compiler_.inertia_group_low || group > compiler_.inertia_group_high) continue;
      const GeomMass mass = geom_mass(g, geom.shape, defs, values_);
      if (!mass.unknown.empty()) unknown = true;
      else if (mass.part) parts.push_back(*mass.part);
    }
    if (unknown) {
      link.mass_from_geoms = true;
      return;
    }
    if (parts.empty()) return;  // no geom carries mass: a massless body, as MuJoCo compiles it
    const physics::MassPart body = physics::combine_parts(parts);
    Inertial in;
    in.span = link.span;
    in.mass = Quantity::unauthored(body.mass, Unit::Kilogram);
    in.com = body.com;
    in.com_span = in.inertia_span = link.span;
    in.inertia = body.inertia;
    in.from_geoms = true;
    link.inertial = in;
  }

  void read_inertial(const XMLElement* el, Link& link) {
    if (compiler_.inertiafromgeom == "true") return;  // MuJoCo ignores <inertial> and derives both from geoms
    Inertial in;
    in.span = values_.element_span(el);
    if (auto m = values_.quantity(own(el, "mass"), "mass", Unit::Kilogram)) in.mass = *m;
    else {
      in.mass = Quantity::unauthored(0.0, Unit::Kilogram);
      in.mass.span = in.span;
      in.mass_authored = false;
    }
    const Eigen::Isometry3d frame = pose(el, compiler_, values_);
    in.com = frame.translation();
    in.com_span = el->Attribute("pos") ? values_.value_span(own(el, "pos"), "pos") : in.span;
    Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero();
    if (auto d = values_.numbers(own(el, "diaginertia"), "diaginertia", 3)) {
      tensor = Eigen::Vector3d((*d)[0], (*d)[1], (*d)[2]).asDiagonal();
      in.inertia_span = values_.value_span(own(el, "diaginertia"), "diaginertia");
    } else if (auto f = values_.numbers(own(el, "fullinertia"), "fullinertia", 6)) {
      // ixx iyy izz ixy ixz iyz
      const auto& v = *f;
      tensor << v[0], v[3], v[4], v[3], v[1], v[5], v[4], v[5], v[2];
      in.inertia_span = values_.value_span(own(el, "fullinertia"), "fullinertia");
    } else {
      in.inertia_span = in.span;
      in.inertia_authored = false;
    }
    in.inertia = frame.linear() * tensor * frame.linear().transpose();
    link.inertial = in;
  }

  static std::optional<JointType> joint_type(std::string_view type) {
    if (type == "hinge") return JointType::Revolute;
    if (type == "slide") return JointType::Prismatic;
    if (type == "ball") return JointType::Spherical;
    if (type == "free") return JointType::Floating;
    return std::nullopt;
  }

  std::size_t read_joint(const XMLElement* el, const std::string& body, const std::string& parent,
                         const Eigen::Isometry3d& body_pose, const std::string& childclass) {
    const auto cls = class_of(el, childclass);
    if (!cls) return 1;
    const auto& defs = defaults_.elements(*cls, "joint");
    const bool free = std::string_view(el->Name()) == "freejoint";
    // A <freejoint> takes nothing from the default classes (MuJoCo compiles it with no armature
    // or damping whatever <default><joint> says).
    auto lookup = [&](const char* name) { return free ? own(el, name) : Defaults::lookup(el, defs, name); };
    Joint joint;
    const char* name = el->Attribute("name");
    joint.span = values_.element_span(el);
    joint.name = Name{name ? name : fmt::format("(unnamed joint at line {})", joint.span.line),
                      name ? values_.value_span(own(el, "name"), "name") : joint.span};
    const Attr type_attr = free ? Attr{} : lookup("type");
    const std::string_view type_text = type_attr ? trim(type_attr.value) : (free ? "free" : "hinge");
    auto type = joint_type(type_text);
    joint.type_span = type_attr ? values_.value_span(type_attr, "type") : joint.span;
    if (!type) {
      values_.error(joint.type_span, fmt::format("<joint type>: expected hinge, slide, ball or free, found '{}'", type_text));
      return 1;
    }
    joint.type = *type;
    joint.parent = Name{parent, joint.span};
    joint.child = Name{body, joint.span};

    Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
    if (auto p = values_.numbers(lookup("pos"), "pos", 3)) at.translation() = Eigen::Vector3d((*p)[0], (*p)[1], (*p)[2]);
    joint.frame_in_link[1] = at;
    joint.frame_in_link[0] = body_pose * at;
    joint.axis = Eigen::Vector3d::UnitZ();
    joint.axis_span = joint.span;
    if (const Attr a = lookup("axis")) {
      if (auto v = values_.numbers(a, "axis", 3); v && Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]).norm() > 0) {
        joint.axis = Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]).normalized();
        joint.axis_span = values_.value_span(a, "axis");
      }
    }

    const bool angular = joint.type == JointType::Revolute;
    const bool linear = joint.type == JointType::Prismatic;
    joint.limit_span = joint.span;
    if (angular || linear) {
      const Attr range = lookup("range");
      const auto bounds = range ? values_.numbers(range, "range", 2) : std::nullopt;
      // limited="auto" (MuJoCo's islimited, user_objects.cc): limited when autolimits is on and
      // range[0] < range[1]; equal bounds ("0 0") leave the joint free. A range written upper
      // bound first is kept, for limits-inverted to report (MuJoCo silently drops it).
      const bool auto_limited = bounds && compiler_.autolimits && (*bounds)[0] != (*bounds)[1];
      const bool limited = values_.flag(lookup("limited"), "limited").value_or(auto_limited);
      const Unit position = linear ? Unit::Meter : compiler_.degree ? Unit::Degree : Unit::Radian;
      if (limited && bounds) {
        joint.limit_span = values_.value_span(range, "range");
        joint.lower = values_.quantity(range, "range", position, 0);
        joint.upper = values_.quantity(range, "range", position, 1);
      }
      if (angular && !limited) joint.type = JointType::Continuous;
    }
    if (const Attr ref = lookup("ref"); ref && (angular || linear))
      if (const auto v = values_.numbers(ref, "ref", 1))
        qpos0_[joint.name.text] = to_model_units((*v)[0], linear ? Unit::Meter : compiler_.degree ? Unit::Degree : Unit::Radian);
    const bool rotational = !linear;
    joint.armature = values_.quantity(lookup("armature"), "armature", rotational ? Unit::KilogramMeter2 : Unit::Kilogram);
    joint.joint_damping = values_.quantity(lookup("damping"), "damping",
                                           rotational ? Unit::NewtonMeterSecondPerRadian : Unit::NewtonSecondPerMeter);
    joint.joint_stiffness = values_.quantity(lookup("stiffness"), "stiffness",
                                             rotational ? Unit::NewtonMeterPerRadian : Unit::NewtonPerMeter);
    joint.joint_friction = values_.quantity(lookup("frictionloss"), "frictionloss", rotational ? Unit::NewtonMeter : Unit::Newton);
    // A joint's own bound on the summed actuator force (actuatorfrcrange) is its effort limit.
    if (const Attr a = lookup("actuatorfrcrange"); a && (angular || linear)) {
      const bool limited = values_.flag(lookup("actuatorfrclimited"), "actuatorfrclimited").value_or(compiler_.autolimits);
      if (auto v = values_.numbers(a, "actuatorfrcrange", 2); v && limited) {
        const std::size_t i = std::abs((*v)[1]) >= std::abs((*v)[0]) ? 1 : 0;
        joint.effort = values_.quantity(a, "actuatorfrcrange", angular ? Unit::NewtonMeter : Unit::Newton, i,
                                        (*v)[i] < 0 ? -1.0 : 1.0);
      }
    }
    // Unset quantities that only restate MuJoCo's zero defaults from a class stay as written.
    result_.asset.joints.push_back(std::move(joint));
    return 1;
  }

  // <equality><joint joint1 joint2 polycoef>: q1 = c0 + c1·q2 + c2·q2² + c3·q2³ + c4·q2⁴.
  // joint1 is the mimic of joint2, unless only joint1 is actuated (see below).
  void read_equality_joint(const XMLElement* el) {
    const char* cls = el->Attribute("class");
    if (cls && !defaults_.has_class(cls)) {
      values_.unknown_class(values_.value_span(own(el, "class"), "class"), "class", cls);
      return;
    }
    const auto& defs = defaults_.elements(cls ? cls : "main", "equality");
    if (values_.flag(Defaults::lookup(el, defs, "active"), "active") == false) return;
    const char* joint1 = el->Attribute("joint1");
    const char* joint2 = el->Attribute("joint2");
    const Span span = values_.element_span(el);
    if (!joint1) {
      values_.error(span, "<equality><joint> without joint1");
      return;
    }
    auto follower = std::find_if(result_.asset.joints.begin(), result_.asset.joints.end(),
                                 [&](const Joint& j) { return j.name.text == joint1; });
    if (follower == result_.asset.joints.end()) {
      values_.error(values_.value_span(own(el, "joint1"), "joint1"), fmt::format("<equality><joint>: unknown joint '{}'", joint1));
      return;
    }
    if (!joint2) {
      values_.unsupported(span, fmt::format("<equality><joint> holds '{}' at a fixed position (no joint2)", joint1))
          .note("A joint held in place is no mimic; asset-lint does not model it.");
      return;
    }
    const Attr coef = own(el, "polycoef");
    auto c = coef ? values_.numbers(coef, "polycoef") : std::optional<std::vector<double>>(std::vector<double>{0, 1});
    if (!c) return;
    for (std::size_t i = 2; i < c->size(); ++i)
      if ((*c)[i] != 0) {
        values_.unsupported(values_.token_span(coef, "polycoef", i),
                            fmt::format("coupling of '{}' is nonlinear (polycoef c{} = {})", joint1, i,
                                        format_number((*c)[i])))
            .note("The mimic rules assume q1 = c0 + c1·q2; a polynomial coupling maps the leader's range elsewhere, so "
                  "they skip this pair rather than judge its linear part.");
        return;
      }
    // MuJoCo's equality is symmetric: it holds q1 − f(q2) at zero without preferring a side.
    // When only joint1 is actuated, joint2 is the one that follows (q2 = (q1 − c0) / c1).
    auto leader = std::find_if(result_.asset.joints.begin(), result_.asset.joints.end(),
                               [&](const Joint& j) { return j.name.text == joint2; });
    const double c0 = c->empty() ? 0.0 : (*c)[0], c1 = c->size() > 1 ? (*c)[1] : 0.0;
    if (leader != result_.asset.joints.end() && follower->actuation == Actuation::Actuated &&
        (leader->actuation == Actuation::Passive || leader->actuation == Actuation::Linkage) && c1 != 0 && std::isfinite(c0 / c1)) {
      if (leader->mimic) return;
      Mimic mimic;
      mimic.span = span;
      mimic.reference = Name{joint1, values_.value_span(own(el, "joint1"), "joint1")};
      mimic.multiplier = Quantity::unauthored(1.0 / c1, Unit::None);
      mimic.offset = Quantity::unauthored(-c0 / c1, leader->type == JointType::Prismatic ? Unit::Meter : Unit::Radian);
      leader->mimic = std::move(mimic);
      return;
    }
    if (follower->mimic) return;
    Mimic mimic;
    mimic.span = span;
    mimic.reference = Name{joint2, values_.value_span(own(el, "joint2"), "joint2")};
    const Unit offset_unit = follower->type == JointType::Prismatic ? Unit::Meter : Unit::Radian;  // polycoef is never in degrees
    auto multiplier = c->size() > 1 && coef ? values_.quantity(coef, "polycoef", Unit::None, 1) : std::nullopt;
    mimic.multiplier = multiplier ? *multiplier : Quantity::unauthored(c->size() > 1 ? (*c)[1] : 0.0, Unit::None);
    auto offset = coef ? values_.quantity(coef, "polycoef", offset_unit, 0) : std::nullopt;
    mimic.offset = offset ? *offset : Quantity::unauthored(0.0, offset_unit);
    follower->mimic = std::move(mimic);
  }

  MjcfSources sources_;
  ReadResult result_;
  std::unordered_map<std::string, double> qpos0_;  // joints whose `ref` is written: their reference position
  Values values_;
  Compiler compiler_;
  Defaults defaults_;
  MeshAssets meshes_;
  MujocoVersion mujoco_;
  physics::DampRatioRule dampratio_rule_;

  // Attributes the release judged for no longer accepts, anywhere in the model: MuJoCo 3.5
  // renamed <camera orthographic="true|false"> to projection="orthographic|perspective" and
  // refuses the old name.
  void report_removed_attributes(const XMLElement* parent) {
    for (const XMLElement* el : sources_.children(parent)) {
      if (std::string_view(el->Name()) == "camera" && el->Attribute("orthographic") &&
          std::make_pair(mujoco_.major, mujoco_.minor) >= std::make_pair(3, 5))
        values_.error(values_.value_span(own(el, "orthographic"), "orthographic"),
                      "<camera orthographic>: MuJoCo 3.5 and later refuse the model (the attribute is now projection)")
            .note("Write projection=\"orthographic\" for orthographic=\"true\", projection=\"perspective\" for \"false\".")
            .note(fmt::format("Judged for MuJoCo {}.{} ([mujoco] version); MuJoCo 3.3 and 3.4 accept it.", mujoco_.major,
                              mujoco_.minor));
      report_removed_attributes(el);
    }
  }
};

}  // namespace

ReadResult read_mjcf(std::shared_ptr<const SourceFile> file, const FileSystem& files, const ReadOptions& options) {
  return Reader(std::move(file), files, options).run();
}

bool looks_like_mjcf(std::string_view text) {
  const xml::XmlScan scan = xml::scan_xml(text);
  return !scan.tags.empty() && scan.tags.front().name == "mujoco";
}

}  // namespace assetlint::mjcf
