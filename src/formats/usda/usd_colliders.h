#pragma once
// The collision shapes of a USD stage's rigid bodies: every Cube, Sphere, Cylinder, Capsule
// and Mesh prim with PhysicsCollisionAPI applied (and physics:collisionEnabled not false), on
// a rigid body prim or below it, becomes a CollisionShape of the nearest such body. Its pose
// is relative to the body frame (the xformOps of the prims between them; the body's own
// scale applies to its shapes, not to its frame), sizes and points are scaled and converted to
// metres with metersPerUnit once, here.
#include <vector>

#include "formats/usda/compose.h"
#include "model/asset.h"

namespace assetlint::usda {

// Adds the shapes to the links of `asset` (named by their prim paths). `on_stage[i]` says
// whether stage.prims[i] is defined and active.
void read_colliders(const Stage& stage, const std::vector<bool>& on_stage, double meters_per_unit, Asset& asset);

}  // namespace assetlint::usda
