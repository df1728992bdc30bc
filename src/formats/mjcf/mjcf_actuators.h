#pragma once
// MJCF actuators as drives. Every actuator kind is a `general` actuator underneath
// (force = gain·ctrl + bias); the shortcuts set its parameters:
//   <position kp kv>: gainprm = kp, biasprm = (0, −kp, −kv), biastype affine
//   <position dampratio=ζ>: biasprm[2] = +ζ; on a position-like actuator (gainprm[0] =
//     −biasprm[1]) MuJoCo reads a positive biasprm[2] as a damping ratio and compiles it to
//     kv = 2ζ·√(kp·M₀/g²) (mjcf_dampratio.h). kv and dampratio write the same slot: the
//     class chain, then the element, each overwrites it.
//   <velocity kv>:    gainprm = kv, biasprm = (0, 0, −kv): a damper towards ctrl (velocity)
//   <motor>:          gainprm = 1, no bias
// A joint-transmission actuator with gear g moves the joint with g²·kp per radian
// (length = g·q, force on the joint = g·force): stiffness = −biasprm[1]·g²,
// damping = −biasprm[2]·g², max force = forcerange·|g|. A motor bounds the joint's effort
// by its control range (×gain×|g|) or force range.
#include <tinyxml2.h>

#include <string>
#include <unordered_map>
#include <vector>

#include "formats/mjcf/mjcf_defaults.h"
#include "formats/mjcf/mjcf_values.h"
#include "model/asset.h"

namespace assetlint::mjcf {

// <tendon><fixed name="t"><joint joint="j" coef="c"/>…: the joints each fixed tendon moves.
struct TendonJoint {
  std::string joint;
  double coef = 1.0;
  Span span;  // the <joint> element
};
struct FixedTendon {
  std::vector<TendonJoint> joints;
  Span span;          // the <fixed> element
  std::string label;  // "fixed tendon 'split'"
};
using FixedTendons = std::unordered_map<std::string, FixedTendon>;

// A servo whose kv MuJoCo derives from a damping ratio once the model is compiled.
struct DampRatio {
  std::size_t joint = 0;  // index into asset.joints; its drive's damping is left unset
  double ratio = 0;       // ζ
  double kp = 0;          // the actuator's gain (gainprm[0])
  double gear = 1;        // joint transmission ratio g (on a tendon: the ratio to the joint carrying the drive)
  // On a fixed tendon: the actuator's moment on each joint it reaches (index into
  // asset.joints, gear·coef); MuJoCo derives kv on the inertia this moment reflects. Empty on a joint.
  std::vector<std::pair<std::size_t, double>> moment;
  Span span;              // the literal holding ζ
  std::string label;      // "actuator 'x'"
  // The joint damping MuJoCo adds on the drive's motion: the joint's own, on a tendon with
  // the mimics that move with it (each times multiplier²).
  double joint_damping = 0;
};

// A damper actuator (a <velocity>, or any affine actuator without a spring: force =
// kv·(ctrl − q̇)) on a joint. Folded into the joint's drive after every actuator is read, so a
// position servo and a velocity actuator on one joint (a PD pair) make one drive.
struct Damper {
  std::size_t joint = 0;   // index into asset.joints
  OptQuantity damping;     // kv·g², N·m·s/rad or N·s/m
  OptQuantity max_force;   // its force range on the joint, when limited
  Span span;               // the actuator element
  std::string label;       // "actuator 'x'"
};

// Reads one actuator element onto the joint it names (already in `asset`), and marks every
// joint it moves, directly or through a fixed tendon, as actuated. A servo damped by a damping
// ratio is appended to `damp_ratios`, a damper to `dampers`, for the passes after the whole
// model is read. An actuator on a fixed tendon is appended to `on_tendons` instead: which
// joint carries its drive depends on the joint equalities, read after the actuators.
void read_actuator(const tinyxml2::XMLElement* el, const Defaults& defaults, const Compiler& compiler,
                   const FixedTendons& tendons, Values& values, Asset& asset, std::vector<DampRatio>& damp_ratios,
                   std::vector<Damper>& dampers, std::vector<const tinyxml2::XMLElement*>& on_tendons);

// Reads an actuator on a fixed tendon (length = Σ coefᵢ·qᵢ) as the drive it is, once the
// mimics are known. The tendon's joints fall into groups, each a joint and the joints that
// mimic it; the group moves the tendon by G = gear·Σ coefᵢ·multiplierᵢ per unit of its joint,
// and that joint gets the drive: stiffness kp·G², damping kv·G² (plus the group's joint
// damping, each times multiplier²), max force |forcerange|·|G|, Transmission ratio |G| with the
// tendon's shares. A motor bounds the joint's effort the same way.
// `qpos0`: each joint's reference position (`ref`) where the file writes one, model units.
void read_tendon_actuator(const tinyxml2::XMLElement* el, const Defaults& defaults, const Compiler& compiler,
                          const FixedTendons& tendons, const std::unordered_map<std::string, double>& qpos0,
                          Values& values, Asset& asset, std::vector<DampRatio>& damp_ratios, std::vector<Damper>& dampers);

// Adds each damper's kv·g² to its joint's drive (after derive_dampratio_damping: a servo's kv
// from dampratio does not count them); a joint with dampers only gets a velocity drive.
void add_dampers(const std::vector<Damper>& dampers, Asset& asset);

}  // namespace assetlint::mjcf
