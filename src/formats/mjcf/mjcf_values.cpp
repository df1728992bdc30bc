#include "formats/mjcf/mjcf_values.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "rules/reader_rules.h"
#include "util/numbers.h"

namespace assetlint::mjcf {

using tinyxml2::XMLElement;

Diagnostic& Values::error(const Span& span, std::string message) {
  out_.push_back({std::string(rules::kParseError.id), rules::kParseError.default_severity, span, std::move(message),
                  std::nullopt, {}, {}, {}});
  return out_.back();
}

Diagnostic& Values::unsupported(const Span& span, std::string message) {
  out_.push_back({std::string(rules::kMjcfUnsupported.id), rules::kMjcfUnsupported.default_severity, span,
                  std::move(message), std::nullopt, {}, {}, {}});
  return out_.back();
}

void Values::unknown_class(const Span& span, std::string_view attribute, std::string_view cls) {
  ++unknown_class_uses_;
  const bool new_name = std::find(unknown_classes_.begin(), unknown_classes_.end(), cls) == unknown_classes_.end();
  if (new_name) unknown_classes_.emplace_back(cls);
  if (!unknown_class_error_) {
    error(span, fmt::format("unknown default class '{}'", cls))
        .note(fmt::format("MuJoCo's compiler refuses the model at the first {}= that names no <default class>; "
                          "a loader that adds the class before compiling makes it valid.",
                          attribute));
    unknown_class_error_ = out_.size() - 1;
    return;
  }
  Diagnostic& d = out_[*unknown_class_error_];
  d.note(span, new_name ? fmt::format("'{}' is not defined either", cls) : fmt::format("'{}' used again", cls));
  std::string names;
  for (std::size_t i = 0; i < unknown_classes_.size() && i < 3; ++i)
    names += (i == 0 ? "'" : ", '") + unknown_classes_[i] + "'";
  if (unknown_classes_.size() > 3) names += ", …";
  d.message = unknown_classes_.size() == 1
                  ? fmt::format("unknown default class {}, used {} times", names, unknown_class_uses_)
                  : fmt::format("{} unknown default classes ({}), used {} times", unknown_classes_.size(), names,
                                unknown_class_uses_);
}

std::optional<std::vector<double>> Values::numbers(const Attr& a, const char* name, std::size_t count) {
  if (!a) return std::nullopt;
  auto values = parse_doubles(a.value);
  if (!values || values->empty() || (count > 0 && values->size() != count)) {
    error(value_span(a, name),
          count > 0 ? fmt::format("<{} {}>: expected {} number{}, found '{}'", a.element->Name(), name, count,
                                  count == 1 ? "" : "s", a.value)
                    : fmt::format("<{} {}>: expected numbers, found '{}'", a.element->Name(), name, a.value));
    return std::nullopt;
  }
  return values;
}

OptQuantity Values::quantity(const Attr& a, const char* name, Unit unit, std::size_t index, double scale) {
  if (!a) return std::nullopt;
  auto values = parse_doubles(a.value);
  if (!values || values->size() <= index) {
    error(value_span(a, name), fmt::format("<{} {}>: expected {} number{}, found '{}'", a.element->Name(), name,
                                           index + 1, index == 0 ? "" : "s", a.value));
    return std::nullopt;
  }
  const Span span = values->size() == 1 ? value_span(a, name) : token_span(a, name, index);
  Quantity q = Quantity::from_authored((*values)[index], unit, span, scale);
  q.declaration = values->size() == 1 ? sources_.document_of(a.element).attribute_span(a.element, name) : span;
  note_use(a, span);
  return q;
}

// A value written inside <default> is inherited by every element of that class.
void Values::note_use(const Attr& a, const Span& span) {
  for (const tinyxml2::XMLNode* node = a.element->Parent(); node; node = node->Parent()) {
    const XMLElement* el = node->ToElement();
    if (!el || std::string_view(el->Name()) != "default") continue;
    InheritedLiteral& literal = inherited_[{span.file, span.offset}];
    if (literal.uses++ == 0) {
      literal.span = span;
      const char* cls = el->Attribute("class");
      literal.owner = fmt::format("default class '{}'", cls ? cls : "main");
    }
    return;
  }
}

std::vector<InheritedLiteral> Values::inherited_literals() const {
  std::vector<InheritedLiteral> out;
  out.reserve(inherited_.size());
  for (const auto& [key, literal] : inherited_) out.push_back(literal);
  return out;
}

std::optional<bool> Values::flag(const Attr& a, const char* name) {
  if (!a) return std::nullopt;
  const std::string_view v = trim(a.value);
  if (v == "true") return true;
  if (v == "false") return false;
  if (v != "auto") error(value_span(a, name), fmt::format("<{} {}>: expected true, false or auto, found '{}'",
                                                          a.element->Name(), name, a.value));
  return std::nullopt;
}

namespace {

Eigen::Matrix3d about(char axis, double angle) {
  const Eigen::Vector3d v = axis == 'x' ? Eigen::Vector3d::UnitX() : axis == 'y' ? Eigen::Vector3d::UnitY()
                                                                                 : Eigen::Vector3d::UnitZ();
  return Eigen::AngleAxisd(angle, v).toRotationMatrix();
}

double angle(double authored, const Compiler& compiler) {
  return compiler.degree ? to_model_units(authored, Unit::Degree) : authored;
}

}  // namespace

Eigen::Matrix3d orientation(const XMLElement* el, const std::vector<const XMLElement*>& defaults,
                            const Compiler& compiler, Values& values) {
  if (auto q = values.numbers(Defaults::lookup(el, defaults, "quat"), "quat", 4)) {
    // MuJoCo writes quaternions real part first: (w, x, y, z).
    Eigen::Quaterniond quat((*q)[0], (*q)[1], (*q)[2], (*q)[3]);
    if (quat.norm() > 1e-12) return quat.normalized().toRotationMatrix();
    return Eigen::Matrix3d::Identity();
  }
  if (auto v = values.numbers(Defaults::lookup(el, defaults, "axisangle"), "axisangle", 4)) {
    const Eigen::Vector3d axis((*v)[0], (*v)[1], (*v)[2]);
    if (axis.norm() > 1e-12) return Eigen::AngleAxisd(angle((*v)[3], compiler), axis.normalized()).toRotationMatrix();
    return Eigen::Matrix3d::Identity();
  }
  if (auto v = values.numbers(Defaults::lookup(el, defaults, "euler"), "euler", 3)) {
    Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
    for (std::size_t i = 0; i < 3 && i < compiler.eulerseq.size(); ++i) {
      const char c = compiler.eulerseq[i];
      const Eigen::Matrix3d step = about(static_cast<char>(std::tolower(static_cast<unsigned char>(c))), angle((*v)[i], compiler));
      // Lower case: about the moving frame's axis (post-multiply); upper case: the fixed parent axis.
      r = std::islower(static_cast<unsigned char>(c)) ? Eigen::Matrix3d(r * step) : Eigen::Matrix3d(step * r);
    }
    return r;
  }
  if (auto v = values.numbers(Defaults::lookup(el, defaults, "xyaxes"), "xyaxes", 6)) {
    Eigen::Vector3d x((*v)[0], (*v)[1], (*v)[2]), y((*v)[3], (*v)[4], (*v)[5]);
    if (x.norm() < 1e-12) return Eigen::Matrix3d::Identity();
    x.normalize();
    y -= x.dot(y) * x;
    if (y.norm() < 1e-12) return Eigen::Matrix3d::Identity();
    y.normalize();
    Eigen::Matrix3d r;
    r.col(0) = x;
    r.col(1) = y;
    r.col(2) = x.cross(y);
    return r;
  }
  if (auto v = values.numbers(Defaults::lookup(el, defaults, "zaxis"), "zaxis", 3)) {
    const Eigen::Vector3d z((*v)[0], (*v)[1], (*v)[2]);
    if (z.norm() < 1e-12) return Eigen::Matrix3d::Identity();
    return Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), z.normalized()).toRotationMatrix();
  }
  return Eigen::Matrix3d::Identity();
}

Eigen::Isometry3d pose(const XMLElement* el, const Compiler& compiler, Values& values) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  if (auto v = values.numbers(Attr{el, el->Attribute("pos")}, "pos", 3)) p.translation() = Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]);
  p.linear() = orientation(el, {}, compiler, values);
  return p;
}

}  // namespace assetlint::mjcf
