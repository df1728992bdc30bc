#include "backends/mujoco/drive_scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "backends/mujoco/mjcf_scene.h"
#include "backends/mujoco/mjcf_text.h"

namespace assetlint::backends::mujoco {
namespace {

class DriveWriter {
 public:
  explicit DriveWriter(const verify::DrivePlan& plan) : plan_(plan), asset_(*plan.asset) {
    for (const verify::TestedJoint& j : plan.joints) {
      moving_.insert(j.joint);
      for (const Joint* follower : j.followers) moving_.insert(follower);
    }
  }

  std::string write(std::vector<std::size_t>& actuated, std::string& error) {
    const double h = plan_.timestep;
    out_ += "<mujoco model=\"asset-lint verify drives\">\n";
    out_ += "  <compiler angle=\"radian\" inertiafromgeom=\"auto\"/>\n";
    out_ += fmt::format("  <option timestep=\"{}\" integrator=\"{}\" gravity=\"0 0 {}\"><flag contact=\"disable\"/></option>\n",
                        mjcf_number(h), kIntegrator, mjcf_number(-plan_.gravity));
    out_ += fmt::format("  <default>\n    <equality solref=\"{} 1\"/>\n  </default>\n", mjcf_number(2 * h));
    if (!write_mesh_assets(asset_, plan_.meshes, [&](const Link& l) { return takes_shape_mass(l); }, out_, mesh_ids_,
                           error))
      return {};
    out_ += "  <worldbody>\n";
    std::set<std::string, std::less<>> children;
    for (const Joint& joint : asset_.joints)
      if (asset_.find_link(joint.parent.text)) children.insert(joint.child.text);
    for (const Link& link : asset_.links) {
      if (children.count(link.name.text)) continue;
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      for (const Joint& joint : asset_.joints)
        if (joint.child.text == link.name.text) pose = joint.frame_in_link[0] * joint.frame_in_link[1].inverse();
      if (!write_link(link, pose, nullptr, 2, error)) return {};
    }
    out_ += "  </worldbody>\n";
    std::string equalities;
    for (const verify::TestedJoint& j : plan_.joints) {
      // A joint without a drive stays a degree of freedom (gravity's pull on it and its inertia
      // are still measured), held at its start by an equality.
      if (!j.drive)
        equalities += fmt::format("    <joint joint1=\"{}\" polycoef=\"{} 0 0 0 0\"/>\n", joint_name(asset_, *j.joint),
                                  mjcf_number(j.start));
      for (const Joint* f : j.followers)
        equalities += fmt::format("    <joint joint1=\"{}\" joint2=\"{}\" polycoef=\"{} {} 0 0 0\"/>\n",
                                  joint_name(asset_, *f), joint_name(asset_, *j.joint), mjcf_number(f->mimic->offset.value),
                                  mjcf_number(f->mimic->multiplier.value));
    }
    if (!equalities.empty()) out_ += "  <equality>\n" + equalities + "  </equality>\n";
    std::string actuators;
    for (std::size_t i = 0; i < plan_.joints.size(); ++i) {
      const verify::TestedJoint& j = plan_.joints[i];
      if (!j.drive) continue;
      const verify::DriveSpec& d = *j.drive;
      actuators += fmt::format(
          "    <general joint=\"{}\" ctrllimited=\"false\" gaintype=\"fixed\" gainprm=\"{}\" biastype=\"affine\" "
          "biasprm=\"0 {} {}\"",
          joint_name(asset_, *j.joint), mjcf_number(d.stiffness), mjcf_number(-d.stiffness), mjcf_number(-d.damping));
      if (d.max_force)
        actuators += fmt::format(" forcelimited=\"true\" forcerange=\"{} {}\"", mjcf_number(-*d.max_force),
                                 mjcf_number(*d.max_force));
      else
        actuators += " forcelimited=\"false\"";
      actuators += "/>\n";
      actuated.push_back(i);
    }
    if (!actuators.empty()) out_ += "  <actuator>\n" + actuators + "  </actuator>\n";
    out_ += "</mujoco>\n";
    return std::move(out_);
  }

 private:
  bool write_link(const Link& link, const Eigen::Isometry3d& pose, const Joint* joint, int indent,
                  std::string& error) {
    if (!visited_.insert(link.name.text).second) return true;
    const std::string pad(indent * 2, ' ');
    out_ += fmt::format("{}<body name=\"{}\" {}>\n", pad, body_name(asset_, link), mjcf_pose(pose));
    if (joint) {
      const Eigen::Isometry3d& in_child = joint->frame_in_link[1];
      out_ += fmt::format("{}  <joint name=\"{}\" type=\"{}\" pos=\"{}\" axis=\"{}\"", pad, joint_name(asset_, *joint),
                          is_angular(joint->type) ? "hinge" : "slide", mjcf_vector(in_child.translation()),
                          mjcf_vector(in_child.linear() * joint->axis.normalized()));
      if (joint->lower && joint->upper && std::isfinite(joint->lower->value) && std::isfinite(joint->upper->value) &&
          joint->type != JointType::Continuous && joint->upper->value > joint->lower->value)
        out_ += fmt::format(" limited=\"true\" range=\"{} {}\"", mjcf_number(joint->lower->value),
                            mjcf_number(joint->upper->value));
      else
        out_ += " limited=\"false\"";
      if (joint->armature && joint->armature->value > 0) out_ += fmt::format(" armature=\"{}\"", mjcf_number(joint->armature->value));
      if (joint->joint_friction && joint->joint_friction->value > 0)
        out_ += fmt::format(" frictionloss=\"{}\"", mjcf_number(joint->joint_friction->value));
      out_ += "/>\n";
    }
    if (has_authored_mass(link)) {
      const Inertial& in = *link.inertial;
      const Eigen::Matrix3d& i = in.inertia;
      out_ += fmt::format("{}  <inertial pos=\"{}\" mass=\"{}\" fullinertia=\"{} {} {} {} {} {}\"/>\n", pad,
                          mjcf_vector(in.com), mjcf_number(in.mass.value), mjcf_number(i(0, 0)), mjcf_number(i(1, 1)),
                          mjcf_number(i(2, 2)), mjcf_number(i(0, 1)), mjcf_number(i(0, 2)), mjcf_number(i(1, 2)));
    } else if (takes_shape_mass(link)) {
      // A massless frame welded to a moving link is fine; a joint of its own needs a mass to move.
      if (joint && link.collisions.empty()) {
        error = fmt::format("link '{}' moves but has neither a mass nor collision shapes to take one from: author its "
                            "mass",
                            link.name.text);
        return false;
      }
      std::size_t k = 0;
      for (const CollisionShape& shape : link.collisions)
        out_ += fmt::format("{}  <geom name=\"g{}_{}\" {} density=\"{}\" contype=\"0\" conaffinity=\"0\" {}/>\n", pad,
                            *asset_.index_of(link), k++, mjcf_pose(shape.pose), mjcf_number(kShapeDensity),
                            mjcf_geometry(shape, mesh_ids_));
    }
    for (const Joint* child : asset_.joints_at(link.name.text)) {
      if (child->parent.text != link.name.text) continue;
      const Link* next = asset_.find_link(child->child.text);
      if (!next) continue;
      const Eigen::Isometry3d child_pose = child->frame_in_link[0] * child->frame_in_link[1].inverse();
      const bool free = moving_.count(child) > 0;
      if (!write_link(*next, child_pose, free ? child : nullptr, indent + 1, error)) return false;
    }
    out_ += pad + "</body>\n";
    return true;
  }

  // A moving link without an authored mass takes it from its shapes, as PhysX does.
  bool takes_shape_mass(const Link& link) const {
    return !has_authored_mass(link) && !plan_.static_links.count(link.name.text);
  }

  const verify::DrivePlan& plan_;
  const Asset& asset_;
  std::set<const Joint*> moving_;
  std::string out_;
  std::set<std::string> visited_;
  MeshIds mesh_ids_;
};

}  // namespace

std::string drive_scene_mjcf(const verify::DrivePlan& plan, std::vector<std::size_t>& actuated, std::string& error) {
  DriveWriter writer(plan);
  return writer.write(actuated, error);
}

}  // namespace assetlint::backends::mujoco
