#include "formats/mjcf/mjcf_geom_inertia.h"

#include <fmt/format.h>

#include <cmath>

#include "util/numbers.h"

namespace assetlint::mjcf {
namespace {

using tinyxml2::XMLElement;

// MuJoCo's geom density default (kg/m³) and the volume and mass below which it treats a geom
// as having none (mjEPS).
constexpr double kDefaultDensity = 1000.0;
constexpr double kTiny = 1e-14;

std::optional<physics::Solid> solid_of(std::string_view type) {
  if (type == "sphere") return physics::Solid::Sphere;
  if (type == "capsule") return physics::Solid::Capsule;
  if (type == "cylinder") return physics::Solid::Cylinder;
  if (type == "box") return physics::Solid::Box;
  if (type == "ellipsoid") return physics::Solid::Ellipsoid;
  return std::nullopt;
}

// The sizes a solid needs, all positive.
bool complete(const physics::SolidShape& shape) {
  const int needed = shape.kind == physics::Solid::Sphere ? 1
                     : (shape.kind == physics::Solid::Capsule || shape.kind == physics::Solid::Cylinder) ? 2
                                                                                                           : 3;
  for (int i = 0; i < needed; ++i)
    if (!(shape.size[i] > 0) || !std::isfinite(shape.size[i])) return false;
  return true;
}

}  // namespace

GeomMass geom_mass(const XMLElement* geom, const std::vector<const XMLElement*>& defaults, const Compiler& compiler,
                   Values& values) {
  auto lookup = [&](const char* name) { return Defaults::lookup(geom, defaults, name); };
  GeomMass out;
  const Span at = values.element_span(geom);
  const Attr type_attr = lookup("type");
  const std::string type(type_attr ? trim(type_attr.value) : std::string_view("sphere"));
  if (type == "plane") return out;  // no volume: MuJoCo gives it no mass whatever its density
  if (lookup("mesh")) {
    out.unknown = fmt::format("a geom at line {} takes its shape from a mesh", at.line);
    return out;
  }
  const auto solid = solid_of(type);
  if (!solid) {
    out.unknown = fmt::format("a geom of type '{}' at line {}", type, at.line);
    return out;
  }
  if (auto shell = values.flag(lookup("shellinertia"), "shellinertia"); shell && *shell) {
    out.unknown = fmt::format("a geom at line {} has shellinertia=\"true\"", at.line);
    return out;
  }

  physics::SolidShape shape{*solid, Eigen::Vector3d::Zero()};
  if (auto s = values.numbers(lookup("size"), "size"))
    for (std::size_t i = 0; i < s->size() && i < 3; ++i) shape.size[static_cast<Eigen::Index>(i)] = (*s)[i];

  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  if (auto ft = values.numbers(lookup("fromto"), "fromto", 6)) {
    const Eigen::Vector3d from((*ft)[0], (*ft)[1], (*ft)[2]), to((*ft)[3], (*ft)[4], (*ft)[5]);
    const Eigen::Vector3d along = to - from;
    // The segment is the shape's z axis; for boxes and ellipsoids size[0] becomes both
    // cross-section half-widths, so the turn about z does not change the inertia.
    shape.size[1] = along.norm() / 2.0;
    if (*solid == physics::Solid::Box || *solid == physics::Solid::Ellipsoid) shape.size = {shape.size[0], shape.size[0], shape.size[1]};
    if (along.norm() > 0) rotation = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), along).toRotationMatrix();
    position = (from + to) / 2.0;
  } else {
    if (auto p = values.numbers(lookup("pos"), "pos", 3)) position = {(*p)[0], (*p)[1], (*p)[2]};
    rotation = orientation(geom, defaults, compiler, values);
  }
  if (!complete(shape)) {
    out.unknown = fmt::format("the {} geom at line {} has no complete size", type, at.line);
    return out;
  }

  const double volume = physics::solid_volume(shape);
  double mass = 0;
  if (auto m = values.numbers(lookup("mass"), "mass", 1)) {
    if ((*m)[0] == 0 || !(volume > kTiny)) return out;
    mass = (*m)[0];
  } else {
    double density = kDefaultDensity;
    if (auto d = values.numbers(lookup("density"), "density", 1)) density = (*d)[0];
    mass = density * volume;
  }
  if (!(mass > kTiny) || !std::isfinite(mass)) {
    if (mass < 0) out.unknown = fmt::format("the geom at line {} has a negative mass or density", at.line);
    return out;
  }
  physics::MassPart part;
  part.mass = mass;
  part.com = position;
  part.inertia = rotation * physics::solid_principal_moments(shape, mass).asDiagonal() * rotation.transpose();
  out.part = part;
  return out;
}

}  // namespace assetlint::mjcf
