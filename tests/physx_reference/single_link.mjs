// One link on a revolute joint to a fixed base, driven toward a target, in real PhysX.
//
// Geometry (metres, world frame): the joint sits at the origin and turns about +x. The link's
// centre of mass is `comOffset` along +y, so a positive joint angle lifts the link toward +z.
// For the hold, a static block rests on the link's bar at joint angle 0; the drive's target
// lies `targetDelta` beyond it, and the block's contact impulses give the torque that holds
// the link there.
//
// PhysX and this npm build have defaults that differ from an Isaac asset (link damping 0.05,
// joint friction 0.05, max joint velocity 100 rad/s, 4 position / 1 velocity iterations,
// drive limits as impulses, sleeping): every one of them is set here explicitly.

const BAR_HALF = { x: 0.002, y: 0.01, z: 0.002 };  // the link's collision box, centred at y = 0.02
const BAR_CENTRE_Y = 0.02;
const BLOCK_HALF = { x: 0.004, y: 0.008, z: 0.005 };  // the static block resting on the bar's top face
const FAR = 1e10;

export class World {
  constructor(PhysX) {
    this.PhysX = PhysX;
    this.allocator = new PhysX.PxDefaultAllocator();
    this.errorCallback = new PhysX.PxDefaultErrorCallback();
    this.foundation = PhysX.CreateFoundation(PhysX.PHYSICS_VERSION, this.allocator, this.errorCallback);
    this.tolerances = new PhysX.PxTolerancesScale();
    this.physics = PhysX.CreatePhysics(PhysX.PHYSICS_VERSION, this.foundation, this.tolerances);
    this.material = this.physics.createMaterial(0, 0, 0);  // no friction, no restitution
    this.dispatcher = PhysX.DefaultCpuDispatcherCreate(0);  // deterministic: the calling thread only
  }

  vec(x, y, z) { return new this.PhysX.PxVec3(x, y, z); }

  pose(x, y, z) {
    return new this.PhysX.PxTransform(this.vec(x, y, z), new this.PhysX.PxQuat(0, 0, 0, 1));
  }
}

// Runs `frames` frames of the case and returns what `observe` collects after each one.
// `withBlock`: add the static block that stops the link at joint angle 0.
export function simulate(world, c, { frames, withBlock, withLimit = false }) {
  const { PhysX, physics } = world;
  const events = [];
  const callback = new PhysX.PxSimulationEventCallbackImpl();
  callback.onContact = (headerPtr, pairsPtr, nbPairs) => {
    for (let i = 0; i < nbPairs; ++i) {
      const pair = PhysX.NativeArrayHelpers.prototype.getContactPairAt(PhysX.wrapPointer(pairsPtr, PhysX.PxContactPair), i);
      const count = pair.contactCount;
      if (count === 0) continue;
      const buffer = new PhysX.PxArray_PxContactPairPoint(count);
      const extracted = pair.extractContacts(buffer.begin(), count);
      for (let k = 0; k < extracted; ++k) {
        const p = buffer.get(k);
        events.push({ px: p.position.x, py: p.position.y, pz: p.position.z,
                      ix: p.impulse.x, iy: p.impulse.y, iz: p.impulse.z, separation: p.separation });
      }
      PhysX.destroy(buffer);
    }
  };
  callback.onConstraintBreak = () => {};
  callback.onWake = () => {};
  callback.onSleep = () => {};
  callback.onTrigger = () => {};

  const sceneDesc = new PhysX.PxSceneDesc(world.tolerances);
  sceneDesc.gravity = world.vec(0, 0, 0);
  sceneDesc.cpuDispatcher = world.dispatcher;
  sceneDesc.filterShader = PhysX.DefaultFilterShader();
  sceneDesc.solverType = c.solver === 'TGS' ? PhysX.PxSolverTypeEnum.eTGS : PhysX.PxSolverTypeEnum.ePGS;
  sceneDesc.bounceThresholdVelocity = FAR;
  sceneDesc.simulationEventCallback = callback;
  const scene = physics.createScene(sceneDesc);

  const articulation = physics.createArticulationReducedCoordinate();
  articulation.setArticulationFlag(PhysX.PxArticulationFlagEnum.eFIX_BASE, true);
  articulation.setArticulationFlag(PhysX.PxArticulationFlagEnum.eDRIVE_LIMITS_ARE_FORCES, c.driveLimitsAreForces);
  articulation.setArticulationFlag(PhysX.PxArticulationFlagEnum.eDISABLE_SELF_COLLISION, true);
  articulation.setSolverIterationCounts(c.positionIterations, c.velocityIterations);
  articulation.setSleepThreshold(0);
  articulation.setStabilizationThreshold(0);

  const base = articulation.createLink(null, world.pose(0, 0, 0));
  base.setMass(1);
  base.setMassSpaceInertiaTensor(world.vec(1, 1, 1));

  const link = articulation.createLink(base, world.pose(0, 0, 0));
  const comInertia = c.inertia - c.mass * c.comOffset * c.comOffset;  // about the COM, parallel to the axis
  link.setMass(c.mass);
  link.setCMassLocalPose(world.pose(0, c.comOffset, 0));
  link.setMassSpaceInertiaTensor(world.vec(comInertia, comInertia, comInertia));
  for (const body of [base, link]) {
    body.setLinearDamping(0);
    body.setAngularDamping(0);
    body.setMaxLinearVelocity(FAR);
    body.setMaxAngularVelocity(FAR);
  }

  const contactFilter = new PhysX.PxFilterData(1, 0xffffffff,
    PhysX.PxPairFlagEnum.eNOTIFY_TOUCH_FOUND | PhysX.PxPairFlagEnum.eNOTIFY_TOUCH_PERSISTS |
    PhysX.PxPairFlagEnum.eNOTIFY_CONTACT_POINTS, 0);
  const shapeFlags = new PhysX.PxShapeFlags(PhysX.PxShapeFlagEnum.eSIMULATION_SHAPE);
  const bar = physics.createShape(new PhysX.PxBoxGeometry(BAR_HALF.x, BAR_HALF.y, BAR_HALF.z), world.material, true, shapeFlags);
  bar.setLocalPose(world.pose(0, BAR_CENTRE_Y, 0));
  bar.setSimulationFilterData(contactFilter);
  bar.setContactOffset(0.002);
  bar.setRestOffset(0);
  link.attachShape(bar);

  const joint = link.getInboundJoint();
  const twist = PhysX.PxArticulationAxisEnum.eTWIST;
  joint.setJointType(PhysX.PxArticulationJointTypeEnum.eREVOLUTE);
  joint.setParentPose(world.pose(0, 0, 0));
  joint.setChildPose(world.pose(0, 0, 0));
  if (withLimit) {
    joint.setMotion(twist, PhysX.PxArticulationMotionEnum.eLIMITED);
    joint.setLimitParams(twist, new PhysX.PxArticulationLimit(-Math.PI / 2, 0));
  } else {
    joint.setMotion(twist, PhysX.PxArticulationMotionEnum.eFREE);
  }
  joint.setFrictionCoefficient(0);
  joint.setMaxJointVelocity(c.maxJointVelocity ?? FAR);
  joint.setArmature(twist, c.armature);
  joint.setDriveParams(twist, new PhysX.PxArticulationDrive(c.stiffness, c.damping, c.maxForce,
    PhysX.PxArticulationDriveTypeEnum.eFORCE));
  joint.setDriveTarget(twist, c.targetDelta);
  joint.setDriveVelocity(twist, 0);
  joint.setJointPosition(twist, 0);
  joint.setJointVelocity(twist, 0);

  scene.addArticulation(articulation);

  let block = null;
  if (withBlock) {
    block = physics.createRigidStatic(world.pose(0, BAR_CENTRE_Y, BAR_HALF.z + BLOCK_HALF.z));
    const blockShape = physics.createShape(new PhysX.PxBoxGeometry(BLOCK_HALF.x, BLOCK_HALF.y, BLOCK_HALF.z),
      world.material, true, shapeFlags);
    blockShape.setSimulationFilterData(contactFilter);
    blockShape.setContactOffset(0.002);
    blockShape.setRestOffset(0);
    block.attachShape(blockShape);
    scene.addActor(block);
  }

  const dt = 1 / c.rate;
  const out = [];
  for (let frame = 1; frame <= frames; ++frame) {
    events.length = 0;
    // A constant load torque about the joint axis (+x), applied anew each frame (PhysX clears it).
    if (c.loadTorque) link.addTorque(world.vec(c.loadTorque, 0, 0));
    scene.simulate(dt);
    scene.fetchResults(true);
    // Torque about the joint axis (+x through the origin) of the impulses the block put on
    // the link, over this frame. PhysX reports each contact's impulse as applied to the
    // first actor of the pair; the sign is fixed below by requiring it to oppose the drive.
    let angularImpulse = 0;
    for (const e of events) angularImpulse += e.py * e.iz - e.pz * e.iy;
    out.push({
      position: joint.getJointPosition(twist),
      velocity: joint.getJointVelocity(twist),
      contactTorque: Math.abs(angularImpulse) / dt,
      contacts: events.length,
    });
  }

  scene.release();
  return out;
}
