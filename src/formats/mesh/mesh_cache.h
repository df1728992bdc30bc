#pragma once
// Collision mesh vertices read once per run: every check of every file that names the same mesh
// file shares one read (and one failure). Vertices are deduplicated (an STL repeats each one in
// every triangle that uses it): what a convex hull needs, a third of the memory.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

namespace assetlint::mesh {

// The distinct vertices of the mesh file at `path` (resolved, in the file's units); nullptr with
// `error` when it cannot be read (read_points' reason).
std::shared_ptr<const std::vector<Eigen::Vector3d>> cached_points(const std::string& path, std::string& error);

}  // namespace assetlint::mesh
