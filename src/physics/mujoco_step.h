#pragma once
// One MuJoCo timestep of a position servo with its force range, a load and a hard stop
// (docs/physics.md "MuJoCo's integrators"): what `simulate` steps for an MJCF asset.
// servo_step.h gives the same step's linear map; this one adds the clamps.
#include "physics/drive_row.h"
#include "physics/servo_step.h"

namespace assetlint::physics {

// The servo force kp·(target − q) + kv·(v_target − q̇), clamped to ±max_force (forcerange);
// the joint's own damping acts besides it, unclamped. Euler solves that joint damping at
// the new velocity; implicit/implicitfast solve the actuator's kv there too, as libmujoco
// does even while the force range clamps the force; RK4 is explicit.
// The velocity is then clamped by `limits` (a hard stop; MuJoCo has no velocity limit)
// and the position advanced with it.
FrameResult mujoco_step(MujocoIntegrator integrator, double h, const Servo& servo, const FrameLimits& limits,
                        JointState state, DriveTarget target, double load = 0);

}  // namespace assetlint::physics
