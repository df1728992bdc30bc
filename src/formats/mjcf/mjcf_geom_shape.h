#pragma once
// A geom's shape as MuJoCo's compiler reads it, before it gives the geom a mass or a collider:
// the type (MuJoCo's default sphere), the size (MuJoCo's radii and half-lengths, `fromto`
// applied), the pose in the body frame (pos and quat / axisangle / euler / xyaxes / zaxis per
// <compiler angle> and eulerseq, or fromto's midpoint and direction) and the mesh it names.
#include <tinyxml2.h>

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "formats/mjcf/mjcf_values.h"

namespace assetlint::mjcf {

struct GeomShape {
  std::string type = "sphere";
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  std::string mesh;  // the <mesh> asset named by the geom (or its class); empty when none
};

// `defaults` are the geom default elements of the geom's class, outermost first.
GeomShape geom_shape(const tinyxml2::XMLElement* geom, const std::vector<const tinyxml2::XMLElement*>& defaults,
                     const Compiler& compiler, Values& values);

}  // namespace assetlint::mjcf
