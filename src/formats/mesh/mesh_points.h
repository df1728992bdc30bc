#pragma once
// The points of a collision mesh file, for shapes that collide as their convex hull:
// binary and ASCII STL and Wavefront OBJ read here, Collada (.dae) through assimp.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace assetlint::mesh {

// Every vertex of the file in its own frame and units (node transforms of a Collada scene
// applied); nullopt with `error` saying why (unreadable, unknown format, no vertices).
std::optional<std::vector<Eigen::Vector3d>> read_points(const std::string& path, std::string& error);

// The file a URDF mesh filename names: `package://pkg/rest` is resolved by finding the
// package.xml whose <name> is pkg under `root` (the checked tree), `file://` and absolute paths
// as they are, a relative path against `base_dir`. nullopt with `error` when nothing matches.
std::optional<std::string> resolve_mesh(const std::string& filename, const std::string& base_dir,
                                        const std::string& root, std::string& error);

}  // namespace assetlint::mesh
