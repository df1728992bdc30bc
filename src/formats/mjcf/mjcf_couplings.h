#pragma once
// The constraints of an MJCF model that tie one joint's motion to another's: what decides
// whether a joint no actuator names is driven anyway, coupled into a mechanism, or free.
//   - A fixed tendon that MuJoCo holds to a narrow range (or an <equality><tendon>) is a
//     transmission: the Shadow hand's distal joint follows its middle joint that way, and the
//     motor that turns one turns both.
//   - A <weld> or <connect> to a mocap body is how a model is driven kinematically (a
//     teleoperated arm): every joint between that body and the root moves with it.
//   - A <connect> or <weld> between two bodies of the robot closes a loop (a four-bar
//     linkage), and an <equality><joint> couples two joints: their joints belong to a mechanism.
//   - A spatial tendon that resists stretching (a range or a stiffness) between a body one joint
//     moves and a body it does not is a rope: the drive that winds it also lifts the other body.
#include <tinyxml2.h>

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "formats/mjcf/mjcf_actuators.h"
#include "formats/mjcf/mjcf_defaults.h"
#include "formats/mjcf/mjcf_values.h"
#include "model/asset.h"

namespace assetlint::mjcf {

// A spatial tendon that pulls when stretched: the bodies its sites sit on (empty: the world).
struct Rope {
  std::vector<std::string> bodies;
  Span span;
  std::string label;  // "spatial tendon 'cable'" / "the spatial tendon at line 123"
};

// A coupling tendon (a fixed tendon held to a narrow range, or one a tendon equality ties).
struct CouplingTendon {
  std::vector<std::string> joints;
  Span span;
  std::string label;  // "fixed tendon 'waist_roll_coupling'"
};

// joint1 and joint2 (empty: none, the joint is held) of an <equality><joint>.
struct JointPair {
  std::string first, second;
  Span span;
};

// Two bodies a connect or weld equality ties together, closing a kinematic loop.
struct Loop {
  std::string body1, body2;
  Span span;
  std::string label;  // "the weld at line 403"
  bool weld = false;
  std::optional<Eigen::Vector3d> anchor;  // in body1's frame; unset when it cannot be placed
};


struct Couplings {
  FixedTendons fixed;                              // every named fixed tendon's joints
  std::vector<CouplingTendon> tendons;
  std::vector<Loop> loops;
  std::vector<std::string> mocap_driven;                   // bodies welded or connected to a mocap body
  std::vector<JointPair> joint_pairs;
  std::vector<Rope> ropes;
};

// Reads the fixed tendons and couplings of a model's top-level sections (after the bodies and
// joints, before the actuators, which name the tendons they pull).
Couplings read_couplings(const MjcfSources& sources, const Defaults& defaults, const Compiler& compiler,
                         const std::vector<const tinyxml2::XMLElement*>& sections, Values& values, const Asset& asset);

// Marks as actuated the joints an actuator reaches through a coupling tendon, and the joints a
// mocap body drives. Runs after the actuators are read, before undriven joints become passive.
void drive_through_couplings(const Couplings& couplings, Asset& asset);

// Notes on each drive that winds a rope hung with a body the drive's joint does not otherwise
// move: MuJoCo's M₀ᵢᵢ leaves that body out. Runs after the actuators are read.
void note_rope_loads(const Couplings& couplings, Asset& asset);

// Notes on each actuated joint of a loop, a coupling tendon or a joint equality that is not a
// mimic (a polynomial coupling) the other joints it turns through it: its Mᵢᵢ (every other
// joint held) leaves them out. Runs after the joint equalities have made their mimics.
void note_coupled_loads(const Couplings& couplings, Asset& asset);

// Marks as part of a linkage the passive joints that a loop, a joint equality or a coupling
// tendon ties to an actuated joint (directly or through other linkage joints). Passive joints
// coupled only to one another (an oven's knobs and the valve each one turns) stay passive: no
// actuator drags what they carry.
void mark_linkages(const Couplings& couplings, Asset& asset);

// The loops whose anchor is known, as the model's loop closures (the world written as "").
std::vector<LoopClosure> loop_closures(const Couplings& couplings);

}  // namespace assetlint::mjcf
