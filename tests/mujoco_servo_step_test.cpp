// physics::servo_step against MuJoCo itself: one hinge with a servo (kp, kv and joint
// damping), stepped once from (q, q̇) = (1, 0) and (0, 1) by libmujoco, gives the columns of
// the integrator's one-step map; ours must match entry by entry. Debian's MuJoCo 2.2 has
// Euler, RK4 and implicit (implicitfast came later and treats a single hinge the same way).
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "physics/mujoco_step.h"
#include "physics/servo_step.h"
#include "test_support.h"

#ifdef ASSET_LINT_HAVE_MUJOCO
#include <mujoco/mujoco.h>
#endif

using namespace assetlint;
using physics::MujocoIntegrator;

namespace {

struct Case {
  MujocoIntegrator integrator;
  double h;
  physics::Servo servo;
};

#ifdef ASSET_LINT_HAVE_MUJOCO
// One hinge of inertia I about its axis, no gravity, a servo as an affine <general>
// actuator (kp, kv), the joint's damping, and a force range when max_force is finite.
mjModel* load_servo(const Case& c, const std::filesystem::path& dir, double max_force) {
  const auto path = dir / "servo.xml";
  const std::string range = std::isfinite(max_force)
                                ? fmt::format(R"( forcelimited="true" forcerange="{} {}")", -max_force, max_force)
                                : std::string();
  std::ofstream(path) << fmt::format(
      R"(<mujoco>
  <option timestep="{}" integrator="{}" gravity="0 0 0"/>
  <worldbody>
    <body>
      <joint name="hinge" type="hinge" axis="0 0 1" damping="{}"/>
      <inertial pos="0 0 0" mass="1" diaginertia="{} {} {}"/>
    </body>
  </worldbody>
  <actuator>
    <general joint="hinge" gainprm="{}" biastype="affine" biasprm="0 {} {}"{}/>
  </actuator>
</mujoco>
)",
      c.h, c.integrator == MujocoIntegrator::ImplicitFast ? "implicit" : physics::integrator_name(c.integrator),
      c.servo.joint_damping, c.servo.inertia, c.servo.inertia, c.servo.inertia, c.servo.stiffness,
      -c.servo.stiffness, -c.servo.actuator_damping, range);
  char error[1000] = "";
  mjModel* model = mj_loadXML(path.string().c_str(), nullptr, error, sizeof error);
  INFO("MuJoCo: " << error);
  REQUIRE(model);
  return model;
}

physics::StepMap mujoco_step_map(const Case& c) {
  test::TempDir dir;
  mjModel* model = load_servo(c, dir.path(), std::numeric_limits<double>::infinity());
  mjData* data = mj_makeData(model);
  const auto step_from = [&](double q, double v) {
    mj_resetData(model, data);
    data->qpos[0] = q;
    data->qvel[0] = v;
    data->ctrl[0] = 0;
    mj_step(model, data);
    return std::pair{data->qpos[0], data->qvel[0]};
  };
  const auto [qq, vq] = step_from(1, 0);
  const auto [qv, vv] = step_from(0, 1);
  mj_deleteData(data);
  mj_deleteModel(model);
  return {qq, qv, vq, vv};
}
#endif

}  // namespace

TEST_CASE("servo_step is MuJoCo's one-step map for each integrator", "[physics][mujoco]") {
#ifndef ASSET_LINT_HAVE_MUJOCO
  WARN("libmujoco-dev is not installed (scripts/bootstrap.sh installs it): MuJoCo servo-step test skipped");
#else
  // Kinova Gen3's joint_1 in MuJoCo Menagerie: kp 2000, kv 100 on the lighter link's 0.00156 kg·m²
  // at 2 ms (h·nf = 2.27, ζ = 28); then a lightly damped servo and a joint-damped one.
  const std::vector<physics::Servo> servos = {
      {0.00156, 2000, 0, 100}, {0.05, 2000, 0, 0.5}, {0.01, 500, 3, 1}, {0.2, 40, 0.5, 0}};
  for (const physics::Servo& servo : servos)
    for (auto integrator : {MujocoIntegrator::Euler, MujocoIntegrator::RK4, MujocoIntegrator::Implicit,
                            MujocoIntegrator::ImplicitFast}) {
      const Case c{integrator, 0.002, servo};
      INFO(physics::integrator_name(integrator) << " I=" << servo.inertia << " k=" << servo.stiffness
                                                << " joint damping=" << servo.joint_damping
                                                << " kv=" << servo.actuator_damping);
      const physics::StepMap ours = physics::servo_step(integrator, c.h, servo);
      const physics::StepMap theirs = mujoco_step_map(c);
      CHECK(ours.qq == Approx(theirs.qq).epsilon(1e-9).margin(1e-12));
      CHECK(ours.qv == Approx(theirs.qv).epsilon(1e-9).margin(1e-12));
      CHECK(ours.vq == Approx(theirs.vq).epsilon(1e-9).margin(1e-12));
      CHECK(ours.vv == Approx(theirs.vv).epsilon(1e-9).margin(1e-12));
    }
#endif
}

TEST_CASE("servo_step: which damping is implicit decides stability past h·nf = 2", "[physics]") {
  // h·nf = 2.27 and ζ = 28: unstable with an explicit spring and explicit kv, stable once kv is implicit.
  const physics::Servo kinova{0.00156, 2000, 0, 100};
  CHECK_FALSE(physics::servo_step(MujocoIntegrator::Euler, 0.002, kinova).stable());
  CHECK_FALSE(physics::servo_step(MujocoIntegrator::RK4, 0.002, kinova).stable());
  CHECK(physics::servo_step(MujocoIntegrator::ImplicitFast, 0.002, kinova).stable());
  // Undamped, semi-implicit Euler is stable exactly below h·ω = 2, RK4 below 2·sqrt(2).
  const auto undamped = [](double h_omega) { return physics::Servo{1.0, h_omega * h_omega, 0, 0}; };
  CHECK(physics::servo_step(MujocoIntegrator::Euler, 1.0, undamped(1.999)).spectral_radius() == Approx(1.0));
  CHECK(physics::servo_step(MujocoIntegrator::Euler, 1.0, undamped(2.001)).spectral_radius() > 1.0);
  CHECK(physics::servo_step(MujocoIntegrator::RK4, 1.0, undamped(2.82)).stable());
  CHECK_FALSE(physics::servo_step(MujocoIntegrator::RK4, 1.0, undamped(2.83)).stable());
  // With the damper implicit: stable iff (hω)² < 4 + 4ζ·hω.
  const double zeta = 3, h_omega_edge = 2 * zeta + std::sqrt(4 * zeta * zeta + 4);
  const auto damped = [&](double h_omega) { return physics::Servo{1.0, h_omega * h_omega, 0, 2 * zeta * h_omega}; };
  CHECK(physics::servo_step(MujocoIntegrator::Implicit, 1.0, damped(h_omega_edge * 0.999)).stable());
  CHECK_FALSE(physics::servo_step(MujocoIntegrator::Implicit, 1.0, damped(h_omega_edge * 1.001)).stable());
}

TEST_CASE("step_verdict: an error only for a growing mode or an undamped spring", "[physics]") {
  using physics::StepVerdict;
  // Kinova Gen3 joint_1 on its lighter link: h·nf = 2.27, ζ = 28. implicitfast damps it, Euler's explicit kv does not.
  const physics::Servo kinova{0.00156, 2000, 0, 100};
  CHECK(physics::step_verdict(MujocoIntegrator::ImplicitFast, 0.002, kinova) == StepVerdict::Decays);
  CHECK(physics::step_verdict(MujocoIntegrator::Euler, 0.002, kinova) == StepVerdict::Grows);
  // Underdamped (ζ = 0.13) past h·nf = 2 under implicitfast: it rings, but the step map decays.
  CHECK(physics::step_verdict(MujocoIntegrator::ImplicitFast, 0.002, physics::Servo{0.0018, 2000, 0, 0.5}) ==
        StepVerdict::Decays);
  // No damping: semi-implicit Euler keeps the oscillation on the unit circle below h·ω = 2 and
  // grows above it; RK4 shrinks it only numerically.
  const auto undamped = [](double h_omega) { return physics::Servo{1.0, h_omega * h_omega, 0, 0}; };
  CHECK(physics::step_verdict(MujocoIntegrator::ImplicitFast, 1.0, undamped(1.5)) == StepVerdict::Undamped);
  CHECK(physics::step_verdict(MujocoIntegrator::Euler, 1.0, undamped(2.5)) == StepVerdict::Grows);
  CHECK(physics::step_verdict(MujocoIntegrator::RK4, 1.0, undamped(1.5)) == StepVerdict::Undamped);
  // Joint damping alone is implicit under Euler: it decays.
  CHECK(physics::step_verdict(MujocoIntegrator::Euler, 1.0, physics::Servo{1.0, 2.25, 0.5, 0}) == StepVerdict::Decays);
}

TEST_CASE("slowest_decay_rate: the slow real pole when overdamped, ζ·ω when underdamped", "[physics]") {
  // k = 2000, c = 100, I = 0.00156: poles solve I·s² + c·s + k = 0.
  const physics::Servo servo{0.00156, 2000, 0, 100};
  const double slow = (100 - std::sqrt(100.0 * 100 - 4 * 0.00156 * 2000)) / (2 * 0.00156);
  CHECK(physics::slowest_decay_rate(servo) == Approx(slow).epsilon(1e-12));
  CHECK(physics::slowest_decay_rate(physics::Servo{1, 4, 0.4, 0}) == Approx(0.2));  // ζ = 0.1, ω = 2
}

namespace {

#ifdef ASSET_LINT_HAVE_MUJOCO
// q after each of `steps` MuJoCo steps from q = from, q̇ = 0 toward ctrl = target, with a
// force range and a constant applied torque.
std::vector<std::pair<double, double>> mujoco_trajectory(const Case& c, double max_force, double from, double target,
                                                         double load, int steps) {
  test::TempDir dir;
  mjModel* model = load_servo(c, dir.path(), max_force);
  mjData* data = mj_makeData(model);
  data->qpos[0] = from;
  data->ctrl[0] = target;
  data->qfrc_applied[0] = load;
  std::vector<std::pair<double, double>> out;
  for (int i = 0; i < steps; ++i) {
    mj_step(model, data);
    out.emplace_back(data->qpos[0], data->qvel[0]);
  }
  mj_deleteData(data);
  mj_deleteModel(model);
  return out;
}
#endif

}  // namespace

TEST_CASE("mujoco_step follows libmujoco's trajectory with the force range and a load", "[physics][mujoco]") {
#ifndef ASSET_LINT_HAVE_MUJOCO
  WARN("libmujoco-dev is not installed (scripts/bootstrap.sh installs it): MuJoCo trajectory test skipped");
#else
  // A stiff, heavily damped servo that starts saturated at its force range, with joint damping
  // and a load against it: every branch of the step (clamped, unclamped, implicit, explicit).
  const physics::Servo servo{0.0018, 2000, 0.5, 100};
  const double max_force = 30, from = 1.0, target = 0.0, load = 4;
  for (auto integrator : {MujocoIntegrator::Euler, MujocoIntegrator::RK4, MujocoIntegrator::Implicit}) {
    // Euler and RK4 would diverge with this kv at 2 ms: use a step they resolve.
    const double h = integrator == MujocoIntegrator::Implicit ? 0.002 : 1e-5;
    const Case c{integrator, h, servo};
    INFO(physics::integrator_name(integrator));
    const int steps = 400;
    const auto theirs = mujoco_trajectory(c, max_force, from, target, load, steps);
    physics::FrameLimits limits;
    limits.force.max_force = max_force;
    physics::JointState state{from, 0.0};
    bool saturated = false, free = false;
    for (int i = 0; i < steps; ++i) {
      const double unclamped = servo.stiffness * (target - state.position) - servo.actuator_damping * state.velocity;
      (std::abs(unclamped) > max_force ? saturated : free) = true;
      state = physics::mujoco_step(integrator, h, servo, limits, state, {target, 0.0}, load).state;
      INFO("step " << i);
      REQUIRE(state.position == Approx(theirs[i].first).epsilon(1e-8).margin(1e-12));
      REQUIRE(state.velocity == Approx(theirs[i].second).epsilon(1e-8).margin(1e-10));
    }
    CHECK(saturated);
    CHECK(free);
  }
#endif
}
