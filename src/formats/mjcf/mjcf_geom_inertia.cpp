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

GeomMass geom_mass(const XMLElement* geom, const GeomShape& geom_shape, const std::vector<const XMLElement*>& defaults,
                   Values& values) {
  auto lookup = [&](const char* name) { return Defaults::lookup(geom, defaults, name); };
  GeomMass out;
  const Span at = values.element_span(geom);
  const std::string& type = geom_shape.type;
  if (type == "plane") return out;  // no volume: MuJoCo gives it no mass whatever its density
  if (!geom_shape.mesh.empty()) {
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
  const physics::SolidShape shape{*solid, geom_shape.size};
  const Eigen::Vector3d position = geom_shape.pose.translation();
  const Eigen::Matrix3d rotation = geom_shape.pose.linear();
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
