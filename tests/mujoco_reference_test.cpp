// MuJoCo's own compiler as the reference for the MJCF reader: tests/mujoco_reference/compile.mjs
// compiles every MJCF fixture and corpus model with MuJoCo 3.14 (npm @mujoco/mujoco, the official
// WebAssembly build, run with Node) and this file holds asset-lint's model of the same file to
// what MuJoCo compiled:
//   joints: range (after autolimits and <compiler angle>), damping, armature, and the
//     joint-space inertia diagonal at qpos0 (dof_M0);
//   servos on a joint: stiffness kp·g², damping kv·g² + joint damping (kv derived from
//     dampratio as 3.14 compiles it, on dof_M0), force bound |forcerange|·|g|; motors: the
//     effort bound;
//   a servo's kv from dampratio as MuJoCo 3.15 derives it: on the operational-space inertia
//     (J·M⁻¹·Jᵀ)⁻¹ at qpos0, which compile.mjs computes from the oracle's own mass matrix
//     (mj_fullM) and actuator moments (compared at 1e-6: a dense inverse each side);
//   joint equalities: the mimic asset-lint makes of them.
// Values agree to 1e-9 relative; every difference is listed by model, element and both values.
// What asset-lint deliberately does not model is counted and listed apart (kDeliberate below).
// Skipped with a message when `node` or the package is absent (scripts/bootstrap.sh installs
// it into tools/node_modules); with CI=true in the environment that is a failure.
#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "engine/file_system.h"
#include "formats/mjcf/mjcf_reader.h"
#include "physics/dampratio.h"
#include "engine/settings.h"
#include "physics/articulation.h"
#include "physics/joint_space_matrix.h"
#include "pipeline/lint.h"
#include "support/mujoco_oracle.h"
#include "test_support.h"

using namespace assetlint;
using assetlint::test::read_file;
using assetlint::test::shell_quote;
using assetlint::test::source_dir;

namespace {

namespace fs = std::filesystem;

// Models, not <include> fragments: MJCF files whose root holds a <worldbody>.
std::vector<fs::path> models_under(const fs::path& root) {
  std::vector<fs::path> found;
  if (!fs::is_directory(root)) return found;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file() || entry.path().extension() != ".xml") continue;
    const std::string text = read_file(entry.path());
    if (mjcf::looks_like_mjcf(text) && text.find("<worldbody") != std::string::npos) found.push_back(entry.path());
  }
  std::sort(found.begin(), found.end());
  return found;
}

bool close(double a, double b, double tolerance = 1e-9) {
  return a == b || std::abs(a - b) <= tolerance * std::max(std::abs(a), std::abs(b));
}

std::string number(double v) { return fmt::format("{:.12g}", v); }

struct Comparison {
  std::string model;
  std::vector<std::string> differences;
  std::map<std::string, int> compared;             // per kind of value: how many agreed or not
  std::map<std::string, std::vector<std::string>> deliberate;  // reason -> elements

  void value(const std::string& kind, const std::string& element, double mujoco, std::optional<double> ours,
             double tolerance = 1e-9) {
    ++compared[kind];
    if (!ours) {
      differences.push_back(fmt::format("{}: {} {}: MuJoCo {}, asset-lint none", model, element, kind, number(mujoco)));
    } else if (!close(mujoco, *ours, tolerance)) {
      differences.push_back(
          fmt::format("{}: {} {}: MuJoCo {}, asset-lint {}", model, element, kind, number(mujoco), number(*ours)));
    }
  }
  void absent(const std::string& kind, const std::string& element, const OptQuantity& ours) {
    ++compared[kind];
    if (ours)
      differences.push_back(fmt::format("{}: {} {}: MuJoCo none, asset-lint {}", model, element, kind, number(ours->value)));
  }
  void skip(const std::string& reason, const std::string& element) { deliberate[reason].push_back(model + ": " + element); }
};

// What asset-lint deliberately does not model, and why (docs/mjcf.md "Held to MuJoCo").
constexpr const char* kGeomInertia =
    "joint-space inertia of joints that move a body whose mass MuJoCo takes from a mesh geom (asset-lint measures "
    "primitive geoms only; the damping a dampratio derives from it stays unknown, and the rules skip it)";
constexpr const char* kStandIn = "quantities depending on a mesh file absent here (MuJoCo compiled a stand-in)";
constexpr const char* kMultiDof = "ball and free joints' own dofs (asset-lint's drive rules judge single-dof joints)";
constexpr const char* kTransmission =
    "actuators acting through a spatial tendon, site or body (joint and fixed-tendon transmissions are modelled)";
constexpr const char* kSecondServo = "a second servo or motor on one joint (the first is what the rules judge)";
constexpr const char* kReversed =
    "a range written upper bound first under limited=\"auto\": MuJoCo drops the limit, asset-lint keeps the range so "
    "that limits-inverted reports it";
constexpr const char* kDiagonalised =
    "joint-space inertia through a body with fullinertia, compared at 1e-5: MuJoCo diagonalises the tensor numerically "
    "(mju_eig3), exact to about 1e-6 relative";
constexpr const char* kMissingInclude =
    "a model whose <include> is missing: MuJoCo refuses it, asset-lint reports layer-unresolved and checks the rest";
constexpr const char* kUnreadReference =
    "a part of a scene that MuJoCo refuses on its own: a sensor, contact pair or skin (none of which asset-lint reads) "
    "names what only the scene holds";
constexpr const char* kKind =
    "actuators other than position servos and motors (velocity servos, dampers, muscles, …)";

// Unknown only because bodies it moves take their mass from geoms.
bool from_geoms(const Asset& asset, const physics::ArticulatedInertia& inertia) {
  return !inertia.unknown_links.empty() &&
         std::all_of(inertia.unknown_links.begin(), inertia.unknown_links.end(), [&](const std::string& link) {
           const Link* l = asset.find_link(link);
           return l && l->mass_from_geoms;
         });
}

// An actuator on a fixed tendon: its moments (gear·coef per joint) are the shares asset-lint
// reads; the joints fall into groups (a joint and the tendon's joints that mimic it), and the
// group's joint carries a drive with ratio G = Σ moment·multiplier: stiffness kp·G², damping
// kv·G² plus the group's joint damping (each times multiplier²), force bound |forcerange|·|G|.
void compare_tendon_actuator(const nlohmann::json& a, const nlohmann::json& joints, const std::vector<const Joint*>& ours,
                             const Asset& asset, const Asset& asset_315, Comparison& c) {
  const std::string element =
      a["name"].is_null() ? fmt::format("actuator #{}", a["index"].get<int>()) : fmt::format("actuator '{}'", a["name"].get<std::string>());
  struct Group {
    double ratio = 0, damping = 0;
  };
  std::map<const Joint*, Group> groups;
  for (const auto& entry : a["moments"]) {
    const Joint& joint = *ours.at(entry[0].get<std::size_t>());
    const double moment = entry[1];
    const Joint* followed = joint.is_mimic() ? asset.followed_joint(joint) : nullptr;
    const Joint* leader = followed ? followed : &joint;
    const double multiplier = followed ? joint.mimic->multiplier.value : 1.0;
    Group& group = groups[leader];
    group.ratio += moment * multiplier;
    group.damping += joints[entry[0].get<std::size_t>()]["dofs"][0]["damping"].get<double>() * multiplier * multiplier;
    // The share asset-lint reads for this joint, on whichever joint carries the drive.
    ++c.compared["tendon moment (gear·coef)"];
    const Transmission* t = leader->transmission ? &*leader->transmission : nullptr;
    const auto share = t ? std::find_if(t->shares.begin(), t->shares.end(),
                                        [&](const TendonShare& s) { return s.joint == joint.name.text; })
                         : std::vector<TendonShare>::const_iterator{};
    if (!t || share == t->shares.end())
      c.differences.push_back(fmt::format("{}: {} moves '{}' by {}, asset-lint has no such tendon share", c.model, element,
                                          joint.name.text, number(moment)));
    else
      c.value("tendon moment (gear·coef)", element + " on '" + joint.name.text + "'", moment, share->coef);
  }
  const double kp = a["biasprm"].is_null() ? 0.0 : -a["biasprm"][1].get<double>();
  const int gaintype = a["gaintype"], biastype = a["biastype"];
  for (const auto& [leader, group] : groups) {
    if (group.ratio == 0) continue;
    const std::string on = element + " on '" + leader->name.text + "'";
    const Transmission* t = leader->transmission ? &*leader->transmission : nullptr;
    ++c.compared["transmission type (tendon)"];
    if (!t || !t->through_tendon()) {
      c.differences.push_back(fmt::format("{}: {}: MuJoCo's transmission is tendon '{}', asset-lint has none", c.model, on,
                                          a["tendon"].is_null() ? "" : a["tendon"].get<std::string>()));
      continue;
    }
    c.value("tendon ratio G", on, std::abs(group.ratio), t->ratio);
    c.value("actuator_length0", on, a["length0"], t->length0);
    if (gaintype != 0 || biastype != 1 || a["biasprm"].is_null() || !(kp > 0)) continue;  // servos only
    ++c.compared["servo (tendon)"];
    if (!leader->drive) {
      c.differences.push_back(fmt::format("{}: {}: MuJoCo compiles a servo, asset-lint has no drive", c.model, on));
      continue;
    }
    const double g2 = group.ratio * group.ratio;
    const Drive& drive = *leader->drive;
    c.value("stiffness (tendon, kp·G²)", on, kp * g2, drive.stiffness ? std::optional(drive.stiffness->value) : std::nullopt);
    const double kv = -a["biasprm"][2].get<double>();
    if (drive.damping_unknown.empty())
      c.value("damping (tendon, kv·G² + joint damping)", on, kv * g2 + group.damping,
              drive.damping ? drive.damping->value : 0.0, 1e-9);
    else
      c.skip(kGeomInertia, on + " kv");
    if (!a["kv_operational"].is_null()) {
      const Joint& leader_315 = asset_315.joints[*asset.index_of(*leader)];
      const Drive* drive_315 = leader_315.drive ? &*leader_315.drive : nullptr;
      c.value("damping from dampratio, MuJoCo 3.15 rule (tendon, kv·G² from (J·M⁻¹·Jᵀ)⁻¹ + joint damping)", on,
              a["kv_operational"].get<double>() * g2 + group.damping,
              drive_315 && drive_315->damping ? std::optional(drive_315->damping->value) : std::nullopt, 1e-6);
    }
    const auto bound = std::max(std::abs(a["forcerange"][0].get<double>()), std::abs(a["forcerange"][1].get<double>()));
    if (a["forcelimited"].get<bool>())
      c.value("max force (tendon, |forcerange|·|G|)", on, bound * std::abs(group.ratio),
              drive.max_force ? std::optional(drive.max_force->value) : std::nullopt);
    else
      c.absent("max force (tendon, |forcerange|·|G|)", on, drive.max_force);
  }
}

void compare_model(const fs::path& path, const nlohmann::json& compiled, Comparison& c) {
  const DiskFileSystem disk;
  // MuJoCo 3.14 compiles dampratio as 3.3 did (M₀): the reader with that rule is held to the
  // compiled gains; the reader with 3.15's rule to the kv the script computes from the
  // oracle's own mass matrix and actuator moments, (J·M⁻¹·Jᵀ)⁻¹ at qpos0.
  const auto read_as = [&](physics::DampRatioRule rule) {
    mjcf::ReadOptions options;
    options.mujoco = rule == physics::DampRatioRule::OperationalSpace ? MujocoVersion{3, 15} : MujocoVersion{3, 14};
    return mjcf::read_mjcf(std::make_shared<const SourceFile>(path.string(), read_file(path)), disk, options);
  };
  const ReadResult read = read_as(physics::DampRatioRule::JointSpaceDiagonal);
  if (!compiled["error"].is_null()) {
    // What MuJoCo refuses to compile, asset-lint reports as an error (reader or rule).
    const FileReport report = lint_file(path.string(), Settings{});
    const bool refused = std::any_of(report.diagnostics.begin(), report.diagnostics.end(),
                                     [](const Diagnostic& d) { return d.severity == Severity::Error; });
    ++c.compared["refused"];
    const bool missing_include = std::any_of(report.diagnostics.begin(), report.diagnostics.end(),
                                             [](const Diagnostic& d) { return d.rule == "layer-unresolved"; });
    const std::string error = compiled["error"].get<std::string>();
    if (!refused && missing_include)
      c.skip(kMissingInclude, "the model");
    else if (!refused && (error.find("of sensorized object") != std::string::npos ||
                          error.find("not found in collision") != std::string::npos ||
                          error.find(".skn'") != std::string::npos))
      c.skip(kUnreadReference, "the model (" + error + ")");
    else if (!refused)
      c.differences.push_back(fmt::format("{}: MuJoCo refuses the model ({}), asset-lint reports no error", c.model,
                                          compiled["error"].get<std::string>()));
    return;
  }
  REQUIRE(read.usable);
  const Asset& asset = read.asset;
  const physics::Articulation articulation(asset);
  const ReadResult read_315 = read_as(physics::DampRatioRule::OperationalSpace);
  REQUIRE(read_315.usable);
  REQUIRE(read_315.asset.joints.size() == asset.joints.size());
  const physics::JointSpaceMatrix matrix(articulation);

  // MuJoCo's joints in order are asset-lint's movable joints in order (bodies depth first).
  std::vector<const Joint*> ours;
  for (const Joint& j : asset.joints)
    if (j.type != JointType::Fixed) ours.push_back(&j);
  const auto& joints = compiled["joints"];
  ++c.compared["joint count"];
  if (joints.size() != ours.size()) {
    c.differences.push_back(fmt::format("{}: MuJoCo has {} joints, asset-lint {}", c.model, joints.size(), ours.size()));
    return;
  }
  const auto value_of = [](const OptQuantity& q) { return q ? q->value : 0.0; };
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const auto& mj = joints[i];
    const Joint& joint = *ours[i];
    const std::string type = mj["type"];
    const std::string name = mj["name"].is_null() ? fmt::format("joint #{}", i) : mj["name"].get<std::string>();
    const std::string element = fmt::format("joint '{}'", name);
    if (!mj["name"].is_null() && joint.name.text != name) {
      c.differences.push_back(fmt::format("{}: joint #{}: MuJoCo '{}', asset-lint '{}'", c.model, i, name, joint.name.text));
      continue;
    }
    const auto& dof = mj["dofs"][0];
    if (type == "free" || type == "ball") {
      // Their armature enters the joint-space matrix MuJoCo 3.15 derives dampratio's kv from.
      c.value("armature (ball, free)", element, dof["armature"], value_of(joint.armature));
      c.skip(kMultiDof, element);
      continue;
    }
    if (!mj["limited"].get<bool>() && joint.lower && joint.upper && joint.lower->value > joint.upper->value) {
      c.skip(kReversed, element);
    } else if (mj["limited"].get<bool>()) {
      c.value("range lower", element, mj["range"][0], joint.lower ? std::optional(joint.lower->value) : std::nullopt);
      c.value("range upper", element, mj["range"][1], joint.upper ? std::optional(joint.upper->value) : std::nullopt);
    } else {
      c.absent("range lower", element, joint.lower);
      c.absent("range upper", element, joint.upper);
    }
    c.value("damping", element, dof["damping"], value_of(joint.joint_damping));
    c.value("armature", element, dof["armature"], value_of(joint.armature));
    const physics::ArticulatedInertia inertia = articulation.joint_space_inertia(joint);
    if (dof["M0"].is_null()) {
      c.skip(kStandIn, element + " M0");
    } else if (!inertia.known && from_geoms(asset, inertia)) {
      c.skip(kGeomInertia, element + " M0");
    } else {
      const bool diagonalised = mj["inertia_diagonalised"].get<bool>();
      if (diagonalised) c.skip(kDiagonalised, element);
      c.value("M0", element, dof["M0"], inertia.known ? std::optional(inertia.value) : std::nullopt,
              diagonalised ? 1e-5 : 1e-9);
    }
  }

  // Dampers (an affine actuator without a spring: <velocity>) add kv·g² to whatever drives
  // their joint; a joint with dampers only has a velocity drive.
  std::map<const Joint*, double> damper_kv;
  for (const auto& a : compiled["actuators"]) {
    if (a["joint"].is_null() || a["biasprm"].is_null() || a["biastype"].get<int>() != 1 || a["gaintype"].get<int>() != 0)
      continue;
    const Joint& joint = *ours.at(a["joint"].get<std::size_t>());
    const double g = a["gear"];
    if (is_single_dof(joint.type) && a["biasprm"][1].get<double>() == 0 && a["biasprm"][2].get<double>() < 0)
      damper_kv[&joint] += -a["biasprm"][2].get<double>() * g * g;
  }

  // Actuators on a joint: the first servo per joint is its drive; motors bound its effort.
  std::map<const Joint*, bool> driven;
  std::map<const Joint*, std::optional<double>> effort_bound;
  for (const auto& a : compiled["actuators"]) {
    const std::string element =
        a["name"].is_null() ? fmt::format("actuator #{}", a["index"].get<int>()) : fmt::format("actuator '{}'", a["name"].get<std::string>());
    if (a["joint"].is_null()) {
      if (a["transmission"] == "tendon" && !a["moments"].is_null() && !a["moments"].empty())
        compare_tendon_actuator(a, joints, ours, asset, read_315.asset, c);
      else
        c.skip(kTransmission, element);
      continue;
    }
    const Joint& joint = *ours.at(a["joint"].get<std::size_t>());
    if (!is_single_dof(joint.type)) {
      c.skip(kMultiDof, element);
      continue;
    }
    const double g = a["gear"];
    const int gaintype = a["gaintype"], biastype = a["biastype"];
    const bool servo = biastype == 1 && gaintype == 0;  // affine bias, fixed gain
    if (gaintype != 0 || (biastype != 0 && biastype != 1)) {
      c.skip(kKind, element);
      continue;
    }
    const auto force_bound = [&](const nlohmann::json& range, double scale) {
      return std::max(std::abs(range[0].get<double>()), std::abs(range[1].get<double>())) * scale;
    };
    if (!servo) {  // a motor: force = gain·ctrl, clamped by the force range
      if (driven[&joint] || joints[a["joint"].get<std::size_t>()]["actfrclimited"].get<bool>()) continue;
      if (effort_bound.count(&joint)) {
        c.skip(kSecondServo, element);
        continue;
      }
      // The joint sees force = gain·ctrl clamped to forcerange, times the gear: the smaller bound.
      std::optional<double> bound;
      if (a["forcelimited"].get<bool>()) bound = force_bound(a["forcerange"], std::abs(g));
      if (a["ctrllimited"].get<bool>()) {
        const double by_control = force_bound(a["ctrlrange"], std::abs(g * a["gainprm"][0].get<double>()));
        if (!bound || by_control < *bound) bound = by_control;
      }
      effort_bound[&joint] = bound;
      if (bound) c.value("effort (motor)", element, *bound, joint.effort ? std::optional(joint.effort->value) : std::nullopt);
      else c.absent("effort (motor)", element, joint.effort);
      continue;
    }
    {
      if (a["biasprm"].is_null()) {
        c.skip(kStandIn, element + " kv");
        continue;
      }
      const double stiffness = -a["biasprm"][1].get<double>() * g * g;
      const double kv = -a["biasprm"][2].get<double>();
      if (!(stiffness > 0 || kv > 0)) continue;  // not a drive
      if (!(stiffness > 0)) continue;  // a damper: compared with its joint's drive below
      if (driven[&joint]) {
        c.skip(kSecondServo, element);
        continue;
      }
      driven[&joint] = true;
      ++c.compared["servo"];
      if (!joint.drive) {
        c.differences.push_back(fmt::format("{}: {} on '{}': MuJoCo compiles a servo, asset-lint has no drive", c.model, element,
                                            joint.name.text));
        continue;
      }
      const Drive& drive = *joint.drive;
      c.value("stiffness", element, stiffness, drive.stiffness ? std::optional(drive.stiffness->value) : std::nullopt);
      const double joint_damping = value_of(joint.joint_damping);
      if (drive.damping_unknown.empty()) {
        const bool diagonalised = joints[a["joint"].get<std::size_t>()]["inertia_diagonalised"].get<bool>();
        c.value("damping (kv·g² + dampers' kv·g² + joint damping)", element,
                kv * g * g + damper_kv[&joint] + joint_damping, value_of(drive.damping), diagonalised ? 1e-5 : 1e-9);
      } else if (from_geoms(asset, articulation.joint_space_inertia(joint))) {
        c.skip(kGeomInertia, element + " kv");
      } else {
        c.differences.push_back(fmt::format("{}: {} damping: MuJoCo {}, asset-lint unknown ({})", c.model, element,
                                            number(kv * g * g + joint_damping), drive.damping_unknown));
      }
      // MuJoCo 3.15's rule, held to the oracle's (J·M⁻¹·Jᵀ)⁻¹.
      if (!a["dampratio"].is_null()) {
        const Joint& joint_315 = read_315.asset.joints[*asset.index_of(joint)];
        const Drive* drive_315 = joint_315.drive ? &*joint_315.drive : nullptr;
        if (a["kv_operational"].is_null()) {
          c.skip(kStandIn, element + " kv (3.15)");
        } else if (drive_315 && drive_315->damping_unknown.empty()) {
          c.value("damping from dampratio, MuJoCo 3.15 rule (kv·g² from (J·M⁻¹·Jᵀ)⁻¹ + dampers' kv·g² + joint damping)",
                  element, a["kv_operational"].get<double>() * g * g + damper_kv[&joint] + joint_damping,
                  drive_315->damping ? std::optional(drive_315->damping->value) : std::nullopt, 1e-6);
        } else if (from_geoms(asset, matrix.operational_inertia(joint))) {
          c.skip(kGeomInertia, element + " kv (3.15)");
        } else {
          c.differences.push_back(fmt::format("{}: {} damping (3.15 rule): MuJoCo {}, asset-lint unknown ({})", c.model,
                                              element, number(a["kv_operational"].get<double>() * g * g + joint_damping),
                                              drive_315 ? drive_315->damping_unknown : "no drive"));
        }
      }
      if (a["forcelimited"].get<bool>())
        c.value("max force", element, force_bound(a["forcerange"], std::abs(g)),
                drive.max_force ? std::optional(drive.max_force->value) : std::nullopt);
      else
        c.absent("max force", element, drive.max_force);
    }
  }

  for (const auto& [joint, kv] : damper_kv) {
    if (driven[joint]) continue;
    ++c.compared["damper"];
    const std::string element = fmt::format("dampers of '{}'", joint->name.text);
    if (!joint->drive) {
      c.differences.push_back(fmt::format("{}: {}: MuJoCo damps the joint with kv {}, asset-lint has no drive", c.model,
                                          element, number(kv)));
      continue;
    }
    c.value("velocity drive damping (dampers' kv·g² + joint damping)", element, kv + value_of(joint->joint_damping),
            value_of(joint->drive->damping));
    c.value("velocity drive stiffness", element, 0.0,
            joint->drive->stiffness ? std::optional(joint->drive->stiffness->value) : std::nullopt);
  }

  // Joint equalities: joint1 follows joint2 (q1 = c0 + c1·q2), or joint2 follows joint1.
  for (const auto& e : compiled["equalities"]) {
    const std::string element = fmt::format("equality #{}", e["index"].get<int>());
    if (e["joint2"].get<int>() < 0 || !e["active"].get<bool>()) continue;
    const Joint& j1 = *ours.at(e["joint1"].get<std::size_t>());
    const Joint& j2 = *ours.at(e["joint2"].get<std::size_t>());
    const double c0 = e["polycoef"][0], c1 = e["polycoef"][1];
    bool nonlinear = false;
    for (std::size_t i = 2; i < e["polycoef"].size(); ++i) nonlinear = nonlinear || e["polycoef"][i].get<double>() != 0;
    ++c.compared["coupling"];
    // A polynomial coupling is no mimic: the reader must not model its linear part as one.
    if (nonlinear) {
      const bool modelled = (j1.mimic && j1.mimic->reference.text == j2.name.text) ||
                            (j2.mimic && j2.mimic->reference.text == j1.name.text);
      if (modelled)
        c.differences.push_back(fmt::format("{}: {} couples '{}' to '{}' by a polynomial, asset-lint models it as a "
                                            "linear mimic", c.model, element, j1.name.text, j2.name.text));
      continue;
    }
    if (j1.mimic && j1.mimic->reference.text == j2.name.text) {
      c.value("coupling multiplier", element, c1, j1.mimic->multiplier.value);
      c.value("coupling offset", element, c0, j1.mimic->offset.value);
    } else if (j2.mimic && j2.mimic->reference.text == j1.name.text) {
      c.value("coupling multiplier (inverted)", element, 1.0 / c1, j2.mimic->multiplier.value);
      c.value("coupling offset (inverted)", element, -c0 / c1, j2.mimic->offset.value);
    } else {
      c.differences.push_back(fmt::format("{}: {} couples '{}' to '{}', asset-lint has no such mimic", c.model, element,
                                          j1.name.text, j2.name.text));
    }
  }
}

// `base`: the directory model paths are named relative to in the listing.
void hold_to_mujoco(const std::vector<fs::path>& models, const fs::path& base) {
  const std::string missing = assetlint::test::mujoco_missing();
  if (!missing.empty()) {
    if (assetlint::test::in_ci()) FAIL("MuJoCo reference missing in CI: " << missing);
    WARN("MuJoCo reference test skipped: " << missing);
    return;
  }
  REQUIRE(!models.empty());
  nlohmann::json compiled;
  try {
    compiled = assetlint::test::compile_with_mujoco(models);
  } catch (const std::exception& e) {
    FAIL(e.what());
  }
  REQUIRE(compiled["models"].size() == models.size());

  std::vector<std::string> differences;
  std::map<std::string, int> compared;
  std::map<std::string, std::vector<std::string>> deliberate;
  for (std::size_t i = 0; i < models.size(); ++i) {
    Comparison c;
    c.model = fs::relative(models[i], base).string();
    compare_model(models[i], compiled["models"][i], c);
    differences.insert(differences.end(), c.differences.begin(), c.differences.end());
    for (const auto& [kind, n] : c.compared) compared[kind] += n;
    for (const auto& [reason, elements] : c.deliberate)
      deliberate[reason].insert(deliberate[reason].end(), elements.begin(), elements.end());
  }
  std::string summary = fmt::format("{} models compiled by MuJoCo {}; values compared:", models.size(),
                                    compiled["mujoco"].get<std::string>());
  for (const auto& [kind, n] : compared) summary += fmt::format(" {} {},", kind, n);
  summary += "\nnot modelled by asset-lint, on purpose:";
  for (const auto& [reason, elements] : deliberate) summary += fmt::format("\n  {} ({}): first {}", reason, elements.size(), elements.front());
  std::string listing;
  for (const auto& d : differences) listing += "\n  " + d;
  INFO(summary);
  INFO(differences.size() << " differences:" << listing);
  if (std::getenv("ASSET_LINT_ORACLE_VERBOSE")) WARN(summary);
  CHECK(differences.empty());
}

}  // namespace

TEST_CASE("the MJCF reader reads what MuJoCo compiles: every MJCF fixture", "[mjcf][mujoco][oracle]") {
  hold_to_mujoco(models_under(source_dir() / "fixtures"), source_dir());
}

TEST_CASE("the MJCF reader reads what MuJoCo compiles: the corpus models", "[mjcf][mujoco][oracle][corpus]") {
  const auto corpus = assetlint::test::corpus_dir();
  if (corpus.empty() || !fs::is_directory(corpus / "mjcf")) {
    WARN("../shared/corpus/mjcf is absent: MuJoCo corpus comparison skipped");
    return;
  }
  hold_to_mujoco(models_under(corpus / "mjcf"), corpus);
}

// For models outside the project (a folder of downloaded robots): ASSET_LINT_ORACLE_MODELS=<dir>.
TEST_CASE("the MJCF reader reads what MuJoCo compiles: models in $ASSET_LINT_ORACLE_MODELS", "[mjcf][mujoco][oracle]") {
  const char* dir = std::getenv("ASSET_LINT_ORACLE_MODELS");
  if (dir == nullptr || *dir == '\0') return;
  hold_to_mujoco(models_under(dir), dir);
}
