#pragma once
// MJCF actuators as drives. Every actuator kind is a `general` actuator underneath
// (force = gain·ctrl + bias); the shortcuts set its parameters:
//   <position kp kv>: gainprm = kp, biasprm = (0, −kp, −kv), biastype affine
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
using FixedTendons = std::unordered_map<std::string, std::vector<std::string>>;

// Reads one actuator element onto the joint it names (already in `asset`), and marks every
// joint it moves, directly or through a fixed tendon, as actuated.
void read_actuator(const tinyxml2::XMLElement* el, const Defaults& defaults, const Compiler& compiler,
                   const FixedTendons& tendons, Values& values, Asset& asset);

}  // namespace assetlint::mjcf
