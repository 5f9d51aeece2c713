/*
 * Friction joint (b2FrictionJoint.h, b2FrictionJoint.cpp).
 *
 * Point-to-point constraint
 * Cdot = v2 - v1
 *      = v2 + cross(w2, r2) - v1 - cross(w1, r1)
 * J = [-I -r1_skew I r2_skew ]
 * Identity used:
 * w k % (rx i + ry j) = w * (-ry i + rx j)
 *
 * Angle constraint
 * Cdot = w2 - w1
 * J = [0 0 -1 0 0 1]
 * K = invI1 + invI2
 */

import { b2Clamp, b2Mat22, b2MulMV, b2MulRV, b2Rot, b2SubVV, b2Vec2 } from '../../common/b2Math';
import { b2Log } from '../../common/b2Settings';
import type { b2Body } from '../b2Body';
import type { b2SolverData } from '../b2TimeStep';
import { b2Joint, b2JointDef, b2JointType, b2CheckJointAlive } from './b2Joint';
import { b2CheckNonNegative } from '../../common/b2ArgumentError';

const s_qA = new b2Rot();
const s_qB = new b2Rot();
const s_K = new b2Mat22();
const s_Cdot = new b2Vec2();
const s_impulse = new b2Vec2();

/** Friction joint definition. */
export class b2FrictionJointDef extends b2JointDef {
  /** The local anchor point relative to bodyA's origin. */
  localAnchorA = new b2Vec2();
  /** The local anchor point relative to bodyB's origin. */
  localAnchorB = new b2Vec2();
  /** The maximum friction force in N. */
  maxForce = 0.0;
  /** The maximum friction torque in N-m. */
  maxTorque = 0.0;

  constructor() {
    super(b2JointType.e_frictionJoint);
  }

  /** Initialize the bodies, anchors, axis, and reference angle using the world anchor and world axis. */
  Initialize(bA: b2Body, bB: b2Body, anchor: Readonly<b2Vec2>): void {
    this.bodyA = bA;
    this.bodyB = bB;
    bA.GetLocalPoint(anchor, this.localAnchorA);
    bB.GetLocalPoint(anchor, this.localAnchorB);
  }
}

/** Friction joint. This is used for top-down friction. It provides 2D translational friction and angular friction. */
export class b2FrictionJoint extends b2Joint {
  readonly m_localAnchorA = new b2Vec2();
  readonly m_localAnchorB = new b2Vec2();

  // Solver shared
  readonly m_linearImpulse = new b2Vec2();
  m_angularImpulse = 0.0;
  m_maxForce = 0.0;
  m_maxTorque = 0.0;

  // Solver temp
  m_indexA = 0;
  m_indexB = 0;
  readonly m_rA = new b2Vec2();
  readonly m_rB = new b2Vec2();
  readonly m_localCenterA = new b2Vec2();
  readonly m_localCenterB = new b2Vec2();
  m_invMassA = 0.0;
  m_invMassB = 0.0;
  m_invIA = 0.0;
  m_invIB = 0.0;
  readonly m_linearMass = new b2Mat22();
  m_angularMass = 0.0;

  constructor(def: b2FrictionJointDef) {
    super(def);

    this.m_localAnchorA.Assign(def.localAnchorA);
    this.m_localAnchorB.Assign(def.localAnchorB);

    this.m_linearImpulse.SetZero();
    this.m_angularImpulse = 0.0;

    this.m_maxForce = def.maxForce;
    this.m_maxTorque = def.maxTorque;
  }

  override InitVelocityConstraints(data: b2SolverData): void {
    const bA = this.m_bodyA;
    const bB = this.m_bodyB;
    this.m_indexA = bA.m_islandIndex;
    this.m_indexB = bB.m_islandIndex;
    this.m_localCenterA.Assign(bA.m_sweep.localCenter);
    this.m_localCenterB.Assign(bB.m_sweep.localCenter);
    this.m_invMassA = bA.m_invMass;
    this.m_invMassB = bB.m_invMass;
    this.m_invIA = bA.m_invI;
    this.m_invIB = bB.m_invI;

    const oA = 3 * this.m_indexA;
    const aA = data.positions[oA + 2];
    const velocities = data.velocities;
    let vAx = velocities[oA];
    let vAy = velocities[oA + 1];
    let wA = velocities[oA + 2];

    const oB = 3 * this.m_indexB;
    const aB = data.positions[oB + 2];
    let vBx = velocities[oB];
    let vBy = velocities[oB + 1];
    let wB = velocities[oB + 2];

    const qA = s_qA.Set(aA);
    const qB = s_qB.Set(aB);

    // Compute the effective mass matrix.
    const rA = b2MulRV(qA, b2SubVV(this.m_localAnchorA, this.m_localCenterA, this.m_rA), this.m_rA);
    const rB = b2MulRV(qB, b2SubVV(this.m_localAnchorB, this.m_localCenterB, this.m_rB), this.m_rB);

    // J = [-I -r1_skew I r2_skew]
    //     [ 0       -1 0       1]
    // r_skew = [-ry; rx]

    // Matlab
    // K = [ mA+r1y^2*iA+mB+r2y^2*iB,  -r1y*iA*r1x-r2y*iB*r2x,          -r1y*iA-r2y*iB]
    //     [  -r1y*iA*r1x-r2y*iB*r2x, mA+r1x^2*iA+mB+r2x^2*iB,           r1x*iA+r2x*iB]
    //     [          -r1y*iA-r2y*iB,           r1x*iA+r2x*iB,                   iA+iB]

    const mA = this.m_invMassA;
    const mB = this.m_invMassB;
    const iA = this.m_invIA;
    const iB = this.m_invIB;

    const K = s_K;
    K.ex.x = mA + mB + iA * rA.y * rA.y + iB * rB.y * rB.y;
    K.ex.y = -iA * rA.x * rA.y - iB * rB.x * rB.y;
    K.ey.x = K.ex.y;
    K.ey.y = mA + mB + iA * rA.x * rA.x + iB * rB.x * rB.x;

    K.GetInverse(this.m_linearMass);

    this.m_angularMass = iA + iB;
    if (this.m_angularMass > 0.0) {
      this.m_angularMass = 1.0 / this.m_angularMass;
    }

    if (data.step.warmStarting) {
      // Scale impulses to support a variable time step.
      this.m_linearImpulse.Multiply(data.step.dtRatio);
      this.m_angularImpulse *= data.step.dtRatio;

      const Px = this.m_linearImpulse.x;
      const Py = this.m_linearImpulse.y;
      vAx -= mA * Px;
      vAy -= mA * Py;
      wA -= iA * (rA.x * Py - rA.y * Px + this.m_angularImpulse);
      vBx += mB * Px;
      vBy += mB * Py;
      wB += iB * (rB.x * Py - rB.y * Px + this.m_angularImpulse);
    } else {
      this.m_linearImpulse.SetZero();
      this.m_angularImpulse = 0.0;
    }

    velocities[oA] = vAx;
    velocities[oA + 1] = vAy;
    velocities[oA + 2] = wA;
    velocities[oB] = vBx;
    velocities[oB + 1] = vBy;
    velocities[oB + 2] = wB;
  }

  override SolveVelocityConstraints(data: b2SolverData): void {
    const oA = 3 * this.m_indexA;
    const velocities = data.velocities;
    const oB = 3 * this.m_indexB;
    let vAx = velocities[oA];
    let vAy = velocities[oA + 1];
    let wA = velocities[oA + 2];
    let vBx = velocities[oB];
    let vBy = velocities[oB + 1];
    let wB = velocities[oB + 2];

    const mA = this.m_invMassA;
    const mB = this.m_invMassB;
    const iA = this.m_invIA;
    const iB = this.m_invIB;
    const rA = this.m_rA;
    const rB = this.m_rB;

    const h = data.step.dt;

    // Solve angular friction
    {
      const Cdot = wB - wA;
      let impulse = -this.m_angularMass * Cdot;

      const oldImpulse = this.m_angularImpulse;
      const maxImpulse = h * this.m_maxTorque;
      this.m_angularImpulse = b2Clamp(this.m_angularImpulse + impulse, -maxImpulse, maxImpulse);
      impulse = this.m_angularImpulse - oldImpulse;

      wA -= iA * impulse;
      wB += iB * impulse;
    }

    // Solve linear friction
    {
      const Cdot = s_Cdot.Set(vBx - wB * rB.y - vAx + wA * rA.y, vBy + wB * rB.x - vAy - wA * rA.x);

      const impulse = b2MulMV(this.m_linearMass, Cdot, s_impulse);
      impulse.x = -impulse.x;
      impulse.y = -impulse.y;
      const oldImpulseX = this.m_linearImpulse.x;
      const oldImpulseY = this.m_linearImpulse.y;
      this.m_linearImpulse.Add(impulse);

      const maxImpulse = h * this.m_maxForce;

      if (this.m_linearImpulse.LengthSquared() > maxImpulse * maxImpulse) {
        this.m_linearImpulse.Normalize();
        this.m_linearImpulse.Multiply(maxImpulse);
      }

      impulse.x = this.m_linearImpulse.x - oldImpulseX;
      impulse.y = this.m_linearImpulse.y - oldImpulseY;

      vAx -= mA * impulse.x;
      vAy -= mA * impulse.y;
      wA -= iA * (rA.x * impulse.y - rA.y * impulse.x);

      vBx += mB * impulse.x;
      vBy += mB * impulse.y;
      wB += iB * (rB.x * impulse.y - rB.y * impulse.x);
    }

    velocities[oA] = vAx;
    velocities[oA + 1] = vAy;
    velocities[oA + 2] = wA;
    velocities[oB] = vBx;
    velocities[oB + 1] = vBy;
    velocities[oB + 2] = wB;
  }

  override SolvePositionConstraints(data: b2SolverData): boolean {
    return true;
  }

  override GetAnchorA(out: b2Vec2): b2Vec2 {
    return this.m_bodyA.GetWorldPoint(this.m_localAnchorA, out);
  }

  override GetAnchorB(out: b2Vec2): b2Vec2 {
    return this.m_bodyB.GetWorldPoint(this.m_localAnchorB, out);
  }

  override GetReactionForce(inv_dt: number, out: b2Vec2): b2Vec2 {
    return out.Set(inv_dt * this.m_linearImpulse.x, inv_dt * this.m_linearImpulse.y);
  }

  override GetReactionTorque(inv_dt: number): number {
    return inv_dt * this.m_angularImpulse;
  }

  /** The local anchor point relative to bodyA's origin. */
  GetLocalAnchorA(): Readonly<b2Vec2> {
    return this.m_localAnchorA;
  }

  /** The local anchor point relative to bodyB's origin. */
  GetLocalAnchorB(): Readonly<b2Vec2> {
    return this.m_localAnchorB;
  }

  /** Set the maximum friction force in N. */
  SetMaxForce(force: number): void {
    b2CheckJointAlive(this, 'b2FrictionJoint.SetMaxForce');
    b2CheckNonNegative('b2FrictionJoint.SetMaxForce', 'force', force);
    this.m_maxForce = force;
  }

  /** Get the maximum friction force in N. */
  GetMaxForce(): number {
    return this.m_maxForce;
  }

  /** Set the maximum friction torque in N*m. */
  SetMaxTorque(torque: number): void {
    b2CheckJointAlive(this, 'b2FrictionJoint.SetMaxTorque');
    b2CheckNonNegative('b2FrictionJoint.SetMaxTorque', 'torque', torque);
    this.m_maxTorque = torque;
  }

  /** Get the maximum friction torque in N*m. */
  GetMaxTorque(): number {
    return this.m_maxTorque;
  }

  /** Dump joint to b2Log. */
  override Dump(): void {
    const indexA = this.m_bodyA.m_islandIndex;
    const indexB = this.m_bodyB.m_islandIndex;

    b2Log('  b2FrictionJointDef jd;\n');
    b2Log('  jd.bodyA = bodies[%d];\n', indexA);
    b2Log('  jd.bodyB = bodies[%d];\n', indexB);
    b2Log('  jd.collideConnected = bool(%d);\n', this.m_collideConnected);
    b2Log('  jd.localAnchorA.Set(%.15lef, %.15lef);\n', this.m_localAnchorA.x, this.m_localAnchorA.y);
    b2Log('  jd.localAnchorB.Set(%.15lef, %.15lef);\n', this.m_localAnchorB.x, this.m_localAnchorB.y);
    b2Log('  jd.maxForce = %.15lef;\n', this.m_maxForce);
    b2Log('  jd.maxTorque = %.15lef;\n', this.m_maxTorque);
    b2Log('  joints[%d] = m_world->CreateJoint(&jd);\n', this.m_index);
  }
}
