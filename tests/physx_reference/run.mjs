#!/usr/bin/env node
// Measures single-link revolute drives in real PhysX (npm physx-js-webidl) and prints JSON:
// for each case its inputs, the joint position and velocity after each of 5 frames of free
// motion from rest toward the target, the torque that holds the link at a hard stop short of
// the target (from the stop's contact impulses) and how far a joint limit at the same place
// lets the joint through; and free motion against a constant load torque (`loaded`).
//
//   node tests/physx_reference/run.mjs [path/to/node_modules/physx-js-webidl]
//
// The package defaults to tools/node_modules/physx-js-webidl (scripts/bootstrap.sh installs it).
import { readFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

import { cases, loadedCases } from './cases.mjs';
import { loadPhysX, versionString } from './load_physx.mjs';
import { World, simulate } from './single_link.mjs';

const PX_MAX_F32 = 3.4028234663852886e38;
const FREE_FRAMES = 5;
const HOLD_FRAMES = 10;  // the hold is steady from the second frame on; the last one is reported
const LIMIT_FRAMES = 5;

const here = dirname(fileURLToPath(import.meta.url));
const packageDir = resolve(process.argv[2] ?? join(here, '..', '..', 'tools', 'node_modules', 'physx-js-webidl'));
const packageVersion = JSON.parse(readFileSync(join(packageDir, 'package.json'), 'utf8')).version;

const PhysX = await loadPhysX(packageDir);
const world = new World(PhysX);

// A case's inputs as the test reads them.
const inputs = (c) => ({
  name: `${c.solver} ${c.name}`,
  solver: c.solver,
  rate: c.rate,
  position_iterations: c.positionIterations,
  velocity_iterations: c.velocityIterations,
  stiffness: c.stiffness,
  damping: c.damping,
  max_force: c.maxForce,
  drive_limits_are_forces: c.driveLimitsAreForces,
  max_joint_velocity: c.maxJointVelocity ?? null,
  load_torque: c.loadTorque ?? 0,
  armature: c.armature,
  inertia: c.inertia,
  target: c.targetDelta,
});

const results = cases.map((c) => {
  const physxCase = { ...c, maxForce: c.maxForce ?? PX_MAX_F32 };
  const free = simulate(world, physxCase, { frames: FREE_FRAMES, withBlock: false });
  const hold = simulate(world, physxCase, { frames: HOLD_FRAMES, withBlock: true });
  const limit = simulate(world, physxCase, { frames: LIMIT_FRAMES, withLimit: true });
  const last = hold[hold.length - 1], previous = hold[hold.length - 2];
  return {
    ...inputs(c),
    free_motion: { position: free.map((s) => s.position), velocity: free.map((s) => s.velocity) },
    hold: {
      torque: last.contactTorque,
      previous_frame_torque: previous.contactTorque,
      position: last.position,
      contacts: last.contacts,
    },
    limit_stop: { max_position: Math.max(...limit.map((s) => s.position)) },
  };
});

const LOADED_FRAMES = 8;
const loaded = loadedCases.map((c) => {
  const free = simulate(world, c, { frames: LOADED_FRAMES, withBlock: false });
  return {
    ...inputs(c),
    free_motion: { position: free.map((s) => s.position), velocity: free.map((s) => s.velocity) },
  };
});

process.stdout.write(JSON.stringify({
  engine: `PhysX ${versionString(PhysX)}`,
  package: `physx-js-webidl ${packageVersion}`,
  cases: results,
  loaded,
}, null, 1) + '\n');
