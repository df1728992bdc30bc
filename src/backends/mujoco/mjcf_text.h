#pragma once
// The pieces of MJCF text every generated scene writes alike: numbers at full precision,
// poses, and collision shapes with their meshes (points inline, one <mesh> per file and scale).
#include <Eigen/Geometry>
#include <functional>
#include <map>
#include <string>

#include "model/asset.h"
#include "verify/gripper_layout.h"

namespace assetlint::backends::mujoco {

std::string mjcf_number(double v);
std::string mjcf_vector(const Eigen::Vector3d& v);
std::string mjcf_quat(const Eigen::Matrix3d& r);
std::string mjcf_pose(const Eigen::Isometry3d& pose);  // pos="…" quat="…"

using MeshIds = std::map<std::string, std::size_t>;

// An <asset> block with one <mesh> per mesh file and scale among the shapes of the links
// `include` accepts (nothing when there is none); false with `error` when a mesh has too few points.
bool write_mesh_assets(const Asset& asset, const verify::MeshPoints& meshes,
                       const std::function<bool(const Link&)>& include, std::string& out, MeshIds& ids,
                       std::string& error);
// type="…" size="…" (or mesh="m<id>") of a shape.
std::string mjcf_geometry(const CollisionShape& shape, const MeshIds& ids);

}  // namespace assetlint::backends::mujoco
