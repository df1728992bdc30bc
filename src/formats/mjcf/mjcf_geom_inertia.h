#pragma once
// A body's mass and inertia as MuJoCo's compiler derives them from its geoms when the body
// has no <inertial> (or <compiler inertiafromgeom="true">): each geom in the compiler's
// inertiagrouprange is a homogeneous solid of its `mass`, or of `density` × volume, and the
// body sums them (user_objects.cc, mjCGeom::Compile, GetVolume, SetInertia and
// mjCBody::InertiaFromGeom).
#include <tinyxml2.h>

#include <optional>
#include <string>
#include <vector>

#include "formats/mjcf/mjcf_defaults.h"
#include "formats/mjcf/mjcf_geom_shape.h"
#include "formats/mjcf/mjcf_values.h"
#include "physics/solid_inertia.h"

namespace assetlint::mjcf {

// One geom's contribution, in its body's frame; a geom whose mass is zero contributes nothing.
struct GeomMass {
  std::optional<physics::MassPart> part;  // nullopt: the geom adds no mass
  std::string unknown;                    // why its mass cannot be computed here (then part is nullopt)
};

// `shape` is the geom's shape (geom_shape); `defaults` the geom default elements of its class,
// outermost first.
GeomMass geom_mass(const tinyxml2::XMLElement* geom, const GeomShape& shape,
                   const std::vector<const tinyxml2::XMLElement*>& defaults, Values& values);

}  // namespace assetlint::mjcf
