#pragma once
// The collision shapes of an MJCF body: its geoms that collide (contype or conaffinity
// nonzero, from the geom or its default class; MuJoCo's default for both is 1), as the model's
// CollisionShape. Boxes, spheres, capsules and cylinders keep their MuJoCo sizes (half-lengths
// become full lengths); mesh geoms take their <mesh> asset's file (with <compiler meshdir> or
// assetdir) or inline vertices, and its scale. Ellipsoids, planes, height fields and primitives
// fitted to a mesh have no CollisionShape kind and are left out.
#include <tinyxml2.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "formats/mjcf/mjcf_defaults.h"
#include "formats/mjcf/mjcf_geom_shape.h"
#include "formats/mjcf/mjcf_sources.h"
#include "formats/mjcf/mjcf_values.h"
#include "model/asset.h"

namespace assetlint::mjcf {

// One <asset><mesh>: its file (meshdir applied, relative to the model's directory unless
// absolute) or its inline vertices (scaled), and its scale.
struct MeshAsset {
  std::string file;
  std::vector<Eigen::Vector3d> vertices;
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
};
using MeshAssets = std::map<std::string, MeshAsset, std::less<>>;

// The <mesh> elements of every <asset> section, by name (MuJoCo's default name: the file's
// name without folder and extension).
MeshAssets read_mesh_assets(const MjcfSources& sources, const std::vector<const tinyxml2::XMLElement*>& sections,
                            const Defaults& defaults, const Compiler& compiler, Values& values);

// Whether the geom collides with anything (contype or conaffinity nonzero).
bool geom_collides(const tinyxml2::XMLElement* geom, const std::vector<const tinyxml2::XMLElement*>& defaults,
                   Values& values);

// The geom as a collision shape; nullopt for a type the model has no shape for, an incomplete
// size, or a mesh asset that is not defined.
std::optional<CollisionShape> collision_shape(const tinyxml2::XMLElement* geom, const GeomShape& shape,
                                              const MeshAssets& meshes, Values& values);

}  // namespace assetlint::mjcf
