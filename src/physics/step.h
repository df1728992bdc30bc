#pragma once
// Which solver steps the scene and the step h a drive row is built with
// (docs/physics.md "The step h"). PhysX builds a joint drive's row with
// `isTGSSolver ? stepDt : dt`: under TGS the frame dt = 1/rate is cut into N sub-steps
// (N = the position iteration count), under PGS the row sees the whole frame.
#include <optional>
#include <string>
#include <string_view>

#include "engine/settings.h"
#include "model/asset.h"
#include "physics/servo_step.h"

namespace assetlint::physics {

// MuJoCo: an MJCF model; one integration step per <option timestep>, no iterations divide it.
enum class Solver { TGS, PGS, MuJoCo };
std::string_view solver_name(Solver solver);

// Time step, solver and iteration counts in effect, each with where it came from: the
// stage's PhysicsScene / articulation when authored, else configuration, else the
// PhysX/omni.physx defaults (60 Hz, TGS, 32 position and 1 velocity iterations).
struct SimulationRate {
  double timesteps_per_second = 60.0;
  std::string rate_origin = "PhysX default";
  double position_iterations = 32.0;  // the articulation's own count, before the scene's clamps
  std::string iterations_origin = "PhysX default";
  double velocity_iterations = 1.0;
  std::string velocity_iterations_origin = "PhysX default";
  // The scene's min/max position iteration clamps, when authored.
  std::optional<double> min_position_iterations;
  std::optional<double> max_position_iterations;
  Solver solver = Solver::TGS;
  std::string solver_origin = "default";
  // MuJoCo only: which integrator takes the step (<option integrator>, default Euler).
  MujocoIntegrator integrator = MujocoIntegrator::Euler;
  std::string integrator_origin = "MuJoCo's default";

  double dt() const { return 1.0 / timesteps_per_second; }  // s, one frame
  // N: the position iterations the solver runs, the articulation's count within the
  // scene's clamps. PhysX runs the largest count in the island, so h ≤ dt / N.
  int iterations() const;
  // M: all drive solves of a PGS frame (position + velocity iterations).
  int iterations_per_frame() const { return iterations() + static_cast<int>(velocity_iterations); }
  int substeps() const { return solver == Solver::TGS ? iterations() : 1; }
  double h() const { return dt() / substeps(); }  // s: TGS dt/N, PGS dt
  // The guide's bound on a natural frequency: rate × N under TGS (= 1/h: h·nf ≤ 1), the
  // rate under PGS, whose row resolves nothing finer than the frame.
  double frequency_bound() const { return 1.0 / h(); }
  double optimistic_bound() const { return frequency_bound(); }  // the old name, kept for rules not yet moved
  // "TGS, h = 1/16000 s"
  std::string step_text() const;
  // "TGS (default), h = dt/64 = 1/16000 s (250 Hz (asset-lint.toml:2) / 64 position iterations (robot.usda:40))"
  std::string describe() const;
};
SimulationRate effective_simulation(const Asset& asset, const Settings& settings);

}  // namespace assetlint::physics
