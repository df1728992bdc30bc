#include "physics/drive_row.h"

#include <algorithm>
#include <cmath>

namespace assetlint::physics {

double DriveRow::x() const {
  if (type == DriveType::Acceleration) return 1.0 / (1.0 + a());
  return response > 0 ? 1.0 / (1.0 + a() * response) : 0.0;
}

double DriveRow::bias_coefficient() const {
  const double coefficient = stiffness * x() * h;
  return type == DriveType::Acceleration ? coefficient / response : coefficient;
}

double DriveRow::velocity_multiplier() const {
  const double multiplier = -x() * a();
  return type == DriveType::Acceleration ? multiplier / response : multiplier;
}

double DriveRow::impulse_multiplier() const { return solver == Solver::TGS ? 1.0 : 1.0 - x(); }

DriveRow drive_row(const SimulationRate& rate, double stiffness, double damping, DriveType type, double inertia) {
  DriveRow row;
  row.solver = rate.solver;
  row.dt = rate.dt();
  row.h = rate.h();
  row.substeps = rate.substeps();
  row.iterations = rate.solver == Solver::TGS ? rate.iterations() : rate.iterations_per_frame();
  row.stiffness = stiffness;
  row.damping = damping;
  row.type = type;
  row.response = inertia > 0 ? 1.0 / inertia : 0.0;
  return row;
}

Hold static_hold(const DriveRow& row, double delta, const ForceLimit& limit) {
  Hold hold;
  const double sign = delta < 0 ? -1.0 : 1.0;
  const double error = std::abs(delta);
  const double per_solve = row.bias_coefficient() * error;  // impulse one solve adds while the joint is still
  double impulse = 0;
  if (row.solver == Solver::TGS) {
    impulse = per_solve * row.substeps;  // carried over the sub-steps: x·k·Δ·dt
  } else {
    // f ← (1 − x)·f + B·Δ, M times from 0: f = (1 − (1 − x)^M)·B·Δ / x.
    const double x = row.x();
    impulse = x > 0 ? (1.0 - std::pow(1.0 - x, row.iterations)) * per_solve / x : 0.0;
  }
  const double stiff_force = row.stiffness * error;
  hold.spring = sign * (row.type == DriveType::Acceleration ? stiff_force / row.response : stiff_force);
  hold.uncapped = sign * impulse / row.dt;
  const double cap = limit.max_average_force(row.dt);
  hold.capped = impulse / row.dt > cap;
  hold.force = sign * std::min(impulse / row.dt, cap);
  return hold;
}

namespace {

// The stop and velocity clamps applied after each solve; `step` is the time the
// velocity will be integrated over.
double clamp_velocity(double velocity, double position, double stop_side, const FrameLimits& limits, double step) {
  velocity = std::clamp(velocity, -limits.max_velocity, limits.max_velocity);
  if (limits.stop) {
    const double room = (*limits.stop - position) / step;
    if (stop_side > 0 && velocity > room) velocity = room;
    if (stop_side < 0 && velocity < room) velocity = room;
  }
  return velocity;
}

double stop_side(const FrameLimits& limits, double position) {
  if (!limits.stop) return 0;
  if (limits.stop_direction != 0) return limits.stop_direction;
  return *limits.stop >= position ? 1.0 : -1.0;
}

}  // namespace

FrameResult step_frame(const DriveRow& row, const FrameLimits& limits, JointState state, DriveTarget target,
                       double load) {
  const double side = stop_side(limits, state.position);
  const double bias = row.bias_coefficient();
  const double velocity_multiplier = row.velocity_multiplier();
  const double impulse_multiplier = row.impulse_multiplier();
  const double max_impulse = limits.force.max_impulse(row.dt);
  const double scale = row.type == DriveType::Acceleration ? 1.0 / row.response : 1.0;
  // The row's constant part, from the error at the frame's start. Under TGS a velocity
  // target shifts the position target back by (dt − h)·v_target and ramps it over the frame.
  const double error = target.position - state.position - (row.dt - row.h) * target.velocity;
  const double constant = row.x() * row.h * row.damping * target.velocity * scale + bias * error;
  const double ramp = row.solver == Solver::TGS ? bias * target.velocity : 0.0;
  FrameResult result;
  double accumulated = 0, moved = 0;
  const auto solve = [&](double elapsed) {
    const double unclamped = accumulated * impulse_multiplier + state.velocity * velocity_multiplier + constant -
                             moved * bias + elapsed * ramp;
    const double clamped = std::clamp(unclamped, -max_impulse, max_impulse);
    state.velocity += (clamped - accumulated) * row.response;
    accumulated = clamped;
  };
  // External forces enter as one velocity change per frame, before the solver runs (PhysX
  // integrates them into the unconstrained velocity over the whole dt, TGS and PGS alike).
  state.velocity += load * row.dt * row.response;
  if (row.solver == Solver::TGS) {
    for (int s = 0; s < row.substeps; ++s) {
      solve(s * row.h);
      state.velocity = clamp_velocity(state.velocity, state.position, side, limits, row.h);
      state.position += state.velocity * row.h;
      moved += state.velocity * row.h;
    }
  } else {
    for (int i = 0; i < row.iterations; ++i) {
      solve(0.0);
      state.velocity = clamp_velocity(state.velocity, state.position, side, limits, row.dt);
    }
    state.position += state.velocity * row.dt;
  }
  result.state = state;
  result.impulse = accumulated;
  return result;
}

FrameResult explicit_frame(const DriveRow& row, const FrameLimits& limits, JointState state, DriveTarget target,
                           double load) {
  const double side = stop_side(limits, state.position);
  const double max_force = limits.force.max_average_force(row.dt);
  FrameResult result;
  for (int s = 0; s < row.substeps; ++s) {
    double force = row.stiffness * (target.position - state.position) + row.damping * (target.velocity - state.velocity);
    if (row.type == DriveType::Acceleration) force /= row.response;  // k and d act as if I = 1
    force = std::clamp(force, -max_force, max_force);
    state.velocity += row.h * (force + load) * row.response;
    state.velocity = clamp_velocity(state.velocity, state.position, side, limits, row.h);
    state.position += state.velocity * row.h;
    result.impulse += force * row.h;
  }
  result.state = state;
  return result;
}

bool explicit_stable(const DriveRow& row) {
  const double r = row.type == DriveType::Acceleration ? 1.0 : row.response;
  const double spring = row.h * row.h * row.stiffness * r, damper = row.h * row.damping * r;
  return damper < 2 && spring + 2 * damper < 4;
}

}  // namespace assetlint::physics
