#include "physics/servo_step.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "physics/drive.h"

namespace assetlint::physics {

std::string_view integrator_name(MujocoIntegrator integrator) {
  switch (integrator) {
    case MujocoIntegrator::Euler: return "Euler";
    case MujocoIntegrator::RK4: return "RK4";
    case MujocoIntegrator::Implicit: return "implicit";
    case MujocoIntegrator::ImplicitFast: return "implicitfast";
  }
  return "";
}

std::optional<MujocoIntegrator> parse_integrator(std::string_view keyword) {
  for (auto integrator : {MujocoIntegrator::Euler, MujocoIntegrator::RK4, MujocoIntegrator::Implicit,
                          MujocoIntegrator::ImplicitFast})
    if (keyword == integrator_name(integrator)) return integrator;
  return std::nullopt;
}

Servo mujoco_servo(const Joint& joint, double stiffness, double damping, double inertia) {
  Servo servo;
  servo.inertia = inertia;
  servo.stiffness = stiffness;
  servo.joint_damping = joint.joint_damping ? std::max(0.0, joint.joint_damping->value) : 0.0;
  servo.actuator_damping = std::max(0.0, damping - servo.joint_damping);
  return servo;
}

double Servo::damping_ratio() const { return physics::damping_ratio(damping(), stiffness, inertia); }

double StepMap::spectral_radius() const {
  const double trace = qq + vv;
  const double determinant = qq * vv - qv * vq;
  const double discriminant = trace * trace / 4 - determinant;
  if (discriminant < 0) return std::sqrt(determinant);  // a complex pair: |λ|² = det
  const double root = std::sqrt(discriminant);
  return std::max(std::abs(trace / 2 + root), std::abs(trace / 2 - root));
}

double implicit_damping(MujocoIntegrator integrator, const Servo& servo) {
  switch (integrator) {
    case MujocoIntegrator::Euler: return servo.joint_damping;
    case MujocoIntegrator::Implicit:
    case MujocoIntegrator::ImplicitFast: return servo.damping();
    case MujocoIntegrator::RK4: return 0;
  }
  return 0;
}

double explicit_damping(MujocoIntegrator integrator, const Servo& servo) {
  return servo.damping() - implicit_damping(integrator, servo);
}

namespace {

using Matrix = std::array<double, 4>;  // row-major 2×2

Matrix multiply(const Matrix& a, const Matrix& b) {
  return {a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2],
          a[2] * b[1] + a[3] * b[3]};
}

// RK4 on a linear system is its Taylor polynomial: Σ (hA)ⁿ/n! for n ≤ 4.
StepMap runge_kutta_step(double h, const Servo& servo) {
  const Matrix ha{0, h, -h * servo.stiffness / servo.inertia, -h * servo.damping() / servo.inertia};
  Matrix sum{1, 0, 0, 1}, power{1, 0, 0, 1};
  for (int n = 1; n <= 4; ++n) {
    power = multiply(power, ha);
    for (double& entry : power) entry /= n;
    for (int i = 0; i < 4; ++i) sum[i] += power[i];
  }
  return {sum[0], sum[1], sum[2], sum[3]};
}

}  // namespace

StepMap servo_step(MujocoIntegrator integrator, double h, const Servo& servo) {
  if (integrator == MujocoIntegrator::RK4) return runge_kutta_step(h, servo);
  // Semi-implicit: the velocity first, with the implicit damping solved at the new
  // velocity, then the position with that new velocity.
  //   (I + h·c_i)·q̇' = (I − h·c_e)·q̇ − h·k·q,   q' = q + h·q̇'
  const double denominator = servo.inertia + h * implicit_damping(integrator, servo);
  const double vq = -h * servo.stiffness / denominator;
  const double vv = (servo.inertia - h * explicit_damping(integrator, servo)) / denominator;
  return {1 + h * vq, h * vv, vq, vv};
}

double slowest_decay_rate(const Servo& servo) {
  const double omega = natural_frequency(servo.stiffness, servo.inertia);
  const double zeta = servo.damping_ratio();
  if (zeta < 1) return zeta * omega;
  return omega / (zeta + std::sqrt(zeta * zeta - 1));  // = ω·(ζ − sqrt(ζ² − 1)) without the cancellation
}

StepVerdict step_verdict(MujocoIntegrator integrator, double h, const Servo& servo) {
  const double radius = servo_step(integrator, h, servo).spectral_radius();
  if (!(radius < 1.0 + 1e-12)) return StepVerdict::Grows;
  if (!(servo.damping() > 0) || radius >= 1.0 - 1e-12) return StepVerdict::Undamped;
  return StepVerdict::Decays;
}

}  // namespace assetlint::physics
