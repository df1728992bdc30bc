// The time constant of a servo on a fixed tendon of several joints (physics/tendon_lag.h).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "physics/tendon_lag.h"
#include "test_support.h"

#ifdef ASSET_LINT_HAVE_MUJOCO
#include <mujoco/mujoco.h>
#endif

using assetlint::physics::TendonJointDamper;
using assetlint::physics::tendon_time_constant;

TEST_CASE("a tendon over several damped joints follows with (kv + 1/sum c^2/d) / kp", "[physics][tendon]") {
  // The spine fixtures: kp 20 on coefs 0.34, 0.33, 0.33. MuJoCo 3.14 brings the length to 63 %
  // of a step in 0.15 s (damping 1) and 0.45 s (damping 3), stepping at 0.5 ms.
  std::vector<TendonJointDamper> spine{{0.34, 1.0}, {0.33, 1.0}, {0.33, 1.0}};
  CHECK(*tendon_time_constant(20, 0, spine) == Approx(1.0 / (0.34 * 0.34 + 0.33 * 0.33 + 0.33 * 0.33) / 20));
  CHECK(*tendon_time_constant(20, 0, spine) == Approx(0.15).margin(0.001));
  for (auto& joint : spine) joint.damping = 3.0;
  CHECK(*tendon_time_constant(20, 0, spine) == Approx(0.45).margin(0.001));
  // Each joint alone would claim d / (kp·c²): three times slower for the first joint.
  CHECK(3.0 / (20 * 0.34 * 0.34) > 2.8 * *tendon_time_constant(20, 0, spine));
  // The actuator's own kv adds to the joints' damper on the tendon.
  CHECK(*tendon_time_constant(20, 2, spine) == Approx(0.45 + 2.0 / 20).margin(0.001));
  // One joint of one coefficient: the joint's own d / (kp·c²).
  const std::vector<TendonJointDamper> one{{0.5, 2.0}};
  CHECK(*tendon_time_constant(10, 0, one) == Approx(2.0 / (10 * 0.25)));
}

TEST_CASE("a tendon with an undamped joint, no damping or no stiffness has no lag to report", "[physics][tendon]") {
  // An undamped joint moves the tendon as fast as its inertia allows: only kv is left.
  const std::vector<TendonJointDamper> mixed{{0.5, 1.0}, {0.5, 0.0}};
  CHECK(*tendon_time_constant(10, 1, mixed) == Approx(0.1));
  CHECK_FALSE(tendon_time_constant(10, 0, mixed));
  CHECK_FALSE(tendon_time_constant(0, 1, mixed));
  const std::vector<TendonJointDamper> still{{0.0, 1.0}};
  CHECK_FALSE(tendon_time_constant(10, 1, still));
}

TEST_CASE("libmujoco brings a spine tendon to 63 % of a step in the tendon's time constant", "[physics][tendon][mujoco]") {
#ifndef ASSET_LINT_HAVE_MUJOCO
  WARN("libmujoco-dev is not installed (scripts/bootstrap.sh installs it): MuJoCo tendon-lag test skipped");
#else
  for (const auto& [fixture, damping] : {std::pair{"tendon_spine.xml", 1.0}, std::pair{"tendon_spine_slow.xml", 3.0}}) {
    const auto path = assetlint::test::fixtures_dir() / "rules" / "drive-damping-ratio" / fixture;
    char error[1000] = "";
    mjModel* model = mj_loadXML(path.string().c_str(), nullptr, error, sizeof error);
    INFO(fixture << ": " << error);
    REQUIRE(model);
    mjData* data = mj_makeData(model);
    const double coef[3] = {0.34, 0.33, 0.33};
    const auto length = [&] { return coef[0] * data->qpos[0] + coef[1] * data->qpos[1] + coef[2] * data->qpos[2]; };
    const double step = 0.1;
    data->ctrl[0] = step;
    double reached = -1;
    for (int i = 1; i <= 8000 && reached < 0; ++i) {
      mj_step(model, data);
      if (length() >= step * (1 - std::exp(-1.0))) reached = data->time;
    }
    mj_deleteData(data);
    mj_deleteModel(model);
    const std::vector<TendonJointDamper> spine{{0.34, damping}, {0.33, damping}, {0.33, damping}};
    CHECK(reached == Approx(*tendon_time_constant(20, 0, spine)).epsilon(0.02));
  }
#endif
}
