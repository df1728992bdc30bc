#include "crate_variant_assets.h"

#include <optional>
#include <utility>

#include "crate_writer.h"

namespace assetlint::test {
namespace {

using namespace crate;

using Fields = std::vector<std::pair<std::string, Value>>;

void append(std::vector<Spec>& to, std::vector<Spec> more) {
  for (auto& s : more) to.push_back(std::move(s));
}

Fields stage_metadata(std::string doc, std::string default_prim) {
  return {{"documentation", String{std::move(doc)}},
          {"defaultPrim", Token{std::move(default_prim)}},
          {"metersPerUnit", Double{1.0}},
          {"kilogramsPerUnit", Double{1.0}},
          {"upAxis", Token{"Z"}}};
}

// A rigid body's opinions on an existing Xform (`over`), as a physics layer or variant adds them.
std::vector<Spec> body(const std::string& path, float mass, Float3 inertia, Fields more = {}) {
  Fields metadata{{"apiSchemas", prepend_tokens({"PhysicsRigidBodyAPI", "PhysicsMassAPI"})}};
  for (auto& m : more) metadata.push_back(std::move(m));
  return {prim(path, Specifier::Over, "", std::move(metadata)),
          attribute(path + ".physics:mass", "float", Float{mass}),
          attribute(path + ".physics:diagonalInertia", "float3", inertia),
          attribute(path + ".physics:centerOfMass", "point3f", Float3{0.0f, 0.0f, 0.01f})};
}

// The gripper's base and finger, the same in every layer that authors them: `prefix` is the
// prim (or variant) path they sit under, ending in '/' or '}'.
std::vector<Spec> gripper_bodies(const std::string& prefix) {
  std::vector<Spec> specs = body(prefix + "base_link", 0.3f, {0.0003f, 0.0003f, 0.0003f});
  append(specs, body(prefix + "finger", 0.0127f, {2.1e-6f, 2.1e-6f, 1.3e-6f}));
  return specs;
}

struct Drive {
  std::optional<float> stiffness;  // unauthored where nested variants author it
  float damping, max_force;
};

// The finger's revolute joint with an angular drive (gains per degree, as USD writes them).
std::vector<Spec> finger_joint(const std::string& path, const std::string& prim_root, Drive drive) {
  std::vector<Spec> specs{prim(path, Specifier::Def, "PhysicsRevoluteJoint", {{"apiSchemas", prepend_tokens({"PhysicsDriveAPI:angular"})}}),
          relationship(path + ".physics:body0", {prim_root + "/base_link"}),
          relationship(path + ".physics:body1", {prim_root + "/finger"}),
          attribute(path + ".physics:axis", "token", Token{"X"}, Variability::Uniform),
          attribute(path + ".physics:lowerLimit", "float", Float{0.0f}),
          attribute(path + ".physics:upperLimit", "float", Float{47.0f}),
          attribute(path + ".drive:angular:physics:damping", "float", Float{drive.damping}),
          attribute(path + ".drive:angular:physics:maxForce", "float", Float{drive.max_force})};
  if (drive.stiffness) specs.push_back(attribute(path + ".drive:angular:physics:stiffness", "float", Float{*drive.stiffness}));
  return specs;
}

std::string physx_payload() {
  std::vector<Spec> specs{
      pseudo_root(stage_metadata("PhysX's physics of the gripper, in a crate layer: the guide's original finger drive, "
                                 "5700 N·m/rad (99.48 N·m/deg).",
                                 "gripper")),
      prim("/gripper", Specifier::Over, "", {{"apiSchemas", prepend_tokens({"PhysicsArticulationRootAPI"})}})};
  append(specs, gripper_bodies("/gripper/"));
  append(specs, finger_joint("/gripper/finger_joint", "/gripper", {99.48f, 0.00106f, 24.0f}));
  return write_crate(specs);
}

std::string simready_gripper() {
  std::vector<Spec> specs{
      pseudo_root(stage_metadata("A SimReady-style gripper in a crate layer: each engine's physics switched on by a "
                                 "variant of its own set, every set selecting \"Disabled\".",
                                 "gripper")),
      prim("/gripper", Specifier::Def, "Xform",
           {{"variantSelection", Selections{{{"MuJoCo", "Disabled"}, {"Newton", "Disabled"}, {"PhysX", "Disabled"}}}},
            {"variantSetNames", prepend_strings({"PhysX", "Newton", "MuJoCo"})}}),
      prim("/gripper/base_link", Specifier::Def, "Xform"),
      prim("/gripper/finger", Specifier::Def, "Xform"),
      variant_set("/gripper", "PhysX"),
      variant("/gripper", "PhysX", "Disabled"),
      variant("/gripper", "PhysX", "Enabled", {{"payload", prepend_payload("./runnables/physics/physx.usd")}}),
      variant_set("/gripper", "Newton"),
      variant("/gripper", "Newton", "Disabled"),
      // Newton's physics lives in the variant itself, with a nested set choosing its solver.
      variant("/gripper", "Newton", "Enabled",
              {{"apiSchemas", prepend_tokens({"PhysicsArticulationRootAPI"})},
               {"variantSelection", Selections{{{"NewtonSolver", "XPBD"}}}},
               {"variantSetNames", prepend_strings({"NewtonSolver"})}}),
      variant_set("/gripper", "MuJoCo"),
      variant("/gripper", "MuJoCo", "Disabled"),
      variant("/gripper", "MuJoCo", "Enabled", {{"payload", prepend_payload("./runnables/physics/mujoco.usda", "/gripper")}}),
  };
  const std::string newton = "/gripper{Newton=Enabled}";
  append(specs, gripper_bodies(newton));
  // The stiffness comes from the nested set: a nested variant is weaker than the variant
  // that holds it, so it can only author what that variant leaves unauthored.
  append(specs, finger_joint(newton + "finger_joint", "/gripper", {std::nullopt, 0.00106f, 24.0f}));
  append(specs, {variant_set(newton, "NewtonSolver")});
  for (const auto& [solver, stiffness] : {std::pair{"XPBD", 4.8f}, std::pair{"Featherstone", 60.0f}}) {
    const std::string over = newton + "{NewtonSolver=" + solver + "}finger_joint";
    append(specs, {variant(newton, "NewtonSolver", solver), prim(over, Specifier::Over),
                   attribute(over + ".drive:angular:physics:stiffness", "float", Float{stiffness})});
  }
  return write_crate(specs);
}

std::string isaac_arm() {
  std::vector<Spec> specs{
      pseudo_root(stage_metadata("An Isaac-style arm in a crate layer: its physics in the \"PhysX\" variant of the "
                                 "\"Physics\" set, which the asset selects.",
                                 "arm")),
      prim("/arm", Specifier::Def, "Xform",
           {{"variantSelection", Selections{{{"Physics", "PhysX"}}}}, {"variantSetNames", prepend_strings({"Physics"})}}),
      prim("/arm/base", Specifier::Def, "Xform"),
      prim("/arm/link1", Specifier::Def, "Xform"),
      variant_set("/arm", "Physics"),
      variant("/arm", "Physics", "None"),
      variant("/arm", "Physics", "PhysX", {{"apiSchemas", prepend_tokens({"PhysicsArticulationRootAPI"})}}),
      variant_set("/arm", "Sensors"),  // a set spec without variants
  };
  const std::string physx = "/arm{Physics=PhysX}";
  append(specs, body(physx + "base", 4.0f, {0.02f, 0.02f, 0.01f}));
  append(specs, body(physx + "link1", 0.8f, {0.002f, 0.002f, 0.001f}));
  const std::string joint = physx + "joint1";
  append(specs,
         {prim(joint, Specifier::Def, "PhysicsRevoluteJoint",
               {{"apiSchemas", prepend_tokens({"PhysicsDriveAPI:angular", "PhysxJointAPI"})}}),
          relationship(joint + ".physics:body0", {"/arm/base"}), relationship(joint + ".physics:body1", {"/arm/link1"}),
          attribute(joint + ".physics:axis", "token", Token{"Z"}, Variability::Uniform),
          attribute(joint + ".physics:lowerLimit", "float", Float{-170.0f}),
          attribute(joint + ".physics:upperLimit", "float", Float{170.0f}),
          attribute(joint + ".drive:angular:physics:type", "token", Token{"force"}, Variability::Uniform),
          attribute(joint + ".drive:angular:physics:stiffness", "float", Float{1000.0f}),
          attribute(joint + ".drive:angular:physics:damping", "float", Float{10.0f}),
          attribute(joint + ".drive:angular:physics:maxForce", "float", Float{50.0f}),
          attribute(joint + ".physxJoint:maxJointVelocity", "float", Float{180.0f}),
          attribute(joint + ".isaac:gainScale", "double", Double{0.1}),
          attribute(joint + ".isaac:note", "string", String{"tuned on the \"real\" arm"})});
  return write_crate(specs);
}

// Variant specs in the less common places and spellings OpenUSD allows.
std::string variant_edge_cases() {
  StringListOp set_names;
  set_names.prepended = {"Physics"};
  set_names.appended = {"Gains"};
  set_names.deleted = {"Legacy"};
  TokenListOp explicit_schemas;
  explicit_schemas.is_explicit = true;
  explicit_schemas.explicit_items = {"PhysicsArticulationRootAPI"};
  TokenListOp deleted_schemas;
  deleted_schemas.deleted = {"PhysicsArticulationRootAPI"};
  PayloadListOp two_payloads;
  two_payloads.is_explicit = true;
  two_payloads.explicit_items = {{"./simready/runnables/physics/mujoco.usda", "/gripper"},
                                 {"./simready/runnables/physics/physx.usd", ""}};
  std::vector<Spec> specs{
      pseudo_root(stage_metadata("Variant specs in less common places: properties on a variant, a variant set on a "
                                 "prim inside a variant, explicit and deleting list ops, an empty selection.",
                                 "robot")),
      // Selections and set names in another order than the set specs; "Gains" selects nothing.
      prim("/robot", Specifier::Def, "Xform",
           {{"variantSelection", Selections{{{"Gains", ""}, {"Physics", "PhysX"}}}}, {"variantSetNames", set_names}}),
      prim("/robot/base", Specifier::Def, "Xform"),
      prim("/robot/link", Specifier::Def, "Xform"),
      prim("/robot/joint", Specifier::Def, "PhysicsRevoluteJoint",
           {{"apiSchemas", prepend_tokens({"PhysicsDriveAPI:angular"})}}),
      relationship("/robot/joint.physics:body0", {"/robot/base"}),
      relationship("/robot/joint.physics:body1", {"/robot/link"}),
      attribute("/robot/joint.physics:axis", "token", Token{"Y"}, Variability::Uniform),
      variant_set("/robot", "Gains"),
      variant("/robot", "Gains", "Stiff"),
      prim("/robot{Gains=Stiff}joint", Specifier::Over),
      attribute("/robot{Gains=Stiff}joint.drive:angular:physics:stiffness", "float", Float{500.0f}),
      attribute("/robot{Gains=Stiff}joint.drive:angular:physics:damping", "double", Double{0.3}),
      variant("/robot", "Gains", "Soft"),
      prim("/robot{Gains=Soft}joint", Specifier::Over),
      attribute("/robot{Gains=Soft}joint.drive:angular:physics:stiffness", "float", Float{5.0f}),
      variant_set("/robot", "Physics"),
      variant("/robot", "Physics", "physx-lite", {{"payload", two_payloads}}),
      variant("/robot", "Physics", "PhysX",
              {{"documentation", String{"PhysX's physics, authored in the variant."}},
               {"apiSchemas", explicit_schemas}}),
      // Properties of the variant itself: opinions on /robot.
      attribute("/robot{Physics=PhysX}.physxArticulation:enabledSelfCollisions", "bool", false, Variability::Uniform),
      relationship("/robot{Physics=PhysX}.physics:filteredPairs", {"/robot/base", "/robot/link"}),
      variant("/robot", "Physics", "None", {{"apiSchemas", deleted_schemas}}),
      // A reference to another crate asset whose set has the same name: the robot's selection
      // ("arm") then selects in the arm's set too, a variant it lacks, so no arm physics arrives.
      variant("/robot", "Physics", "arm", {{"references", prepend_reference("./isaac_arm.usd", "/arm")}}),
  };
  const std::string physx = "/robot{Physics=PhysX}";
  append(specs, body(physx + "base", 2.0f, {0.01f, 0.01f, 0.01f}));
  // A variant set on a prim inside the variant, with its selection there too.
  append(specs, body(physx + "link", 0.5f, {0.001f, 0.001f, 0.0005f},
                     {{"variantSelection", Selections{{{"Collider", "Box"}}}},
                      {"variantSetNames", prepend_strings({"Collider"})}}));
  append(specs, {variant_set(physx + "link", "Collider"), variant(physx + "link", "Collider", "Mesh"),
                 variant(physx + "link", "Collider", "Box",
                         {{"apiSchemas", prepend_tokens({"PhysicsCollisionAPI"})}})});
  return write_crate(specs);
}

}  // namespace

std::vector<CrateAsset> crate_variant_assets() {
  return {{"usdc/variants/simready/gripper.usd", simready_gripper()},
          {"usdc/variants/simready/runnables/physics/physx.usd", physx_payload()},
          {"usdc/variants/isaac_arm.usd", isaac_arm()},
          {"usdc/variants/edge_cases.usd", variant_edge_cases()}};
}

}  // namespace assetlint::test
