/*
 * Weld joint (b2WeldJoint.h, b2WeldJoint.cpp).
 *
 * Point-to-point constraint
 * C = p2 - p1
 * Cdot = v2 - v1
 *      = v2 + cross(w2, r2) - v1 - cross(w1, r1)
 * J = [-I -r1_skew I r2_skew ]
 * Identity used:
 * w k % (rx i + ry j) = w * (-ry i + rx j)
 *
 * Angle constraint
 * C = angle2 - angle1 - referenceAngle
 * Cdot = w2 - w1
 * J = [0 0 -1 0 0 1]
 * K = invI1 + invI2
 */

import { b2Abs, b2Mat33, b2Mul22, b2Mul33, b2MulRV, b2Rot, b2SubVV, b2Vec2, b2Vec3 } from '../../common/b2Math';
import { b2_angularSlop, b2_linearSlop, b2_pi, b2Log } from '../../common/b2Settings';
import type { b2Body } from '../b2Body';
import type { b2SolverData } from '../b2TimeStep';
import { b2Joint, b2JointDef, b2JointType, b2CheckJointAlive } from './b2Joint';
import { b2CheckNonNegative } from '../../common/b2ArgumentError';

const s_qA = new b2Rot();
const s_qB = new b2Rot();
const s_rA = new b2Vec2();
const s_rB = new b2Vec2();
const s_K = new b2Mat33();
const s_v2 = new b2Vec2();
const s_out2 = new b2Vec2();
const s_v3 = new b2Vec3();
const s_out3 = new b2Vec3();

/**
 * Weld joint definition. You need to specify local anchor points where they are attached and the
 * relative body angle. The position of the anchor points is important for computing the reaction
 * torque.
 */
export class b2WeldJointDef extends b2JointDef {
  /** The local anchor point relative to bodyA's origin. */
  localAnchorA = new b2Vec2(0.0, 0.0);
  /** The local anchor point relative to bodyB's origin. */
  localAnchorB = new b2Vec2(0.0, 0.0);
  /** The bodyB angle minus bodyA angle in the reference state (radians). */
  referenceAngle = 0.0;
  /** The mass-spring-damper frequency in Hertz. Rotation only. Disable softness with a value of 0. */
  frequencyHz = 0.0;
  /** The damping ratio. 0 = no damping, 1 = critical damping. */
  dampingRatio = 0.0;

  constructor() {
    super(b2JointType.e_weldJoint);
  }

  /** Initialize the bodies, anchors, and reference angle using a world anchor point. */
  Initialize(bA: b2Body, bB: b2Body, anchor: Readonly<b2Vec2>): void {
    this.bodyA = bA;
    this.bodyB = bB;
    bA.GetLocalPoint(anchor, this.localAnchorA);
    bB.GetLocalPoint(anchor, this.localAnchorB);
    this.referenceAngle = bB.GetAngle() - bA.GetAngle();
  }
}

/**
 * A weld joint essentially glues two bodies together. A weld joint may distort somewhat because
 * the island constraint solver is approximate.
 */
export class b2WeldJoint extends b2Joint {
  m_frequencyHz = 0.0;
  m_dampingRatio = 0.0;
  // m_bias and m_gamma are first computed by InitVelocityConstraints (the C++ constructor leaves
  // them unset).
  m_bias = 0.0;

  // Solver shared
  readonly m_localAnchorA = new b2Vec2();
  readonly m_localAnchorB = new b2Vec2();
  m_referenceAngle = 0.0;
  m_gamma = 0.0;
  readonly m_impulse = new b2Vec3();

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
  readonly m_mass = new b2Mat33();

  constructor(def: b2WeldJointDef) {
    super(def);

    this.m_localAnchorA.Assign(def.localAnchorA);
    this.m_localAnchorB.Assign(def.localAnchorB);
    this.m_referenceAngle = def.referenceAngle;
    this.m_frequencyHz = def.frequencyHz;
    this.m_dampingRatio = def.dampingRatio;

    this.m_impulse.SetZero();
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
    K.ex.x = mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB;
    K.ey.x = -rA.y * rA.x * iA - rB.y * rB.x * iB;
    K.ez.x = -rA.y * iA - rB.y * iB;
    K.ex.y = K.ey.x;
    K.ey.y = mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB;
    K.ez.y = rA.x * iA + rB.x * iB;
    K.ex.z = K.ez.x;
    K.ey.z = K.ez.y;
    K.ez.z = iA + iB;

    if (this.m_frequencyHz > 0.0) {
      K.GetInverse22(this.m_mass);

      let invM = iA + iB;
      const m = invM > 0.0 ? 1.0 / invM : 0.0;

      const C = aB - aA - this.m_referenceAngle;

      // Frequency
      const omega = 2.0 * b2_pi * this.m_frequencyHz;

      // Damping coefficient
      const d = 2.0 * m * this.m_dampingRatio * omega;

      // Spring stiffness
      const k = m * omega * omega;

      // magic formulas
      const h = data.step.dt;
      this.m_gamma = h * (d + h * k);
      this.m_gamma = this.m_gamma !== 0.0 ? 1.0 / this.m_gamma : 0.0;
      this.m_bias = C * h * k * this.m_gamma;

      invM += this.m_gamma;
      this.m_mass.ez.z = invM !== 0.0 ? 1.0 / invM : 0.0;
    } else {
      K.GetSymInverse33(this.m_mass);
      this.m_gamma = 0.0;
      this.m_bias = 0.0;
    }

    if (data.step.warmStarting) {
      // Scale impulses to support a variable time step.
      this.m_impulse.Multiply(data.step.dtRatio);

      const Px = this.m_impulse.x;
      const Py = this.m_impulse.y;

      vAx -= mA * Px;
      vAy -= mA * Py;
      wA -= iA * (rA.x * Py - rA.y * Px + this.m_impulse.z);

      vBx += mB * Px;
      vBy += mB * Py;
      wB += iB * (rB.x * Py - rB.y * Px + this.m_impulse.z);
    } else {
      this.m_impulse.SetZero();
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

    if (this.m_frequencyHz > 0.0) {
      const Cdot2 = wB - wA;

      const impulse2 = -this.m_mass.ez.z * (Cdot2 + this.m_bias + this.m_gamma * this.m_impulse.z);
      this.m_impulse.z += impulse2;

      wA -= iA * impulse2;
      wB += iB * impulse2;

      const Cdot1 = s_v2.Set(vBx - wB * rB.y - vAx + wA * rA.y, vBy + wB * rB.x - vAy - wA * rA.x);

      const impulse1 = b2Mul22(this.m_mass, Cdot1, s_out2);
      impulse1.x = -impulse1.x;
      impulse1.y = -impulse1.y;
      this.m_impulse.x += impulse1.x;
      this.m_impulse.y += impulse1.y;

      const Px = impulse1.x;
      const Py = impulse1.y;

      vAx -= mA * Px;
      vAy -= mA * Py;
      wA -= iA * (rA.x * Py - rA.y * Px);

      vBx += mB * Px;
      vBy += mB * Py;
      wB += iB * (rB.x * Py - rB.y * Px);
    } else {
      const Cdot1x = vBx - wB * rB.y - vAx + wA * rA.y;
      const Cdot1y = vBy + wB * rB.x - vAy - wA * rA.x;
      const Cdot2 = wB - wA;
      const Cdot = s_v3.Set(Cdot1x, Cdot1y, Cdot2);

      const impulse = b2Mul33(this.m_mass, Cdot, s_out3);
      impulse.x = -impulse.x;
      impulse.y = -impulse.y;
      impulse.z = -impulse.z;
      this.m_impulse.Add(impulse);

      const Px = impulse.x;
      const Py = impulse.y;

      vAx -= mA * Px;
      vAy -= mA * Py;
      wA -= iA * (rA.x * Py - rA.y * Px + impulse.z);

      vBx += mB * Px;
      vBy += mB * Py;
      wB += iB * (rB.x * Py - rB.y * Px + impulse.z);
    }

    velocities[oA] = vAx;
    velocities[oA + 1] = vAy;
    velocities[oA + 2] = wA;
    velocities[oB] = vBx;
    velocities[oB + 1] = vBy;
    velocities[oB + 2] = wB;
  }

  override SolvePositionConstraints(data: b2SolverData): boolean {
    const oA = 3 * this.m_indexA;
    const positions = data.positions;
    const oB = 3 * this.m_indexB;
    let cAx = positions[oA];
    let cAy = positions[oA + 1];
    let aA = positions[oA + 2];
    let cBx = positions[oB];
    let cBy = positions[oB + 1];
    let aB = positions[oB + 2];

    const qA = s_qA.Set(aA);
    const qB = s_qB.Set(aB);

    const mA = this.m_invMassA;
    const mB = this.m_invMassB;
    const iA = this.m_invIA;
    const iB = this.m_invIB;

    const rA = b2MulRV(qA, b2SubVV(this.m_localAnchorA, this.m_localCenterA, s_rA), s_rA);
    const rB = b2MulRV(qB, b2SubVV(this.m_localAnchorB, this.m_localCenterB, s_rB), s_rB);

    let positionError: number;
    let angularError: number;

    const K = s_K;
    K.ex.x = mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB;
    K.ey.x = -rA.y * rA.x * iA - rB.y * rB.x * iB;
    K.ez.x = -rA.y * iA - rB.y * iB;
    K.ex.y = K.ey.x;
    K.ey.y = mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB;
    K.ez.y = rA.x * iA + rB.x * iB;
    K.ex.z = K.ez.x;
    K.ey.z = K.ez.y;
    K.ez.z = iA + iB;

    if (this.m_frequencyHz > 0.0) {
      const C1x = cBx + rB.x - cAx - rA.x;
      const C1y = cBy + rB.y - cAy - rA.y;

      positionError = Math.sqrt(C1x * C1x + C1y * C1y);
      angularError = 0.0;

      const P = K.Solve22(s_v2.Set(C1x, C1y), s_out2);
      P.x = -P.x;
      P.y = -P.y;

      cAx -= mA * P.x;
      cAy -= mA * P.y;
      aA -= iA * (rA.x * P.y - rA.y * P.x);

      cBx += mB * P.x;
      cBy += mB * P.y;
      aB += iB * (rB.x * P.y - rB.y * P.x);
    } else {
      const C1x = cBx + rB.x - cAx - rA.x;
      const C1y = cBy + rB.y - cAy - rA.y;
      const C2 = aB - aA - this.m_referenceAngle;

      positionError = Math.sqrt(C1x * C1x + C1y * C1y);
      angularError = b2Abs(C2);

      const impulse = K.Solve33(s_v3.Set(C1x, C1y, C2), s_out3);
      impulse.x = -impulse.x;
      impulse.y = -impulse.y;
      impulse.z = -impulse.z;
      const Px = impulse.x;
      const Py = impulse.y;

      cAx -= mA * Px;
      cAy -= mA * Py;
      aA -= iA * (rA.x * Py - rA.y * Px + impulse.z);

      cBx += mB * Px;
      cBy += mB * Py;
      aB += iB * (rB.x * Py - rB.y * Px + impulse.z);
    }

    positions[oA] = cAx;
    positions[oA + 1] = cAy;
    positions[oA + 2] = aA;
    positions[oB] = cBx;
    positions[oB + 1] = cBy;
    positions[oB + 2] = aB;

    return positionError <= b2_linearSlop && angularError <= b2_angularSlop;
  }

  override GetAnchorA(out: b2Vec2): b2Vec2 {
    return this.m_bodyA.GetWorldPoint(this.m_localAnchorA, out);
  }

  override GetAnchorB(out: b2Vec2): b2Vec2 {
    return this.m_bodyB.GetWorldPoint(this.m_localAnchorB, out);
  }

  override GetReactionForce(inv_dt: number, out: b2Vec2): b2Vec2 {
    return out.Set(inv_dt * this.m_impulse.x, inv_dt * this.m_impulse.y);
  }

  override GetReactionTorque(inv_dt: number): number {
    return inv_dt * this.m_impulse.z;
  }

  /** The local anchor point relative to bodyA's origin. */
  GetLocalAnchorA(): Readonly<b2Vec2> {
    return this.m_localAnchorA;
  }

  /** The local anchor point relative to bodyB's origin. */
  GetLocalAnchorB(): Readonly<b2Vec2> {
    return this.m_localAnchorB;
  }

  /** Get the reference angle. */
  GetReferenceAngle(): number {
    return this.m_referenceAngle;
  }

  /** Set/get frequency in Hz. */
  SetFrequency(hz: number): void {
    b2CheckJointAlive(this, 'b2WeldJoint.SetFrequency');
    b2CheckNonNegative('b2WeldJoint.SetFrequency', 'hz', hz);
    this.m_frequencyHz = hz;
  }

  GetFrequency(): number {
    return this.m_frequencyHz;
  }

  /** Set/get damping ratio. */
  SetDampingRatio(ratio: number): void {
    b2CheckJointAlive(this, 'b2WeldJoint.SetDampingRatio');
    b2CheckNonNegative('b2WeldJoint.SetDampingRatio', 'ratio', ratio);
    this.m_dampingRatio = ratio;
  }

  GetDampingRatio(): number {
    return this.m_dampingRatio;
  }

  /** Dump to b2Log. */
  override Dump(): void {
    const indexA = this.m_bodyA.m_islandIndex;
    const indexB = this.m_bodyB.m_islandIndex;

    b2Log('  b2WeldJointDef jd;\n');
    b2Log('  jd.bodyA = bodies[%d];\n', indexA);
    b2Log('  jd.bodyB = bodies[%d];\n', indexB);
    b2Log('  jd.collideConnected = bool(%d);\n', this.m_collideConnected);
    b2Log('  jd.localAnchorA.Set(%.15lef, %.15lef);\n', this.m_localAnchorA.x, this.m_localAnchorA.y);
    b2Log('  jd.localAnchorB.Set(%.15lef, %.15lef);\n', this.m_localAnchorB.x, this.m_localAnchorB.y);
    b2Log('  jd.referenceAngle = %.15lef;\n', this.m_referenceAngle);
    b2Log('  jd.frequencyHz = %.15lef;\n', this.m_frequencyHz);
    b2Log('  jd.dampingRatio = %.15lef;\n', this.m_dampingRatio);
    b2Log('  joints[%d] = m_world->CreateJoint(&jd);\n', this.m_index);
  }
}
