// physics::servo_step against MuJoCo itself: one hinge with a servo (kp, kv and joint
// damping), stepped once from (q, q̇) = (1, 0) and (0, 1) by libmujoco, gives the columns of
// the integrator's one-step map; ours must match entry by entry. Debian's MuJoCo 2.2 has
// Euler, RK4 and implicit (implicitfast came later and treats a single hinge the same way).
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <cmath>
#include <fstream>

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
physics::StepMap mujoco_step_map(const Case& c) {
  test::TempDir dir;
  const auto path = dir.path() / "servo.xml";
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
    <general joint="hinge" gainprm="{}" biastype="affine" biasprm="0 {} {}"/>
  </actuator>
</mujoco>
)",
      c.h, c.integrator == MujocoIntegrator::ImplicitFast ? "implicit" : physics::integrator_name(c.integrator),
      c.servo.joint_damping, c.servo.inertia, c.servo.inertia, c.servo.inertia, c.servo.stiffness,
      -c.servo.stiffness, -c.servo.actuator_damping);
  char error[1000] = "";
  mjModel* model = mj_loadXML(path.string().c_str(), nullptr, error, sizeof error);
  INFO("MuJoCo: " << error);
  REQUIRE(model);
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

TEST_CASE("slowest_decay_rate: the slow real pole when overdamped, ζ·ω when underdamped", "[physics]") {
  // k = 2000, c = 100, I = 0.00156: poles solve I·s² + c·s + k = 0.
  const physics::Servo servo{0.00156, 2000, 0, 100};
  const double slow = (100 - std::sqrt(100.0 * 100 - 4 * 0.00156 * 2000)) / (2 * 0.00156);
  CHECK(physics::slowest_decay_rate(servo) == Approx(slow).epsilon(1e-12));
  CHECK(physics::slowest_decay_rate(physics::Servo{1, 4, 0.4, 0}) == Approx(0.2));  // ζ = 0.1, ω = 2
}
