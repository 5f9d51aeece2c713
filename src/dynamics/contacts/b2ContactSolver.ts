/*
 * The contact constraint solver (b2ContactSolver.h, b2ContactSolver.cpp).
 *
 * The C++ builds a solver per island on the stack allocator. Here the constructor's work is in
 * Initialize(def), so one solver can be re-initialised for every island; its constraint arrays
 * grow to the largest island seen and are reused, and the hot loops work on scalar locals in the
 * exact operation order of the C++ vector expressions.
 */

import { b2Manifold, b2WorldManifold } from '../../collision/b2Collision';
import { b2Clamp, b2Mat22, b2Max, b2Min, b2MulRV, b2MulXV, b2SubVV, b2Transform, b2Vec2 } from '../../common/b2Math';
import {
  b2Assert,
  b2_baumgarte,
  b2_linearSlop,
  b2_maxLinearCorrection,
  b2_maxManifoldPoints,
  b2_toiBaugarte,
  b2_velocityThreshold,
} from '../../common/b2Settings';
import { b2TimeStep } from '../b2TimeStep';
import type { b2Position, b2Velocity } from '../b2TimeStep';
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
  readonly points: b2VelocityConstraintPoint[] = [];
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

  constructor() {
    for (let i = 0; i < b2_maxManifoldPoints; ++i) {
      this.points.push(new b2VelocityConstraintPoint());
    }
  }
}

export class b2ContactPositionConstraint {
  readonly localPoints: b2Vec2[] = [];
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
  type = b2Manifold.e_circles;
  radiusA = 0.0;
  radiusB = 0.0;
  pointCount = 0;

  constructor() {
    for (let i = 0; i < b2_maxManifoldPoints; ++i) {
      this.localPoints.push(new b2Vec2());
    }
  }
}

/**
 * The island's data for one solve. `contacts`, `positions` and `velocities` are shared by
 * reference (the C++ passes pointers); the solver copies `step`.
 */
export class b2ContactSolverDef {
  step = new b2TimeStep();
  contacts: b2Contact[] = [];
  count = 0;
  positions: b2Position[] = [];
  velocities: b2Velocity[] = [];
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
        this.separation =
          (clipPoint.x - planePoint.x) * normal.x + (clipPoint.y - planePoint.y) * normal.y - pc.radiusA - pc.radiusB;
        this.point.Assign(clipPoint);
        break;
      }

      case b2Manifold.e_faceB: {
        const normal = b2MulRV(xfB.q, pc.localNormal, this.normal);
        const planePoint = b2MulXV(xfB, pc.localPoint, s_planePoint);

        const clipPoint = b2MulXV(xfA, pc.localPoints[index], s_clipPoint);
        this.separation =
          (clipPoint.x - planePoint.x) * normal.x + (clipPoint.y - planePoint.y) * normal.y - pc.radiusA - pc.radiusB;
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
const s_xfA = new b2Transform();
const s_xfB = new b2Transform();
const s_worldManifold = new b2WorldManifold();
const s_psm = new b2PositionSolverManifold();

export class b2ContactSolver {
  readonly m_step = new b2TimeStep();
  m_positions: b2Position[] = [];
  m_velocities: b2Velocity[] = [];
  /** Grown to the largest island seen; only the first m_count entries are current. */
  readonly m_positionConstraints: b2ContactPositionConstraint[] = [];
  /** Grown to the largest island seen; only the first m_count entries are current. */
  readonly m_velocityConstraints: b2ContactVelocityConstraint[] = [];
  m_contacts: b2Contact[] = [];
  m_count = 0;

  constructor(def?: b2ContactSolverDef) {
    if (def) {
      this.Initialize(def);
    }
  }

  /** The C++ constructor: set up the solver for an island, reusing the constraint storage. */
  Initialize(def: b2ContactSolverDef): this {
    this.m_step.Assign(def.step);
    this.m_count = def.count;
    while (this.m_positionConstraints.length < this.m_count) {
      this.m_positionConstraints.push(new b2ContactPositionConstraint());
      this.m_velocityConstraints.push(new b2ContactVelocityConstraint());
    }
    this.m_positions = def.positions;
    this.m_velocities = def.velocities;
    this.m_contacts = def.contacts;

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

      const vc = this.m_velocityConstraints[i];
      vc.friction = contact.m_friction;
      vc.restitution = contact.m_restitution;
      vc.indexA = bodyA.m_islandIndex;
      vc.indexB = bodyB.m_islandIndex;
      vc.invMassA = bodyA.m_invMass;
      vc.invMassB = bodyB.m_invMass;
      vc.invIA = bodyA.m_invI;
      vc.invIB = bodyB.m_invI;
      vc.contactIndex = i;
      vc.pointCount = pointCount;
      vc.K.SetZero();
      vc.normalMass.SetZero();

      const pc = this.m_positionConstraints[i];
      pc.indexA = bodyA.m_islandIndex;
      pc.indexB = bodyB.m_islandIndex;
      pc.invMassA = bodyA.m_invMass;
      pc.invMassB = bodyB.m_invMass;
      pc.localCenterA.Assign(bodyA.m_sweep.localCenter);
      pc.localCenterB.Assign(bodyB.m_sweep.localCenter);
      pc.invIA = bodyA.m_invI;
      pc.invIB = bodyB.m_invI;
      pc.localNormal.Assign(manifold.localNormal);
      pc.localPoint.Assign(manifold.localPoint);
      pc.pointCount = pointCount;
      pc.radiusA = radiusA;
      pc.radiusB = radiusB;
      pc.type = manifold.type;

      for (let j = 0; j < pointCount; ++j) {
        const cp = manifold.points[j];
        const vcp = vc.points[j];

        if (this.m_step.warmStarting) {
          vcp.normalImpulse = this.m_step.dtRatio * cp.normalImpulse;
          vcp.tangentImpulse = this.m_step.dtRatio * cp.tangentImpulse;
        } else {
          vcp.normalImpulse = 0.0;
          vcp.tangentImpulse = 0.0;
        }

        vcp.rA.SetZero();
        vcp.rB.SetZero();
        vcp.normalMass = 0.0;
        vcp.tangentMass = 0.0;
        vcp.velocityBias = 0.0;

        pc.localPoints[j].Assign(cp.localPoint);
      }
    }
    return this;
  }

  /** Initialize position dependent portions of the velocity constraints. */
  InitializeVelocityConstraints(): void {
    for (let i = 0; i < this.m_count; ++i) {
      const vc = this.m_velocityConstraints[i];
      const pc = this.m_positionConstraints[i];

      const radiusA = pc.radiusA;
      const radiusB = pc.radiusB;
      const manifold = this.m_contacts[vc.contactIndex].GetManifold();

      const indexA = vc.indexA;
      const indexB = vc.indexB;

      const mA = vc.invMassA;
      const mB = vc.invMassB;
      const iA = vc.invIA;
      const iB = vc.invIB;
      const localCenterA = pc.localCenterA;
      const localCenterB = pc.localCenterB;

      const cA = this.m_positions[indexA].c;
      const aA = this.m_positions[indexA].a;
      const vA = this.m_velocities[indexA].v;
      const wA = this.m_velocities[indexA].w;

      const cB = this.m_positions[indexB].c;
      const aB = this.m_positions[indexB].a;
      const vB = this.m_velocities[indexB].v;
      const wB = this.m_velocities[indexB].w;

      b2Assert(manifold.pointCount > 0);

      const xfA = s_xfA;
      const xfB = s_xfB;
      xfA.q.Set(aA);
      xfB.q.Set(aB);
      b2SubVV(cA, b2MulRV(xfA.q, localCenterA, xfA.p), xfA.p);
      b2SubVV(cB, b2MulRV(xfB.q, localCenterB, xfB.p), xfB.p);

      const worldManifold = s_worldManifold;
      worldManifold.Initialize(manifold, xfA, radiusA, xfB, radiusB);

      const normal = vc.normal.Assign(worldManifold.normal);
      // tangent = b2Cross(normal, 1.0) = (normal.y, -normal.x), exactly
      const tangentX = normal.y;
      const tangentY = -normal.x;

      const pointCount = vc.pointCount;
      for (let j = 0; j < pointCount; ++j) {
        const vcp = vc.points[j];
        const rA = b2SubVV(worldManifold.points[j], cA, vcp.rA);
        const rB = b2SubVV(worldManifold.points[j], cB, vcp.rB);

        const rnA = rA.x * normal.y - rA.y * normal.x;
        const rnB = rB.x * normal.y - rB.y * normal.x;

        const kNormal = mA + mB + iA * rnA * rnA + iB * rnB * rnB;

        vcp.normalMass = kNormal > 0.0 ? 1.0 / kNormal : 0.0;

        const rtA = rA.x * tangentY - rA.y * tangentX;
        const rtB = rB.x * tangentY - rB.y * tangentX;

        const kTangent = mA + mB + iA * rtA * rtA + iB * rtB * rtB;

        vcp.tangentMass = kTangent > 0.0 ? 1.0 / kTangent : 0.0;

        // Setup a velocity bias for restitution.
        vcp.velocityBias = 0.0;
        const dvX = vB.x + -wB * rB.y - vA.x - -wA * rA.y;
        const dvY = vB.y + wB * rB.x - vA.y - wA * rA.x;
        const vRel = normal.x * dvX + normal.y * dvY;
        if (vRel < -b2_velocityThreshold) {
          vcp.velocityBias = -vc.restitution * vRel;
        }
      }

      // If we have two points, then prepare the block solver.
      if (vc.pointCount === 2) {
        const vcp1 = vc.points[0];
        const vcp2 = vc.points[1];

        const rn1A = vcp1.rA.x * normal.y - vcp1.rA.y * normal.x;
        const rn1B = vcp1.rB.x * normal.y - vcp1.rB.y * normal.x;
        const rn2A = vcp2.rA.x * normal.y - vcp2.rA.y * normal.x;
        const rn2B = vcp2.rB.x * normal.y - vcp2.rB.y * normal.x;

        const k11 = mA + mB + iA * rn1A * rn1A + iB * rn1B * rn1B;
        const k22 = mA + mB + iA * rn2A * rn2A + iB * rn2B * rn2B;
        const k12 = mA + mB + iA * rn1A * rn2A + iB * rn1B * rn2B;

        // Ensure a reasonable condition number.
        const k_maxConditionNumber = 1000.0;
        if (k11 * k11 < k_maxConditionNumber * (k11 * k22 - k12 * k12)) {
          // K is safe to invert.
          vc.K.ex.Set(k11, k12);
          vc.K.ey.Set(k12, k22);
          vc.K.GetInverse(vc.normalMass);
        } else {
          // The constraints are redundant, just use one.
          // TODO_ERIN use deepest?
          vc.pointCount = 1;
        }
      }
    }
  }

  WarmStart(): void {
    // Warm start.
    for (let i = 0; i < this.m_count; ++i) {
      const vc = this.m_velocityConstraints[i];

      const indexA = vc.indexA;
      const indexB = vc.indexB;
      const mA = vc.invMassA;
      const iA = vc.invIA;
      const mB = vc.invMassB;
      const iB = vc.invIB;
      const pointCount = vc.pointCount;

      const velocityA = this.m_velocities[indexA];
      const velocityB = this.m_velocities[indexB];
      let vAx = velocityA.v.x;
      let vAy = velocityA.v.y;
      let wA = velocityA.w;
      let vBx = velocityB.v.x;
      let vBy = velocityB.v.y;
      let wB = velocityB.w;

      const normalX = vc.normal.x;
      const normalY = vc.normal.y;
      const tangentX = normalY;
      const tangentY = -normalX;

      for (let j = 0; j < pointCount; ++j) {
        const vcp = vc.points[j];
        const PX = vcp.normalImpulse * normalX + vcp.tangentImpulse * tangentX;
        const PY = vcp.normalImpulse * normalY + vcp.tangentImpulse * tangentY;
        wA -= iA * (vcp.rA.x * PY - vcp.rA.y * PX);
        vAx -= mA * PX;
        vAy -= mA * PY;
        wB += iB * (vcp.rB.x * PY - vcp.rB.y * PX);
        vBx += mB * PX;
        vBy += mB * PY;
      }

      velocityA.v.x = vAx;
      velocityA.v.y = vAy;
      velocityA.w = wA;
      velocityB.v.x = vBx;
      velocityB.v.y = vBy;
      velocityB.w = wB;
    }
  }

  SolveVelocityConstraints(): void {
    for (let i = 0; i < this.m_count; ++i) {
      const vc = this.m_velocityConstraints[i];

      const indexA = vc.indexA;
      const indexB = vc.indexB;
      const mA = vc.invMassA;
      const iA = vc.invIA;
      const mB = vc.invMassB;
      const iB = vc.invIB;
      const pointCount = vc.pointCount;

      const velocityA = this.m_velocities[indexA];
      const velocityB = this.m_velocities[indexB];
      let vAx = velocityA.v.x;
      let vAy = velocityA.v.y;
      let wA = velocityA.w;
      let vBx = velocityB.v.x;
      let vBy = velocityB.v.y;
      let wB = velocityB.w;

      const normalX = vc.normal.x;
      const normalY = vc.normal.y;
      const tangentX = normalY;
      const tangentY = -normalX;
      const friction = vc.friction;

      b2Assert(pointCount === 1 || pointCount === 2);

      // Solve tangent constraints first because non-penetration is more important
      // than friction.
      for (let j = 0; j < pointCount; ++j) {
        const vcp = vc.points[j];
        const rA = vcp.rA;
        const rB = vcp.rB;

        // Relative velocity at contact
        const dvX = vBx + -wB * rB.y - vAx - -wA * rA.y;
        const dvY = vBy + wB * rB.x - vAy - wA * rA.x;

        // Compute tangent force
        const vt = dvX * tangentX + dvY * tangentY;
        let lambda = vcp.tangentMass * -vt;

        // b2Clamp the accumulated force
        const maxFriction = friction * vcp.normalImpulse;
        const newImpulse = b2Clamp(vcp.tangentImpulse + lambda, -maxFriction, maxFriction);
        lambda = newImpulse - vcp.tangentImpulse;
        vcp.tangentImpulse = newImpulse;

        // Apply contact impulse
        const PX = lambda * tangentX;
        const PY = lambda * tangentY;

        vAx -= mA * PX;
        vAy -= mA * PY;
        wA -= iA * (rA.x * PY - rA.y * PX);

        vBx += mB * PX;
        vBy += mB * PY;
        wB += iB * (rB.x * PY - rB.y * PX);
      }

      // Solve normal constraints
      if (vc.pointCount === 1) {
        const vcp = vc.points[0];
        const rA = vcp.rA;
        const rB = vcp.rB;

        // Relative velocity at contact
        const dvX = vBx + -wB * rB.y - vAx - -wA * rA.y;
        const dvY = vBy + wB * rB.x - vAy - wA * rA.x;

        // Compute normal impulse
        const vn = dvX * normalX + dvY * normalY;
        let lambda = -vcp.normalMass * (vn - vcp.velocityBias);

        // b2Clamp the accumulated impulse
        const newImpulse = b2Max(vcp.normalImpulse + lambda, 0.0);
        lambda = newImpulse - vcp.normalImpulse;
        vcp.normalImpulse = newImpulse;

        // Apply contact impulse
        const PX = lambda * normalX;
        const PY = lambda * normalY;
        vAx -= mA * PX;
        vAy -= mA * PY;
        wA -= iA * (rA.x * PY - rA.y * PX);

        vBx += mB * PX;
        vBy += mB * PY;
        wB += iB * (rB.x * PY - rB.y * PX);
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

        const cp1 = vc.points[0];
        const cp2 = vc.points[1];
        const r1A = cp1.rA;
        const r1B = cp1.rB;
        const r2A = cp2.rA;
        const r2B = cp2.rB;

        const aX = cp1.normalImpulse;
        const aY = cp2.normalImpulse;
        b2Assert(aX >= 0.0 && aY >= 0.0);

        // Relative velocity at contact
        const dv1X = vBx + -wB * r1B.y - vAx - -wA * r1A.y;
        const dv1Y = vBy + wB * r1B.x - vAy - wA * r1A.x;
        const dv2X = vBx + -wB * r2B.y - vAx - -wA * r2A.y;
        const dv2Y = vBy + wB * r2B.x - vAy - wA * r2A.x;

        // Compute normal velocity
        let vn1 = dv1X * normalX + dv1Y * normalY;
        let vn2 = dv2X * normalX + dv2Y * normalY;

        let bX = vn1 - cp1.velocityBias;
        let bY = vn2 - cp2.velocityBias;

        // Compute b'
        const K = vc.K;
        bX -= K.ex.x * aX + K.ey.x * aY;
        bY -= K.ex.y * aX + K.ey.y * aY;

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
        const normalMass = vc.normalMass;
        xX = -(normalMass.ex.x * bX + normalMass.ey.x * bY);
        xY = -(normalMass.ex.y * bX + normalMass.ey.y * bY);

        if (!(xX >= 0.0 && xY >= 0.0)) {
          //
          // Case 2: vn1 = 0 and x2 = 0
          //
          //   0 = a11 * x1 + a12 * 0 + b1'
          // vn2 = a21 * x1 + a22 * 0 + b2'
          //
          xX = -cp1.normalMass * bX;
          xY = 0.0;
          vn2 = K.ex.y * xX + bY;

          if (!(xX >= 0.0 && vn2 >= 0.0)) {
            //
            // Case 3: vn2 = 0 and x1 = 0
            //
            // vn1 = a11 * 0 + a12 * x2 + b1'
            //   0 = a21 * 0 + a22 * x2 + b2'
            //
            xX = 0.0;
            xY = -cp2.normalMass * bY;
            vn1 = K.ey.x * xY + bX;

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
          wA -= iA * (r1A.x * P1Y - r1A.y * P1X + (r2A.x * P2Y - r2A.y * P2X));

          vBx += mB * (P1X + P2X);
          vBy += mB * (P1Y + P2Y);
          wB += iB * (r1B.x * P1Y - r1B.y * P1X + (r2B.x * P2Y - r2B.y * P2X));

          // Accumulate
          cp1.normalImpulse = xX;
          cp2.normalImpulse = xY;
        }
      }

      velocityA.v.x = vAx;
      velocityA.v.y = vAy;
      velocityA.w = wA;
      velocityB.v.x = vBx;
      velocityB.v.y = vBy;
      velocityB.w = wB;
    }
  }

  StoreImpulses(): void {
    for (let i = 0; i < this.m_count; ++i) {
      const vc = this.m_velocityConstraints[i];
      const manifold = this.m_contacts[vc.contactIndex].GetManifold();

      for (let j = 0; j < vc.pointCount; ++j) {
        manifold.points[j].normalImpulse = vc.points[j].normalImpulse;
        manifold.points[j].tangentImpulse = vc.points[j].tangentImpulse;
      }
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
   * them on every call V8 does not inline.
   */
  private SolvePositionConstraintsOf(toi: boolean, toiIndexA: number, toiIndexB: number): boolean {
    let minSeparation = 0.0;
    const baumgarte = toi ? b2_toiBaugarte : b2_baumgarte;
    const positions = this.m_positions;
    const xfA = s_xfA;
    const xfB = s_xfB;
    const psm = s_psm;

    for (let i = 0; i < this.m_count; ++i) {
      const pc = this.m_positionConstraints[i];

      const indexA = pc.indexA;
      const indexB = pc.indexB;
      const localCenterA = pc.localCenterA;
      const localCenterB = pc.localCenterB;
      const pointCount = pc.pointCount;

      let mA = pc.invMassA;
      let iA = pc.invIA;
      if (toi && indexA !== toiIndexA && indexA !== toiIndexB) {
        mA = 0.0;
        iA = 0.0;
      }

      // Box2D 2.2.1 gives body B its mass whether or not it is one of the two TOI bodies (its
      // test of indexB assigns the same values; 2.3.0 starts mB at zero), so body B of every
      // contact in a TOI island moves.
      const mB = pc.invMassB;
      const iB = pc.invIB;

      const positionA = positions[indexA];
      const positionB = positions[indexB];
      let cAx = positionA.c.x;
      let cAy = positionA.c.y;
      let aA = positionA.a;

      let cBx = positionB.c.x;
      let cBy = positionB.c.y;
      let aB = positionB.a;

      // Solve normal constraints
      for (let j = 0; j < pointCount; ++j) {
        xfA.q.Set(aA);
        xfB.q.Set(aB);
        xfA.p.x = cAx - (xfA.q.c * localCenterA.x - xfA.q.s * localCenterA.y);
        xfA.p.y = cAy - (xfA.q.s * localCenterA.x + xfA.q.c * localCenterA.y);
        xfB.p.x = cBx - (xfB.q.c * localCenterB.x - xfB.q.s * localCenterB.y);
        xfB.p.y = cBy - (xfB.q.s * localCenterB.x + xfB.q.c * localCenterB.y);

        psm.Initialize(pc, xfA, xfB, j);
        const normal = psm.normal;

        const point = psm.point;
        const separation = psm.separation;

        const rAx = point.x - cAx;
        const rAy = point.y - cAy;
        const rBx = point.x - cBx;
        const rBy = point.y - cBy;

        // Track max constraint error.
        minSeparation = b2Min(minSeparation, separation);

        // Prevent large corrections and allow slop.
        const C = b2Clamp(baumgarte * (separation + b2_linearSlop), -b2_maxLinearCorrection, 0.0);

        // Compute the effective mass.
        const rnA = rAx * normal.y - rAy * normal.x;
        const rnB = rBx * normal.y - rBy * normal.x;
        const K = mA + mB + iA * rnA * rnA + iB * rnB * rnB;

        // Compute normal impulse
        const impulse = K > 0.0 ? -C / K : 0.0;

        const PX = impulse * normal.x;
        const PY = impulse * normal.y;

        cAx -= mA * PX;
        cAy -= mA * PY;
        aA -= iA * (rAx * PY - rAy * PX);

        cBx += mB * PX;
        cBy += mB * PY;
        aB += iB * (rBx * PY - rBy * PX);
      }

      positionA.c.x = cAx;
      positionA.c.y = cAy;
      positionA.a = aA;

      positionB.c.x = cBx;
      positionB.c.y = cBy;
      positionB.a = aB;
    }

    // We can't expect minSpeparation >= -b2_linearSlop because we don't
    // push the separation above -b2_linearSlop.
    if (toi) {
      return minSeparation >= -1.5 * b2_linearSlop;
    }
    return minSeparation >= -3.0 * b2_linearSlop;
  }
}
