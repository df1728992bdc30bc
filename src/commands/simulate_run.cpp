#include "commands/simulate_run.h"

#include <fmt/format.h>

#include <cmath>

#include "physics/mujoco_step.h"

namespace assetlint::commands {

SimulationRun run_simulation(const SimulationSetup& setup) {
  SimulationRun run;
  if (setup.mujoco) run.engine = fmt::format("MuJoCo ({})", physics::integrator_name(setup.mujoco->integrator));
  const double dt = setup.row.dt;
  const physics::DriveTarget target{setup.target, 0.0};
  physics::JointState implicit{setup.from, 0.0}, explicit_state{setup.from, 0.0};
  run.implicit.push_back({0.0, setup.from, 0.0, 0.0});
  run.explicit_spring.push_back({0.0, setup.from, 0.0, 0.0});
  const double size = std::max(std::abs(setup.target - setup.from), 1e-9);
  bool explicit_running = true;
  for (int f = 1; f <= setup.frames; ++f) {
    const double t = f * dt;
    auto step = setup.mujoco ? physics::mujoco_step(setup.mujoco->integrator, dt, setup.mujoco->servo, setup.limits,
                                                    implicit, target, setup.load)
                             : physics::step_frame(setup.row, setup.limits, implicit, target, setup.load);
    implicit = step.state;
    run.implicit.push_back({t, implicit.position, implicit.velocity, step.average_force(dt)});
    if (explicit_running) {
      auto e = physics::explicit_frame(setup.row, setup.limits, explicit_state, target, setup.load);
      explicit_state = e.state;
      run.explicit_spring.push_back({t, explicit_state.position, explicit_state.velocity, e.average_force(dt)});
      // Far beyond the motion (or non-finite): it has diverged; stop before it overflows.
      if (!std::isfinite(explicit_state.position) || std::abs(explicit_state.position - setup.target) > 10 * size)
        explicit_running = false;
    }
  }
  const Limits limits{setup.limits.force.max_average_force(dt), setup.limits.max_velocity};
  run.implicit_metrics = measure(run.implicit, setup.from, setup.target, dt, limits);
  run.explicit_stable = physics::explicit_stable(setup.row);
  run.explicit_metrics = measure(run.explicit_spring, setup.from, setup.target, dt, limits);
  return run;
}

}  // namespace assetlint::commands
