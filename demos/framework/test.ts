/*
 * The Testbed framework (Test.h / Test.cpp of Box2D 2.2.1): the base class of every test. It owns
 * the world, is its contact listener (PreSolve records the contact points), nulls the mouse joint
 * in the destruction listener, drags bodies with a b2MouseJoint, launches bombs, and in Step sets
 * the world from the settings, steps it, draws it and prints the statistics and the profile.
 */

import {
  b2AABB,
  b2Body,
  b2BodyDef,
  b2CircleShape,
  b2Color,
  b2ContactListener,
  b2DestructionListener,
  b2Draw,
  b2FixtureDef,
  b2GetPointStates,
  b2Max,
  b2MouseJoint,
  b2MouseJointDef,
  b2PointState,
  b2Profile,
  b2QueryCallback,
  b2Vec2,
  b2World,
  b2WorldManifold,
  b2_dynamicBody,
  b2_maxManifoldPoints,
} from '../../src/index';
import type { b2Contact, b2ContactImpulse, b2Fixture, b2Joint, b2Manifold } from '../../src/index';
import { WebGPUBackend } from '../../src-gpu/backend/backend';
import { RandomFloat } from './random';
import { g_debugDraw, TestbedDraw } from './render';
import type { Settings, StepSettings } from './settings';

export const k_maxContactPoints = 2048;

export class ContactPoint {
  fixtureA: b2Fixture | null = null;
  fixtureB: b2Fixture | null = null;
  readonly normal = new b2Vec2();
  readonly position = new b2Vec2();
  state: b2PointState = b2PointState.b2_nullState;
  // Box2D 2.3 added these to draw the contact and friction impulses (2.2.1 has the drawing code
  // commented out for want of them): the warm-starting impulses PreSolve sees.
  normalImpulse = 0.0;
  tangentImpulse = 0.0;
}

/**
 * This is called when a joint in the world is implicitly destroyed because an attached body is
 * destroyed. This gives us a chance to nullify the mouse joint.
 */
class DestructionListener extends b2DestructionListener {
  constructor(readonly test: Test) {
    super();
  }

  SayGoodbyeFixture(fixture: b2Fixture): void {}

  SayGoodbyeJoint(joint: b2Joint): void {
    if (this.test.m_mouseJoint === joint) {
      this.test.m_mouseJoint = null;
    } else {
      this.test.JointDestroyed(joint);
    }
  }
}

/**
 * Not in the C++: the contact listener while the WebGPU backend steps the world. The GPU solves a
 * whole step without calling back into JavaScript, so PreSolve, where the Testbed records its
 * contact points, cannot run; the backend delivers BeginContact, EndContact and PostSolve after
 * the step. This listener has only the ones the test overrides (the backend reads back and logs
 * only what a listener has), and PostSolve records the contact points when they are drawn or
 * the test uses them (UsesContactPoints).
 */
function gpuContactListener(test: Test, recordPoints: boolean): b2ContactListener {
  const listener = new b2ContactListener();
  const own = (name: 'BeginContact' | 'EndContact' | 'PostSolve') => test[name] !== Test.prototype[name];
  if (own('BeginContact')) listener.BeginContact = (contact) => test.BeginContact(contact);
  if (own('EndContact')) listener.EndContact = (contact) => test.EndContact(contact);
  if (own('PostSolve') || recordPoints) {
    listener.PostSolve = (contact, impulse) => {
      if (recordPoints) test.RecordSolvedPoints(contact, impulse);
      if (own('PostSolve')) test.PostSolve(contact, impulse);
    };
  }
  return listener;
}

class QueryCallback extends b2QueryCallback {
  readonly m_point = new b2Vec2();
  m_fixture: b2Fixture | null = null;

  constructor(point: b2Vec2) {
    super();
    this.m_point.Assign(point);
  }

  ReportFixture(fixture: b2Fixture): boolean {
    const body = fixture.GetBody();
    if (body.GetType() === b2_dynamicBody) {
      const inside = fixture.TestPoint(this.m_point);
      if (inside) {
        this.m_fixture = fixture;
        // We are done, terminate the query.
        return false;
      }
    }
    // Continue the query.
    return true;
  }
}

const s_state1: b2PointState[] = new Array(b2_maxManifoldPoints).fill(b2PointState.b2_nullState);
const s_state2: b2PointState[] = new Array(b2_maxManifoldPoints).fill(b2PointState.b2_nullState);
const s_worldManifold = new b2WorldManifold();

export class Test extends b2ContactListener {
  m_groundBody: b2Body;
  readonly m_worldAABB = new b2AABB();
  readonly m_points: ContactPoint[] = [];
  m_pointCount = 0;
  readonly m_destructionListener: DestructionListener;
  readonly m_debugDraw: TestbedDraw = g_debugDraw;
  m_textLine = 30;
  m_world: b2World;
  m_bomb: b2Body | null = null;
  m_mouseJoint: b2MouseJoint | null = null;
  readonly m_bombSpawnPoint = new b2Vec2();
  m_bombSpawning = false;
  readonly m_mouseWorld = new b2Vec2();
  m_stepCount = 0;
  readonly m_maxProfile = new b2Profile();
  readonly m_totalProfile = new b2Profile();
  /** Not in the C++: performance.now() when Step last called the world's Step (the GPU step's timer starts there). */
  m_stepStart = 0;
  /**
   * Set by the testbed while GpuRenderer draws the shapes and joints from the GPU's buffers (a
   * large world on WebGPU): DrawDebugData then draws only the other layers, and is not called at
   * all without one, so that no body is read back for drawing.
   */
  m_gpuDrawsWorld = false;
  /** The listener set while the WebGPU backend steps the world, and whether it records points. */
  private m_gpuListener: b2ContactListener | null = null;
  private m_gpuListenerRecords = false;

  /** `world`: use this world (a loaded scene) instead of a new one with gravity (0, -10). */
  constructor(world?: b2World) {
    super();
    for (let i = 0; i < k_maxContactPoints; ++i) this.m_points.push(new ContactPoint());
    this.m_world = world ?? new b2World(new b2Vec2(0.0, -10.0));
    this.m_destructionListener = new DestructionListener(this);
    this.m_world.SetDestructionListener(this.m_destructionListener);
    this.m_world.SetContactListener(this);
    this.m_world.SetDebugDraw(this.m_debugDraw);
    // The testbed shows the step's times (GetProfile), which the engine measures only on request.
    this.m_world.SetProfiling(true);

    const bodyDef = new b2BodyDef();
    this.m_groundBody = this.m_world.CreateBody(bodyDef);
  }

  SetTextLine(line: number): void {
    this.m_textLine = line;
  }

  DrawTitle(x: number, y: number, title: string): void {
    this.m_debugDraw.DrawString(x, y, title);
  }

  Keyboard(key: string): void {}

  KeyboardUp(key: string): void {}

  // Let derived tests know that a joint was destroyed.
  JointDestroyed(joint: b2Joint): void {}

  // Callbacks for derived classes.
  override BeginContact(contact: b2Contact): void {}

  override EndContact(contact: b2Contact): void {}

  override PreSolve(contact: b2Contact, oldManifold: b2Manifold): void {
    const manifold = contact.GetManifold();

    if (manifold.pointCount === 0) {
      return;
    }

    b2GetPointStates(s_state1, s_state2, oldManifold, manifold);

    this.RecordPoints(contact, s_state2, null);
  }

  /**
   * The contact's manifold points into m_points (PreSolve's loop), with their states (all persisting
   * when null) and impulses: the step's from PostSolve, else the manifold's warm-starting ones.
   */
  private RecordPoints(contact: b2Contact, states: readonly b2PointState[] | null, impulse: b2ContactImpulse | null): void {
    const manifold = contact.GetManifold();
    const fixtureA = contact.GetFixtureA();
    const fixtureB = contact.GetFixtureB();

    contact.GetWorldManifold(s_worldManifold);

    for (let i = 0; i < manifold.pointCount && this.m_pointCount < k_maxContactPoints; ++i) {
      const cp = this.m_points[this.m_pointCount];
      cp.fixtureA = fixtureA;
      cp.fixtureB = fixtureB;
      cp.position.Assign(s_worldManifold.points[i]);
      cp.normal.Assign(s_worldManifold.normal);
      cp.state = states === null ? b2PointState.b2_persistState : states[i];
      cp.normalImpulse = impulse === null ? manifold.points[i].normalImpulse : impulse.normalImpulses[i];
      cp.tangentImpulse = impulse === null ? manifold.points[i].tangentImpulse : impulse.tangentImpulses[i];
      ++this.m_pointCount;
    }
  }

  override PostSolve(contact: b2Contact, impulse: b2ContactImpulse): void {}

  /**
   * Not in the C++: why this test cannot run on the WebGPU backend, or null when it can. A test with
   * its own PreSolve cannot (it must run inside the solver); a test with another reason overrides
   * this.
   */
  GpuRefusal(): string | null {
    if (this.PreSolve !== Test.prototype.PreSolve) {
      return 'its PreSolve changes contacts between collision and the solve, and the GPU solves a step without calling back into JavaScript';
    }
    return null;
  }

  /**
   * Not in the C++: whether the test reads m_points itself (not only to draw them), so that the
   * WebGPU backend's listener records them from PostSolve whether they are drawn or not.
   */
  UsesContactPoints(): boolean {
    return false;
  }

  /**
   * Not in the C++: the contact listener for the WebGPU backend (see gpuContactListener), one
   * object as long as `recordPoints` (the contact points are drawn or used) stays the same.
   */
  GpuContactListener(recordPoints: boolean): b2ContactListener {
    if (this.m_gpuListener === null || this.m_gpuListenerRecords !== recordPoints) {
      this.m_gpuListener = gpuContactListener(this, recordPoints);
      this.m_gpuListenerRecords = recordPoints;
    }
    return this.m_gpuListener;
  }

  /**
   * Not in the C++: the contact points of a solved contact from PostSolve, on the WebGPU backend,
   * where PreSolve does not run. Drawn as persisting points with the step's impulses.
   */
  RecordSolvedPoints(contact: b2Contact, impulse: b2ContactImpulse): void {
    this.RecordPoints(contact, null, impulse);
  }

  MouseDown(p: b2Vec2): void {
    this.m_mouseWorld.Assign(p);

    if (this.m_mouseJoint !== null) {
      return;
    }

    // Make a small box.
    const aabb = new b2AABB();
    aabb.lowerBound.Set(p.x - 0.001, p.y - 0.001);
    aabb.upperBound.Set(p.x + 0.001, p.y + 0.001);

    // Query the world for overlapping shapes.
    const callback = new QueryCallback(p);
    this.m_world.QueryAABB(callback, aabb);

    if (callback.m_fixture !== null) {
      const body = callback.m_fixture.GetBody();
      const md = new b2MouseJointDef();
      md.bodyA = this.m_groundBody;
      md.bodyB = body;
      md.target.Assign(p);
      md.maxForce = 1000.0 * body.GetMass();
      this.m_mouseJoint = this.m_world.CreateJoint(md) as b2MouseJoint;
      body.SetAwake(true);
    }
  }

  SpawnBomb(worldPt: b2Vec2): void {
    this.m_bombSpawnPoint.Assign(worldPt);
    this.m_bombSpawning = true;
  }

  CompleteBombSpawn(p: b2Vec2): void {
    if (this.m_bombSpawning === false) {
      return;
    }

    const multiplier = 30.0;
    const vel = new b2Vec2(this.m_bombSpawnPoint.x - p.x, this.m_bombSpawnPoint.y - p.y);
    vel.Multiply(multiplier);
    this.LaunchBombAt(this.m_bombSpawnPoint, vel);
    this.m_bombSpawning = false;
  }

  ShiftMouseDown(p: b2Vec2): void {
    this.m_mouseWorld.Assign(p);

    if (this.m_mouseJoint !== null) {
      return;
    }

    this.SpawnBomb(p);
  }

  MouseUp(p: b2Vec2): void {
    if (this.m_mouseJoint !== null) {
      this.m_world.DestroyJoint(this.m_mouseJoint);
      this.m_mouseJoint = null;
    }

    if (this.m_bombSpawning) {
      this.CompleteBombSpawn(p);
    }
  }

  MouseMove(p: b2Vec2): void {
    this.m_mouseWorld.Assign(p);

    if (this.m_mouseJoint !== null) {
      this.m_mouseJoint.SetTarget(p);
    }
  }

  LaunchBomb(): void {
    const p = new b2Vec2(RandomFloat(-15.0, 15.0), 30.0);
    const v = new b2Vec2(-5.0 * p.x, -5.0 * p.y);
    this.LaunchBombAt(p, v);
  }

  /** Test::LaunchBomb(position, velocity). */
  LaunchBombAt(position: b2Vec2, velocity: b2Vec2): void {
    if (this.m_bomb !== null) {
      this.m_world.DestroyBody(this.m_bomb);
      this.m_bomb = null;
    }

    const bd = new b2BodyDef();
    bd.type = b2_dynamicBody;
    bd.position.Assign(position);
    bd.bullet = true;
    this.m_bomb = this.m_world.CreateBody(bd);
    this.m_bomb.SetLinearVelocity(velocity);

    const circle = new b2CircleShape();
    circle.m_radius = 0.3;

    const fd = new b2FixtureDef();
    fd.shape = circle;
    fd.density = 20.0;
    fd.restitution = 0.0;

    this.m_bomb.CreateFixture(fd);
  }

  Step(settings: Settings): void {
    let timeStep = settings.hz > 0.0 ? 1.0 / settings.hz : 0.0;

    if (settings.pause) {
      if (settings.singleStep) {
        settings.singleStep = 0;
      } else {
        timeStep = 0.0;
      }

      this.m_debugDraw.DrawString(5, this.m_textLine, '****PAUSED****');
      this.m_textLine += 15;
    }

    let flags = 0;
    flags += settings.drawShapes * b2Draw.e_shapeBit;
    flags += settings.drawJoints * b2Draw.e_jointBit;
    flags += settings.drawAABBs * b2Draw.e_aabbBit;
    flags += settings.drawPairs * b2Draw.e_pairBit;
    flags += settings.drawCOMs * b2Draw.e_centerOfMassBit;
    if (this.m_gpuDrawsWorld) flags &= ~(b2Draw.e_shapeBit | b2Draw.e_jointBit);
    this.m_debugDraw.SetFlags(flags);

    // The Sleep setting is Box2D 2.3's; a no-op while it keeps the world's value.
    this.m_world.SetAllowSleeping(settings.enableSleep > 0);
    this.m_world.SetWarmStarting(settings.enableWarmStarting > 0);
    this.m_world.SetContinuousPhysics(settings.enableContinuous > 0);
    this.m_world.SetSubStepping(settings.enableSubStepping > 0);

    // On the WebGPU backend the points come with the synchronisation after the step (the testbed
    // clears them before it), and this frame draws the last synchronised step's.
    const backend = this.m_world.GetBackend();
    if (backend === null) this.m_pointCount = 0;

    this.m_stepStart = performance.now();
    this.m_world.Step(timeStep, settings.velocityIterations, settings.positionIterations);

    if (flags !== 0) this.m_world.DrawDebugData();

    if (settings.drawPairs) {
      this.DrawPairs();
    }

    if (timeStep > 0.0) {
      ++this.m_stepCount;
    }

    if (settings.drawStats) {
      const bodyCount = this.m_world.GetBodyCount();
      // The GPU keeps its contacts (the world's list is empty while it steps).
      const contactCount = backend instanceof WebGPUBackend ? (backend.contactCounts?.contacts ?? 0) : this.m_world.GetContactCount();
      const jointCount = this.m_world.GetJointCount();
      this.m_debugDraw.DrawString(5, this.m_textLine, 'bodies/contacts/joints = %d/%d/%d', bodyCount, contactCount, jointCount);
      this.m_textLine += 15;

      const proxyCount = this.m_world.GetProxyCount();
      const height = this.m_world.GetTreeHeight();
      const balance = this.m_world.GetTreeBalance();
      const quality = this.m_world.GetTreeQuality();
      this.m_debugDraw.DrawString(5, this.m_textLine, 'proxies/height/balance/quality = %d/%d/%d/%g', proxyCount, height, balance, quality);
      this.m_textLine += 15;
    }

    // Track maximum profile times
    {
      const p = this.m_world.GetProfile();
      const max = this.m_maxProfile;
      const total = this.m_totalProfile;
      max.step = b2Max(max.step, p.step);
      max.collide = b2Max(max.collide, p.collide);
      max.solve = b2Max(max.solve, p.solve);
      max.solveInit = b2Max(max.solveInit, p.solveInit);
      max.solveVelocity = b2Max(max.solveVelocity, p.solveVelocity);
      max.solvePosition = b2Max(max.solvePosition, p.solvePosition);
      max.solveTOI = b2Max(max.solveTOI, p.solveTOI);
      max.broadphase = b2Max(max.broadphase, p.broadphase);

      total.step += p.step;
      total.collide += p.collide;
      total.solve += p.solve;
      total.solveInit += p.solveInit;
      total.solveVelocity += p.solveVelocity;
      total.solvePosition += p.solvePosition;
      total.solveTOI += p.solveTOI;
      total.broadphase += p.broadphase;
    }

    if (settings.drawProfile && backend !== null) {
      this.m_debugDraw.DrawString(5, this.m_textLine, 'profile: the JavaScript engine times its stages; the GPU step is one submission');
      this.m_textLine += 15;
    } else if (settings.drawProfile) {
      const p = this.m_world.GetProfile();

      const aveProfile = new b2Profile();
      if (this.m_stepCount > 0) {
        const scale = 1.0 / this.m_stepCount;
        const total = this.m_totalProfile;
        aveProfile.step = scale * total.step;
        aveProfile.collide = scale * total.collide;
        aveProfile.solve = scale * total.solve;
        aveProfile.solveInit = scale * total.solveInit;
        aveProfile.solveVelocity = scale * total.solveVelocity;
        aveProfile.solvePosition = scale * total.solvePosition;
        aveProfile.solveTOI = scale * total.solveTOI;
        aveProfile.broadphase = scale * total.broadphase;
      }

      const max = this.m_maxProfile;
      const line = (label: string, current: number, ave: number, maximum: number) => {
        this.m_debugDraw.DrawString(5, this.m_textLine, `${label} [ave] (max) = %5.2f [%6.2f] (%6.2f)`, current, ave, maximum);
        this.m_textLine += 15;
      };
      line('step', p.step, aveProfile.step, max.step);
      line('collide', p.collide, aveProfile.collide, max.collide);
      line('solve', p.solve, aveProfile.solve, max.solve);
      line('solve init', p.solveInit, aveProfile.solveInit, max.solveInit);
      line('solve velocity', p.solveVelocity, aveProfile.solveVelocity, max.solveVelocity);
      line('solve position', p.solvePosition, aveProfile.solvePosition, max.solvePosition);
      line('solveTOI', p.solveTOI, aveProfile.solveTOI, max.solveTOI);
      line('broad-phase', p.broadphase, aveProfile.broadphase, max.broadphase);
    }

    if (this.m_mouseJoint !== null) {
      const p1 = this.m_mouseJoint.GetAnchorB(new b2Vec2());
      const p2 = this.m_mouseJoint.GetTarget();

      const c = new b2Color();
      c.Set(0.0, 1.0, 0.0);
      this.m_debugDraw.DrawPoint(p1, 4.0, c);
      this.m_debugDraw.DrawPoint(p2, 4.0, c);

      c.Set(0.8, 0.8, 0.8);
      this.m_debugDraw.DrawSegment(p1, p2, c);
    }

    if (this.m_bombSpawning) {
      const c = new b2Color();
      c.Set(0.0, 0.0, 1.0);
      this.m_debugDraw.DrawPoint(this.m_bombSpawnPoint, 4.0, c);

      c.Set(0.8, 0.8, 0.8);
      this.m_debugDraw.DrawSegment(this.m_mouseWorld, this.m_bombSpawnPoint, c);
    }

    if (settings.drawContactPoints) {
      const k_impulseScale = 0.1;
      const k_axisScale = 0.3;
      const p2 = new b2Vec2();

      for (let i = 0; i < this.m_pointCount; ++i) {
        const point = this.m_points[i];

        if (point.state === b2PointState.b2_addState) {
          // Add
          this.m_debugDraw.DrawPoint(point.position, 10.0, new b2Color(0.3, 0.95, 0.3));
        } else if (point.state === b2PointState.b2_persistState) {
          // Persist
          this.m_debugDraw.DrawPoint(point.position, 5.0, new b2Color(0.3, 0.3, 0.95));
        }

        if (settings.drawContactNormals === 1) {
          const p1 = point.position;
          p2.Set(p1.x + k_axisScale * point.normal.x, p1.y + k_axisScale * point.normal.y);
          this.m_debugDraw.DrawSegment(p1, p2, new b2Color(0.9, 0.9, 0.9));
        } else if (settings.drawContactForces === 1) {
          // 2.2.1 leaves this commented out; this is Box2D 2.3's completion of it.
          const p1 = point.position;
          p2.Set(p1.x + k_impulseScale * point.normalImpulse * point.normal.x, p1.y + k_impulseScale * point.normalImpulse * point.normal.y);
          this.m_debugDraw.DrawSegment(p1, p2, new b2Color(0.9, 0.9, 0.3));
        }

        if (settings.drawFrictionForces === 1) {
          // tangent = b2Cross(normal, 1.0) = (normal.y, -normal.x); as drawContactForces.
          const p1 = point.position;
          p2.Set(p1.x + k_impulseScale * point.tangentImpulse * point.normal.y, p1.y - k_impulseScale * point.tangentImpulse * point.normal.x);
          this.m_debugDraw.DrawSegment(p1, p2, new b2Color(0.9, 0.9, 0.3));
        }
      }
    }
  }

  /**
   * e_pairBit: b2World::DrawDebugData of 2.2.1 has this code commented out (a segment between the
   * centres of the two fixtures' AABBs of every contact); the testbed draws it.
   */
  private DrawPairs(): void {
    const color = new b2Color(0.3, 0.9, 0.9);
    const cA = new b2Vec2();
    const cB = new b2Vec2();
    for (let c = this.m_world.GetContactList(); c !== null; c = c.GetNext()) {
      const aabbA = c.GetFixtureA().GetAABB(c.GetChildIndexA());
      const aabbB = c.GetFixtureB().GetAABB(c.GetChildIndexB());
      cA.Set(0.5 * (aabbA.lowerBound.x + aabbA.upperBound.x), 0.5 * (aabbA.lowerBound.y + aabbA.upperBound.y));
      cB.Set(0.5 * (aabbB.lowerBound.x + aabbB.upperBound.x), 0.5 * (aabbB.lowerBound.y + aabbB.upperBound.y));
      this.m_debugDraw.DrawSegment(cA, cB, color);
    }
  }

  /**
   * Where the view starts when the test is selected: null for the Testbed's (0, 20) at zoom 1.
   * The benchmark and file scenes frame themselves.
   */
  InitialView(): { x: number; y: number; zoom: number } | null {
    return null;
  }

  /** Step settings the scene comes with (a b2dJson file's, a benchmark's), applied when selected. */
  StepSettingsOverride(): Partial<StepSettings> | null {
    return null;
  }
}

/** A test's constructor, as TestEntries.cpp's createFcn. */
export type TestCreateFcn = () => Test;

export interface TestEntry {
  /** The name in the test list (TestEntries.cpp's, for the Testbed's tests). */
  name: string;
  createFcn: TestCreateFcn;
  /** Which group of the list: the 2.2.1 Testbed's, the benchmark scenes, or loaded files. */
  group?: 'Testbed' | 'Benchmarks' | 'Files';
}
