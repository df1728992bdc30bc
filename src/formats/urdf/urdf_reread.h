#pragma once
// What the model does not keep of a URDF document, read again when a rule needs it: a link's
// <visual> (the model keeps only collision shapes, but a link that is drawn is a part of the
// robot, not a frame) and the <mujoco><compiler> section MuJoCo's URDF importer reads.
#include "model/asset.h"
#include "physics/mujoco_inertia.h"

namespace assetlint::urdf {

// Whether the URDF element of `link` has a <visual> child. False when the link's file is not a
// URDF document that can be read again (a link built in memory, a file that is not XML).
bool link_has_visual(const Asset& asset, const Link& link);

// How MuJoCo's compiler receives the file's <inertia> tensors: full tensors, with the
// boundinertia and balanceinertia of a <mujoco><compiler> element under <robot> when there is one.
physics::MujocoInertiaInput mujoco_inertia_input(const Asset& asset);

}  // namespace assetlint::urdf
