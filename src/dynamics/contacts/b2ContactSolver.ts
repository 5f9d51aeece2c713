/*
 * The contact constraint solver (b2ContactSolver.h, b2ContactSolver.cpp).
 *
 * The C++ builds a solver per island on the stack allocator. Here the constructor's work is in
 * Initialize(def), so one solver can be re-initialised for every island; its constraint storage
 * grows to the largest island seen and is reused, and the hot loops work on scalar locals in the
 * exact operation order of the C++ vector expressions. The constraints live in typed arrays (see
 * VcF below); the C++ structs remain as the classes below, which m_velocityConstraints and
 * m_positionConstraints fill on demand.
 */

import { b2Manifold } from '../../collision/b2Collision';
import { b2ManifoldField, b2ManifoldPointField } from '../../collision/b2ManifoldRecord';
import { b2MakeArray } from '../../common/b2MakeArray';
import { b2Clamp, b2Mat22, b2Max, b2Min, b2MulRV, b2MulXV, b2Rot, b2SubVV, b2Vec2 } from '../../common/b2Math';
import type { b2Transform } from '../../common/b2Math';
import {
  b2Assert,
  b2_baumgarte,
  b2_epsilon,
  b2_linearSlop,
  b2_maxLinearCorrection,
  b2_maxManifoldPoints,
  b2_toiBaugarte,
  b2_velocityThreshold,
} from '../../common/b2Settings';
import { b2TimeStep } from '../b2TimeStep';
import type { b2ContactImpulse } from '../b2WorldCallbacks';
import type { b2Contact } from './b2Contact';

export class b2VelocityConstraintPoint {
  readonly rA = new b2Vec2();
  readonly rB = new b2Vec2();
  normalImpulse = 0.0;
  tangentImpulse = 0.0;
  normalMass = 0.0;
  tangentMass = 0.0;
  velocityBias = 0.0;
}

export class b2ContactVelocityConstraint {
  readonly points: b2VelocityConstraintPoint[] = b2MakeArray(b2_maxManifoldPoints, () => new b2VelocityConstraintPoint());
  readonly normal = new b2Vec2();
  readonly normalMass = new b2Mat22();
  readonly K = new b2Mat22();
  indexA = 0;
  indexB = 0;
  invMassA = 0.0;
  invMassB = 0.0;
  invIA = 0.0;
  invIB = 0.0;
  friction = 0.0;
  restitution = 0.0;
  pointCount = 0;
  contactIndex = 0;
}

export class b2ContactPositionConstraint {
  readonly localPoints: b2Vec2[] = b2MakeArray(b2_maxManifoldPoints, () => new b2Vec2());
  readonly localNormal = new b2Vec2();
  readonly localPoint = new b2Vec2();
  indexA = 0;
  indexB = 0;
  invMassA = 0.0;
  invMassB = 0.0;
  readonly localCenterA = new b2Vec2();
  readonly localCenterB = new b2Vec2();
  invIA = 0.0;
  invIB = 0.0;
  type: number = b2Manifold.e_circles;
  radiusA = 0.0;
  radiusB = 0.0;
  pointCount = 0;
}

/**
 * The island's data for one solve. `contacts`, `positions` and `velocities` are shared by
 * reference (the C++ passes pointers); the solver copies `step`. `positions` and `velocities`
 * hold b2Position and b2Velocity records, three doubles a body (see b2SolverData).
 */
export class b2ContactSolverDef {
  step = new b2TimeStep();
  contacts: b2Contact[] = [];
  count = 0;
  positions = new Float64Array(0);
  velocities = new Float64Array(0);
}

export class b2PositionSolverManifold {
  readonly normal = new b2Vec2();
  readonly point = new b2Vec2();
  separation = 0.0;

  Initialize(pc: b2ContactPositionConstraint, xfA: b2Transform, xfB: b2Transform, index: number): void {
    b2Assert(pc.pointCount > 0);

    switch (pc.type) {
      case b2Manifold.e_circles: {
        const pointA = b2MulXV(xfA, pc.localPoint, s_pointA);
        const pointB = b2MulXV(xfB, pc.localPoints[0], s_pointB);
        const normal = b2SubVV(pointB, pointA, this.normal);
        normal.Normalize();
        this.point.x = 0.5 * (pointA.x + pointB.x);
        this.point.y = 0.5 * (pointA.y + pointB.y);
        this.separation = (pointB.x - pointA.x) * normal.x + (pointB.y - pointA.y) * normal.y - pc.radiusA - pc.radiusB;
        break;
      }

      case b2Manifold.e_faceA: {
        const normal = b2MulRV(xfA.q, pc.localNormal, this.normal);
        const planePoint = b2MulXV(xfA, pc.localPoint, s_planePoint);

        const clipPoint = b2MulXV(xfB, pc.localPoints[index], s_clipPoint);
        this.separation = (clipPoint.x - planePoint.x) * normal.x + (clipPoint.y - planePoint.y) * normal.y - pc.radiusA - pc.radiusB;
        this.point.Assign(clipPoint);
        break;
      }

      case b2Manifold.e_faceB: {
        const normal = b2MulRV(xfB.q, pc.localNormal, this.normal);
        const planePoint = b2MulXV(xfB, pc.localPoint, s_planePoint);

        const clipPoint = b2MulXV(xfA, pc.localPoints[index], s_clipPoint);
        this.separation = (clipPoint.x - planePoint.x) * normal.x + (clipPoint.y - planePoint.y) * normal.y - pc.radiusA - pc.radiusB;
        this.point.Assign(clipPoint);

        // Ensure normal points from A to B
        normal.x = -normal.x;
        normal.y = -normal.y;
        break;
      }
    }
  }
}

const s_pointA = new b2Vec2();
const s_pointB = new b2Vec2();
const s_planePoint = new b2Vec2();
const s_clipPoint = new b2Vec2();
const s_qA = new b2Rot();
const s_qB = new b2Rot();

/*
 * Constraint storage. The solver keeps its constraints in typed arrays, one fixed-size record per
 * constraint, instead of the b2ContactVelocityConstraint and b2ContactPositionConstraint objects
 * the C++ declares: V8 boxes every double held in an object field, so a constraint object is some
 * thirty small heap objects, and the solver's passes over them were bound by memory latency. The
 * records hold the same values under the same names; m_velocityConstraints and
 * m_positionConstraints present them as those objects (see there). The offsets are const enums,
 * which esbuild and TypeScript inline as literals.
 */

/** Doubles of a velocity constraint record in m_vcFloats. */
const enum VcF {
  normalX = 0,
  normalY = 1,
  // normalMass and K, column-major as b2Mat22: ex.x, ex.y, ey.x, ey.y
  normalMassExX = 2,
  normalMassExY = 3,
  normalMassEyX = 4,
  normalMassEyY = 5,
  KExX = 6,
  KExY = 7,
  KEyX = 8,
  KEyY = 9,
  invMassA = 10,
  invMassB = 11,
  invIA = 12,
  invIB = 13,
  friction = 14,
  restitution = 15,
  /** The first point's record (VcP); the second follows it. */
  points = 16,
  stride = 16 + 2 * 9,
}

/** Doubles of a velocity constraint point (b2VelocityConstraintPoint), from VcF.points. */
const enum VcP {
  rAx = 0,
  rAy = 1,
  rBx = 2,
  rBy = 3,
  normalImpulse = 4,
  tangentImpulse = 5,
  normalMass = 6,
  tangentMass = 7,
  velocityBias = 8,
  stride = 9,
}

/** Integers of a velocity constraint record in m_vcInts. */
const enum VcI {
  indexA = 0,
  indexB = 1,
  pointCount = 2,
  contactIndex = 3,
  manifoldOffset = 4,
  stride = 5,
}

/** Doubles of a position constraint record in m_pcFloats. */
const enum PcF {
  localPoint0X = 0,
  localPoint0Y = 1,
  localPoint1X = 2,
  localPoint1Y = 3,
  localNormalX = 4,
  localNormalY = 5,
  localPointX = 6,
  localPointY = 7,
  invMassA = 8,
  invMassB = 9,
  localCenterAX = 10,
  localCenterAY = 11,
  localCenterBX = 12,
  localCenterBY = 13,
  invIA = 14,
  invIB = 15,
  radiusA = 16,
  radiusB = 17,
  stride = 18,
}

/** Integers of a position constraint record in m_pcInts. */
const enum PcI {
  indexA = 0,
  indexB = 1,
  type = 2,
  pointCount = 3,
  stride = 4,
}

/**
 * Masks applied where the loops compute a record offset or read a body index or point count
 * (`(i * VcF.stride) & Mask.offset`). They tell V8 that `o + field` and `3 * index + 2` fit in 32
 * bits, so it leaves out the overflow check it otherwise puts on each of the hundred-odd typed
 * array reads and writes a contact makes per pass. They change no value: Initialize refuses an
 * island whose records or bodies would reach them, and a manifold has at most two points.
 */
const enum Mask {
  offset = 0x3fffffff,
  index = 0x0fffffff,
  pointCount = 3,
}

// The records have room for two points.
b2Assert(b2_maxManifoldPoints === 2);

export class b2ContactSolver {
  readonly m_step = new b2TimeStep();
  /** b2Position and b2Velocity records, three doubles a body (see b2SolverData). */
  m_positions = new Float64Array(0);
  m_velocities = new Float64Array(0);
  m_contacts: b2Contact[] = [];
  m_count = 0;

  /** The constraint records (see VcF, VcI, PcF, PcI); grown to the largest island seen. */
  m_vcFloats = new Float64Array(0);
  m_vcInts = new Int32Array(0);
  m_pcFloats = new Float64Array(0);
  m_pcInts = new Int32Array(0);
  private m_capacity = 0;
  /**
   * Constraint i's manifold record (its offset is VcI.manifoldOffset), so StoreImpulses writes the
   * impulses back without reading the contact and its manifold, two objects elsewhere in memory.
   */
  private readonly m_manifoldRecords: Float64Array[] = [];

  /**
   * Per island body: the last angle whose rotation was computed, and its sine and cosine (three
   * doubles a body). xf.q.Set(a) is a pure function of a, so a body whose angle has not changed
   * since (its other contacts, the static ground, a resting body in the position solver) reuses
   * the value instead of running sin and cos again. Starts at NaN, which matches no angle.
   */
  private m_rotCache = new Float64Array(0);

  // The objects m_velocityConstraints and m_positionConstraints return, kept for their identity.
  private readonly m_velocityConstraintViews: b2ContactVelocityConstraint[] = [];
  private readonly m_positionConstraintViews: b2ContactPositionConstraint[] = [];

  constructor(def?: b2ContactSolverDef) {
    if (def) {
      this.Initialize(def);
    }
  }

  /**
   * The velocity constraints of the current island as the C++ objects: the first m_count entries
   * are filled from the records on every read (the solver itself never reads them). Grown to the
   * largest island seen; an entry keeps its identity across islands. Writing to them does not
   * change the solver.
   */
  get m_velocityConstraints(): readonly b2ContactVelocityConstraint[] {
    const views = this.m_velocityConstraintViews;
    while (views.length < this.m_count) {
      views.push(new b2ContactVelocityConstraint());
    }
    const f = this.m_vcFloats;
    const n = this.m_vcInts;
    for (let i = 0; i < this.m_count; ++i) {
      const vc = views[i];
      const o = i * VcF.stride;
      const oi = i * VcI.stride;
      vc.normal.Set(f[o + VcF.normalX], f[o + VcF.normalY]);
      vc.normalMass.ex.Set(f[o + VcF.normalMassExX], f[o + VcF.normalMassExY]);
      vc.normalMass.ey.Set(f[o + VcF.normalMassEyX], f[o + VcF.normalMassEyY]);
      vc.K.ex.Set(f[o + VcF.KExX], f[o + VcF.KExY]);
      vc.K.ey.Set(f[o + VcF.KEyX], f[o + VcF.KEyY]);
      vc.invMassA = f[o + VcF.invMassA];
      vc.invMassB = f[o + VcF.invMassB];
      vc.invIA = f[o + VcF.invIA];
      vc.invIB = f[o + VcF.invIB];
      vc.friction = f[o + VcF.friction];
      vc.restitution = f[o + VcF.restitution];
      vc.indexA = n[oi + VcI.indexA];
      vc.indexB = n[oi + VcI.indexB];
      vc.pointCount = n[oi + VcI.pointCount];
      vc.contactIndex = n[oi + VcI.contactIndex];
      for (let j = 0; j < b2_maxManifoldPoints; ++j) {
        const vcp = vc.points[j];
        const op = o + VcF.points + j * VcP.stride;
        vcp.rA.Set(f[op + VcP.rAx], f[op + VcP.rAy]);
        vcp.rB.Set(f[op + VcP.rBx], f[op + VcP.rBy]);
        vcp.normalImpulse = f[op + VcP.normalImpulse];
        vcp.tangentImpulse = f[op + VcP.tangentImpulse];
        vcp.normalMass = f[op + VcP.normalMass];
        vcp.tangentMass = f[op + VcP.tangentMass];
        vcp.velocityBias = f[op + VcP.velocityBias];
      }
    }
    return views;
  }

  /** The position constraints of the current island as the C++ objects; see m_velocityConstraints. */
  get m_positionConstraints(): readonly b2ContactPositionConstraint[] {
    const views = this.m_positionConstraintViews;
    while (views.length < this.m_count) {
      views.push(new b2ContactPositionConstraint());
    }
    const f = this.m_pcFloats;
    const n = this.m_pcInts;
    for (let i = 0; i < this.m_count; ++i) {
      const pc = views[i];
      const o = i * PcF.stride;
      const oi = i * PcI.stride;
      pc.localPoints[0].Set(f[o + PcF.localPoint0X], f[o + PcF.localPoint0Y]);
      pc.localPoints[1].Set(f[o + PcF.localPoint1X], f[o + PcF.localPoint1Y]);
      pc.localNormal.Set(f[o + PcF.localNormalX], f[o + PcF.localNormalY]);
      pc.localPoint.Set(f[o + PcF.localPointX], f[o + PcF.localPointY]);
      pc.invMassA = f[o + PcF.invMassA];
      pc.invMassB = f[o + PcF.invMassB];
      pc.localCenterA.Set(f[o + PcF.localCenterAX], f[o + PcF.localCenterAY]);
      pc.localCenterB.Set(f[o + PcF.localCenterBX], f[o + PcF.localCenterBY]);
      pc.invIA = f[o + PcF.invIA];
      pc.invIB = f[o + PcF.invIB];
      pc.radiusA = f[o + PcF.radiusA];
      pc.radiusB = f[o + PcF.radiusB];
      pc.indexA = n[oi + PcI.indexA];
      pc.indexB = n[oi + PcI.indexB];
      pc.type = n[oi + PcI.type];
      pc.pointCount = n[oi + PcI.pointCount];
    }
    return views;
  }

  /** The C++ constructor: set up the solver for an island, reusing the constraint storage. */
  Initialize(def: b2ContactSolverDef): this {
    b2Assert(def.count * VcF.stride <= Mask.offset && def.positions.length / 3 <= Mask.index, 'island too large');
    this.m_step.Assign(def.step);
    this.m_count = def.count;
    if (this.m_capacity < this.m_count) {
      // The old records are dead (every island rewrites its own), so nothing is copied.
      const capacity = b2Max(this.m_count, 2 * this.m_capacity);
      this.m_vcFloats = new Float64Array(capacity * VcF.stride);
      this.m_vcInts = new Int32Array(capacity * VcI.stride);
      this.m_pcFloats = new Float64Array(capacity * PcF.stride);
      this.m_pcInts = new Int32Array(capacity * PcI.stride);
      this.m_capacity = capacity;
    }
    this.m_positions = def.positions;
    this.m_velocities = def.velocities;
    this.m_contacts = def.contacts;
    if (this.m_rotCache.length < this.m_positions.length) {
      this.m_rotCache = new Float64Array(this.m_positions.length).fill(NaN);
    }

    const vf = this.m_vcFloats;
    const vi = this.m_vcInts;
    const pf = this.m_pcFloats;
    const pi = this.m_pcInts;
    const warmStarting = this.m_step.warmStarting;
    const dtRatio = this.m_step.dtRatio;

    // Initialize position independent portions of the constraints.
    for (let i = 0; i < this.m_count; ++i) {
      const contact = this.m_contacts[i];

      const fixtureA = contact.m_fixtureA;
      const fixtureB = contact.m_fixtureB;
      const shapeA = fixtureA.GetShape();
      const shapeB = fixtureB.GetShape();
      const radiusA = shapeA.m_radius;
      const radiusB = shapeB.m_radius;
      const bodyA = fixtureA.GetBody();
      const bodyB = fixtureB.GetBody();
      const manifold = contact.GetManifold();

      const pointCount = manifold.pointCount;
      b2Assert(pointCount > 0);

      const o = (i * VcF.stride) & Mask.offset;
      const oi = (i * VcI.stride) & Mask.offset;
      const record = manifold.m_record;
      const mo = manifold.m_offset;
      vf[o + VcF.friction] = record[mo + b2ManifoldField.friction];
      vf[o + VcF.restitution] = record[mo + b2ManifoldField.restitution];
      vi[oi + VcI.indexA] = bodyA.m_islandIndex;
      vi[oi + VcI.indexB] = bodyB.m_islandIndex;
      vf[o + VcF.invMassA] = bodyA.m_invMass;
      vf[o + VcF.invMassB] = bodyB.m_invMass;
      vf[o + VcF.invIA] = bodyA.m_invI;
      vf[o + VcF.invIB] = bodyB.m_invI;
      vi[oi + VcI.contactIndex] = i;
      vi[oi + VcI.manifoldOffset] = mo;
      this.m_manifoldRecords[i] = record;
      vi[oi + VcI.pointCount] = pointCount;
      vf[o + VcF.KExX] = 0.0;
      vf[o + VcF.KEyX] = 0.0;
      vf[o + VcF.KExY] = 0.0;
      vf[o + VcF.KEyY] = 0.0;
      vf[o + VcF.normalMassExX] = 0.0;
      vf[o + VcF.normalMassEyX] = 0.0;
      vf[o + VcF.normalMassExY] = 0.0;
      vf[o + VcF.normalMassEyY] = 0.0;

      const q = (i * PcF.stride) & Mask.offset;
      const qi = (i * PcI.stride) & Mask.offset;
      pi[qi + PcI.indexA] = bodyA.m_islandIndex;
      pi[qi + PcI.indexB] = bodyB.m_islandIndex;
      pf[q + PcF.invMassA] = bodyA.m_invMass;
      pf[q + PcF.invMassB] = bodyB.m_invMass;
      const localCenterA = bodyA.m_sweep.localCenter;
      const localCenterB = bodyB.m_sweep.localCenter;
      pf[q + PcF.localCenterAX] = localCenterA.x;
      pf[q + PcF.localCenterAY] = localCenterA.y;
      pf[q + PcF.localCenterBX] = localCenterB.x;
      pf[q + PcF.localCenterBY] = localCenterB.y;
      pf[q + PcF.invIA] = bodyA.m_invI;
      pf[q + PcF.invIB] = bodyB.m_invI;
      pf[q + PcF.localNormalX] = record[mo + b2ManifoldField.localNormalX];
      pf[q + PcF.localNormalY] = record[mo + b2ManifoldField.localNormalY];
      pf[q + PcF.localPointX] = record[mo + b2ManifoldField.localPointX];
      pf[q + PcF.localPointY] = record[mo + b2ManifoldField.localPointY];
      pi[qi + PcI.pointCount] = pointCount;
      pf[q + PcF.radiusA] = radiusA;
      pf[q + PcF.radiusB] = radiusB;
      pi[qi + PcI.type] = manifold.type;

      for (let j = 0; j < pointCount; ++j) {
        const mp = mo + b2ManifoldField.points + j * b2ManifoldPointField.stride;
        const op = o + VcF.points + j * VcP.stride;

        if (warmStarting) {
          vf[op + VcP.normalImpulse] = dtRatio * record[mp + b2ManifoldPointField.normalImpulse];
          vf[op + VcP.tangentImpulse] = dtRatio * record[mp + b2ManifoldPointField.tangentImpulse];
        } else {
          vf[op + VcP.normalImpulse] = 0.0;
          vf[op + VcP.tangentImpulse] = 0.0;
        }

        vf[op + VcP.rAx] = 0.0;
        vf[op + VcP.rAy] = 0.0;
        vf[op + VcP.rBx] = 0.0;
        vf[op + VcP.rBy] = 0.0;
        vf[op + VcP.normalMass] = 0.0;
        vf[op + VcP.tangentMass] = 0.0;
        vf[op + VcP.velocityBias] = 0.0;

        pf[q + PcF.localPoint0X + 2 * j] = record[mp + b2ManifoldPointField.localPointX];
        pf[q + PcF.localPoint0Y + 2 * j] = record[mp + b2ManifoldPointField.localPointY];
      }
    }
    return this;
  }

  /**
   * rot.Set(angle) for the island body `index`, through m_rotCache. The cached angle must be the
   * same double: === alone would take -0 for +0, whose sines differ in sign.
   */
  private SetRot(index: number, angle: number, rot: b2Rot): void {
    const cache = this.m_rotCache;
    const o = 3 * index;
    const cached = cache[o];
    if (angle === cached && (angle !== 0.0 || 1.0 / angle === 1.0 / cached)) {
      rot.s = cache[o + 1];
      rot.c = cache[o + 2];
    } else {
      rot.Set(angle);
      cache[o] = angle;
      cache[o + 1] = rot.s;
      cache[o + 2] = rot.c;
    }
  }

  /**
   * Initialize position dependent portions of the velocity constraints. The world manifold
   * (b2WorldManifold.Initialize, the same operations) is computed from the position constraint's
   * copy of the manifold, which Initialize took and nothing has changed since.
   */
  InitializeVelocityConstraints(): void {
    const vf = this.m_vcFloats;
    const vi = this.m_vcInts;
    const pf = this.m_pcFloats;
    const pi = this.m_pcInts;
    const positions = this.m_positions;
    const velocities = this.m_velocities;
    const qA = s_qA;
    const qB = s_qB;

    for (let i = 0; i < this.m_count; ++i) {
      const o = (i * VcF.stride) & Mask.offset;
      const oi = (i * VcI.stride) & Mask.offset;
      // The position constraint i holds the copy of contact i's manifold (vc.contactIndex is i).
      const q = (i * PcF.stride) & Mask.offset;
      const qi = (i * PcI.stride) & Mask.offset;

      const radiusA = pf[q + PcF.radiusA];
      const radiusB = pf[q + PcF.radiusB];
      const manifoldPointCount = pi[qi + PcI.pointCount] & Mask.pointCount;

      const indexA = vi[oi + VcI.indexA] & Mask.index;
      const indexB = vi[oi + VcI.indexB] & Mask.index;

      const mA = vf[o + VcF.invMassA];
      const mB = vf[o + VcF.invMassB];
      const iA = vf[o + VcF.invIA];
      const iB = vf[o + VcF.invIB];
      const localCenterAX = pf[q + PcF.localCenterAX];
      const localCenterAY = pf[q + PcF.localCenterAY];
      const localCenterBX = pf[q + PcF.localCenterBX];
      const localCenterBY = pf[q + PcF.localCenterBY];

      const cAx = positions[3 * indexA];
      const cAy = positions[3 * indexA + 1];
      const aA = positions[3 * indexA + 2];
      const vAx = velocities[3 * indexA];
      const vAy = velocities[3 * indexA + 1];
      const wA = velocities[3 * indexA + 2];

      const cBx = positions[3 * indexB];
      const cBy = positions[3 * indexB + 1];
      const aB = positions[3 * indexB + 2];
      const vBx = velocities[3 * indexB];
      const vBy = velocities[3 * indexB + 1];
      const wB = velocities[3 * indexB + 2];

      b2Assert(manifoldPointCount > 0);

      // xfA.q.Set(aA); xfA.p = cA - b2Mul(xfA.q, localCenterA); likewise xfB.
      this.SetRot(indexA, aA, qA);
      this.SetRot(indexB, aB, qB);
      const qAs = qA.s;
      const qAc = qA.c;
      const qBs = qB.s;
      const qBc = qB.c;
      const xfApx = cAx - (qAc * localCenterAX - qAs * localCenterAY);
      const xfApy = cAy - (qAs * localCenterAX + qAc * localCenterAY);
      const xfBpx = cBx - (qBc * localCenterBX - qBs * localCenterBY);
      const xfBpy = cBy - (qBs * localCenterBX + qBc * localCenterBY);

      // worldManifold.Initialize(manifold, xfA, radiusA, xfB, radiusB)
      let normalX: number;
      let normalY: number;
      let point0X = 0.0;
      let point0Y = 0.0;
      let point1X = 0.0;
      let point1Y = 0.0;
      switch (pi[qi + PcI.type]) {
        case b2Manifold.e_circles: {
          normalX = 1.0;
          normalY = 0.0;
          const lpx = pf[q + PcF.localPointX];
          const lpy = pf[q + PcF.localPointY];
          const pointAx = qAc * lpx - qAs * lpy + xfApx;
          const pointAy = qAs * lpx + qAc * lpy + xfApy;
          const l0x = pf[q + PcF.localPoint0X];
          const l0y = pf[q + PcF.localPoint0Y];
          const pointBx = qBc * l0x - qBs * l0y + xfBpx;
          const pointBy = qBs * l0x + qBc * l0y + xfBpy;
          const dx = pointAx - pointBx;
          const dy = pointAy - pointBy;
          if (dx * dx + dy * dy > b2_epsilon * b2_epsilon) {
            normalX = pointBx - pointAx;
            normalY = pointBy - pointAy;
            // normal.Normalize()
            const length = Math.sqrt(normalX * normalX + normalY * normalY);
            if (!(length < b2_epsilon)) {
              const invLength = 1.0 / length;
              normalX *= invLength;
              normalY *= invLength;
            }
          }

          const cAX = pointAx + radiusA * normalX;
          const cAY = pointAy + radiusA * normalY;
          const cBX = pointBx - radiusB * normalX;
          const cBY = pointBy - radiusB * normalY;
          point0X = 0.5 * (cAX + cBX);
          point0Y = 0.5 * (cAY + cBY);
          break;
        }

        case b2Manifold.e_faceA: {
          const lnx = pf[q + PcF.localNormalX];
          const lny = pf[q + PcF.localNormalY];
          normalX = qAc * lnx - qAs * lny;
          normalY = qAs * lnx + qAc * lny;
          const lpx = pf[q + PcF.localPointX];
          const lpy = pf[q + PcF.localPointY];
          const planePointX = qAc * lpx - qAs * lpy + xfApx;
          const planePointY = qAs * lpx + qAc * lpy + xfApy;

          for (let j = 0; j < manifoldPointCount; ++j) {
            const lx = pf[q + PcF.localPoint0X + 2 * j];
            const ly = pf[q + PcF.localPoint0Y + 2 * j];
            const clipPointX = qBc * lx - qBs * ly + xfBpx;
            const clipPointY = qBs * lx + qBc * ly + xfBpy;
            const k = radiusA - ((clipPointX - planePointX) * normalX + (clipPointY - planePointY) * normalY);
            const cAX = clipPointX + k * normalX;
            const cAY = clipPointY + k * normalY;
            const cBX = clipPointX - radiusB * normalX;
            const cBY = clipPointY - radiusB * normalY;
            if (j === 0) {
              point0X = 0.5 * (cAX + cBX);
              point0Y = 0.5 * (cAY + cBY);
            } else {
              point1X = 0.5 * (cAX + cBX);
              point1Y = 0.5 * (cAY + cBY);
            }
          }
          break;
        }

        default: {
          // b2Manifold.e_faceB
          const lnx = pf[q + PcF.localNormalX];
          const lny = pf[q + PcF.localNormalY];
          normalX = qBc * lnx - qBs * lny;
          normalY = qBs * lnx + qBc * lny;
          const lpx = pf[q + PcF.localPointX];
          const lpy = pf[q + PcF.localPointY];
          const planePointX = qBc * lpx - qBs * lpy + xfBpx;
          const planePointY = qBs * lpx + qBc * lpy + xfBpy;

          for (let j = 0; j < manifoldPointCount; ++j) {
            const lx = pf[q + PcF.localPoint0X + 2 * j];
            const ly = pf[q + PcF.localPoint0Y + 2 * j];
            const clipPointX = qAc * lx - qAs * ly + xfApx;
            const clipPointY = qAs * lx + qAc * ly + xfApy;
            const k = radiusB - ((clipPointX - planePointX) * normalX + (clipPointY - planePointY) * normalY);
            const cBX = clipPointX + k * normalX;
            const cBY = clipPointY + k * normalY;
            const cAX = clipPointX - radiusA * normalX;
            const cAY = clipPointY - radiusA * normalY;
            if (j === 0) {
              point0X = 0.5 * (cAX + cBX);
              point0Y = 0.5 * (cAY + cBY);
            } else {
              point1X = 0.5 * (cAX + cBX);
              point1Y = 0.5 * (cAY + cBY);
            }
          }

          // Ensure normal points from A to B.
          normalX = -normalX;
          normalY = -normalY;
          break;
        }
      }

      vf[o + VcF.normalX] = normalX;
      vf[o + VcF.normalY] = normalY;
      // tangent = b2Cross(normal, 1.0) = (normal.y, -normal.x), exactly
      const tangentX = normalY;
      const tangentY = -normalX;
      const restitution = vf[o + VcF.restitution];

      const pointCount = vi[oi + VcI.pointCount] & Mask.pointCount;
      for (let j = 0; j < pointCount; ++j) {
        const op = o + VcF.points + j * VcP.stride;
        const pointX = j === 0 ? point0X : point1X;
        const pointY = j === 0 ? point0Y : point1Y;
        const rAx = pointX - cAx;
        const rAy = pointY - cAy;
        const rBx = pointX - cBx;
        const rBy = pointY - cBy;
        vf[op + VcP.rAx] = rAx;
        vf[op + VcP.rAy] = rAy;
        vf[op + VcP.rBx] = rBx;
        vf[op + VcP.rBy] = rBy;

        const rnA = rAx * normalY - rAy * normalX;
        const rnB = rBx * normalY - rBy * normalX;

        const kNormal = mA + mB + iA * rnA * rnA + iB * rnB * rnB;

        vf[op + VcP.normalMass] = kNormal > 0.0 ? 1.0 / kNormal : 0.0;

        const rtA = rAx * tangentY - rAy * tangentX;
        const rtB = rBx * tangentY - rBy * tangentX;

        const kTangent = mA + mB + iA * rtA * rtA + iB * rtB * rtB;

        vf[op + VcP.tangentMass] = kTangent > 0.0 ? 1.0 / kTangent : 0.0;

        // Setup a velocity bias for restitution.
        let velocityBias = 0.0;
        const dvX = vBx + -wB * rBy - vAx - -wA * rAy;
        const dvY = vBy + wB * rBx - vAy - wA * rAx;
        const vRel = normalX * dvX + normalY * dvY;
        if (vRel < -b2_velocityThreshold) {
          velocityBias = -restitution * vRel;
        }
        vf[op + VcP.velocityBias] = velocityBias;
      }

      // If we have two points, then prepare the block solver.
      if (pointCount === 2) {
        const op1 = o + VcF.points;
        const op2 = op1 + VcP.stride;

        const rn1A = vf[op1 + VcP.rAx] * normalY - vf[op1 + VcP.rAy] * normalX;
        const rn1B = vf[op1 + VcP.rBx] * normalY - vf[op1 + VcP.rBy] * normalX;
        const rn2A = vf[op2 + VcP.rAx] * normalY - vf[op2 + VcP.rAy] * normalX;
        const rn2B = vf[op2 + VcP.rBx] * normalY - vf[op2 + VcP.rBy] * normalX;

        const k11 = mA + mB + iA * rn1A * rn1A + iB * rn1B * rn1B;
        const k22 = mA + mB + iA * rn2A * rn2A + iB * rn2B * rn2B;
        const k12 = mA + mB + iA * rn1A * rn2A + iB * rn1B * rn2B;

        // Ensure a reasonable condition number.
        const k_maxConditionNumber = 1000.0;
        if (k11 * k11 < k_maxConditionNumber * (k11 * k22 - k12 * k12)) {
          // K is safe to invert.
          vf[o + VcF.KExX] = k11;
          vf[o + VcF.KExY] = k12;
          vf[o + VcF.KEyX] = k12;
          vf[o + VcF.KEyY] = k22;
          // normalMass = K.GetInverse()
          let det = k11 * k22 - k12 * k12;
          if (det !== 0.0) {
            det = 1.0 / det;
          }
          vf[o + VcF.normalMassExX] = det * k22;
          vf[o + VcF.normalMassEyX] = -det * k12;
          vf[o + VcF.normalMassExY] = -det * k12;
          vf[o + VcF.normalMassEyY] = det * k11;
        } else {
          // The constraints are redundant, just use one.
          // TODO_ERIN use deepest?
          vi[oi + VcI.pointCount] = 1;
        }
      }
    }
  }

  WarmStart(): void {
    const vf = this.m_vcFloats;
    const vi = this.m_vcInts;
    const velocities = this.m_velocities;

    // Warm start.
    for (let i = 0; i < this.m_count; ++i) {
      const o = (i * VcF.stride) & Mask.offset;
      const oi = (i * VcI.stride) & Mask.offset;

      const indexA = vi[oi + VcI.indexA] & Mask.index;
      const indexB = vi[oi + VcI.indexB] & Mask.index;
      const mA = vf[o + VcF.invMassA];
      const iA = vf[o + VcF.invIA];
      const mB = vf[o + VcF.invMassB];
      const iB = vf[o + VcF.invIB];
      const pointCount = vi[oi + VcI.pointCount] & Mask.pointCount;

      let vAx = velocities[3 * indexA];
      let vAy = velocities[3 * indexA + 1];
      let wA = velocities[3 * indexA + 2];
      let vBx = velocities[3 * indexB];
      let vBy = velocities[3 * indexB + 1];
      let wB = velocities[3 * indexB + 2];

      const normalX = vf[o + VcF.normalX];
      const normalY = vf[o + VcF.normalY];
      const tangentX = normalY;
      const tangentY = -normalX;

      for (let j = 0; j < pointCount; ++j) {
        const op = o + VcF.points + j * VcP.stride;
        const normalImpulse = vf[op + VcP.normalImpulse];
        const tangentImpulse = vf[op + VcP.tangentImpulse];
        const PX = normalImpulse * normalX + tangentImpulse * tangentX;
        const PY = normalImpulse * normalY + tangentImpulse * tangentY;
        wA -= iA * (vf[op + VcP.rAx] * PY - vf[op + VcP.rAy] * PX);
        vAx -= mA * PX;
        vAy -= mA * PY;
        wB += iB * (vf[op + VcP.rBx] * PY - vf[op + VcP.rBy] * PX);
        vBx += mB * PX;
        vBy += mB * PY;
      }

      velocities[3 * indexA] = vAx;
      velocities[3 * indexA + 1] = vAy;
      velocities[3 * indexA + 2] = wA;
      velocities[3 * indexB] = vBx;
      velocities[3 * indexB + 1] = vBy;
      velocities[3 * indexB + 2] = wB;
    }
  }

  SolveVelocityConstraints(): void {
    const vf = this.m_vcFloats;
    const vi = this.m_vcInts;
    const velocities = this.m_velocities;

    for (let i = 0; i < this.m_count; ++i) {
      const o = (i * VcF.stride) & Mask.offset;
      const oi = (i * VcI.stride) & Mask.offset;

      const indexA = vi[oi + VcI.indexA] & Mask.index;
      const indexB = vi[oi + VcI.indexB] & Mask.index;
      const mA = vf[o + VcF.invMassA];
      const iA = vf[o + VcF.invIA];
      const mB = vf[o + VcF.invMassB];
      const iB = vf[o + VcF.invIB];
      const pointCount = vi[oi + VcI.pointCount] & Mask.pointCount;

      let vAx = velocities[3 * indexA];
      let vAy = velocities[3 * indexA + 1];
      let wA = velocities[3 * indexA + 2];
      let vBx = velocities[3 * indexB];
      let vBy = velocities[3 * indexB + 1];
      let wB = velocities[3 * indexB + 2];

      const normalX = vf[o + VcF.normalX];
      const normalY = vf[o + VcF.normalY];
      const tangentX = normalY;
      const tangentY = -normalX;
      const friction = vf[o + VcF.friction];

      b2Assert(pointCount === 1 || pointCount === 2);

      // Solve tangent constraints first because non-penetration is more important
      // than friction.
      for (let j = 0; j < pointCount; ++j) {
        const op = o + VcF.points + j * VcP.stride;
        const rAx = vf[op + VcP.rAx];
        const rAy = vf[op + VcP.rAy];
        const rBx = vf[op + VcP.rBx];
        const rBy = vf[op + VcP.rBy];

        // Relative velocity at contact
        const dvX = vBx + -wB * rBy - vAx - -wA * rAy;
        const dvY = vBy + wB * rBx - vAy - wA * rAx;

        // Compute tangent force
        const vt = dvX * tangentX + dvY * tangentY;
        let lambda = vf[op + VcP.tangentMass] * -vt;

        // b2Clamp the accumulated force
        const maxFriction = friction * vf[op + VcP.normalImpulse];
        const tangentImpulse = vf[op + VcP.tangentImpulse];
        const newImpulse = b2Clamp(tangentImpulse + lambda, -maxFriction, maxFriction);
        lambda = newImpulse - tangentImpulse;
        vf[op + VcP.tangentImpulse] = newImpulse;

        // Apply contact impulse
        const PX = lambda * tangentX;
        const PY = lambda * tangentY;

        vAx -= mA * PX;
        vAy -= mA * PY;
        wA -= iA * (rAx * PY - rAy * PX);

        vBx += mB * PX;
        vBy += mB * PY;
        wB += iB * (rBx * PY - rBy * PX);
      }

      // Solve normal constraints
      if (pointCount === 1) {
        const op = o + VcF.points;
        const rAx = vf[op + VcP.rAx];
        const rAy = vf[op + VcP.rAy];
        const rBx = vf[op + VcP.rBx];
        const rBy = vf[op + VcP.rBy];

        // Relative velocity at contact
        const dvX = vBx + -wB * rBy - vAx - -wA * rAy;
        const dvY = vBy + wB * rBx - vAy - wA * rAx;

        // Compute normal impulse
        const vn = dvX * normalX + dvY * normalY;
        let lambda = -vf[op + VcP.normalMass] * (vn - vf[op + VcP.velocityBias]);

        // b2Clamp the accumulated impulse
        const normalImpulse = vf[op + VcP.normalImpulse];
        // b2Max(normalImpulse + lambda, 0.0) written out: V8 may compile this function before a
        // scene's first one-point manifold, and a call it has never seen run is not inlined, so its
        // doubles would be boxed on every call (docs/PORTING.md).
        const sum = normalImpulse + lambda;
        const newImpulse = sum > 0.0 ? sum : 0.0;
        lambda = newImpulse - normalImpulse;
        vf[op + VcP.normalImpulse] = newImpulse;

        // Apply contact impulse
        const PX = lambda * normalX;
        const PY = lambda * normalY;
        vAx -= mA * PX;
        vAy -= mA * PY;
        wA -= iA * (rAx * PY - rAy * PX);

        vBx += mB * PX;
        vBy += mB * PY;
        wB += iB * (rBx * PY - rBy * PX);
      } else {
        // Block solver developed in collaboration with Dirk Gregorius (back in 01/07 on Box2D_Lite).
        // Build the mini LCP for this contact patch
        //
        // vn = A * x + b, vn >= 0, , vn >= 0, x >= 0 and vn_i * x_i = 0 with i = 1..2
        //
        // A = J * W * JT and J = ( -n, -r1 x n, n, r2 x n )
        // b = vn0 - velocityBias
        //
        // The system is solved using the "Total enumeration method" (s. Murty). The complementary constraint vn_i * x_i
        // implies that we must have in any solution either vn_i = 0 or x_i = 0. So for the 2D contact problem the cases
        // vn1 = 0 and vn2 = 0, x1 = 0 and x2 = 0, x1 = 0 and vn2 = 0, x2 = 0 and vn1 = 0 need to be tested. The first valid
        // solution that satisfies the problem is chosen.
        //
        // In order to account of the accumulated impulse 'a' (because of the iterative nature of the solver which only requires
        // that the accumulated impulse is clamped and not the incremental impulse) we change the impulse variable (x_i).
        //
        // Substitute:
        //
        // x = a + d
        //
        // a := old total impulse
        // x := new total impulse
        // d := incremental impulse
        //
        // For the current iteration we extend the formula for the incremental impulse
        // to compute the new total impulse:
        //
        // vn = A * d + b
        //    = A * (x - a) + b
        //    = A * x + b - A * a
        //    = A * x + b'
        // b' = b - A * a;

        const op1 = o + VcF.points;
        const op2 = op1 + VcP.stride;
        const r1Ax = vf[op1 + VcP.rAx];
        const r1Ay = vf[op1 + VcP.rAy];
        const r1Bx = vf[op1 + VcP.rBx];
        const r1By = vf[op1 + VcP.rBy];
        const r2Ax = vf[op2 + VcP.rAx];
        const r2Ay = vf[op2 + VcP.rAy];
        const r2Bx = vf[op2 + VcP.rBx];
        const r2By = vf[op2 + VcP.rBy];

        const aX = vf[op1 + VcP.normalImpulse];
        const aY = vf[op2 + VcP.normalImpulse];
        b2Assert(aX >= 0.0 && aY >= 0.0);

        // Relative velocity at contact
        const dv1X = vBx + -wB * r1By - vAx - -wA * r1Ay;
        const dv1Y = vBy + wB * r1Bx - vAy - wA * r1Ax;
        const dv2X = vBx + -wB * r2By - vAx - -wA * r2Ay;
        const dv2Y = vBy + wB * r2Bx - vAy - wA * r2Ax;

        // Compute normal velocity
        let vn1 = dv1X * normalX + dv1Y * normalY;
        let vn2 = dv2X * normalX + dv2Y * normalY;

        let bX = vn1 - vf[op1 + VcP.velocityBias];
        let bY = vn2 - vf[op2 + VcP.velocityBias];

        // Compute b'
        const KExX = vf[o + VcF.KExX];
        const KExY = vf[o + VcF.KExY];
        const KEyX = vf[o + VcF.KEyX];
        const KEyY = vf[o + VcF.KEyY];
        bX -= KExX * aX + KEyX * aY;
        bY -= KExY * aX + KEyY * aY;

        // The C++ tries the four cases in a for (;;) loop and applies the first valid one; each
        // case's apply-and-accumulate code is the same, so it is written once below.
        let xX: number;
        let xY: number;
        let solved = true;

        //
        // Case 1: vn = 0
        //
        // 0 = A * x + b'
        //
        // Solve for x:
        //
        // x = - inv(A) * b'
        //
        xX = -(vf[o + VcF.normalMassExX] * bX + vf[o + VcF.normalMassEyX] * bY);
        xY = -(vf[o + VcF.normalMassExY] * bX + vf[o + VcF.normalMassEyY] * bY);

        if (!(xX >= 0.0 && xY >= 0.0)) {
          //
          // Case 2: vn1 = 0 and x2 = 0
          //
          //   0 = a11 * x1 + a12 * 0 + b1'
          // vn2 = a21 * x1 + a22 * 0 + b2'
          //
          xX = -vf[op1 + VcP.normalMass] * bX;
          xY = 0.0;
          vn2 = KExY * xX + bY;

          if (!(xX >= 0.0 && vn2 >= 0.0)) {
            //
            // Case 3: vn2 = 0 and x1 = 0
            //
            // vn1 = a11 * 0 + a12 * x2 + b1'
            //   0 = a21 * 0 + a22 * x2 + b2'
            //
            xX = 0.0;
            xY = -vf[op2 + VcP.normalMass] * bY;
            vn1 = KEyX * xY + bX;

            if (!(xY >= 0.0 && vn1 >= 0.0)) {
              //
              // Case 4: x1 = 0 and x2 = 0
              //
              // vn1 = b1
              // vn2 = b2;
              xX = 0.0;
              xY = 0.0;
              vn1 = bX;
              vn2 = bY;

              // No solution, give up. This is hit sometimes, but it doesn't seem to matter.
              solved = vn1 >= 0.0 && vn2 >= 0.0;
            }
          }
        }

        if (solved) {
          // Get the incremental impulse
          const dX = xX - aX;
          const dY = xY - aY;

          // Apply incremental impulse
          const P1X = dX * normalX;
          const P1Y = dX * normalY;
          const P2X = dY * normalX;
          const P2Y = dY * normalY;
          vAx -= mA * (P1X + P2X);
          vAy -= mA * (P1Y + P2Y);
          wA -= iA * (r1Ax * P1Y - r1Ay * P1X + (r2Ax * P2Y - r2Ay * P2X));

          vBx += mB * (P1X + P2X);
          vBy += mB * (P1Y + P2Y);
          wB += iB * (r1Bx * P1Y - r1By * P1X + (r2Bx * P2Y - r2By * P2X));

          // Accumulate
          vf[op1 + VcP.normalImpulse] = xX;
          vf[op2 + VcP.normalImpulse] = xY;
        }
      }

      velocities[3 * indexA] = vAx;
      velocities[3 * indexA + 1] = vAy;
      velocities[3 * indexA + 2] = wA;
      velocities[3 * indexB] = vBx;
      velocities[3 * indexB + 1] = vBy;
      velocities[3 * indexB + 2] = wB;
    }
  }

  StoreImpulses(): void {
    const vf = this.m_vcFloats;
    const vi = this.m_vcInts;
    for (let i = 0; i < this.m_count; ++i) {
      const o = (i * VcF.stride) & Mask.offset;
      const oi = (i * VcI.stride) & Mask.offset;
      const record = this.m_manifoldRecords[i];
      const mo = vi[oi + VcI.manifoldOffset] + b2ManifoldField.points;

      const pointCount = vi[oi + VcI.pointCount] & Mask.pointCount;
      for (let j = 0; j < pointCount; ++j) {
        const op = o + VcF.points + j * VcP.stride;
        const mp = mo + j * b2ManifoldPointField.stride;
        record[mp + b2ManifoldPointField.normalImpulse] = vf[op + VcP.normalImpulse];
        record[mp + b2ManifoldPointField.tangentImpulse] = vf[op + VcP.tangentImpulse];
      }
    }
  }

  /** The impulses of constraint i, as b2Island.Report reads them from a b2ContactVelocityConstraint. */
  GetImpulses(i: number, impulse: b2ContactImpulse): void {
    const vf = this.m_vcFloats;
    const o = i * VcF.stride;
    const pointCount = this.m_vcInts[i * VcI.stride + VcI.pointCount];
    impulse.count = pointCount;
    for (let j = 0; j < pointCount; ++j) {
      const op = o + VcF.points + j * VcP.stride;
      impulse.normalImpulses[j] = vf[op + VcP.normalImpulse];
      impulse.tangentImpulses[j] = vf[op + VcP.tangentImpulse];
    }
  }

  /** Sequential solver. */
  SolvePositionConstraints(): boolean {
    return this.SolvePositionConstraintsOf(false, -1, -1);
  }

  /** Sequential position solver for position constraints. */
  SolveTOIPositionConstraints(toiIndexA: number, toiIndexB: number): boolean {
    return this.SolvePositionConstraintsOf(true, toiIndexA, toiIndexB);
  }

  /**
   * The body of SolvePositionConstraints (toi false) and SolveTOIPositionConstraints (toi true),
   * which differ only in body A's masses, the Baumgarte factor and the final test. One loop with
   * integer and boolean arguments: a per-contact helper taking and returning doubles would box
   * them on every call V8 does not inline. b2PositionSolverManifold.Initialize is written out
   * (the same operations) on the record's scalars.
   */
  private SolvePositionConstraintsOf(toi: boolean, toiIndexA: number, toiIndexB: number): boolean {
    let minSeparation = 0.0;
    const baumgarte = toi ? b2_toiBaugarte : b2_baumgarte;
    const positions = this.m_positions;
    const pf = this.m_pcFloats;
    const pi = this.m_pcInts;
    const qA = s_qA;
    const qB = s_qB;

    for (let i = 0; i < this.m_count; ++i) {
      const q = (i * PcF.stride) & Mask.offset;
      const qi = (i * PcI.stride) & Mask.offset;

      const indexA = pi[qi + PcI.indexA] & Mask.index;
      const indexB = pi[qi + PcI.indexB] & Mask.index;
      const localCenterAX = pf[q + PcF.localCenterAX];
      const localCenterAY = pf[q + PcF.localCenterAY];
      const localCenterBX = pf[q + PcF.localCenterBX];
      const localCenterBY = pf[q + PcF.localCenterBY];
      const pointCount = pi[qi + PcI.pointCount] & Mask.pointCount;
      const type = pi[qi + PcI.type];
      const radiusA = pf[q + PcF.radiusA];
      const radiusB = pf[q + PcF.radiusB];

      let mA = pf[q + PcF.invMassA];
      let iA = pf[q + PcF.invIA];
      if (toi && indexA !== toiIndexA && indexA !== toiIndexB) {
        mA = 0.0;
        iA = 0.0;
      }

      // Box2D 2.2.1 gives body B its mass whether or not it is one of the two TOI bodies (its
      // test of indexB assigns the same values; 2.3.0 starts mB at zero), so body B of every
      // contact in a TOI island moves.
      const mB = pf[q + PcF.invMassB];
      const iB = pf[q + PcF.invIB];

      let cAx = positions[3 * indexA];
      let cAy = positions[3 * indexA + 1];
      let aA = positions[3 * indexA + 2];

      let cBx = positions[3 * indexB];
      let cBy = positions[3 * indexB + 1];
      let aB = positions[3 * indexB + 2];

      // Solve normal constraints
      for (let j = 0; j < pointCount; ++j) {
        this.SetRot(indexA, aA, qA);
        this.SetRot(indexB, aB, qB);
        const qAs = qA.s;
        const qAc = qA.c;
        const qBs = qB.s;
        const qBc = qB.c;
        const xfApx = cAx - (qAc * localCenterAX - qAs * localCenterAY);
        const xfApy = cAy - (qAs * localCenterAX + qAc * localCenterAY);
        const xfBpx = cBx - (qBc * localCenterBX - qBs * localCenterBY);
        const xfBpy = cBy - (qBs * localCenterBX + qBc * localCenterBY);

        // psm.Initialize(pc, xfA, xfB, j)
        b2Assert(pointCount > 0);
        let normalX: number;
        let normalY: number;
        let pointX: number;
        let pointY: number;
        let separation: number;
        if (type === b2Manifold.e_circles) {
          const lpx = pf[q + PcF.localPointX];
          const lpy = pf[q + PcF.localPointY];
          const pointAx = qAc * lpx - qAs * lpy + xfApx;
          const pointAy = qAs * lpx + qAc * lpy + xfApy;
          const l0x = pf[q + PcF.localPoint0X];
          const l0y = pf[q + PcF.localPoint0Y];
          const pointBx = qBc * l0x - qBs * l0y + xfBpx;
          const pointBy = qBs * l0x + qBc * l0y + xfBpy;
          normalX = pointBx - pointAx;
          normalY = pointBy - pointAy;
          // normal.Normalize()
          const length = Math.sqrt(normalX * normalX + normalY * normalY);
          if (!(length < b2_epsilon)) {
            const invLength = 1.0 / length;
            normalX *= invLength;
            normalY *= invLength;
          }
          pointX = 0.5 * (pointAx + pointBx);
          pointY = 0.5 * (pointAy + pointBy);
          separation = (pointBx - pointAx) * normalX + (pointBy - pointAy) * normalY - radiusA - radiusB;
        } else if (type === b2Manifold.e_faceA) {
          const lnx = pf[q + PcF.localNormalX];
          const lny = pf[q + PcF.localNormalY];
          normalX = qAc * lnx - qAs * lny;
          normalY = qAs * lnx + qAc * lny;
          const lpx = pf[q + PcF.localPointX];
          const lpy = pf[q + PcF.localPointY];
          const planePointX = qAc * lpx - qAs * lpy + xfApx;
          const planePointY = qAs * lpx + qAc * lpy + xfApy;

          const lx = pf[q + PcF.localPoint0X + 2 * j];
          const ly = pf[q + PcF.localPoint0Y + 2 * j];
          const clipPointX = qBc * lx - qBs * ly + xfBpx;
          const clipPointY = qBs * lx + qBc * ly + xfBpy;
          separation = (clipPointX - planePointX) * normalX + (clipPointY - planePointY) * normalY - radiusA - radiusB;
          pointX = clipPointX;
          pointY = clipPointY;
        } else {
          // b2Manifold.e_faceB
          const lnx = pf[q + PcF.localNormalX];
          const lny = pf[q + PcF.localNormalY];
          normalX = qBc * lnx - qBs * lny;
          normalY = qBs * lnx + qBc * lny;
          const lpx = pf[q + PcF.localPointX];
          const lpy = pf[q + PcF.localPointY];
          const planePointX = qBc * lpx - qBs * lpy + xfBpx;
          const planePointY = qBs * lpx + qBc * lpy + xfBpy;

          const lx = pf[q + PcF.localPoint0X + 2 * j];
          const ly = pf[q + PcF.localPoint0Y + 2 * j];
          const clipPointX = qAc * lx - qAs * ly + xfApx;
          const clipPointY = qAs * lx + qAc * ly + xfApy;
          separation = (clipPointX - planePointX) * normalX + (clipPointY - planePointY) * normalY - radiusA - radiusB;
          pointX = clipPointX;
          pointY = clipPointY;

          // Ensure normal points from A to B
          normalX = -normalX;
          normalY = -normalY;
        }

        const rAx = pointX - cAx;
        const rAy = pointY - cAy;
        const rBx = pointX - cBx;
        const rBy = pointY - cBy;

        // Track max constraint error.
        minSeparation = b2Min(minSeparation, separation);

        // Prevent large corrections and allow slop.
        const C = b2Clamp(baumgarte * (separation + b2_linearSlop), -b2_maxLinearCorrection, 0.0);

        // Compute the effective mass.
        const rnA = rAx * normalY - rAy * normalX;
        const rnB = rBx * normalY - rBy * normalX;
        const K = mA + mB + iA * rnA * rnA + iB * rnB * rnB;

        // Compute normal impulse
        const impulse = K > 0.0 ? -C / K : 0.0;

        const PX = impulse * normalX;
        const PY = impulse * normalY;

        cAx -= mA * PX;
        cAy -= mA * PY;
        aA -= iA * (rAx * PY - rAy * PX);

        cBx += mB * PX;
        cBy += mB * PY;
        aB += iB * (rBx * PY - rBy * PX);
      }

      positions[3 * indexA] = cAx;
      positions[3 * indexA + 1] = cAy;
      positions[3 * indexA + 2] = aA;

      positions[3 * indexB] = cBx;
      positions[3 * indexB + 1] = cBy;
      positions[3 * indexB + 2] = aB;
    }

    // We can't expect minSpeparation >= -b2_linearSlop because we don't
    // push the separation above -b2_linearSlop.
    if (toi) {
      return minSeparation >= -1.5 * b2_linearSlop;
    }
    return minSeparation >= -3.0 * b2_linearSlop;
  }
}
