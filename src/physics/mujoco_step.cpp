#include "physics/mujoco_step.h"

#include <algorithm>
#include <cmath>

namespace assetlint::physics {

namespace {

double actuator_force(const Servo& servo, double max_force, JointState s, DriveTarget target) {
  const double force = servo.stiffness * (target.position - s.position) +
                       servo.actuator_damping * (target.velocity - s.velocity);
  return std::clamp(force, -max_force, max_force);
}

double acceleration(const Servo& servo, double max_force, JointState s, DriveTarget target, double load) {
  return (actuator_force(servo, max_force, s, target) - servo.joint_damping * s.velocity + load) / servo.inertia;
}

double stop_clamped(double velocity, double position, const FrameLimits& limits, double h) {
  velocity = std::clamp(velocity, -limits.max_velocity, limits.max_velocity);
  if (!limits.stop) return velocity;
  const double side = limits.stop_direction != 0 ? limits.stop_direction : (*limits.stop >= position ? 1.0 : -1.0);
  const double room = (*limits.stop - position) / h;
  if (side > 0) return std::min(velocity, room);
  return std::max(velocity, room);
}

}  // namespace

FrameResult mujoco_step(MujocoIntegrator integrator, double h, const Servo& servo, const FrameLimits& limits,
                        JointState state, DriveTarget target, double load) {
  const double max_force = limits.force.max_force;
  FrameResult result;
  result.impulse = actuator_force(servo, max_force, state, target) * h;
  if (integrator == MujocoIntegrator::RK4) {
    const auto derivative = [&](JointState s) { return JointState{s.velocity, acceleration(servo, max_force, s, target, load)}; };
    const auto along = [](JointState s, JointState d, double t) {
      return JointState{s.position + t * d.position, s.velocity + t * d.velocity};
    };
    const JointState k1 = derivative(state), k2 = derivative(along(state, k1, h / 2)),
                     k3 = derivative(along(state, k2, h / 2)), k4 = derivative(along(state, k3, h));
    JointState next{state.position + h / 6 * (k1.position + 2 * k2.position + 2 * k3.position + k4.position),
                    state.velocity + h / 6 * (k1.velocity + 2 * k2.velocity + 2 * k3.velocity + k4.velocity)};
    // A stop removes what would carry the joint into it, as for the other integrators.
    next.velocity = stop_clamped(next.velocity, state.position, limits, h);
    if (limits.stop && next.velocity == (*limits.stop - state.position) / h) next.position = *limits.stop;
    result.state = next;
    return result;
  }
  // libmujoco keeps kv in the implicit solve even while the force range clamps the force
  // (tests/mujoco_servo_step_test.cpp checks this against its trajectory).
  const double implicit = implicit_damping(integrator, servo);
  const double force = actuator_force(servo, max_force, state, target) - servo.joint_damping * state.velocity + load;
  state.velocity += h * force / (servo.inertia + h * implicit);
  state.velocity = stop_clamped(state.velocity, state.position, limits, h);
  state.position += h * state.velocity;
  result.state = state;
  return result;
}

}  // namespace assetlint::physics
