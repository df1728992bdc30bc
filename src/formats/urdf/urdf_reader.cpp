#include "formats/urdf/urdf_reader.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <memory>

#include "formats/urdf/mujoco_singletons.h"
#include "formats/urdf/urdfdom_check.h"
#include "formats/urdf/urdfdom_verdict.h"
#include "formats/xml/scanned_document.h"
#include "formats/xml/xml_spans.h"
#include "rules/reader_rules.h"
#include "util/numbers.h"

namespace assetlint::urdf {
namespace {

using xml::Element;

constexpr FileId kFile = 0;

class UrdfReader {
 public:
  explicit UrdfReader(std::shared_ptr<const SourceFile> file) : file_(*file), doc_(file_, kFile) {
    result_.asset.format = SourceFormat::Urdf;
    result_.asset.sources.push_back(std::move(file));
  }

  ReadResult run() {
    for (const auto& error : doc_.errors()) parse_error(error.span, error.message);
    const Element* robot = doc_.root();
    if (!robot) return fail();
    if (robot->name != "robot") {
      parse_error(element_span(robot), fmt::format("not a URDF: the root element is <{}>, expected <robot>", robot->name));
      return fail();
    }
    if (may_hold_xacro(doc_.document()) && find_xacro_expression()) return fail();

    result_.asset.robot_name = name_of(robot);
    result_.asset.robot_span = element_span(robot);
    read_mujoco_compiler(robot);
    std::size_t links = 0, joints = 0;
    for (const Element* el = doc_.first_child(robot); el; el = doc_.next_sibling(el)) {
      links += el->name == "link" ? 1 : 0;
      joints += el->name == "joint" ? 1 : 0;
    }
    result_.asset.links.reserve(links);
    result_.asset.joints.reserve(joints);
    for (const Element* el = doc_.first_child(robot); el; el = doc_.next_sibling(el)) {
      if (el->name == "link") read_link(el);
      else if (el->name == "joint") read_joint(el);
    }
    result_.asset.index_names();
    for (Diagnostic& d : repeated_singletons(doc_)) result_.diagnostics.push_back(std::move(d));
    std::optional<std::vector<std::string>> urdfdom_messages = predicted_urdfdom_errors(doc_);
    report_urdfdom(urdfdom_messages ? std::move(*urdfdom_messages) : urdfdom_errors(doc_.document()));
    return std::move(result_);
  }

 private:
  ReadResult fail() {
    result_.usable = false;
    return std::move(result_);
  }

  void parse_error(const Span& span, std::string message) {
    result_.diagnostics.push_back({std::string(rules::kParseError.id), rules::kParseError.default_severity, span,
                                   std::move(message), std::nullopt, {}, {}, {}});
  }

  Span element_span(const Element* el) const { return doc_.element_span(el); }
  Span value_span(const Element* el, std::string_view attr) const { return doc_.value_span(el, attr); }
  Span attribute_span(const Element* el, std::string_view attr) const { return doc_.attribute_span(el, attr); }
  std::optional<std::string_view> attribute(const Element* el, std::string_view attr) const { return doc_.value(el, attr); }

  Name name_of(const Element* el) const {
    const auto name = attribute(el, "name");
    return Name{name ? std::string(trim(*name)) : std::string(), name ? value_span(el, "name") : element_span(el)};
  }

  OptQuantity quantity(const Element* el, std::string_view attr, Unit unit) {
    if (!el) return std::nullopt;
    const xml::XmlAttributeSpan* a = el->attribute(attr);
    if (!a) return std::nullopt;
    const std::string_view raw = doc_.value(*a);
    const Span span = xml::value_span(file_, kFile, *a);
    auto value = parse_double(trim(raw));
    if (!value) {
      parse_error(span, fmt::format("<{} {}>: expected a number, found '{}'", el->name, attr, raw));
      return std::nullopt;
    }
    Quantity q = Quantity::from_authored(*value, unit, span);
    q.declaration = xml::attribute_span(file_, kFile, *a);
    return q;
  }

  std::optional<Eigen::Vector3d> vector3(const Element* el, std::string_view attr) {
    if (!el) return std::nullopt;
    const auto raw = attribute(el, attr);
    if (!raw) return std::nullopt;
    auto values = parse_doubles(*raw);
    if (!values || values->size() != 3) {
      parse_error(value_span(el, attr), fmt::format("<{} {}>: expected three numbers, found '{}'", el->name, attr, *raw));
      return std::nullopt;
    }
    return Eigen::Vector3d((*values)[0], (*values)[1], (*values)[2]);
  }

  Eigen::Isometry3d pose(const Element* origin) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    if (!origin) return pose;
    if (auto xyz = vector3(origin, "xyz")) pose.translation() = *xyz;
    if (auto rpy = vector3(origin, "rpy")) {
      // URDF fixed-axis roll, pitch, yaw: R = Rz(yaw) · Ry(pitch) · Rx(roll).
      pose.linear() = (Eigen::AngleAxisd((*rpy)[2], Eigen::Vector3d::UnitZ()) *
                       Eigen::AngleAxisd((*rpy)[1], Eigen::Vector3d::UnitY()) *
                       Eigen::AngleAxisd((*rpy)[0], Eigen::Vector3d::UnitX()))
                          .toRotationMatrix();
    }
    return pose;
  }

  // Whether find_xacro has anything to find: a walk over every attribute of a large file
  // costs more than searching its bytes (entities could spell "${", so '&' counts too).
  static bool may_hold_xacro(std::string_view document) {
    for (std::string_view marker : {"<xacro:", "${", "$(", "&"})
      if (document.find(marker) != std::string_view::npos) return true;
    return false;
  }

  // An unexpanded `${…}` or `$(…)` in a value means the file is xacro source: its values are not
  // values yet, so nothing in it can be judged. The first one is a parse error. In a file name
  // (a mesh, a texture) urdfdom keeps the text as written and reads the rest of the file, so
  // the file is checked and the names that no consumer can resolve get one warning.
  bool find_xacro_expression() {
    std::vector<const xml::XmlAttributeSpan*> file_names;
    for (const Element& el : doc_.scan().tags) {
      for (const xml::XmlAttributeSpan& a : el.attributes) {
        const std::string_view value = doc_.value(a);
        if (value.find("${") == std::string_view::npos && value.find("$(") == std::string_view::npos) continue;
        if (a.name == "filename") {
          file_names.push_back(&a);
          continue;
        }
        parse_error(xml::value_span(file_, kFile, a),
                    fmt::format("unexpanded xacro expression '{}'; check the .xacro source instead (asset-lint expands it)", value));
        return true;
      }
    }
    if (!file_names.empty()) report_unexpanded_file_names(file_names);
    report_stray_xacro_elements();
    return false;
  }

  void report_unexpanded_file_names(const std::vector<const xml::XmlAttributeSpan*>& names) {
    const std::string_view first = doc_.value(*names.front());
    Diagnostic finding{std::string(rules::kXacroUnexpanded.id), rules::kXacroUnexpanded.default_severity,
                       xml::value_span(file_, kFile, *names.front()),
                       fmt::format("unexpanded xacro expression '{}' in a file name; no URDF reader expands it",
                                   first_expression(first)),
                       std::nullopt, {}, {}, {}};
    finding.note(fmt::format("The file name is '{}'.", first));
    if (names.size() > 1) {
      std::vector<std::uint32_t> lines;
      for (std::size_t i = 1; i < names.size(); ++i) lines.push_back(xml::value_span(file_, kFile, *names[i]).line);
      finding.note(fmt::format("{} more file name{} hold one {}.", lines.size(), lines.size() == 1 ? "" : "s",
                               at_lines(lines)));
    }
    finding.note("urdfdom keeps the name as written; RViz, Gazebo and Isaac Sim's URDF importer then look for a file "
                 "of that literal name and find none, so the mesh, and any collider made from it, is missing from the "
                 "robot. The rest of the file is checked.");
    const std::string_view find = "$(find ";
    const auto at = first.find(find);
    const auto close = at == std::string_view::npos ? at : first.find(')', at);
    if (close != std::string_view::npos) {
      const std::string_view package = trim(first.substr(at + find.size(), close - at - find.size()));
      finding.note(fmt::format("Expand the xacro source again, or name the file through its package: "
                               "'package://{}{}'.",
                               package, first.substr(close + 1)));
    } else {
      finding.note("Expand the xacro source again.");
    }
    result_.diagnostics.push_back(std::move(finding));
  }

  // "(line 13)" or "(lines 13, 21, …)": where the other occurrences are, the first five named.
  static std::string at_lines(const std::vector<std::uint32_t>& lines) {
    std::string listed;
    for (std::size_t i = 0; i < lines.size() && i < 5; ++i) listed += fmt::format("{}{}", i ? ", " : "", lines[i]);
    return fmt::format("(line{} {}{})", lines.size() == 1 ? "" : "s", listed, lines.size() > 5 ? ", …" : "");
  }

  // The first `${…}` or `$(…)` in `text`, up to its closing bracket (the rest of the text when
  // it has none), cut at 40 characters.
  static std::string first_expression(std::string_view text) {
    const std::size_t a = text.find("${"), b = text.find("$(");
    const std::size_t start = std::min(a, b);
    const char close = start == a ? '}' : ')';
    const std::size_t end = text.find(close, start);
    std::string expression(text.substr(start, end == std::string_view::npos ? end : end - start + 1));
    if (expression.size() > 40) expression = expression.substr(0, 39) + "…";
    return expression;
  }

  static bool xacro_definition(std::string_view element) {
    return element == "xacro:property" || element == "xacro:arg" || element == "xacro:macro";
  }

  // Without expressions, an <xacro:…> element is a leftover in an expanded URDF: urdfdom and the
  // importers skip elements they do not know, so the file is read, and what the element was
  // meant to produce (a material, a sensor, a whole macro's links) is simply absent.
  void report_stray_xacro_elements() {
    // One finding per element name: an exporter that left a colour macro in every <visual>
    // left one problem, not thirty.
    std::vector<std::pair<std::string_view, std::vector<const Element*>>> by_name;
    for (const Element& el : doc_.scan().tags) {
      if (!el.name.starts_with("xacro:")) continue;
      auto same = std::find_if(by_name.begin(), by_name.end(), [&](const auto& entry) { return entry.first == el.name; });
      if (same == by_name.end()) by_name.push_back({el.name, {&el}});
      else same->second.push_back(&el);
    }
    for (const auto& [name, elements] : by_name) {
      Diagnostic finding{std::string(rules::kXacroUnexpanded.id), rules::kXacroUnexpanded.default_severity,
                         element_span(elements.front()),
                         fmt::format("<{}> left in an expanded URDF; URDF readers skip it", name), std::nullopt, {}, {}, {}};
      if (elements.size() > 1) {
        std::vector<std::uint32_t> lines;
        for (std::size_t i = 1; i < elements.size(); ++i) lines.push_back(element_span(elements[i]).line);
        finding.note(fmt::format("{} more <{}> element{} in the file {}.", lines.size(), name,
                                 lines.size() == 1 ? "" : "s", at_lines(lines)));
      }
      if (xacro_definition(name)) {
        // A definition produces nothing where it stands; what uses it would be reported itself
        // (a ${…} in a value, a macro call element).
        finding.severity = Severity::Info;
        finding.note("urdfdom, ROS and simulator importers ignore elements they do not know. A definition produces "
                     "nothing by itself and nothing in the file uses it, so the robot lacks nothing.");
        finding.note("Delete the element.");
      } else {
        finding.note("urdfdom, ROS and simulator importers ignore elements they do not know: whatever this xacro "
                     "element would have produced is missing from the robot. The rest of the file is checked.");
        finding.note("Expand the xacro source again, or delete the element if nothing is missing.");
      }
      result_.diagnostics.push_back(std::move(finding));
    }
  }

  // <mujoco><compiler boundinertia balanceinertia>: read as MuJoCo's URDF importer reads them.
  void read_mujoco_compiler(const Element* robot) {
    const Element* mujoco = doc_.first_child(robot, "mujoco");
    const Element* compiler = mujoco ? doc_.first_child(mujoco, "compiler") : nullptr;
    if (!compiler) return;
    UrdfMujocoCompiler& section = result_.asset.urdf_mujoco_compiler;
    if (const auto bound = attribute(compiler, "boundinertia"))
      if (const auto value = parse_double(*bound)) section.boundinertia = *value;
    section.balanceinertia = attribute(compiler, "balanceinertia") == std::optional<std::string_view>("true");
  }

  void read_link(const Element* el) {
    Link link;
    link.name = name_of(el);
    link.span = element_span(el);
    link.visual = doc_.first_child(el, "visual") != nullptr;
    if (const Element* in = doc_.first_child(el, "inertial")) {
      Inertial inertial;
      inertial.span = element_span(in);
      const Element* mass = doc_.first_child(in, "mass");
      auto m = quantity(mass, "value", Unit::Kilogram);
      inertial.mass = m ? *m : Quantity::unauthored(0.0, Unit::Kilogram);
      if (!m) inertial.mass.span = mass ? element_span(mass) : inertial.span;
      inertial.mass_authored = m.has_value();
      const Element* origin = doc_.first_child(in, "origin");
      const Eigen::Isometry3d frame = pose(origin);
      inertial.com = frame.translation();
      inertial.com_span = origin ? element_span(origin) : inertial.span;
      if (const Element* tensor = doc_.first_child(in, "inertia")) {
        inertial.inertia_span = element_span(tensor);
        auto component = [&](const char* attr) {
          auto q = quantity(tensor, attr, Unit::KilogramMeter2);
          return q ? q->value : 0.0;
        };
        const double ixx = component("ixx"), ixy = component("ixy"), ixz = component("ixz");
        const double iyy = component("iyy"), iyz = component("iyz"), izz = component("izz");
        Eigen::Matrix3d inertia;
        inertia << ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz;
        // The tensor is given in the inertial frame; rotate it into the link frame.
        inertial.inertia = frame.linear() * inertia * frame.linear().transpose();
      } else {
        inertial.inertia_span = inertial.span;
        inertial.inertia_authored = false;
      }
      link.inertial = inertial;
    }
    for (const Element* c = doc_.first_child(el, "collision"); c; c = doc_.next_sibling(c, "collision"))
      if (auto shape = collision(c)) link.collisions.push_back(std::move(*shape));
    result_.asset.links.push_back(std::move(link));
  }

  // One <collision>: its pose and its one geometry; an unreadable size leaves the shape out
  // (the parse error says why).
  std::optional<CollisionShape> collision(const Element* c) {
    const Element* geometry = doc_.first_child(c, "geometry");
    const Element* g = geometry ? doc_.first_child(geometry) : nullptr;
    if (!g) return std::nullopt;
    CollisionShape shape;
    shape.pose = pose(doc_.first_child(c, "origin"));
    shape.span = element_span(c);
    const auto length = [&](std::string_view attr) { return quantity(g, attr, Unit::Meter); };
    if (g->name == "box") {
      const auto size = vector3(g, "size");
      if (!size) return std::nullopt;
      shape.kind = CollisionShape::Kind::Box;
      shape.size = *size;
    } else if (g->name == "cylinder") {
      const auto radius = length("radius"), height = length("length");
      if (!radius || !height) return std::nullopt;
      shape.kind = CollisionShape::Kind::Cylinder;
      shape.size = {radius->value, height->value, 0};
    } else if (g->name == "sphere") {
      const auto radius = length("radius");
      if (!radius) return std::nullopt;
      shape.kind = CollisionShape::Kind::Sphere;
      shape.size = {radius->value, 0, 0};
    } else if (g->name == "mesh") {
      const auto file = attribute(g, "filename");
      if (!file) return std::nullopt;
      shape.kind = CollisionShape::Kind::Mesh;
      shape.mesh = std::string(trim(*file));
      if (attribute(g, "scale")) {
        const auto scale = vector3(g, "scale");
        if (!scale) return std::nullopt;
        shape.mesh_scale = *scale;
      }
    } else {
      return std::nullopt;
    }
    return shape;
  }

  static std::optional<JointType> joint_type(std::string_view text) {
    if (text == "revolute") return JointType::Revolute;
    if (text == "continuous") return JointType::Continuous;
    if (text == "prismatic") return JointType::Prismatic;
    if (text == "fixed") return JointType::Fixed;
    if (text == "floating") return JointType::Floating;
    if (text == "planar") return JointType::Planar;
    return std::nullopt;
  }

  void read_joint(const Element* el) {
    Joint joint;
    joint.name = name_of(el);
    joint.span = element_span(el);
    const auto type = attribute(el, "type");
    joint.type_span = type ? value_span(el, "type") : joint.span;
    auto parsed_type = joint_type(type ? trim(*type) : std::string_view());
    if (!parsed_type) return;  // urdfdom reports the unknown type (urdf-invalid); nothing to model
    joint.type = *parsed_type;
    const bool angular = is_angular(joint.type);

    auto link_ref = [&](std::string_view tag) {
      const Element* ref = doc_.first_child(el, tag);
      const auto link = attribute(ref, "link");
      return Name{link ? std::string(trim(*link)) : std::string(),
                  link ? value_span(ref, "link") : (ref ? element_span(ref) : joint.span)};
    };
    joint.parent = link_ref("parent");
    joint.child = link_ref("child");
    joint.frame_in_link[0] = pose(doc_.first_child(el, "origin"));

    if (const Element* axis = doc_.first_child(el, "axis")) {
      joint.axis_span = value_span(axis, "xyz");
      if (auto xyz = vector3(axis, "xyz"); xyz && xyz->norm() > 0) joint.axis = xyz->normalized();
    } else {
      joint.axis_span = joint.span;
    }

    if (const Element* limit = doc_.first_child(el, "limit")) {
      joint.limit_span = element_span(limit);
      const Unit position = angular ? Unit::Radian : Unit::Meter;
      joint.lower = quantity(limit, "lower", position);
      joint.upper = quantity(limit, "upper", position);
      joint.bounds_unreadable = (!joint.lower && limit->attribute("lower")) || (!joint.upper && limit->attribute("upper"));
      joint.effort = quantity(limit, "effort", angular ? Unit::NewtonMeter : Unit::Newton);
      joint.velocity = quantity(limit, "velocity", angular ? Unit::RadianPerSecond : Unit::MeterPerSecond);
    } else {
      joint.limit_span = joint.span;
    }
    if (const Element* dynamics = doc_.first_child(el, "dynamics")) {
      joint.joint_damping = quantity(dynamics, "damping", angular ? Unit::NewtonMeterSecondPerRadian : Unit::NewtonSecondPerMeter);
      joint.joint_friction = quantity(dynamics, "friction", angular ? Unit::NewtonMeter : Unit::Newton);
    }
    if (const Element* mimic = doc_.first_child(el, "mimic")) {
      Mimic m;
      m.span = element_span(mimic);
      const auto ref = attribute(mimic, "joint");
      m.reference = Name{ref ? std::string(trim(*ref)) : std::string(), ref ? value_span(mimic, "joint") : m.span};
      auto multiplier = quantity(mimic, "multiplier", Unit::None);
      m.multiplier = multiplier ? *multiplier : Quantity::unauthored(1.0, Unit::None);
      auto offset = quantity(mimic, "offset", angular ? Unit::Radian : Unit::Meter);
      m.offset = offset ? *offset : Quantity::unauthored(0.0, angular ? Unit::Radian : Unit::Meter);
      joint.mimic = m;
    }
    read_drake_armature(el, joint);
    result_.asset.joints.push_back(std::move(joint));
  }

  // Drake's URDF extension models the motor as rotor inertia and gear ratio; the
  // armature PhysX would see is their reflected inertia G²·I_rotor.
  void read_drake_armature(const Element* el, Joint& joint) {
    const Element* actuator = doc_.first_child(el, "drake:rotor_inertia");
    if (!actuator) return;
    auto rotor = quantity(actuator, "value", Unit::KilogramMeter2);
    if (!rotor) return;
    double gear = 1.0;
    if (auto ratio = quantity(doc_.first_child(el, "drake:gear_ratio"), "value", Unit::None)) gear = ratio->value;
    Quantity armature = *rotor;
    armature.value = rotor->value * gear * gear;
    joint.armature = armature;
    joint.motor = Motor{*rotor, gear, fmt::format("<drake:rotor_inertia> and <drake:gear_ratio> at line {}", rotor->span.line)};
  }

  // Reports urdfdom's complaints (empty: it accepts the file) as one finding: the first is
  // the cause, the rest (urdfdom's cascade, e.g. "Could not parse collision element" after
  // an unknown geometry) become located notes.
  void report_urdfdom(std::vector<std::string> messages) {
    // urdfdom's generic epilogue says nothing the specific messages before it do not.
    if (messages.size() > 1) std::erase(messages, std::string("joint xml is not initialized correctly"));
    // An undefined link is structure-undefined-link's finding, which says that urdfdom rejects it.
    // Only where asset-lint misses the link too: urdfdom does not trim names, so "palm " is
    // undefined to it but not to us, and then urdfdom's message is the only finding.
    std::erase_if(messages, [this](const std::string& m) {
      if (!m.starts_with("Failed to build tree: parent link [") && !m.starts_with("Failed to build tree: child link ["))
        return false;
      const std::size_t open = m.find('['), close = m.find(']', open);
      if (close == std::string::npos) return false;
      const std::string name = m.substr(open + 1, close - open - 1);
      return trim(name) == name && !result_.asset.find_link(name);
    });
    std::vector<std::pair<Span, std::string>> located;
    for (const auto& message : messages) {
      const Span span = locate_message(message);
      // urdfdom repeats a message once per element it rejects without naming it.
      const bool repeated = std::any_of(located.begin(), located.end(), [&](const auto& seen) {
        return seen.first.offset == span.offset && seen.second == message;
      });
      if (!repeated) located.emplace_back(span, message);
    }
    if (located.empty()) return;
    const auto& [span, first] = located.front();
    Diagnostic finding{std::string(rules::kUrdfInvalid.id), rules::kUrdfInvalid.default_severity, span, {}, std::nullopt, {}, {}, {}};
    const std::string primary = fmt::format("urdfdom rejects the file: {}", first);
    if (primary.size() <= kMaxPrimaryMessage) {
      finding.message = primary;
    } else {
      finding.message = "urdfdom rejects the file";
      finding.note(fmt::format("urdfdom: {}", first));
    }
    if (located.size() > 1)
      finding.note(fmt::format("urdfdom then reports {} more problem{}, most often consequences of the first:",
                               located.size() - 1, located.size() == 2 ? "" : "s"));
    for (std::size_t i = 1; i < located.size(); ++i) finding.note(located[i].first, located[i].second);
    finding.note("ROS tools, check_urdf, Gazebo's URDF path and the simulator importers built on urdfdom refuse it.");
    result_.diagnostics.push_back(std::move(finding));
  }

  Span locate_message(std::string_view message) const {
    std::vector<std::string_view> names;
    for (std::size_t pos = 0; pos < message.size(); ++pos) {
      const char open = message[pos];
      const char close = open == '[' ? ']' : open == '(' ? ')' : (open == '\'' || open == '"') ? open : '\0';
      if (!close) continue;
      const auto end = message.find(close, pos + 1);
      if (end == std::string_view::npos) break;
      names.push_back(message.substr(pos + 1, end - pos - 1));
      pos = end;
    }
    // "link 'x' is not unique": point at the repeated definition, not the first.
    if (message.find("not unique") != std::string_view::npos) {
      for (auto name : names) {
        const Span* last = nullptr;
        for (const auto& joint : result_.asset.joints)
          if (joint.name.text == name) last = &joint.name.span;
        for (const auto& link : result_.asset.links)
          if (link.name.text == name && (!last || link.name.span.offset > last->offset)) last = &link.name.span;
        if (last) return *last;
      }
    }
    for (auto name : names)
      if (const Joint* j = result_.asset.find_joint(name)) return j->name.span;
    for (auto name : names)
      if (const Link* l = result_.asset.find_link(name)) return l->name.span;
    // An element the model leaves out (a joint of unknown type): its name attribute.
    for (auto name : names)
      for (const auto& tag : doc_.scan().tags)
        if (const xml::XmlAttributeSpan* a = tag.attribute("name");
            a && trim(file_.view().substr(a->value_offset, a->value_length)) == name)
          return file_.span(kFile, a->value_offset, a->value_length);
    // A quoted element name ("Unknown geometry type 'capsule'"): its first occurrence.
    for (auto name : names)
      for (const auto& tag : doc_.scan().tags)
        if (tag.name == name) return file_.span(kFile, tag.offset, tag.end - tag.offset);
    return result_.asset.robot_span;
  }

  const SourceFile& file_;
  ReadResult result_;
  xml::ScannedDocument doc_;
};

}  // namespace

ReadResult read_urdf(std::shared_ptr<const SourceFile> file) { return UrdfReader(std::move(file)).run(); }

}  // namespace assetlint::urdf
