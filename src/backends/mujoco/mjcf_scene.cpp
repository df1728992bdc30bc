#include "backends/mujoco/mjcf_scene.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "backends/mujoco/mjcf_text.h"

namespace assetlint::backends::mujoco {
namespace {

using verify::SceneSpec;
using verify::VerifyPlan;

std::string num(double v) { return mjcf_number(v); }
std::string vec(const Eigen::Vector3d& v) { return mjcf_vector(v); }
std::string quat(const Eigen::Matrix3d& r) { return mjcf_quat(r); }
std::string pose_attributes(const Eigen::Isometry3d& pose) { return mjcf_pose(pose); }

class Writer {
 public:
  Writer(const VerifyPlan& plan, const SceneSpec& scene) : plan_(plan), scene_(scene), asset_(*plan.asset) {}

  std::string write(std::string& error) {
    const double h = plan_.timestep;
    const double mu = scene_.object ? scene_.object->friction : 1.0;
    out_ += "<mujoco model=\"asset-lint verify\">\n";
    out_ += "  <compiler angle=\"radian\" inertiafromgeom=\"auto\"/>\n";
    // multiccd: a flat convex (mesh) face on a box touches in several points, not one it pivots about.
    out_ += fmt::format("  <option timestep=\"{}\" integrator=\"{}\" cone=\"{}\" impratio=\"{}\" gravity=\"0 0 0\">"
                        "<flag multiccd=\"enable\"/></option>\n",
                        num(h), kIntegrator, kCone, num(kImpratio));
    out_ += "  <size njmax=\"1000\" nconmax=\"300\" nstack=\"2000000\"/>\n";
    out_ += "  <default>\n";
    // Contacts: stiff (a time constant of two steps), friction from the spec on both sides.
    out_ += fmt::format("    <geom solref=\"{} 1\" solimp=\"0.95 0.99 0.001\" friction=\"{} 0.005 0.0001\"/>\n",
                        num(2 * h), num(mu));
    out_ += fmt::format("    <equality solref=\"{} 1\"/>\n", num(2 * h));
    out_ += "  </default>\n";
    if (!write_meshes(error)) return {};
    out_ += "  <worldbody>\n";
    out_ += "    <body name=\"mount\" mocap=\"true\"/>\n";
    out_ += fmt::format("    <body name=\"mount_body\"><freejoint name=\"mount_free\"/>"
                        "<inertial pos=\"0 0 0\" mass=\"{}\" diaginertia=\"0.01 0.01 0.01\"/>\n",
                        num(kMountMass));
    if (!write_link(plan_.layout.root, Eigen::Isometry3d::Identity(), nullptr, 3, error)) return {};
    out_ += "    </body>\n";
    if (scene_.object) write_object(*scene_.object);
    out_ += "  </worldbody>\n";
    out_ += "  <equality>\n    <weld body1=\"mount\" body2=\"mount_body\"/>\n";
    for (const Joint* mimic : plan_.layout.mimics)
      out_ += fmt::format("    <joint joint1=\"{}\" joint2=\"{}\" polycoef=\"{} {} 0 0 0\"/>\n", joint_name(*mimic),
                          joint_name(*plan_.layout.driven), num(mimic->mimic->offset.value),
                          num(mimic->mimic->multiplier.value));
    out_ += "  </equality>\n";
    const verify::DriveSpec& d = plan_.drive;
    out_ += fmt::format(
        "  <actuator>\n    <general name=\"drive\" joint=\"{}\" ctrllimited=\"false\" gaintype=\"fixed\" gainprm=\"{}\" "
        "biastype=\"affine\" biasprm=\"0 {} {}\"",
        joint_name(*plan_.layout.driven), num(d.stiffness), num(-d.stiffness), num(-d.damping));
    if (d.max_force) out_ += fmt::format(" forcelimited=\"true\" forcerange=\"{} {}\"", num(-*d.max_force), num(*d.max_force));
    else out_ += " forcelimited=\"false\"";
    out_ += "/>\n  </actuator>\n</mujoco>\n";
    return std::move(out_);
  }

  private:
  std::string joint_name(const Joint& joint) const { return mujoco::joint_name(asset_, joint); }

  bool write_meshes(std::string& error) {
    return write_mesh_assets(asset_, plan_.meshes, [](const Link&) { return true; }, out_, mesh_ids_, error);
  }

  bool write_link(const std::string& name, const Eigen::Isometry3d& pose, const Joint* joint, int indent,
                  std::string& error) {
    const Link* link = asset_.find_link(name);
    if (!link || !visited_.insert(name).second) return true;
    const std::string pad(indent * 2, ' ');
    out_ += fmt::format("{}<body name=\"{}\" {}>\n", pad, body_name(asset_, *link), pose_attributes(pose));
    if (joint) {
      const bool angular = is_angular(joint->type);
      const Eigen::Isometry3d& in_child = joint->frame_in_link[1];
      out_ += fmt::format("{}  <joint name=\"{}\" type=\"{}\" pos=\"{}\" axis=\"{}\"", pad, joint_name(*joint),
                          angular ? "hinge" : "slide", vec(in_child.translation()),
                          vec(in_child.linear() * joint->axis.normalized()));
      if (joint->lower && joint->upper && std::isfinite(joint->lower->value) && std::isfinite(joint->upper->value) &&
          joint->type != JointType::Continuous)
        out_ += fmt::format(" limited=\"true\" range=\"{} {}\"", num(joint->lower->value), num(joint->upper->value));
      else
        out_ += " limited=\"false\"";
      if (joint->armature && joint->armature->value > 0) out_ += fmt::format(" armature=\"{}\"", num(joint->armature->value));
      out_ += "/>\n";
    }
    const bool massive = has_authored_mass(*link);
    if (massive) {
      const Inertial& in = *link->inertial;
      const Eigen::Matrix3d& i = in.inertia;
      out_ += fmt::format("{}  <inertial pos=\"{}\" mass=\"{}\" fullinertia=\"{} {} {} {} {} {}\"/>\n", pad, vec(in.com),
                          num(in.mass.value), num(i(0, 0)), num(i(1, 1)), num(i(2, 2)), num(i(0, 1)), num(i(0, 2)),
                          num(i(1, 2)));
    } else if (joint && link->collisions.empty()) {
      error = fmt::format("link '{}' moves (joint '{}') but has neither a mass nor collision shapes to take one from: "
                          "author its <inertial>",
                          name, joint->name.text);
      return false;
    }
    std::size_t k = 0;
    for (const CollisionShape& shape : link->collisions) {
      out_ += fmt::format("{}  <geom name=\"g{}_{}\" {} density=\"{}\" contype=\"1\" conaffinity=\"2\" {}/>\n", pad,
                          *asset_.index_of(*link), k++, pose_attributes(shape.pose),
                          massive ? std::string("0") : num(kShapeDensity), geometry(shape));
    }
    for (const Joint* child : asset_.joints_at(name)) {
      if (child->parent.text != name) continue;
      const JointType t = child->type;
      if (t != JointType::Fixed && !is_single_dof(t)) {
        error = fmt::format("joint '{}' is {}: verify steps grippers made of revolute, continuous, prismatic and fixed "
                            "joints",
                            child->name.text, joint_type_name(t));
        return false;
      }
      const Eigen::Isometry3d child_pose = child->frame_in_link[0] * child->frame_in_link[1].inverse();
      if (!write_link(child->child.text, child_pose, t == JointType::Fixed ? nullptr : child, indent + 1, error))
        return false;
    }
    out_ += pad + "</body>\n";
    return true;
  }

  std::string geometry(const CollisionShape& shape) const { return mjcf_geometry(shape, mesh_ids_); }

  void write_object(const verify::ObjectSpec& object) {
    const verify::GripperLayout& l = plan_.layout;
    Eigen::Matrix3d r;
    r.col(0) = l.closing;
    r.col(1) = l.lateral;
    r.col(2) = l.approach;
    out_ += fmt::format("    <body name=\"object\" pos=\"{}\" quat=\"{}\"><freejoint name=\"object_free\"/>\n",
                        vec(object.centre), quat(r));
    out_ += fmt::format("      <geom name=\"object\" type=\"box\" size=\"{} {} {}\" mass=\"{}\" contype=\"2\" "
                        "conaffinity=\"1\"/>\n    </body>\n",
                        num(0.5 * object.width), num(0.5 * object.depth), num(0.5 * object.height), num(object.mass));
  }

  const VerifyPlan& plan_;
  const SceneSpec& scene_;
  const Asset& asset_;
  std::string out_;
  std::set<std::string> visited_;
  MeshIds mesh_ids_;
};

}  // namespace

bool has_authored_mass(const Link& link) {
  return link.inertial && link.inertial->mass_authored && link.inertial->mass.value > 0;
}

std::string body_name(const Asset& asset, const Link& link) { return fmt::format("b{}", *asset.index_of(link)); }
std::string joint_name(const Asset& asset, const Joint& joint) { return fmt::format("j{}", *asset.index_of(joint)); }

std::string scene_mjcf(const verify::VerifyPlan& plan, const verify::SceneSpec& scene, std::string& error) {
  Writer writer(plan, scene);
  return writer.write(error);
}

}  // namespace assetlint::backends::mujoco
