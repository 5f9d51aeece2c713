/*
 * The world (b2World.h, b2World.cpp): bodies, joints, the contact manager, the time step with its
 * discrete island solve and continuous (TOI) solve, queries and debug drawing.
 *
 * Where the C++ builds an island, a DFS stack or a struct on the stack for every solve, the world
 * here keeps one and re-initialises it, so steady-state steps do not allocate. The C++ asserts
 * that the world is unlocked in CreateBody, DestroyBody, CreateJoint and DestroyJoint and returns
 * without effect in release builds; here those calls throw, leaving the world unchanged.
 */

import type { b2BroadPhase } from '../collision/b2BroadPhase';
import { b2RayCastInput, b2RayCastOutput, type b2AABB } from '../collision/b2Collision';
import type { b2ChainShape } from '../collision/shapes/b2ChainShape';
import type { b2CircleShape } from '../collision/shapes/b2CircleShape';
import type { b2EdgeShape } from '../collision/shapes/b2EdgeShape';
import type { b2PolygonShape } from '../collision/shapes/b2PolygonShape';
import { b2Shape } from '../collision/shapes/b2Shape';
import { b2TOIInput, b2TOIOutput, b2TimeOfImpact } from '../collision/b2TimeOfImpact';
import { b2Color, b2Draw } from '../common/b2Draw';
import { b2MulRV, b2MulXV, b2Sweep, b2SweepTime, b2Transform, b2Vec2 } from '../common/b2Math';
import { b2Assert, b2Log, b2_epsilon, b2_maxPolygonVertices, b2_maxSubSteps, b2_maxTOIContacts } from '../common/b2Settings';
import { b2Timer } from '../common/b2Timer';
import { b2BodyType, b2JointType, b2WorldFlags } from '../common/b2Constants';
import { b2ArgumentError, b2CheckInteger, b2CheckObject, b2CheckVec2, b2DescribeNumber, b2LockedError } from '../common/b2ArgumentError';
import { b2CheckBodyOf, b2CheckJointDef, b2CheckJointOf } from './b2DefValidation';
import { b2Body, type b2BodyDef } from './b2Body';
import { b2ContactManager } from './b2ContactManager';
import { b2WorldBackendEngineFunctions, type b2WorldBackend } from './b2WorldBackend';
import { b2AccuracyController, b2CheckAccuracyTarget, type b2Accuracy, type b2AccuracyTargetDef } from './b2AccuracyTarget';
import type { b2FixtureProxy } from './b2Fixture';
import { b2Island } from './b2Island';
import { b2Profile, b2TimeStep } from './b2TimeStep';
import type { b2ChangeListener, b2ContactFilter, b2ContactListener, b2DestructionListener, b2QueryCallback, b2RayCastCallback } from './b2WorldCallbacks';
import { b2Contact, b2ContactScalars } from './contacts/b2Contact';
import type { b2Joint, b2JointDef } from './joints/b2Joint';
import { b2JointFactory } from './joints/b2JointFactory';
import type { b2PulleyJoint } from './joints/b2PulleyJoint';
import type { b2GearJoint } from './joints/b2GearJoint';

/** The broad-phase query callback of b2World.QueryAABB (the .cpp's b2WorldQueryWrapper). */
class b2WorldQueryWrapper {
  readonly broadPhase: b2BroadPhase;
  callback: b2QueryCallback | null = null;

  constructor(broadPhase: b2BroadPhase) {
    this.broadPhase = broadPhase;
  }

  QueryCallback(proxyId: number): boolean {
    const proxy = this.broadPhase.GetUserData(proxyId) as b2FixtureProxy;
    return (this.callback as b2QueryCallback).ReportFixture(proxy.fixture);
  }
}

/** The broad-phase ray-cast callback of b2World.RayCast (the .cpp's b2WorldRayCastWrapper). */
class b2WorldRayCastWrapper {
  readonly broadPhase: b2BroadPhase;
  callback: b2RayCastCallback | null = null;
  readonly input = new b2RayCastInput();
  private readonly output = new b2RayCastOutput();
  private readonly point = new b2Vec2();

  constructor(broadPhase: b2BroadPhase) {
    this.broadPhase = broadPhase;
  }

  RayCastCallback(input: Readonly<b2RayCastInput>, proxyId: number): number {
    const proxy = this.broadPhase.GetUserData(proxyId) as b2FixtureProxy;
    const fixture = proxy.fixture;
    const index = proxy.childIndex;
    const output = this.output;
    const hit = fixture.RayCast(output, input, index);

    if (hit) {
      const fraction = output.fraction;
      const point = this.point;
      point.x = (1.0 - fraction) * input.p1.x + fraction * input.p2.x;
      point.y = (1.0 - fraction) * input.p1.y + fraction * input.p2.y;
      return (this.callback as b2RayCastCallback).ReportFixture(fixture, point, output.normal, fraction);
    }

    return input.maxFraction;
  }
}

// Debug draw colors, as the .cpp's b2Color temporaries.
const s_inactiveColor = new b2Color(0.5, 0.5, 0.3);
const s_staticColor = new b2Color(0.5, 0.9, 0.5);
const s_kinematicColor = new b2Color(0.5, 0.5, 0.9);
const s_sleepingColor = new b2Color(0.6, 0.6, 0.6);
const s_awakeColor = new b2Color(0.9, 0.7, 0.7);
const s_jointColor = new b2Color(0.5, 0.8, 0.8);
const s_aabbColor = new b2Color(0.9, 0.3, 0.9);
const s_unitX: Readonly<b2Vec2> = new b2Vec2(1.0, 0.0);

function lockedError(method: string): Error {
  return b2LockedError(`b2World.${method}`);
}

/**
 * A gear joint that couples `joint`, or null. Box2D 2.2.1 requires destroying the gear first (a
 * gear left with a destroyed joint reads freed bodies). A gear joint is attached to the moving
 * body (bodyB) of each joint it couples, so only that body's joint list is searched.
 */
function gearCoupling(joint: b2Joint): b2Joint | null {
  if (joint.m_type !== b2JointType.e_revoluteJoint && joint.m_type !== b2JointType.e_prismaticJoint) {
    return null;
  }
  for (let je = joint.m_bodyB.m_jointList; je; je = je.next) {
    const gear = je.joint as b2GearJoint;
    if (gear.m_type === b2JointType.e_gearJoint && (gear.m_joint1 === joint || gear.m_joint2 === joint)) {
      return gear;
    }
  }
  return null;
}

/** A query or ray-cast callback: an object with a ReportFixture method. */
function checkCallback(method: string, callback: { ReportFixture: unknown } | null): void {
  if (typeof callback !== 'object' || callback === null || typeof callback.ReportFixture !== 'function') {
    throw new b2ArgumentError(method, 'callback', `must be an object with a ReportFixture method, got ${b2DescribeNumber(callback)}`);
  }
}

/**
 * The world class manages all physics entities, dynamic simulation, and asynchronous queries.
 * The world also contains efficient memory management facilities.
 */
export class b2World {
  // m_flags
  static readonly e_newFixture = b2WorldFlags.e_newFixture;
  static readonly e_locked = b2WorldFlags.e_locked;
  static readonly e_clearForces = b2WorldFlags.e_clearForces;

  m_flags: number = b2World.e_clearForces;

  readonly m_contactManager = new b2ContactManager();

  m_bodyList: b2Body | null = null;
  m_jointList: b2Joint | null = null;

  m_bodyCount = 0;
  m_jointCount = 0;

  /**
   * Not in the C++: the joints' island flags (b2Joint::m_islandFlag there), one byte a joint at its
   * edges' islandSlot; free slots in m_freeJointSlots, the first m_jointSlotCount ever used. Solve
   * clears them with one fill, where the C++ walks the joint list, and the island search tests them
   * from the edge without loading the joint: in a 20,000-joint grid those loads were a tenth of
   * the step.
   */
  private m_jointIslandFlags = new Uint8Array(16);
  private readonly m_freeJointSlots: number[] = [];
  private m_jointSlotCount = 0;

  readonly m_gravity = new b2Vec2();
  m_allowSleep = true;

  m_destructionListener: b2DestructionListener | null = null;
  m_debugDraw: b2Draw | null = null;
  /** Not in the C++: see SetChangeListener. */
  m_changeListener: b2ChangeListener | null = null;

  /**
   * Not in the C++: advanced by a backend at each synchronisation. A body whose m_stateEpoch lags
   * behind fetches its state from the backend when it is read (b2Body.PullState).
   */
  m_stateEpoch = 0;

  /** This is used to compute the time step ratio to support a variable time step. */
  m_inv_dt0 = 0.0;

  // These are for debugging the solver.
  m_warmStarting = true;
  m_continuousPhysics = true;
  m_subStepping = false;

  m_stepComplete = true;

  readonly m_profile = new b2Profile();
  /** Not in the C++: whether Step times itself into m_profile (SetProfiling). */
  m_profiling = false;

  /** Not in the C++: the backend that steps this world (SetBackend), null for this engine. */
  private m_backend: b2WorldBackend | null = null;
  private m_backendSwitching = false;
  /**
   * Not in the C++: steps a backend let this engine take (b2WorldBackendEngine.step), so that the
   * accuracy target's controller knows the world shows a new state without a synchronisation.
   */
  m_engineStepsOnBackend = 0;
  /** Not in the C++: the accuracy target's controller (SetAccuracyTarget), null without a target. */
  private m_accuracy: b2AccuracyController | null = null;

  // Reused in place of the C++ stack temporaries of Step, Solve and SolveTOI.
  private readonly m_island = new b2Island(0, 0, 0, null);
  private readonly m_stack: b2Body[] = [];
  private readonly m_step = new b2TimeStep();
  private readonly m_subStep = new b2TimeStep();
  private readonly m_islandProfile = new b2Profile();
  private readonly m_stepTimer = new b2Timer();
  private readonly m_timer = new b2Timer();
  private readonly m_broadphaseTimer = new b2Timer();
  private readonly m_toiInput = new b2TOIInput();
  private readonly m_toiOutput = new b2TOIOutput();
  private readonly m_backup = new b2Sweep();
  private readonly m_backup1 = new b2Sweep();
  private readonly m_backup2 = new b2Sweep();
  private readonly m_toiBodies: b2Body[] = [];
  /**
   * Not in the C++: the contacts SolveTOI's search visits (IsTOICandidate), the first
   * m_toiCandidateCount entries, in the reverse of their contact list order. Kept from step to
   * step (UpdateTOICandidates).
   */
  private readonly m_toiCandidates: b2Contact[] = [];
  private m_toiCandidateCount = 0;
  /**
   * Not in the C++: the contacts whose island flag this world has set since Solve last cleared
   * the flags (FlagContact), the first m_flaggedContactCount entries. Destroyed ones may remain:
   * clearing the flag of a contact in the world's store, or reused since, changes nothing.
   */
  private readonly m_flaggedContacts: b2Contact[] = [];
  private m_flaggedContactCount = 0;
  /** ComputeContactTOI's result. */
  private m_contactAlpha = 0.0;
  /**
   * Set by b2Body.SetBullet and SetType, b2Fixture.SetSensor, SetBackend and the solver-state
   * reader: SolveTOI's candidates may be out of date, or contacts may carry TOI state it does not
   * know of.
   */
  m_toiCandidatesStale = false;

  // One query/ray-cast wrapper per nesting level, so a callback may query the world again.
  private readonly m_queryWrappers: b2WorldQueryWrapper[] = [];
  private m_queryDepth = 0;
  private readonly m_rayCastWrappers: b2WorldRayCastWrapper[] = [];
  private m_rayCastDepth = 0;

  // Debug draw scratch.
  private readonly m_drawVertices: b2Vec2[] = [];
  private readonly m_drawCenter = new b2Vec2();
  private readonly m_drawAxis = new b2Vec2();
  private readonly m_drawV1 = new b2Vec2();
  private readonly m_drawV2 = new b2Vec2();
  private readonly m_drawP1 = new b2Vec2();
  private readonly m_drawP2 = new b2Vec2();
  private readonly m_drawS1 = new b2Vec2();
  private readonly m_drawS2 = new b2Vec2();
  private readonly m_drawXf = new b2Transform();

  /**
   * Construct a world object.
   * @param gravity the world gravity vector.
   */
  constructor(gravity: Readonly<b2Vec2>) {
    b2CheckVec2('new b2World', 'gravity', gravity);
    // The other fields start with the C++ constructor's values (see their declarations).
    this.m_gravity.Assign(gravity);

    for (let i = 0; i < b2_maxPolygonVertices; ++i) {
      this.m_drawVertices.push(new b2Vec2());
    }
  }

  /** Register a destruction listener. The listener is owned by you and must remain in scope. */
  SetDestructionListener(listener: b2DestructionListener | null): void {
    this.m_destructionListener = listener;
  }

  /**
   * Register a contact filter to provide specific control over collision. Otherwise the default
   * filter is used (b2_defaultFilter). The listener is owned by you and must remain in scope.
   */
  SetContactFilter(filter: b2ContactFilter | null): void {
    this.m_contactManager.m_contactFilter = filter;
  }

  /** Register a contact event listener. The listener is owned by you and must remain in scope. */
  SetContactListener(listener: b2ContactListener | null): void {
    this.m_contactManager.m_contactListener = listener;
  }

  /**
   * Not in the C++: register a listener told when the API changes bodies, fixtures and the
   * world's structure (b2ChangeListener). The WebGPU backend's mirror uses it; one per world.
   */
  SetChangeListener(listener: b2ChangeListener | null): void {
    this.m_changeListener = listener;
  }

  /**
   * Register a routine for debug drawing. The debug draw functions are called inside with
   * b2World.DrawDebugData method. The debug draw object is owned by you and must remain in scope.
   */
  SetDebugDraw(debugDraw: b2Draw | null): void {
    this.m_debugDraw = debugDraw;
  }

  /**
   * Create a rigid body given a definition. No reference to the definition is retained.
   * @warning This function is locked during callbacks.
   */
  CreateBody(def: Readonly<b2BodyDef>): b2Body {
    if (this.IsLocked()) {
      throw lockedError('CreateBody');
    }

    // The constructor checks the def (b2CheckBodyDef) before this world changes.
    const b = new b2Body(def, this);

    // Add to world doubly linked list.
    b.m_prev = null;
    b.m_next = this.m_bodyList;
    if (this.m_bodyList) {
      this.m_bodyList.m_prev = b;
    }
    this.m_bodyList = b;
    ++this.m_bodyCount;

    this.m_changeListener?.StructureChanged();
    return b;
  }

  /**
   * Destroy a rigid body given a definition. No reference to the definition is retained. This
   * function is locked during callbacks.
   * @warning This automatically deletes all associated shapes and joints.
   * @warning This function is locked during callbacks.
   */
  DestroyBody(b: b2Body): void {
    if (this.IsLocked()) {
      throw lockedError('DestroyBody');
    }
    b2CheckBodyOf('b2World.DestroyBody', 'body', b, this);
    // Its joints go with it, and so do gear joints attached to it; one attached elsewhere must go first.
    for (let je = b.m_jointList; je; je = je.next) {
      const gear = gearCoupling(je.joint);
      if (gear !== null && gear.m_bodyA !== b && gear.m_bodyB !== b) {
        throw new b2ArgumentError('b2World.DestroyBody', 'body', 'has a joint that a gear joint on other bodies couples (destroy the gear joint first)');
      }
    }
    b2Assert(this.m_bodyCount > 0);

    // Delete the attached joints.
    let je = b.m_jointList;
    while (je) {
      const je0 = je;
      je = je.next;

      if (this.m_destructionListener) {
        this.m_destructionListener.SayGoodbyeJoint(je0.joint);
      }

      this.DestroyJoint(je0.joint);

      b.m_jointList = je;
    }
    b.m_jointList = null;

    // Delete the attached contacts.
    let ce = b.m_contactList;
    while (ce) {
      const ce0 = ce;
      ce = ce.next;
      this.m_contactManager.Destroy(ce0.contact);
    }
    b.m_contactList = null;

    // Delete the attached fixtures. This destroys broad-phase proxies.
    let f = b.m_fixtureList;
    while (f) {
      const f0 = f;
      f = f.m_next;

      if (this.m_destructionListener) {
        this.m_destructionListener.SayGoodbyeFixture(f0);
      }

      f0.DestroyProxies(this.m_contactManager.m_broadPhase);
      f0.Destroy();

      b.m_fixtureList = f;
      b.m_fixtureCount -= 1;
    }
    b.m_fixtureList = null;
    b.m_fixtureCount = 0;

    // Remove world body list.
    if (b.m_prev) {
      b.m_prev.m_next = b.m_next;
    }

    if (b.m_next) {
      b.m_next.m_prev = b.m_prev;
    }

    if (b === this.m_bodyList) {
      this.m_bodyList = b.m_next;
    }

    --this.m_bodyCount;

    // The C++ frees the body; here it is marked, so later calls on it throw. Its list links stay:
    // the engine never reads them again, and Box2DWeb apps that destroy bodies while walking the
    // list read GetNext() of the body just destroyed to carry on (2.1a kept the links too).
    b.m_destroyed = true;
    this.m_changeListener?.StructureChanged();
  }

  /**
   * Create a joint to constrain bodies together. No reference to the definition is retained.
   * This may cause the connected bodies to cease colliding.
   * @warning This function is locked during callbacks.
   */
  CreateJoint(def: Readonly<b2JointDef>): b2Joint {
    if (this.IsLocked()) {
      throw lockedError('CreateJoint');
    }
    b2CheckJointDef('b2World.CreateJoint', def, this);

    const j = b2JointFactory.Create(def);

    // Connect to the world list.
    j.m_prev = null;
    j.m_next = this.m_jointList;
    if (this.m_jointList) {
      this.m_jointList.m_prev = j;
    }
    this.m_jointList = j;
    ++this.m_jointCount;

    let slot = this.m_freeJointSlots.pop();
    if (slot === undefined) {
      slot = this.m_jointSlotCount++;
      if (slot === this.m_jointIslandFlags.length) {
        const flags = new Uint8Array(2 * slot);
        flags.set(this.m_jointIslandFlags);
        this.m_jointIslandFlags = flags;
      }
    }
    j.m_edgeA.islandSlot = slot;
    j.m_edgeB.islandSlot = slot;

    // Connect to the bodies' doubly linked lists.
    j.m_edgeA.joint = j;
    j.m_edgeA.other = j.m_bodyB;
    j.m_edgeA.prev = null;
    j.m_edgeA.next = j.m_bodyA.m_jointList;
    if (j.m_bodyA.m_jointList) j.m_bodyA.m_jointList.prev = j.m_edgeA;
    j.m_bodyA.m_jointList = j.m_edgeA;

    j.m_edgeB.joint = j;
    j.m_edgeB.other = j.m_bodyA;
    j.m_edgeB.prev = null;
    j.m_edgeB.next = j.m_bodyB.m_jointList;
    if (j.m_bodyB.m_jointList) j.m_bodyB.m_jointList.prev = j.m_edgeB;
    j.m_bodyB.m_jointList = j.m_edgeB;

    // The def's bodies, not the joint's: a gear joint's m_bodyA/m_bodyB differ from them.
    const bodyA = def.bodyA as b2Body;
    const bodyB = def.bodyB as b2Body;

    // If the joint prevents collisions, then flag any contacts for filtering.
    if (def.collideConnected === false) {
      this.FlagContactsForFiltering(bodyA, bodyB);
    }

    // Note: creating a joint doesn't wake the bodies.

    this.m_changeListener?.StructureChanged();
    return j;
  }

  /**
   * Destroy a joint. This may cause the connected bodies to begin colliding.
   * @warning This function is locked during callbacks.
   */
  DestroyJoint(j: b2Joint): void {
    if (this.IsLocked()) {
      throw lockedError('DestroyJoint');
    }
    b2CheckJointOf('b2World.DestroyJoint', 'joint', j, this);
    if (gearCoupling(j) !== null) {
      throw new b2ArgumentError('b2World.DestroyJoint', 'joint', 'is coupled by a gear joint (destroy the gear joint first)');
    }

    const collideConnected = j.m_collideConnected;

    // Remove from the doubly linked list.
    if (j.m_prev) {
      j.m_prev.m_next = j.m_next;
    }

    if (j.m_next) {
      j.m_next.m_prev = j.m_prev;
    }

    if (j === this.m_jointList) {
      this.m_jointList = j.m_next;
    }

    // Disconnect from island graph.
    const bodyA = j.m_bodyA;
    const bodyB = j.m_bodyB;

    // Wake up connected bodies.
    bodyA.SetAwake(true);
    bodyB.SetAwake(true);

    // Remove from body 1.
    if (j.m_edgeA.prev) {
      j.m_edgeA.prev.next = j.m_edgeA.next;
    }

    if (j.m_edgeA.next) {
      j.m_edgeA.next.prev = j.m_edgeA.prev;
    }

    if (j.m_edgeA === bodyA.m_jointList) {
      bodyA.m_jointList = j.m_edgeA.next;
    }

    j.m_edgeA.prev = null;
    j.m_edgeA.next = null;

    // Remove from body 2
    if (j.m_edgeB.prev) {
      j.m_edgeB.prev.next = j.m_edgeB.next;
    }

    if (j.m_edgeB.next) {
      j.m_edgeB.next.prev = j.m_edgeB.prev;
    }

    if (j.m_edgeB === bodyB.m_jointList) {
      bodyB.m_jointList = j.m_edgeB.next;
    }

    j.m_edgeB.prev = null;
    j.m_edgeB.next = null;

    const slot = j.m_edgeA.islandSlot;
    this.m_jointIslandFlags[slot] = 0;
    this.m_freeJointSlots.push(slot);
    j.m_edgeA.islandSlot = -1;
    j.m_edgeB.islandSlot = -1;

    b2JointFactory.Destroy(j);

    b2Assert(this.m_jointCount > 0);
    --this.m_jointCount;

    // The C++ frees the joint; here it is marked, so later calls on it throw. Its list links stay,
    // as a body's do (see DestroyBody).
    j.m_destroyed = true;

    // If the joint prevents collisions, then flag any contacts for filtering.
    if (collideConnected === false) {
      this.FlagContactsForFiltering(bodyA, bodyB);
    }
    this.m_changeListener?.StructureChanged();
  }

  /**
   * Take a time step. This performs collision detection, integration, and constraint solution.
   * Not in the C++: with an accuracy target set (SetAccuracyTarget), the step runs with the
   * iterations and sub-steps the target's controller chose (GetAccuracy says which) instead of
   * velocityIterations and positionIterations, which are still checked; without one, exactly as
   * the C++.
   * @param dt the amount of time to simulate, this should not vary.
   * @param velocityIterations for the velocity constraint solver.
   * @param positionIterations for the position constraint solver.
   */
  Step(dt: number, velocityIterations: number, positionIterations: number): void {
    if (!(dt >= 0.0 && dt < Infinity)) {
      throw new b2ArgumentError('b2World.Step', 'dt', `must be a finite number >= 0, got ${b2DescribeNumber(dt)}`);
    }
    b2CheckInteger('b2World.Step', 'velocityIterations', velocityIterations, 0, 0x7fffffff);
    b2CheckInteger('b2World.Step', 'positionIterations', positionIterations, 0, 0x7fffffff);
    if (this.IsLocked()) {
      throw lockedError('Step');
    }
    if (this.m_accuracy !== null) {
      this.m_accuracy.Step(this, dt);
      return;
    }
    if (this.m_backend !== null) {
      this.m_backend.Step(dt, velocityIterations, positionIterations);
      return;
    }
    this.StepOnEngine(dt, velocityIterations, positionIterations);
  }

  /**
   * Not in the C++: Step after its checks, with these settings whatever the accuracy target: on
   * the backend, or on this engine. The accuracy target's controller steps the world with it.
   */
  StepDirect(dt: number, velocityIterations: number, positionIterations: number): void {
    if (this.m_backend !== null) {
      this.m_backend.Step(dt, velocityIterations, positionIterations);
      return;
    }
    this.StepOnEngine(dt, velocityIterations, positionIterations);
  }

  /**
   * Not in the C++: give the world an accuracy target in the accuracy study's units, or take it
   * away with null (docs/ACCURACY.md, "Accuracy targets"): `{ penetration?: m, jointError?: m,
   * jitter?: m/s }`, each the largest error allowed, at least one given. From then on Step uses the
   * velocity / position iterations and sub-steps a controller chooses from a ladder of settings
   * ordered by cost: first the cheapest the accuracy study measured below every target, then
   * corrected from the errors measured in this world after each step (up a rung when one exceeds
   * its target, down after a sustained margin). The choices depend on the world's state only, so a
   * replay makes the same ones. Throws a b2ArgumentError (the world unchanged) for a target that
   * is not an object of finite numbers > 0 with known keys. Setting a target starts the
   * controller afresh.
   */
  SetAccuracyTarget(target: Readonly<b2AccuracyTargetDef> | null): void {
    if (this.IsLocked()) {
      throw lockedError('SetAccuracyTarget');
    }
    this.m_accuracy = target === null ? null : new b2AccuracyController(b2CheckAccuracyTarget('b2World.SetAccuracyTarget', target));
  }

  /**
   * Not in the C++: the accuracy target and what it chose (SetAccuracyTarget): the target, the
   * iterations and sub-steps Step uses now, the errors measured after the last step (on a backend,
   * at its last synchronisation), and the reason in words and numbers; null without a target.
   */
  GetAccuracy(): b2Accuracy | null {
    return this.m_accuracy === null ? null : this.m_accuracy.report(this);
  }

  /**
   * Not in the C++: the body of b2World::Step, run on this engine whether or not a backend is
   * attached (a backend that steps the world here, webphysics/gpu's AutoBackend, calls it through
   * b2WorldBackendEngine.step). Step checks the arguments and the lock first.
   */
  StepOnEngine(dt: number, velocityIterations: number, positionIterations: number): void {
    const profiling = this.m_profiling;
    const stepTimer = this.m_stepTimer;
    if (profiling) stepTimer.Reset();

    // If new fixtures were added, we need to find the new contacts.
    if (this.m_flags & b2World.e_newFixture) {
      this.m_contactManager.FindNewContacts();
      this.m_flags &= ~b2World.e_newFixture;
    }

    this.m_flags |= b2World.e_locked;

    // A callback that throws leaves the step unfinished; unlocking keeps the world usable.
    try {
      const step = this.m_step;
      step.dt = dt;
      step.velocityIterations = velocityIterations;
      step.positionIterations = positionIterations;
      if (dt > 0.0) {
        step.inv_dt = 1.0 / dt;
      } else {
        step.inv_dt = 0.0;
      }

      step.dtRatio = this.m_inv_dt0 * dt;

      step.warmStarting = this.m_warmStarting;

      const timer = this.m_timer;

      // Update contacts. This is where some contacts are destroyed.
      if (profiling) timer.Reset();
      this.m_contactManager.Collide();
      if (profiling) this.m_profile.collide = timer.GetMilliseconds();

      // Integrate velocities, solve velocity constraints, and integrate positions.
      if (this.m_stepComplete && step.dt > 0.0) {
        if (profiling) timer.Reset();
        this.Solve(step);
        if (profiling) this.m_profile.solve = timer.GetMilliseconds();
      }

      // Handle TOI events.
      if (this.m_continuousPhysics && step.dt > 0.0) {
        if (profiling) timer.Reset();
        this.SolveTOI(step);
        if (profiling) this.m_profile.solveTOI = timer.GetMilliseconds();
      }

      if (step.dt > 0.0) {
        this.m_inv_dt0 = step.inv_dt;
      }

      if (this.m_flags & b2World.e_clearForces) {
        this.ClearForces();
      }
    } finally {
      this.m_flags &= ~b2World.e_locked;
    }

    if (profiling) this.m_profile.step = stepTimer.GetMilliseconds();
  }

  /**
   * Not in the C++: Step, resolving once the world's objects show the step's result. On this
   * engine that is at once; on a backend (SetBackend) after its read-back.
   */
  async StepAsync(dt: number, velocityIterations: number, positionIterations: number): Promise<void> {
    if (this.m_accuracy !== null) {
      // The chosen settings; the step's measures read the synchronisation before it.
      this.Step(dt, velocityIterations, positionIterations);
      await this.Synchronize();
      return;
    }
    if (this.m_backend !== null && !this.IsLocked()) {
      return this.m_backend.StepAsync(dt, velocityIterations, positionIterations);
    }
    this.Step(dt, velocityIterations, positionIterations);
  }

  /**
   * Not in the C++: resolves once the world's objects (positions, velocities, contacts and the
   * contact listener's events) show every step taken so far; at once on this engine.
   */
  async Synchronize(): Promise<void> {
    if (this.m_backend !== null) await this.m_backend.Synchronize();
  }

  /**
   * Not in the C++: steps this world on another backend (webphysics/gpu's WebGPUBackend) from now
   * on, or on this engine again with null. Attaching happens at once (the backend throws when it
   * cannot step this world); detaching waits for the backend's steps and writes its state into
   * the world, so the promise must be awaited before the next Step (Step throws until then). When
   * detaching fails (a lost device) the promise rejects and the world is on this engine anyway.
   */
  async SetBackend(backend: b2WorldBackend | null): Promise<void> {
    if (this.IsLocked()) {
      throw lockedError('SetBackend');
    }
    if (this.m_backendSwitching) {
      throw new Error('b2World.SetBackend: a backend switch is in progress; await the previous SetBackend first');
    }
    if (backend === this.m_backend) {
      return;
    }
    this.m_backendSwitching = true;
    try {
      if (this.m_backend !== null) {
        // A failed detach (the device lost) still leaves the world on this engine.
        try {
          await this.m_backend.Detach();
        } finally {
          this.m_backend = null;
        }
      }
      if (backend !== null) {
        backend.Attach(this, b2WorldBackendEngineFunctions);
        this.m_backend = backend;
      }
    } finally {
      this.m_backendSwitching = false;
      // A backend takes the contacts over and hands back contacts of its own.
      this.m_toiCandidatesStale = true;
    }
  }

  /** Not in the C++: the backend set with SetBackend, or null when this engine steps the world. */
  GetBackend(): b2WorldBackend | null {
    return this.m_backend;
  }

  /** Not in the C++: the last synchronisation's state into `body` (b2Body.PullState calls this). */
  PullBody(body: b2Body): void {
    body.m_stateEpoch = this.m_stateEpoch;
    this.m_backend?.PullBody(body);
  }

  /**
   * Not in the C++: on a backend, every body's last synchronised state, and the broad-phase proxies
   * moved to it; queries, ray casts, the debug draw and Dump call it first. A no-op on this engine.
   */
  PullState(): void {
    this.m_backend?.PullAll();
  }

  /**
   * Manually clear the force buffer on all bodies. By default, forces are cleared automatically
   * after each call to Step. The default behavior is modified by calling SetAutoClearForces.
   * The purpose of this function is to support sub-stepping. Sub-stepping is often used to
   * maintain a fixed sized time step under a variable frame-rate. When you perform sub-stepping
   * you will disable auto clearing of forces and instead call ClearForces after all sub-steps
   * are complete in one pass of your game loop.
   * @see SetAutoClearForces
   */
  ClearForces(): void {
    for (let body = this.m_bodyList; body; body = body.GetNext()) {
      body.m_force.SetZero();
      body.m_torque = 0.0;
    }
  }

  /** Call this to draw shapes and other debug draw data. */
  DrawDebugData(): void {
    const debugDraw = this.m_debugDraw;
    if (debugDraw === null) {
      return;
    }
    this.PullState();

    const flags = debugDraw.GetFlags();

    if (flags & b2Draw.e_shapeBit) {
      for (let b = this.m_bodyList; b; b = b.GetNext()) {
        const xf = b.GetTransform();
        for (let f = b.GetFixtureList(); f; f = f.GetNext()) {
          if (b.IsActive() === false) {
            this.DrawShape(f.GetShape(), xf, s_inactiveColor);
          } else if (b.GetType() === b2BodyType.b2_staticBody) {
            this.DrawShape(f.GetShape(), xf, s_staticColor);
          } else if (b.GetType() === b2BodyType.b2_kinematicBody) {
            this.DrawShape(f.GetShape(), xf, s_kinematicColor);
          } else if (b.IsAwake() === false) {
            this.DrawShape(f.GetShape(), xf, s_sleepingColor);
          } else {
            this.DrawShape(f.GetShape(), xf, s_awakeColor);
          }
        }
      }
    }

    if (flags & b2Draw.e_jointBit) {
      for (let j = this.m_jointList; j; j = j.GetNext()) {
        this.DrawJoint(j);
      }
    }

    // e_pairBit draws nothing: its drawing code is commented out in Box2D 2.2.1.

    if (flags & b2Draw.e_aabbBit) {
      const bp = this.m_contactManager.m_broadPhase;
      const vs = this.m_drawVertices;

      for (let b = this.m_bodyList; b; b = b.GetNext()) {
        if (b.IsActive() === false) {
          continue;
        }

        for (let f = b.GetFixtureList(); f; f = f.GetNext()) {
          for (let i = 0; i < f.m_proxyCount; ++i) {
            const proxy = f.m_proxies[i];
            const aabb = bp.GetFatAABB(proxy.proxyId);
            vs[0].Set(aabb.lowerBound.x, aabb.lowerBound.y);
            vs[1].Set(aabb.upperBound.x, aabb.lowerBound.y);
            vs[2].Set(aabb.upperBound.x, aabb.upperBound.y);
            vs[3].Set(aabb.lowerBound.x, aabb.upperBound.y);

            debugDraw.DrawPolygon(vs, 4, s_aabbColor);
          }
        }
      }
    }

    if (flags & b2Draw.e_centerOfMassBit) {
      const xf = this.m_drawXf;
      for (let b = this.m_bodyList; b; b = b.GetNext()) {
        xf.Assign(b.GetTransform());
        xf.p.Assign(b.GetWorldCenter());
        debugDraw.DrawTransform(xf);
      }
    }
  }

  /**
   * Query the world for all fixtures that potentially overlap the provided AABB.
   * @param callback a user implemented callback class.
   * @param aabb the query box.
   */
  QueryAABB(callback: b2QueryCallback, aabb: Readonly<b2AABB>): void {
    checkCallback('b2World.QueryAABB', callback);
    b2CheckObject('b2World.QueryAABB', 'aabb', aabb);
    b2CheckVec2('b2World.QueryAABB', 'aabb.lowerBound', aabb.lowerBound);
    b2CheckVec2('b2World.QueryAABB', 'aabb.upperBound', aabb.upperBound);
    this.PullState();
    const depth = this.m_queryDepth;
    if (depth === this.m_queryWrappers.length) {
      this.m_queryWrappers.push(new b2WorldQueryWrapper(this.m_contactManager.m_broadPhase));
    }
    const wrapper = this.m_queryWrappers[depth];
    wrapper.callback = callback;
    this.m_queryDepth = depth + 1;
    try {
      this.m_contactManager.m_broadPhase.Query(wrapper, aabb);
    } finally {
      wrapper.callback = null;
      this.m_queryDepth = depth;
    }
  }

  /**
   * Ray-cast the world for all fixtures in the path of the ray. Your callback controls whether
   * you get the closest point, any point, or n-points. The ray-cast ignores shapes that contain
   * the starting point. The point and normal passed to the callback are reused: copy them to
   * keep them.
   * @param callback a user implemented callback class.
   * @param point1 the ray starting point
   * @param point2 the ray ending point
   */
  RayCast(callback: b2RayCastCallback, point1: Readonly<b2Vec2>, point2: Readonly<b2Vec2>): void {
    checkCallback('b2World.RayCast', callback);
    b2CheckVec2('b2World.RayCast', 'point1', point1);
    b2CheckVec2('b2World.RayCast', 'point2', point2);
    // The tree asserts |point2 - point1|^2 > 0, which also fails for points a few subnormals apart.
    const dx = point2.x - point1.x;
    const dy = point2.y - point1.y;
    if (!(dx * dx + dy * dy > 0.0)) {
      throw new b2ArgumentError('b2World.RayCast', 'point2', 'must differ from point1 (|point2 - point1|^2 must be > 0)');
    }
    this.PullState();
    const depth = this.m_rayCastDepth;
    if (depth === this.m_rayCastWrappers.length) {
      this.m_rayCastWrappers.push(new b2WorldRayCastWrapper(this.m_contactManager.m_broadPhase));
    }
    const wrapper = this.m_rayCastWrappers[depth];
    wrapper.callback = callback;
    const input = wrapper.input;
    input.maxFraction = 1.0;
    input.p1.Assign(point1);
    input.p2.Assign(point2);
    this.m_rayCastDepth = depth + 1;
    try {
      this.m_contactManager.m_broadPhase.RayCast(wrapper, input);
    } finally {
      wrapper.callback = null;
      this.m_rayCastDepth = depth;
    }
  }

  /**
   * Get the world body list. With the returned body, use b2Body.GetNext to get the next body in
   * the world list. A null body indicates the end of the list.
   * @return the head of the world body list.
   */
  GetBodyList(): b2Body | null {
    return this.m_bodyList;
  }

  /**
   * Get the world joint list. With the returned joint, use b2Joint.GetNext to get the next joint
   * in the world list. A null joint indicates the end of the list.
   * @return the head of the world joint list.
   */
  GetJointList(): b2Joint | null {
    return this.m_jointList;
  }

  /**
   * Get the world contact list. With the returned contact, use b2Contact.GetNext to get the next
   * contact in the world list. A null contact indicates the end of the list.
   * @return the head of the world contact list.
   * @warning contacts are created and destroyed in the middle of a time step.
   * Use b2ContactListener to avoid missing contacts.
   */
  GetContactList(): b2Contact | null {
    return this.m_contactManager.m_contactList;
  }

  /** Enable/disable sleep. */
  SetAllowSleeping(flag: boolean): void {
    if (flag === this.m_allowSleep) {
      return;
    }

    this.m_allowSleep = flag;
    if (this.m_allowSleep === false) {
      for (let b = this.m_bodyList; b; b = b.m_next) {
        b.SetAwake(true);
      }
    }
  }

  GetAllowSleeping(): boolean {
    return this.m_allowSleep;
  }

  /** Enable/disable warm starting. For testing. */
  SetWarmStarting(flag: boolean): void {
    this.m_warmStarting = flag;
  }

  GetWarmStarting(): boolean {
    return this.m_warmStarting;
  }

  /** Enable/disable continuous physics. For testing. */
  SetContinuousPhysics(flag: boolean): void {
    this.m_continuousPhysics = flag;
  }

  GetContinuousPhysics(): boolean {
    return this.m_continuousPhysics;
  }

  /** Enable/disable single stepped continuous physics. For testing. */
  SetSubStepping(flag: boolean): void {
    this.m_subStepping = flag;
  }

  GetSubStepping(): boolean {
    return this.m_subStepping;
  }

  /** Get the number of broad-phase proxies. */
  GetProxyCount(): number {
    return this.m_contactManager.m_broadPhase.GetProxyCount();
  }

  /** Get the number of bodies. */
  GetBodyCount(): number {
    return this.m_bodyCount;
  }

  /** Get the number of joints. */
  GetJointCount(): number {
    return this.m_jointCount;
  }

  /** Get the number of contacts (each may have 0 or more contact points). */
  GetContactCount(): number {
    return this.m_contactManager.m_contactCount;
  }

  /** Get the height of the dynamic tree. */
  GetTreeHeight(): number {
    return this.m_contactManager.m_broadPhase.GetTreeHeight();
  }

  /** Get the balance of the dynamic tree. */
  GetTreeBalance(): number {
    return this.m_contactManager.m_broadPhase.GetTreeBalance();
  }

  /** Get the quality metric of the dynamic tree. The smaller the better. The minimum is 1. */
  GetTreeQuality(): number {
    return this.m_contactManager.m_broadPhase.GetTreeQuality();
  }

  /** Change the global gravity vector. */
  SetGravity(gravity: Readonly<b2Vec2>): void {
    b2CheckVec2('b2World.SetGravity', 'gravity', gravity);
    this.m_gravity.Assign(gravity);
  }

  /** Get the global gravity vector. */
  GetGravity(out: b2Vec2): b2Vec2 {
    return out.Assign(this.m_gravity);
  }

  /** Is the world locked (in the middle of a time step). */
  IsLocked(): boolean {
    return (this.m_flags & b2World.e_locked) === b2World.e_locked;
  }

  /** Set flag to control automatic clearing of forces after each time step. */
  SetAutoClearForces(flag: boolean): void {
    if (flag) {
      this.m_flags |= b2World.e_clearForces;
    } else {
      this.m_flags &= ~b2World.e_clearForces;
    }
  }

  /** Get the flag that controls automatic clearing of forces after each time step. */
  GetAutoClearForces(): boolean {
    return (this.m_flags & b2World.e_clearForces) === b2World.e_clearForces;
  }

  /** Get the contact manager for testing. */
  GetContactManager(): b2ContactManager {
    return this.m_contactManager;
  }

  /**
   * Get the current profile: the times of the last step, in milliseconds. Not in the C++: they are
   * measured only while SetProfiling(true) is in force, and stay zero otherwise.
   */
  GetProfile(): Readonly<b2Profile> {
    return this.m_profile;
  }

  /**
   * Not in the C++: enable/disable the step's timing into GetProfile (off by default). Each reading
   * of the host clock (performance.now) allocates a number on the JavaScript heap, about twenty per
   * step, which a game loop that never waits on the garbage collector does not want.
   */
  SetProfiling(flag: boolean): void {
    this.m_profiling = flag;
  }

  GetProfiling(): boolean {
    return this.m_profiling;
  }

  /**
   * Dump the world into the log file.
   * @warning this should be called outside of a time step.
   */
  Dump(): void {
    if ((this.m_flags & b2World.e_locked) === b2World.e_locked) {
      return;
    }
    this.PullState();

    b2Log('b2Vec2 g(%.15lef, %.15lef);\n', this.m_gravity.x, this.m_gravity.y);
    b2Log('m_world->SetGravity(g);\n');

    b2Log('b2Body** bodies = (b2Body**)b2Alloc(%d * sizeof(b2Body*));\n', this.m_bodyCount);
    b2Log('b2Joint** joints = (b2Joint**)b2Alloc(%d * sizeof(b2Joint*));\n', this.m_jointCount);
    let i = 0;
    for (let b = this.m_bodyList; b; b = b.m_next) {
      b.m_islandIndex = i;
      b.Dump();
      ++i;
    }

    i = 0;
    for (let j = this.m_jointList; j; j = j.m_next) {
      j.m_index = i;
      ++i;
    }

    // First pass on joints, skip gear joints.
    for (let j = this.m_jointList; j; j = j.m_next) {
      if (j.m_type === b2JointType.e_gearJoint) {
        continue;
      }

      b2Log('{\n');
      j.Dump();
      b2Log('}\n');
    }

    // Second pass on joints, only gear joints.
    for (let j = this.m_jointList; j; j = j.m_next) {
      if (j.m_type !== b2JointType.e_gearJoint) {
        continue;
      }

      b2Log('{\n');
      j.Dump();
      b2Log('}\n');
    }

    b2Log('b2Free(joints);\n');
    b2Log('b2Free(bodies);\n');
    b2Log('joints = NULL;\n');
    b2Log('bodies = NULL;\n');
  }

  /** Find islands, integrate and solve constraints, solve position constraints. */
  Solve(step: Readonly<b2TimeStep>): void {
    this.m_profile.solveInit = 0.0;
    this.m_profile.solveVelocity = 0.0;
    this.m_profile.solvePosition = 0.0;

    // Size the island for the worst case.
    const island = this.m_island;
    island.Initialize(this.m_bodyCount, this.m_contactManager.m_contactCount, this.m_jointCount, this.m_contactManager.m_contactListener);

    // Clear all the island flags.
    for (let b = this.m_bodyList; b; b = b.m_next) {
      b.m_flags &= ~b2Body.e_islandFlag;
    }
    // The C++ walks the whole contact list here.
    this.ClearFlaggedContacts();
    // The C++ walks the joint list here.
    const jointFlags = this.m_jointIslandFlags;
    jointFlags.fill(0, 0, this.m_jointSlotCount);

    // Build and simulate all awake islands.
    const stackSize = this.m_bodyCount;
    const stack = this.m_stack;
    for (let seed = this.m_bodyList; seed; seed = seed.m_next) {
      if (seed.m_flags & b2Body.e_islandFlag) {
        continue;
      }

      if ((seed.m_flags & b2Body.e_awakeFlag) === 0 || seed.IsActive() === false) {
        continue;
      }

      // The seed can be dynamic or kinematic.
      if (seed.GetType() === b2BodyType.b2_staticBody) {
        continue;
      }

      // Reset island and stack.
      island.Clear();
      let stackCount = 0;
      stack[stackCount++] = seed;
      seed.m_flags |= b2Body.e_islandFlag;

      // Perform a depth first search (DFS) on the constraint graph.
      while (stackCount > 0) {
        // Grab the next body off the stack and add it to the island.
        const b = stack[--stackCount];
        b2Assert(b.IsActive() === true);
        island.Add(b);

        // Make sure the body is awake.
        b.SetAwake(true);

        // To keep islands as small as possible, we don't
        // propagate islands across static bodies.
        if (b.GetType() === b2BodyType.b2_staticBody) {
          continue;
        }

        // Search all contacts connected to this body.
        for (let ce = b.m_contactList; ce; ce = ce.next) {
          const contact = ce.contact;

          // Has this contact already been added to an island?
          if (contact.m_flags & b2Contact.e_islandFlag) {
            continue;
          }

          // Is this contact solid and touching?
          if (contact.IsEnabled() === false || contact.IsTouching() === false) {
            continue;
          }

          // Skip sensors.
          const sensorA = contact.m_fixtureA.m_isSensor;
          const sensorB = contact.m_fixtureB.m_isSensor;
          if (sensorA || sensorB) {
            continue;
          }

          island.AddContact(contact);
          this.FlagContact(contact);

          const other = ce.other;

          // Was the other body already added to this island?
          if (other.m_flags & b2Body.e_islandFlag) {
            continue;
          }

          b2Assert(stackCount < stackSize);
          stack[stackCount++] = other;
          other.m_flags |= b2Body.e_islandFlag;
        }

        // Search all joints connect to this body.
        for (let je = b.m_jointList; je; je = je.next) {
          const slot = je.islandSlot;
          if (jointFlags[slot] === 1) {
            continue;
          }

          const other = je.other;

          // Don't simulate joints connected to inactive bodies.
          if (other.IsActive() === false) {
            continue;
          }

          island.AddJoint(je.joint);
          jointFlags[slot] = 1;

          if (other.m_flags & b2Body.e_islandFlag) {
            continue;
          }

          b2Assert(stackCount < stackSize);
          stack[stackCount++] = other;
          other.m_flags |= b2Body.e_islandFlag;
        }
      }

      const profile = this.m_profiling ? this.m_islandProfile : null;
      island.Solve(profile, step, this.m_gravity, this.m_allowSleep);
      if (profile !== null) {
        this.m_profile.solveInit += profile.solveInit;
        this.m_profile.solveVelocity += profile.solveVelocity;
        this.m_profile.solvePosition += profile.solvePosition;
      }

      // Post solve cleanup.
      for (let i = 0; i < island.m_bodyCount; ++i) {
        // Allow static bodies to participate in other islands.
        const b = island.m_bodies[i];
        if (b.GetType() === b2BodyType.b2_staticBody) {
          b.m_flags &= ~b2Body.e_islandFlag;
        }
      }
    }

    {
      const timer = this.m_broadphaseTimer;
      if (this.m_profiling) timer.Reset();
      // Synchronize fixtures, check for out of range bodies.
      for (let b = this.m_bodyList; b; b = b.GetNext()) {
        // If a body was not in an island then it did not move.
        if ((b.m_flags & b2Body.e_islandFlag) === 0) {
          continue;
        }

        if (b.GetType() === b2BodyType.b2_staticBody) {
          continue;
        }

        // Update fixtures (for broad-phase).
        b.SynchronizeFixtures();
      }

      // Look for new contacts.
      this.m_contactManager.FindNewContacts();
      if (this.m_profiling) this.m_profile.broadphase = timer.GetMilliseconds();
    }
  }

  /**
   * Not in the C++: set contact c's island flag and note it for Solve's clearing
   * (m_flaggedContacts). For the engine and for readers that restore a contact's flags.
   */
  FlagContact(c: b2Contact): void {
    c.m_flags |= b2Contact.e_islandFlag;
    this.m_flaggedContacts[this.m_flaggedContactCount++] = c;
  }

  /**
   * Not in the C++: clears the island flag of every contact, which only the contacts this world
   * flagged can carry: the same flags as a walk over the contact list, for an array read.
   */
  private ClearFlaggedContacts(): void {
    const flagged = this.m_flaggedContacts;
    for (let i = 0; i < this.m_flaggedContactCount; ++i) {
      flagged[i].m_flags &= ~b2Contact.e_islandFlag;
    }
    this.m_flaggedContactCount = 0;
  }

  /**
   * One contact of SolveTOI's search for the first TOI, as the C++ loop body: false where the C++
   * skips the contact with `continue`, else true with the contact's TOI (computed and cached, or
   * the cached one) in m_contactAlpha, not returned: V8 boxes a double returned by a call it does
   * not inline, an allocation per contact and search.
   */
  private ComputeContactTOI(c: b2Contact): boolean {
    const input = this.m_toiInput;
    const output = this.m_toiOutput;

    // Is this contact disabled?
    if (c.IsEnabled() === false) {
      return false;
    }

    // Prevent excessive sub-stepping.
    if (c.m_toiCount > b2_maxSubSteps) {
      return false;
    }

    let alpha = 1.0;
    if (c.m_flags & b2Contact.e_toiFlag) {
      // This contact has a valid cached TOI.
      alpha = c.m_scalars!.toi;
    } else {
      const fA = c.GetFixtureA();
      const fB = c.GetFixtureB();

      // Is there a sensor?
      if (fA.IsSensor() || fB.IsSensor()) {
        return false;
      }

      const bA = fA.GetBody();
      const bB = fB.GetBody();

      const typeA = bA.m_type;
      const typeB = bB.m_type;
      b2Assert(typeA === b2BodyType.b2_dynamicBody || typeB === b2BodyType.b2_dynamicBody);

      const activeA = (bA.m_flags & b2Body.e_awakeFlag) !== 0 && typeA !== b2BodyType.b2_staticBody;
      const activeB = (bB.m_flags & b2Body.e_awakeFlag) !== 0 && typeB !== b2BodyType.b2_staticBody;

      // Is at least one body active (awake and dynamic or kinematic)?
      if (activeA === false && activeB === false) {
        return false;
      }

      const collideA = bA.IsBullet() || typeA !== b2BodyType.b2_dynamicBody;
      const collideB = bB.IsBullet() || typeB !== b2BodyType.b2_dynamicBody;

      // Are these two non-bullet dynamic bodies?
      if (collideA === false && collideB === false) {
        return false;
      }

      // Compute the TOI for this contact.
      // Put the sweeps onto the same time interval.
      let alpha0 = bA.m_sweep.alpha0;

      if (bA.m_sweep.alpha0 < bB.m_sweep.alpha0) {
        alpha0 = bB.m_sweep.alpha0;
        b2SweepTime[0] = alpha0;
        bA.m_sweep.AdvanceAt();
      } else if (bB.m_sweep.alpha0 < bA.m_sweep.alpha0) {
        alpha0 = bA.m_sweep.alpha0;
        b2SweepTime[0] = alpha0;
        bB.m_sweep.AdvanceAt();
      }

      b2Assert(alpha0 < 1.0);

      const indexA = c.GetChildIndexA();
      const indexB = c.GetChildIndexB();

      // Compute the time of impact in interval [0, minTOI]
      input.proxyA.Set(fA.GetShape(), indexA);
      input.proxyB.Set(fB.GetShape(), indexB);
      input.sweepA.Assign(bA.m_sweep);
      input.sweepB.Assign(bB.m_sweep);
      input.tMax = 1.0;

      b2TimeOfImpact(output, input);

      // Beta is the fraction of the remaining portion of the .
      const beta = output.t;
      if (output.state === b2TOIOutput.e_touching) {
        // b2Min(alpha0 + (1.0 - alpha0) * beta, 1.0) written out: most calls of this function take
        // the cached TOI above, and V8 does not inline calls on a path that rare, so the helper's
        // double result would keep alpha boxed on every path (docs/PORTING.md).
        const t = alpha0 + (1.0 - alpha0) * beta;
        alpha = t < 1.0 ? t : 1.0;
      } else {
        alpha = 1.0;
      }

      c.m_scalars!.toi = alpha;
      c.m_flags |= b2Contact.e_toiFlag;
    }

    this.m_contactAlpha = alpha;
    return true;
  }

  /**
   * Not in the C++: whether SolveTOI's search must visit contact c. A contact without a cached TOI
   * whose fixtures include a sensor, or whose bodies are both dynamic and not bullets, has no TOI
   * (ComputeContactTOI returns false for it, changing nothing), and only b2Body.SetBullet and
   * SetType and b2Fixture.SetSensor change that (they set m_toiCandidatesStale). In a pyramid of n
   * boxes that leaves the few contacts with the ground.
   */
  private static IsTOICandidate(c: b2Contact): boolean {
    if (c.m_flags & b2Contact.e_toiFlag) {
      return true;
    }
    const fA = c.m_fixtureA;
    const fB = c.m_fixtureB;
    if (fA.m_isSensor || fB.m_isSensor) {
      return false;
    }
    const bA = fA.m_body;
    const bB = fB.m_body;
    const collideA = bA.IsBullet() || bA.m_type !== b2BodyType.b2_dynamicBody;
    const collideB = bB.IsBullet() || bB.m_type !== b2BodyType.b2_dynamicBody;
    return collideA || collideB;
  }

  /**
   * Not in the C++: brings SolveTOI's candidates up to date before a search, and with invalidateTOI
   * does the C++'s invalidation of every contact's TOI and island flag. The C++ walks the whole
   * contact list for both, every step. Here only a contact's creation or destruction, and the
   * calls that set m_toiCandidatesStale, change the candidates:
   * - a destroyed contact (m_toiSearch 0 again) is dropped from the array;
   * - contacts created since the last search head the contact list (AddPair prepends them), so a
   *   walk from the head up to the first contact seen before (m_toiSearch not 0) finds them all;
   *   their candidates go on the end of the array, which keeps it in reverse list order;
   * - a contact can hold a TOI flag, count or value only while it is a candidate (only the search
   *   sets them), so invalidating the candidates resets the same state as the C++'s walk, and its
   *   island flag is set only by FlagContact, so clearing the flagged contacts clears the rest.
   * When stale, the walk covers the whole list, as the C++'s, and rebuilds the array.
   */
  private UpdateTOICandidates(invalidateTOI: boolean): void {
    const candidates = this.m_toiCandidates;
    const oldCount = this.m_toiCandidateCount;
    const whole = this.m_toiCandidatesStale;
    this.m_toiCandidatesStale = false;
    let count = 0;
    if (!whole) {
      for (let i = 0; i < oldCount; ++i) {
        const c = candidates[i];
        if (c.m_toiSearch !== 2) {
          continue;
        }
        if (invalidateTOI) {
          b2World.InvalidateTOI(c);
        }
        candidates[count++] = c;
      }
      if (invalidateTOI) {
        this.ClearFlaggedContacts();
      }
    } else if (invalidateTOI) {
      this.m_flaggedContactCount = 0;
    }

    const first = count;
    for (let c = this.m_contactManager.m_contactList; c !== null && (whole || c.m_toiSearch === 0); c = c.m_next) {
      if (whole && invalidateTOI) {
        b2World.InvalidateTOI(c);
      }
      if (b2World.IsTOICandidate(c)) {
        c.m_toiSearch = 2;
        c.m_scalars ??= new b2ContactScalars();
        candidates[count++] = c;
      } else {
        c.m_toiSearch = 1;
      }
    }
    for (let i = first, j = count - 1; i < j; ++i, --j) {
      const c = candidates[i];
      candidates[i] = candidates[j];
      candidates[j] = c;
    }
    // Let go of destroyed contacts.
    for (let i = count; i < oldCount; ++i) {
      candidates[i] = null as unknown as b2Contact;
    }
    this.m_toiCandidateCount = count;
  }

  /** The C++'s loop body that invalidates a contact's TOI (and island flag) in SolveTOI. */
  private static InvalidateTOI(c: b2Contact): void {
    c.m_flags &= ~(b2Contact.e_toiFlag | b2Contact.e_islandFlag);
    c.m_toiCount = 0;
    if (c.m_scalars !== null) c.m_scalars.toi = 1.0;
  }

  /** Find TOI contacts and solve them. */
  SolveTOI(step: Readonly<b2TimeStep>): void {
    const island = this.m_island;
    island.Initialize(2 * b2_maxTOIContacts, b2_maxTOIContacts, 0, this.m_contactManager.m_contactListener);

    let invalidateTOI = this.m_stepComplete;
    if (this.m_stepComplete) {
      for (let b = this.m_bodyList; b; b = b.m_next) {
        b.m_flags &= ~b2Body.e_islandFlag;
        b.m_sweep.alpha0 = 0.0;
      }
    }

    const backup1 = this.m_backup1;
    const backup2 = this.m_backup2;
    const backup = this.m_backup;
    const bodies = this.m_toiBodies;
    const candidates = this.m_toiCandidates;

    // Find TOI events and solve them.
    for (;;) {
      // Find the first TOI: the C++ walks the whole contact list; the candidates are the contacts
      // of that walk with a TOI, in the same order.
      this.UpdateTOICandidates(invalidateTOI);
      invalidateTOI = false;
      let minContact: b2Contact | null = null;
      let minAlpha = 1.0;
      for (let i = this.m_toiCandidateCount - 1; i >= 0; --i) {
        const c = candidates[i];
        if (this.ComputeContactTOI(c) && this.m_contactAlpha < minAlpha) {
          // This is the minimum TOI found so far.
          minContact = c;
          minAlpha = this.m_contactAlpha;
        }
      }

      if (minContact === null || 1.0 - 10.0 * b2_epsilon < minAlpha) {
        // No more TOI events. Done!
        this.m_stepComplete = true;
        break;
      }

      // Advance the bodies to the TOI.
      const fA = minContact.GetFixtureA();
      const fB = minContact.GetFixtureB();
      const bA = fA.GetBody();
      const bB = fB.GetBody();

      backup1.Assign(bA.m_sweep);
      backup2.Assign(bB.m_sweep);

      b2SweepTime[0] = minAlpha;
      bA.AdvanceAt();
      bB.AdvanceAt();

      // The TOI contact likely has some new contact points.
      minContact.Update(this.m_contactManager.m_contactListener);
      minContact.m_flags &= ~b2Contact.e_toiFlag;
      ++minContact.m_toiCount;

      // Is the contact solid?
      if (minContact.IsEnabled() === false || minContact.IsTouching() === false) {
        // Restore the sweeps.
        minContact.SetEnabled(false);
        bA.m_sweep.Assign(backup1);
        bB.m_sweep.Assign(backup2);
        bA.SynchronizeTransform();
        bB.SynchronizeTransform();
        continue;
      }

      bA.SetAwake(true);
      bB.SetAwake(true);

      // Build the island
      island.Clear();
      island.Add(bA);
      island.Add(bB);
      island.AddContact(minContact);

      bA.m_flags |= b2Body.e_islandFlag;
      bB.m_flags |= b2Body.e_islandFlag;
      this.FlagContact(minContact);

      // Get contacts on bodyA and bodyB.
      bodies[0] = bA;
      bodies[1] = bB;
      for (let i = 0; i < 2; ++i) {
        const body = bodies[i];
        if (body.m_type === b2BodyType.b2_dynamicBody) {
          for (let ce = body.m_contactList; ce; ce = ce.next) {
            if (island.m_bodyCount === island.m_bodyCapacity) {
              break;
            }

            if (island.m_contactCount === island.m_contactCapacity) {
              break;
            }

            const contact = ce.contact;

            // Has this contact already been added to the island?
            if (contact.m_flags & b2Contact.e_islandFlag) {
              continue;
            }

            // Only add static, kinematic, or bullet bodies.
            const other = ce.other;
            if (other.m_type === b2BodyType.b2_dynamicBody && body.IsBullet() === false && other.IsBullet() === false) {
              continue;
            }

            // Skip sensors.
            const sensorA = contact.m_fixtureA.m_isSensor;
            const sensorB = contact.m_fixtureB.m_isSensor;
            if (sensorA || sensorB) {
              continue;
            }

            // Tentatively advance the body to the TOI.
            backup.Assign(other.m_sweep);
            if ((other.m_flags & b2Body.e_islandFlag) === 0) {
              b2SweepTime[0] = minAlpha;
              other.AdvanceAt();
            }

            // Update the contact points
            contact.Update(this.m_contactManager.m_contactListener);

            // Was the contact disabled by the user?
            if (contact.IsEnabled() === false) {
              other.m_sweep.Assign(backup);
              other.SynchronizeTransform();
              continue;
            }

            // Are there contact points?
            if (contact.IsTouching() === false) {
              other.m_sweep.Assign(backup);
              other.SynchronizeTransform();
              continue;
            }

            // Add the contact to the island
            this.FlagContact(contact);
            island.AddContact(contact);

            // Has the other body already been added to the island?
            if (other.m_flags & b2Body.e_islandFlag) {
              continue;
            }

            // Add the other body to the island.
            other.m_flags |= b2Body.e_islandFlag;

            if (other.m_type !== b2BodyType.b2_staticBody) {
              other.SetAwake(true);
            }

            island.Add(other);
          }
        }
      }

      const subStep = this.m_subStep;
      subStep.dt = (1.0 - minAlpha) * step.dt;
      subStep.inv_dt = 1.0 / subStep.dt;
      subStep.dtRatio = 1.0;
      subStep.positionIterations = 20;
      subStep.velocityIterations = step.velocityIterations;
      subStep.warmStarting = false;
      island.SolveTOI(subStep, bA.m_islandIndex, bB.m_islandIndex);

      // Reset island flags and synchronize broad-phase proxies.
      for (let i = 0; i < island.m_bodyCount; ++i) {
        const body = island.m_bodies[i];
        body.m_flags &= ~b2Body.e_islandFlag;

        if (body.m_type !== b2BodyType.b2_dynamicBody) {
          continue;
        }

        body.SynchronizeFixtures();

        // Invalidate all contact TOIs on this displaced body.
        for (let ce = body.m_contactList; ce; ce = ce.next) {
          ce.contact.m_flags &= ~(b2Contact.e_toiFlag | b2Contact.e_islandFlag);
        }
      }

      // Commit fixture proxy movements to the broad-phase so that new contacts are created.
      // Also, some contacts can be destroyed.
      this.m_contactManager.FindNewContacts();

      if (this.m_subStepping) {
        this.m_stepComplete = false;
        break;
      }
    }
  }

  /** The contact loop CreateJoint and DestroyJoint share: bodyB's contacts with bodyA, in list order. */
  private FlagContactsForFiltering(bodyA: b2Body, bodyB: b2Body): void {
    let edge = bodyB.GetContactList();
    while (edge) {
      if (edge.other === bodyA) {
        // Flag the contact for filtering at the next time step (where either
        // body is awake).
        edge.contact.FlagForFiltering();
      }

      edge = edge.next;
    }
  }

  private DrawJoint(joint: b2Joint): void {
    const debugDraw = this.m_debugDraw as b2Draw;
    const bodyA = joint.GetBodyA();
    const bodyB = joint.GetBodyB();
    const xf1 = bodyA.GetTransform();
    const xf2 = bodyB.GetTransform();
    const x1 = xf1.p;
    const x2 = xf2.p;
    const p1 = joint.GetAnchorA(this.m_drawP1);
    const p2 = joint.GetAnchorB(this.m_drawP2);

    const color = s_jointColor;

    switch (joint.GetType()) {
      case b2JointType.e_distanceJoint:
        debugDraw.DrawSegment(p1, p2, color);
        break;

      case b2JointType.e_pulleyJoint: {
        const pulley = joint as b2PulleyJoint;
        const s1 = pulley.GetGroundAnchorA(this.m_drawS1);
        const s2 = pulley.GetGroundAnchorB(this.m_drawS2);
        debugDraw.DrawSegment(s1, p1, color);
        debugDraw.DrawSegment(s2, p2, color);
        debugDraw.DrawSegment(s1, s2, color);
        break;
      }

      case b2JointType.e_mouseJoint:
        // don't draw this
        break;

      default:
        debugDraw.DrawSegment(x1, p1, color);
        debugDraw.DrawSegment(p1, p2, color);
        debugDraw.DrawSegment(x2, p2, color);
    }
  }

  /**
   * Draw a shape at a transform with the debug draw. The C++ takes the fixture, only to reach its
   * shape; taking the shape makes this Box2DWeb 2.1a's public DrawShape(shape, xf, color).
   */
  DrawShape(shape: b2Shape, xf: Readonly<b2Transform>, color: b2Color): void {
    const debugDraw = this.m_debugDraw as b2Draw;
    switch (shape.GetType()) {
      case b2Shape.e_circle: {
        const circle = shape as b2CircleShape;

        const center = b2MulXV(xf, circle.m_p, this.m_drawCenter);
        const radius = circle.m_radius;
        const axis = b2MulRV(xf.q, s_unitX, this.m_drawAxis);

        debugDraw.DrawSolidCircle(center, radius, axis, color);
        break;
      }

      case b2Shape.e_edge: {
        const edge = shape as b2EdgeShape;
        const v1 = b2MulXV(xf, edge.m_vertex1, this.m_drawV1);
        const v2 = b2MulXV(xf, edge.m_vertex2, this.m_drawV2);
        debugDraw.DrawSegment(v1, v2, color);
        break;
      }

      case b2Shape.e_chain: {
        const chain = shape as b2ChainShape;
        const count = chain.m_count;
        const vertices = chain.m_vertices;

        const v1 = b2MulXV(xf, vertices[0], this.m_drawV1);
        for (let i = 1; i < count; ++i) {
          const v2 = b2MulXV(xf, vertices[i], this.m_drawV2);
          debugDraw.DrawSegment(v1, v2, color);
          debugDraw.DrawCircle(v1, 0.05, color);
          v1.Assign(v2);
        }
        break;
      }

      case b2Shape.e_polygon: {
        const poly = shape as b2PolygonShape;
        const vertexCount = poly.m_vertexCount;
        b2Assert(vertexCount <= b2_maxPolygonVertices);
        const vertices = this.m_drawVertices;

        for (let i = 0; i < vertexCount; ++i) {
          b2MulXV(xf, poly.m_vertices[i], vertices[i]);
        }

        debugDraw.DrawSolidPolygon(vertices, vertexCount, color);
        break;
      }

      default:
        break;
    }
  }
}
