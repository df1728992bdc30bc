// The drive row PhysX builds (docs/physics.md), checked against rows computed by hand
// and the numbers of issue 14 / PHYSICS.md §3.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/file_system.h"
#include "formats/usda/usd_reader.h"
#include "physics/drive_row.h"
#include "util/numbers.h"

using namespace assetlint;
using namespace assetlint::physics;

namespace {

constexpr double kLighterLink = 3.37e-6;  // the guide's lighter link, kg·m²

SimulationRate rate(double hz, double iterations, Solver solver = Solver::TGS, double velocity_iterations = 1) {
  SimulationRate r;
  r.timesteps_per_second = hz;
  r.rate_origin = "test";
  r.position_iterations = iterations;
  r.iterations_origin = "test";
  r.velocity_iterations = velocity_iterations;
  r.solver = solver;
  return r;
}

const double kDelta = radians_from_degrees(5.0);

}  // namespace

TEST_CASE("step h: TGS cuts the frame into position-iteration sub-steps, PGS does not", "[physics][drive-row]") {
  SimulationRate tgs = rate(250, 64);
  CHECK(tgs.h() == Approx(1.0 / 16000).epsilon(1e-12));
  CHECK(tgs.frequency_bound() == Approx(16000));
  CHECK(tgs.step_text() == "TGS, h = 1/16000 s");
  CHECK(tgs.describe() == "TGS (default), h = dt/64 = 1/16000 s (250 Hz (test) / 64 position iterations (test))");
  SimulationRate pgs = rate(250, 64, Solver::PGS, 1);
  CHECK(pgs.h() == Approx(1.0 / 250).epsilon(1e-12));
  CHECK(pgs.frequency_bound() == Approx(250));
  CHECK(pgs.iterations_per_frame() == 65);
  CHECK(pgs.describe() == "PGS (default), h = dt = 1/250 s (250 Hz (test))");
  // The scene's clamps bound the articulation's count.
  tgs.max_position_iterations = 32;
  CHECK(tgs.iterations() == 32);
  CHECK(tgs.h() == Approx(1.0 / 8000).epsilon(1e-12));
  CHECK(tgs.describe() ==
        "TGS (default), h = dt/32 = 1/8000 s (250 Hz (test) / 64 position iterations (test), clamped to 32 by the scene)");
  tgs.max_position_iterations.reset();
  tgs.min_position_iterations = 100;
  CHECK(tgs.iterations() == 100);
  CHECK(rate(60, 64).step_text() == "TGS, h = 1/3840 s");
  CHECK(rate(70, 3).step_text() == "TGS, h = 1/210 s");
  CHECK(rate(100.5, 1).step_text() == "TGS, h = 0.00995 s");
}

TEST_CASE("implicit factor x = 1/(1 + h·(h·k + d)·r): the guide's drives at 250 Hz × 64", "[physics][drive-row]") {
  const SimulationRate r = rate(250, 64);
  // Hand-computed: h = 6.25e-5 s, r = 1/3.37e-6.
  // k 5700, d 0.277: a = 6.25e-5·(0.35625 + 0.277) = 3.95781e-5, a·r = 11.7443.
  CHECK(drive_row(r, 5700, 0.277, DriveType::Force, kLighterLink).x() == Approx(1 / (1 + 3.957813e-5 / kLighterLink)).epsilon(1e-6));
  CHECK(drive_row(r, 5700, 0.277, DriveType::Force, kLighterLink).x() == Approx(0.078).margin(5e-4));
  CHECK(drive_row(r, 5700, 0.1, DriveType::Force, kLighterLink).x() == Approx(0.106).margin(5e-4));
  CHECK(drive_row(r, 5700, 0.0, DriveType::Force, kLighterLink).x() == Approx(0.131).margin(5e-4));
  CHECK(drive_row(r, 275, 0.061, DriveType::Force, kLighterLink).x() == Approx(0.408).margin(5e-4));
  CHECK(drive_row(r, 275, 0.0, DriveType::Force, kLighterLink).x() == Approx(0.76).margin(5e-3));
  // Armature 5e-3 at 60 Hz × 64 (h = 1/3840): x = 0.993, holding 23.8 of 24 N·m.
  const DriveRow armature = drive_row(rate(60, 64), 275, 0.061, DriveType::Force, kLighterLink + 5e-3);
  CHECK(armature.x() == Approx(0.99315).epsilon(1e-4));
  const Hold hold = static_hold(armature, kDelta);
  CHECK(hold.spring == Approx(23.998).epsilon(1e-4));
  CHECK(hold.force == Approx(23.83).epsilon(1e-3));
  CHECK_FALSE(hold.capped);
}

TEST_CASE("acceleration drives: x = 1/(1 + a), k and d act as if I = 1", "[physics][drive-row]") {
  const DriveRow row = drive_row(rate(250, 64), 5700, 0.277, DriveType::Acceleration, kLighterLink);
  CHECK(row.x() == Approx(1 / (1 + 3.957813e-5)).epsilon(1e-9));
  CHECK(row.bias_coefficient() == Approx(5700 * row.x() * 6.25e-5 * kLighterLink).epsilon(1e-12));
  CHECK(row.velocity_multiplier() == Approx(-row.x() * 3.957813e-5 * kLighterLink).epsilon(1e-6));
  // Held at a stop: the force is x·k·Δ·I.
  const Hold hold = static_hold(row, kDelta);
  CHECK(hold.force == Approx(row.x() * 5700 * kDelta * kLighterLink).epsilon(1e-9));
  CHECK(hold.spring == Approx(5700 * kDelta * kLighterLink).epsilon(1e-9));
}

TEST_CASE("hold at a hard stop: TGS x·k·Δ, PGS (1 − (1 − x)^M)·k·Δ, capped at max force", "[physics][drive-row]") {
  const DriveRow tgs = drive_row(rate(250, 64), 5700, 0.277, DriveType::Force, kLighterLink);
  const Hold t = static_hold(tgs, kDelta);
  CHECK(t.spring == Approx(5700 * kDelta).epsilon(1e-12));
  CHECK(t.force == Approx(tgs.x() * 5700 * kDelta).epsilon(1e-9));
  CHECK(t.force == Approx(39.03).epsilon(1e-3));  // real PhysX 5.6.1: 39.05 at k·Δ = 497.6
  // PGS: x at h = dt = 1/250 is 3.6507e-5; M = 64 + 1.
  const DriveRow pgs = drive_row(rate(250, 64, Solver::PGS), 5700, 0.277, DriveType::Force, kLighterLink);
  CHECK(pgs.x() == Approx(1 / (1 + 0.004 * (0.004 * 5700 + 0.277) / kLighterLink)).epsilon(1e-9));
  const Hold p = static_hold(pgs, kDelta);
  CHECK(p.force == Approx((1 - std::pow(1 - pgs.x(), 65)) * 5700 * kDelta).epsilon(1e-9));
  CHECK(p.force == Approx(1.18).epsilon(3e-3));  // real PhysX 5.6.1: 1.18
  // With the forces flag the frame's impulse is capped at maxForce·dt: 24 N·m on average.
  const Hold capped = static_hold(tgs, kDelta, ForceLimit{24.0, true});
  CHECK(capped.capped);
  CHECK(capped.force == Approx(24.0));
  CHECK(capped.uncapped == Approx(t.force));
  // Without it 24 is an impulse per frame: 6000 N·m on average at 250 Hz, not reached.
  CHECK_FALSE(static_hold(tgs, kDelta, ForceLimit{24.0, false}).capped);
  // A negative error holds the other way.
  CHECK(static_hold(tgs, -kDelta).force == Approx(-t.force));
  // A heavy link: PGS reaches k·Δ (PhysX: 24.01 of 24.0 with I = 0.01).
  const DriveRow heavy = drive_row(rate(250, 64, Solver::PGS), 275, 0.061, DriveType::Force, 0.01);
  CHECK(static_hold(heavy, kDelta).fraction() == Approx(1.0).margin(1e-3));
}

TEST_CASE("frame stepper: holds at a stop what static_hold says, under both solvers", "[physics][drive-row]") {
  for (Solver solver : {Solver::TGS, Solver::PGS}) {
    for (double damping : {0.0, 0.277}) {
      const DriveRow row = drive_row(rate(250, 64, solver), 5700, damping, DriveType::Force, kLighterLink);
      FrameLimits limits;
      limits.stop = 0.0;
      const FrameResult frame = step_frame(row, limits, JointState{}, DriveTarget{kDelta, 0});
      CHECK(frame.state.position == 0.0);
      CHECK(frame.average_force(row.dt) == Approx(static_hold(row, kDelta).force).epsilon(1e-9));
      limits.force = ForceLimit{24.0, true};
      CHECK(step_frame(row, limits, JointState{}, DriveTarget{kDelta, 0}).average_force(row.dt) ==
            Approx(std::min(24.0, static_hold(row, kDelta).force)).epsilon(1e-9));
    }
  }
}

TEST_CASE("frame stepper, free motion: TGS is N backward-Euler steps of h, PGS one of dt", "[physics][drive-row]") {
  const double k = 275, d = 0.061, inertia = 1e-4, e0 = 0.1;
  // One sub-step from rest: v1 = x·h·k·r·e0, q1 = h·v1.
  {
    const DriveRow row = drive_row(rate(250, 1), k, d, DriveType::Force, inertia);
    const double h = 0.004, x = 1 / (1 + h * (h * k + d) / inertia);
    const FrameResult frame = step_frame(row, {}, JointState{}, DriveTarget{e0, 0});
    CHECK(frame.state.velocity == Approx(x * h * k / inertia * e0).epsilon(1e-12));
    CHECK(frame.state.position == Approx(h * x * h * k / inertia * e0).epsilon(1e-12));
  }
  // Two sub-steps, iterated by hand: the row keeps the frame-start error and subtracts the
  // distance moved so far.
  {
    const DriveRow row = drive_row(rate(250, 2), k, d, DriveType::Force, inertia);
    const double h = 0.002, x = 1 / (1 + h * (h * k + d) / inertia);
    const double v1 = x * (0 + h * k / inertia * e0);
    const double q1 = h * v1;
    const double v2 = x * (v1 + h * k / inertia * (e0 - q1));
    const FrameResult frame = step_frame(row, {}, JointState{}, DriveTarget{e0, 0});
    CHECK(frame.state.velocity == Approx(v2).epsilon(1e-12));
    CHECK(frame.state.position == Approx(q1 + h * v2).epsilon(1e-12));
    CHECK(frame.impulse == Approx(v2 * inertia).epsilon(1e-12));
  }
  // PGS: one backward-Euler step of dt however many iterations (the row converges after one).
  {
    const DriveRow row = drive_row(rate(250, 8, Solver::PGS, 4), k, d, DriveType::Force, inertia);
    const double h = 0.004, x = 1 / (1 + h * (h * k + d) / inertia);
    const JointState start{0.01, 0.5};
    const double v1 = x * (start.velocity + h * k / inertia * (e0 - start.position));
    const FrameResult frame = step_frame(row, {}, start, DriveTarget{e0, 0});
    CHECK(frame.state.velocity == Approx(v1).epsilon(1e-9));
    CHECK(frame.state.position == Approx(start.position + h * v1).epsilon(1e-9));
  }
}

TEST_CASE("frame stepper: velocity clamp and force clamp shape the motion", "[physics][drive-row]") {
  const DriveRow row = drive_row(rate(250, 64), 5700, 0.277, DriveType::Force, kLighterLink);
  FrameLimits limits;
  limits.max_velocity = 2.9;
  const FrameResult slow = step_frame(row, limits, JointState{}, DriveTarget{0.8, 0});
  CHECK(slow.state.velocity == Approx(2.9));
  CHECK(slow.state.position == Approx(2.9 * 0.004).epsilon(1e-9));  // every sub-step at the clamp
  // A heavy link far from its target: the frame's impulse hits maxForce·dt in the first
  // sub-step and stays there.
  const DriveRow heavy = drive_row(rate(250, 64), 5700, 0.277, DriveType::Force, 0.01);
  limits = FrameLimits{};
  limits.force = ForceLimit{24.0, true};
  const FrameResult weak = step_frame(heavy, limits, JointState{}, DriveTarget{0.8, 0});
  CHECK(weak.impulse == Approx(24.0 * 0.004));
  CHECK(weak.state.velocity == Approx(24.0 * 0.004 / 0.01));
  CHECK(weak.state.position == Approx(0.004 * 9.6).epsilon(1e-9));
}

TEST_CASE("explicit spring at the same h diverges past h·nf = 2 where the row converges", "[physics][drive-row]") {
  // 5700 N·m/rad on the lighter link at 250 Hz × 64: h·nf = 2.57.
  const DriveRow stiff = drive_row(rate(250, 64), 5700, 0.0, DriveType::Force, kLighterLink);
  CHECK(stiff.h * std::sqrt(5700 / kLighterLink) == Approx(2.57).margin(0.01));
  JointState implicit_state, explicit_state;
  for (int frame = 0; frame < 5; ++frame) {
    implicit_state = step_frame(stiff, {}, implicit_state, DriveTarget{0.1, 0}).state;
    explicit_state = explicit_frame(stiff, {}, explicit_state, DriveTarget{0.1, 0}).state;
  }
  CHECK(implicit_state.position == Approx(0.1).margin(1e-6));
  CHECK(std::abs(explicit_state.position) > 1e6);
  // 275 N·m/rad + 5e-3 armature at 60 Hz: PGS (h = dt, h·nf = 3.9) diverges explicitly,
  // TGS (h = 1/3840) is well behaved either way.
  const DriveRow pgs = drive_row(rate(60, 64, Solver::PGS), 275, 0.0, DriveType::Force, kLighterLink + 5e-3);
  CHECK(pgs.h * std::sqrt(275 / (kLighterLink + 5e-3)) == Approx(3.9).margin(0.02));
  const DriveRow tgs = drive_row(rate(60, 64), 275, 0.0, DriveType::Force, kLighterLink + 5e-3);
  JointState p_implicit, p_explicit, t_explicit;
  for (int frame = 0; frame < 20; ++frame) {
    p_implicit = step_frame(pgs, {}, p_implicit, DriveTarget{0.1, 0}).state;
    p_explicit = explicit_frame(pgs, {}, p_explicit, DriveTarget{0.1, 0}).state;
    t_explicit = explicit_frame(tgs, {}, t_explicit, DriveTarget{0.1, 0}).state;
  }
  CHECK(std::abs(p_implicit.position) < 0.2);
  CHECK(std::abs(p_explicit.position) > 1e3);
  CHECK(std::abs(t_explicit.position) < 0.21);
}

TEST_CASE("the stage's solver, iteration counts and clamps set h, before configuration", "[physics][drive-row][usd]") {
  const std::string text = R"(#usda 1.0
def PhysicsScene "scene" (
    prepend apiSchemas = ["PhysxSceneAPI"]
)
{
    uint physxScene:timeStepsPerSecond = 120
    uniform token physxScene:solverType = "PGS"
    uniform uint physxScene:maxPositionIterationCount = 16
}
def Xform "robot" (
    prepend apiSchemas = ["PhysicsArticulationRootAPI", "PhysxArticulationAPI"]
)
{
    int physxArticulation:solverPositionIterationCount = 64
    int physxArticulation:solverVelocityIterationCount = 4
}
)";
  const ReadResult read = usda::read_usda(std::make_shared<const SourceFile>("mem/stage.usda", text), disk());
  Settings settings;
  settings.simulation.solver = Configured<std::string>{"TGS", "asset-lint.toml:4"};
  settings.simulation.timesteps_per_second = Configured<double>{250.0, "asset-lint.toml:2"};
  SimulationRate r = effective_simulation(read.asset, settings);
  CHECK(r.solver == Solver::PGS);
  CHECK(r.solver_origin == "mem/stage.usda:7");
  CHECK(r.timesteps_per_second == 120);
  CHECK(r.iterations() == 16);
  CHECK(r.iterations_per_frame() == 20);
  CHECK(r.h() == Approx(1.0 / 120));
  CHECK(r.describe() == "PGS (mem/stage.usda:7), h = dt = 1/120 s (120 Hz (mem/stage.usda:6))");
  // Configuration decides what the stage does not author; TGS then sub-steps the frame.
  const ReadResult bare = usda::read_usda(std::make_shared<const SourceFile>("mem/bare.usda", "#usda 1.0\n"), disk());
  settings.simulation.position_iterations = Configured<double>{64.0, "asset-lint.toml:3"};
  r = effective_simulation(bare.asset, settings);
  CHECK(r.solver == Solver::TGS);
  CHECK(r.velocity_iterations == 1);
  CHECK(r.describe() ==
        "TGS (asset-lint.toml:4), h = dt/64 = 1/16000 s (250 Hz (asset-lint.toml:2) / 64 position iterations "
        "(asset-lint.toml:3))");
}
