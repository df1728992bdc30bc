// The drives measured in real PhysX. Defaults: the guide's lighter finger link (0.0127 kg, COM
// 0.01 m from the axis, 3.37e-6 kg·m² about it), 250 Hz, 64 position and 1 velocity
// iterations, the target 5° beyond the stop (0.0873 rad, the guide's Δ: PHYSICS.md's table has
// k·Δ = 497.6 for k = 5700), no force cap, omni.physx's forces flag set.
// Every drive is run under both solvers.

const defaults = {
  rate: 250,
  positionIterations: 64,
  velocityIterations: 1,
  stiffness: 5700,
  damping: 0.277,
  maxForce: null,  // null: PhysX's default, PX_MAX_F32 (no cap)
  driveLimitsAreForces: true,
  armature: 0,
  mass: 0.0127,
  comOffset: 0.01,
  inertia: 3.37e-6,
  targetDelta: 0.0873,
};

// name: what the drive is; the rest overrides `defaults`.
const drives = [
  // PHYSICS.md §2 "Measured in real PhysX", row by row.
  { name: 'k5700 d0.277', },
  { name: 'k5700 d0', damping: 0 },
  { name: 'k5700 d2.77', damping: 2.77 },
  { name: 'k5700 d0.277 N4', positionIterations: 4 },
  { name: 'k5700 d0.277 armature1e-5', armature: 1e-5 },
  { name: 'k275 d0.061', stiffness: 275, damping: 0.061 },
  { name: 'k5700 d0.277 I1.4e-4', inertia: 1.4e-4 },
  { name: 'k275 d0.061 I0.01', stiffness: 275, damping: 0.061, inertia: 0.01 },
  { name: 'k5700 d0.277 maxForce24 forces', maxForce: 24 },
  // Beyond the table: one position iteration (TGS's h = dt), no forces flag (maxForce is then
  // an impulse per frame: 0.05 N·m·s = 12.5 N·m at 250 Hz), the guide's armature case at 60 Hz,
  // and drives slow enough that free motion takes several frames.
  { name: 'k5700 d0.277 N1', positionIterations: 1 },
  { name: 'k5700 d0.277 maxForce0.05 impulse', maxForce: 0.05, driveLimitsAreForces: false },
  { name: 'k275 d0.061 armature5e-3 60Hz', stiffness: 275, damping: 0.061, armature: 5e-3, rate: 60 },
  { name: 'k275 d0 I0.01 N4', stiffness: 275, damping: 0, inertia: 0.01, positionIterations: 4 },
  { name: 'k275 d0.061 I1.4e-4 N1', stiffness: 275, damping: 0.061, inertia: 1.4e-4, positionIterations: 1 },
  { name: 'k275 d2 I0.01 maxForce5 forces', stiffness: 275, damping: 2, inertia: 0.01, maxForce: 5 },
];

export const cases = drives.flatMap((drive) =>
  ['TGS', 'PGS'].map((solver) => ({ ...defaults, ...drive, solver })));

// Free motion against a constant load torque about the axis (`loadTorque`, N·m, applied each
// frame; negative opposes the drive), with and without a max joint velocity: what
// `asset-lint simulate --load-torque` steps. 8 frames each, under both solvers.
const loaded = [
  { name: 'k275 d2 I0.01 N4 maxForce5 load-3', stiffness: 275, damping: 2, inertia: 0.01, positionIterations: 4,
    maxForce: 5, loadTorque: -3 },
  { name: 'k275 d2 I0.01 N4 maxForce5 load-8', stiffness: 275, damping: 2, inertia: 0.01, positionIterations: 4,
    maxForce: 5, loadTorque: -8 },
  { name: 'k275 d0.061 I8.57e-5 maxForce24 maxVelocity2.9 load-30', stiffness: 275, damping: 0.061, inertia: 8.57e-5,
    maxForce: 24, maxJointVelocity: 2.9, targetDelta: 0.82, loadTorque: -30 },
];

export const loadedCases = loaded.flatMap((drive) =>
  ['TGS', 'PGS'].map((solver) => ({ ...defaults, ...drive, solver })));
