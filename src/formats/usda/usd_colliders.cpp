#include "formats/usda/usd_colliders.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <unordered_map>

#include "formats/usda/parser.h"
#include "model/units.h"

namespace assetlint::usda {
namespace {

constexpr std::size_t kNone = static_cast<std::size_t>(-1);

std::optional<std::vector<double>> numbers_of(const Stage& stage, const ComposedPrim& prim, std::string_view name) {
  auto opinion = prim.attribute(name);
  if (!opinion || !opinion->attribute->default_value) return std::nullopt;
  std::vector<double> out;
  if (!read_numbers(*opinion->attribute->default_value, stage.sources.at(opinion->file)->view(), out)) return std::nullopt;
  return out;
}

double scalar_of(const Stage& stage, const ComposedPrim& prim, std::string_view name, double fallback) {
  auto v = numbers_of(stage, prim, name);
  return v && v->size() == 1 && std::isfinite((*v)[0]) ? (*v)[0] : fallback;
}

std::optional<std::string> token_of(const ComposedPrim& prim, std::string_view name) {
  auto opinion = prim.attribute(name);
  if (!opinion || !opinion->attribute->default_value) return std::nullopt;
  auto token = opinion->attribute->default_value->as_string();
  return token ? std::optional<std::string>(std::string(*token)) : std::nullopt;
}

Eigen::Matrix3d axis_rotation(char axis, double degrees) {
  const double radians = radians_from_degrees(degrees);
  const Eigen::Vector3d about = axis == 'X' ? Eigen::Vector3d::UnitX() : axis == 'Y' ? Eigen::Vector3d::UnitY()
                                                                                      : Eigen::Vector3d::UnitZ();
  return Eigen::AngleAxisd(radians, about).toRotationMatrix();
}

// One xformOp's matrix (column vectors, stage units); identity for an op without a readable value.
Eigen::Affine3d op_matrix(const Stage& stage, const ComposedPrim& prim, std::string_view op) {
  Eigen::Affine3d m = Eigen::Affine3d::Identity();
  const auto v = numbers_of(stage, prim, op);
  if (!v || std::any_of(v->begin(), v->end(), [](double x) { return !std::isfinite(x); })) return m;
  std::string_view kind = op.substr(std::string_view("xformOp:").size());
  kind = kind.substr(0, kind.find(':'));
  if (kind == "translate" && v->size() == 3) m.translation() = Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]);
  else if (kind == "scale" && v->size() == 3) m.linear() = Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]).asDiagonal();
  else if (kind == "orient" && v->size() == 4) {
    Eigen::Quaterniond q((*v)[0], (*v)[1], (*v)[2], (*v)[3]);  // USD writes the real part first
    if (q.norm() > 1e-12) m.linear() = q.normalized().toRotationMatrix();
  } else if (kind == "transform" && v->size() == 16) {
    // USD matrices act on row vectors, translation in the last row: the transpose acts on columns.
    Eigen::Matrix4d row_major;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) row_major(r, c) = (*v)[static_cast<std::size_t>(4 * r + c)];
    m.matrix() = row_major.transpose();
  } else if (kind.size() == 7 && kind.starts_with("rotate") && v->size() == 1) {
    m.linear() = axis_rotation(kind[6], (*v)[0]);
  } else if (kind.size() == 9 && kind.starts_with("rotate") && v->size() == 3) {
    // rotateXYZ: about X first, then Y, then Z.
    for (int i = 0; i < 3; ++i) m.linear() = axis_rotation(kind[6 + static_cast<std::size_t>(i)], (*v)[static_cast<std::size_t>(i)]) * m.linear();
  }
  return m;
}

// The prim's local transform: its xformOpOrder, first op outermost.
Eigen::Affine3d local_transform(const Stage& stage, const ComposedPrim& prim) {
  Eigen::Affine3d m = Eigen::Affine3d::Identity();
  auto opinion = prim.attribute("xformOpOrder");
  if (!opinion || !opinion->attribute->default_value) return m;
  auto order = opinion->attribute->default_value->as_string_list();
  if (!order) return m;
  for (std::string_view op : *order) {
    constexpr std::string_view kInvert = "!invert!";
    const bool invert = op.starts_with(kInvert);
    if (invert) op.remove_prefix(kInvert.size());
    if (!op.starts_with("xformOp:")) continue;  // !resetXformStack!
    Eigen::Affine3d step = op_matrix(stage, prim, op);
    if (invert && std::abs(step.linear().determinant()) > 1e-30) step = step.inverse();
    m = m * step;
  }
  return m;
}

// The rotation of a linear map without its scale (polar decomposition), a proper rotation.
Eigen::Matrix3d rotation_of(const Eigen::Matrix3d& linear) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(linear, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d r = svd.matrixU() * svd.matrixV().transpose();
  if (r.determinant() < 0) r = svd.matrixU() * Eigen::Vector3d(1, 1, -1).asDiagonal() * svd.matrixV().transpose();
  return r;
}

// Shapes along z in the model: the rotation that turns z onto the USD axis token.
Eigen::Matrix3d z_onto(char axis) {
  if (axis == 'X') return Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  if (axis == 'Y') return Eigen::AngleAxisd(-std::numbers::pi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  return Eigen::Matrix3d::Identity();
}

class Colliders {
 public:
  Colliders(const Stage& stage, double mpu, Asset& asset) : stage_(stage), mpu_(mpu), asset_(asset) {
    for (std::size_t i = 0; i < asset.links.size(); ++i) link_of_.emplace(asset.links[i].name.text, i);
  }

  void read(std::size_t index, const std::vector<bool>& on_stage) {
    const ComposedPrim& prim = stage_.prims[index];
    if (!prim.has_api_schema("PhysicsCollisionAPI")) return;
    if (auto enabled = prim.attribute("physics:collisionEnabled"); enabled && enabled->attribute->default_value)
      if (!enabled->attribute->default_value->as_bool().value_or(true)) return;
    // The nearest rigid body at or above the collider, and the transform from it.
    Eigen::Affine3d below = Eigen::Affine3d::Identity();
    std::size_t at = index;
    while (at != kNone && !(on_stage[at] && stage_.prims[at].has_api_schema("PhysicsRigidBodyAPI"))) {
      below = local_transform(stage_, stage_.prims[at]) * below;
      at = stage_.prims[at].parent;
    }
    if (at == kNone) return;  // a static collider: not part of the robot
    const auto link = link_of_.find(stage_.prims[at].path);
    if (link == link_of_.end()) return;
    const Eigen::Affine3d body = local_transform(stage_, stage_.prims[at]);
    Eigen::Affine3d body_frame = Eigen::Affine3d::Identity();
    body_frame.linear() = rotation_of(body.linear());
    body_frame.translation() = body.translation();
    const Eigen::Affine3d in_body = body_frame.inverse() * body * below;
    if (auto shape = shape_of(prim, in_body)) {
      asset_.links[link->second].collisions.push_back(std::move(*shape));
      return;
    }
    // PhysX merges the meshes below a collider with PhysxMeshMergeCollisionAPI into one shape
    // (Isaac Sim's importers write a link's colliders so: an Xform referencing its meshes).
    if (prim.has_api_schema("PhysxMeshMergeCollisionAPI")) merged_meshes(index, in_body, on_stage, link->second);
  }

  void merged_meshes(std::size_t index, const Eigen::Affine3d& in_body, const std::vector<bool>& on_stage,
                     std::size_t link) {
    std::vector<std::pair<std::size_t, Eigen::Affine3d>> pending{{index, in_body}};
    while (!pending.empty()) {
      auto [at, transform] = pending.back();
      pending.pop_back();
      for (std::size_t child : stage_.prims[at].children) {
        if (!on_stage[child]) continue;
        const ComposedPrim& prim = stage_.prims[child];
        const Eigen::Affine3d below = transform * local_transform(stage_, prim);
        if (prim.has_api_schema("PhysicsCollisionAPI")) continue;  // a collider of its own: read() takes it
        if (prim.type_name == "Mesh") {
          if (auto shape = shape_of(prim, below)) asset_.links[link].collisions.push_back(std::move(*shape));
        } else {
          pending.emplace_back(child, below);
        }
      }
    }
  }

 private:
  // `in_body`: the collider's transform in the body frame, stage units, scale included.
  std::optional<CollisionShape> shape_of(const ComposedPrim& prim, const Eigen::Affine3d& in_body) const {
    CollisionShape shape;
    shape.span = prim.span();
    const Eigen::Matrix3d rotation = rotation_of(in_body.linear());
    const Eigen::Matrix3d stretch = rotation.transpose() * in_body.linear();  // the scale in the shape's frame
    const Eigen::Vector3d scale = stretch.diagonal().cwiseAbs();
    shape.pose.translation() = in_body.translation() * mpu_;
    shape.pose.linear() = rotation;
    const std::string& type = prim.type_name;
    if (type == "Cube") {
      shape.kind = CollisionShape::Kind::Box;
      shape.size = scale * (scalar_of(stage_, prim, "size", 2.0) * mpu_);
    } else if (type == "Sphere") {
      shape.kind = CollisionShape::Kind::Sphere;
      shape.size = {scalar_of(stage_, prim, "radius", 1.0) * scale.maxCoeff() * mpu_, 0, 0};
    } else if (type == "Cylinder" || type == "Capsule") {
      const bool capsule = type == "Capsule";
      shape.kind = capsule ? CollisionShape::Kind::Capsule : CollisionShape::Kind::Cylinder;
      const std::string axis = token_of(prim, "axis").value_or("Z");
      const char a = axis == "X" || axis == "Y" ? axis[0] : 'Z';
      const int along = a == 'X' ? 0 : a == 'Y' ? 1 : 2;
      double radial = 0;
      for (int i = 0; i < 3; ++i)
        if (i != along) radial = std::max(radial, scale[i]);
      shape.size = {scalar_of(stage_, prim, "radius", capsule ? 0.5 : 1.0) * radial * mpu_,
                    scalar_of(stage_, prim, "height", capsule ? 1.0 : 2.0) * scale[along] * mpu_, 0};
      shape.pose.linear() = rotation * z_onto(a);
    } else if (type == "Mesh") {
      shape.kind = CollisionShape::Kind::Mesh;
      shape.mesh = prim.path;
      const auto values = numbers_of(stage_, prim, "points");
      if (values && values->size() % 3 == 0)
        for (std::size_t i = 0; i < values->size(); i += 3)
          shape.points.push_back(stretch * Eigen::Vector3d((*values)[i], (*values)[i + 1], (*values)[i + 2]) * mpu_);
    } else {
      return std::nullopt;
    }
    return shape;
  }

  const Stage& stage_;
  double mpu_;
  Asset& asset_;
  std::unordered_map<std::string, std::size_t> link_of_;
};

}  // namespace

void read_colliders(const Stage& stage, const std::vector<bool>& on_stage, double meters_per_unit, Asset& asset) {
  Colliders colliders(stage, meters_per_unit, asset);
  for (std::size_t i = 0; i < stage.prims.size(); ++i)
    if (on_stage[i]) colliders.read(i, on_stage);
}

}  // namespace assetlint::usda
