/*
 * Distance joint (b2DistanceJoint.h, b2DistanceJoint.cpp).
 *
 * 1-D constrained system
 * m (v2 - v1) = lambda
 * v2 + (beta/h) * x1 + gamma * lambda = 0, gamma has units of inverse mass.
 * x2 = x1 + h * v2
 *
 * 1-D mass-damper-spring system
 * m (v2 - v1) + h * d * v2 + h * k *
 *
 * C = norm(p2 - p1) - L
 * u = (p2 - p1) / norm(p2 - p1)
 * Cdot = dot(u, v2 + cross(w2, r2) - v1 - cross(w1, r1))
 * J = [-u -cross(r1, u) u cross(r2, u)]
 * K = J * invM * JT
 *   = invMass1 + invI1 * cross(r1, u)^2 + invMass2 + invI2 * cross(r2, u)^2
 */

import { b2Abs, b2Clamp, b2MulRV, b2Rot, b2SubVV, b2Vec2 } from '../../common/b2Math';
import { b2_linearSlop, b2_maxLinearCorrection, b2_pi, b2Log } from '../../common/b2Settings';
import type { b2Body } from '../b2Body';
import type { b2SolverData } from '../b2TimeStep';
import { b2Joint, b2JointDef, b2JointType, b2CheckJointAlive } from './b2Joint';
import { b2CheckNonNegative } from '../../common/b2ArgumentError';

const s_qA = new b2Rot();
const s_qB = new b2Rot();
const s_rA = new b2Vec2();
const s_rB = new b2Vec2();
const s_u = new b2Vec2();

/**
 * Distance joint definition. This requires defining an anchor point on both bodies and the
 * non-zero length of the distance joint. The definition uses local anchor points so that the
 * initial configuration can violate the constraint slightly. This helps when saving and loading
 * a game.
 * @warning Do not use a zero or short length.
 */
export class b2DistanceJointDef extends b2JointDef {
  /** The local anchor point relative to bodyA's origin. */
  localAnchorA = new b2Vec2(0.0, 0.0);
  /** The local anchor point relative to bodyB's origin. */
  localAnchorB = new b2Vec2(0.0, 0.0);
  /** The natural length between the anchor points. */
  length = 1.0;
  /** The mass-spring-damper frequency in Hertz. A value of 0 disables softness. */
  frequencyHz = 0.0;
  /** The damping ratio. 0 = no damping, 1 = critical damping. */
  dampingRatio = 0.0;

  constructor() {
    super(b2JointType.e_distanceJoint);
  }

  /** Initialize the bodies, anchors, and length using the world anchors. */
  Initialize(b1: b2Body, b2: b2Body, anchor1: Readonly<b2Vec2>, anchor2: Readonly<b2Vec2>): void {
    this.bodyA = b1;
    this.bodyB = b2;
    b1.GetLocalPoint(anchor1, this.localAnchorA);
    b2.GetLocalPoint(anchor2, this.localAnchorB);
    const dx = anchor2.x - anchor1.x;
    const dy = anchor2.y - anchor1.y;
    this.length = Math.sqrt(dx * dx + dy * dy);
  }
}

/**
 * A distance joint constrains two points on two bodies to remain at a fixed distance from each
 * other. You can view this as a massless, rigid rod.
 */
export class b2DistanceJoint extends b2Joint {
  m_frequencyHz = 0.0;
  m_dampingRatio = 0.0;
  m_bias = 0.0;

  // Solver shared
  readonly m_localAnchorA = new b2Vec2();
  readonly m_localAnchorB = new b2Vec2();
  m_gamma = 0.0;
  m_impulse = 0.0;
  m_length = 0.0;

  // Solver temp
  m_indexA = 0;
  m_indexB = 0;
  readonly m_u = new b2Vec2();
  readonly m_rA = new b2Vec2();
  readonly m_rB = new b2Vec2();
  readonly m_localCenterA = new b2Vec2();
  readonly m_localCenterB = new b2Vec2();
  m_invMassA = 0.0;
  m_invMassB = 0.0;
  m_invIA = 0.0;
  m_invIB = 0.0;
  m_mass = 0.0;

  constructor(def: b2DistanceJointDef) {
    super(def);

    this.m_localAnchorA.Assign(def.localAnchorA);
    this.m_localAnchorB.Assign(def.localAnchorB);
    this.m_length = def.length;
    this.m_frequencyHz = def.frequencyHz;
    this.m_dampingRatio = def.dampingRatio;
    this.m_impulse = 0.0;
    this.m_gamma = 0.0;
    this.m_bias = 0.0;
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
    const positions = data.positions;
    const velocities = data.velocities;
    const cAx = positions[oA];
    const cAy = positions[oA + 1];
    const aA = positions[oA + 2];
    let vAx = velocities[oA];
    let vAy = velocities[oA + 1];
    let wA = velocities[oA + 2];

    const oB = 3 * this.m_indexB;
    const cBx = positions[oB];
    const cBy = positions[oB + 1];
    const aB = positions[oB + 2];
    let vBx = velocities[oB];
    let vBy = velocities[oB + 1];
    let wB = velocities[oB + 2];

    const qA = s_qA.Set(aA);
    const qB = s_qB.Set(aB);

    const rA = b2MulRV(qA, b2SubVV(this.m_localAnchorA, this.m_localCenterA, this.m_rA), this.m_rA);
    const rB = b2MulRV(qB, b2SubVV(this.m_localAnchorB, this.m_localCenterB, this.m_rB), this.m_rB);
    const u = this.m_u.Set(cBx + rB.x - cAx - rA.x, cBy + rB.y - cAy - rA.y);

    // Handle singularity.
    const length = u.Length();
    if (length > b2_linearSlop) {
      u.Multiply(1.0 / length);
    } else {
      u.Set(0.0, 0.0);
    }

    const crAu = rA.x * u.y - rA.y * u.x;
    const crBu = rB.x * u.y - rB.y * u.x;
    let invMass = this.m_invMassA + this.m_invIA * crAu * crAu + this.m_invMassB + this.m_invIB * crBu * crBu;

    // Compute the effective mass matrix.
    this.m_mass = invMass !== 0.0 ? 1.0 / invMass : 0.0;

    if (this.m_frequencyHz > 0.0) {
      const C = length - this.m_length;

      // Frequency
      const omega = 2.0 * b2_pi * this.m_frequencyHz;

      // Damping coefficient
      const d = 2.0 * this.m_mass * this.m_dampingRatio * omega;

      // Spring stiffness
      const k = this.m_mass * omega * omega;

      // magic formulas
      const h = data.step.dt;
      this.m_gamma = h * (d + h * k);
      this.m_gamma = this.m_gamma !== 0.0 ? 1.0 / this.m_gamma : 0.0;
      this.m_bias = C * h * k * this.m_gamma;

      invMass += this.m_gamma;
      this.m_mass = invMass !== 0.0 ? 1.0 / invMass : 0.0;
    } else {
      this.m_gamma = 0.0;
      this.m_bias = 0.0;
    }

    if (data.step.warmStarting) {
      // Scale the impulse to support a variable time step.
      this.m_impulse *= data.step.dtRatio;

      const Px = this.m_impulse * u.x;
      const Py = this.m_impulse * u.y;
      vAx -= this.m_invMassA * Px;
      vAy -= this.m_invMassA * Py;
      wA -= this.m_invIA * (rA.x * Py - rA.y * Px);
      vBx += this.m_invMassB * Px;
      vBy += this.m_invMassB * Py;
      wB += this.m_invIB * (rB.x * Py - rB.y * Px);
    } else {
      this.m_impulse = 0.0;
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

    const rA = this.m_rA;
    const rB = this.m_rB;
    const u = this.m_u;

    // Cdot = dot(u, v + cross(w, r))
    const vpAx = vAx - wA * rA.y;
    const vpAy = vAy + wA * rA.x;
    const vpBx = vBx - wB * rB.y;
    const vpBy = vBy + wB * rB.x;
    const Cdot = u.x * (vpBx - vpAx) + u.y * (vpBy - vpAy);

    const impulse = -this.m_mass * (Cdot + this.m_bias + this.m_gamma * this.m_impulse);
    this.m_impulse += impulse;

    const Px = impulse * u.x;
    const Py = impulse * u.y;
    vAx -= this.m_invMassA * Px;
    vAy -= this.m_invMassA * Py;
    wA -= this.m_invIA * (rA.x * Py - rA.y * Px);
    vBx += this.m_invMassB * Px;
    vBy += this.m_invMassB * Py;
    wB += this.m_invIB * (rB.x * Py - rB.y * Px);

    velocities[oA] = vAx;
    velocities[oA + 1] = vAy;
    velocities[oA + 2] = wA;
    velocities[oB] = vBx;
    velocities[oB + 1] = vBy;
    velocities[oB + 2] = wB;
  }

  override SolvePositionConstraints(data: b2SolverData): boolean {
    if (this.m_frequencyHz > 0.0) {
      // There is no position correction for soft distance constraints.
      return true;
    }

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

    const rA = b2MulRV(qA, b2SubVV(this.m_localAnchorA, this.m_localCenterA, s_rA), s_rA);
    const rB = b2MulRV(qB, b2SubVV(this.m_localAnchorB, this.m_localCenterB, s_rB), s_rB);
    const u = s_u.Set(cBx + rB.x - cAx - rA.x, cBy + rB.y - cAy - rA.y);

    const length = u.Normalize();
    let C = length - this.m_length;
    C = b2Clamp(C, -b2_maxLinearCorrection, b2_maxLinearCorrection);

    const impulse = -this.m_mass * C;
    const Px = impulse * u.x;
    const Py = impulse * u.y;

    cAx -= this.m_invMassA * Px;
    cAy -= this.m_invMassA * Py;
    aA -= this.m_invIA * (rA.x * Py - rA.y * Px);
    cBx += this.m_invMassB * Px;
    cBy += this.m_invMassB * Py;
    aB += this.m_invIB * (rB.x * Py - rB.y * Px);

    positions[oA] = cAx;
    positions[oA + 1] = cAy;
    positions[oA + 2] = aA;
    positions[oB] = cBx;
    positions[oB + 1] = cBy;
    positions[oB + 2] = aB;

    return b2Abs(C) < b2_linearSlop;
  }

  override GetAnchorA(out: b2Vec2): b2Vec2 {
    return this.m_bodyA.GetWorldPoint(this.m_localAnchorA, out);
  }

  override GetAnchorB(out: b2Vec2): b2Vec2 {
    return this.m_bodyB.GetWorldPoint(this.m_localAnchorB, out);
  }

  /** Get the reaction force given the inverse time step. Unit is N. */
  override GetReactionForce(inv_dt: number, out: b2Vec2): b2Vec2 {
    const s = inv_dt * this.m_impulse;
    return out.Set(s * this.m_u.x, s * this.m_u.y);
  }

  /** Get the reaction torque given the inverse time step. Unit is N*m. This is always zero for a distance joint. */
  override GetReactionTorque(inv_dt: number): number {
    return 0.0;
  }

  /** The local anchor point relative to bodyA's origin. */
  GetLocalAnchorA(): Readonly<b2Vec2> {
    return this.m_localAnchorA;
  }

  /** The local anchor point relative to bodyB's origin. */
  GetLocalAnchorB(): Readonly<b2Vec2> {
    return this.m_localAnchorB;
  }

  /**
   * Set/get the natural length.
   * Manipulating the length can lead to non-physical behavior when the frequency is zero.
   */
  SetLength(length: number): void {
    b2CheckJointAlive(this, 'b2DistanceJoint.SetLength');
    b2CheckNonNegative('b2DistanceJoint.SetLength', 'length', length);
    this.m_length = length;
  }

  GetLength(): number {
    return this.m_length;
  }

  /** Set/get frequency in Hz. */
  SetFrequency(hz: number): void {
    b2CheckJointAlive(this, 'b2DistanceJoint.SetFrequency');
    b2CheckNonNegative('b2DistanceJoint.SetFrequency', 'hz', hz);
    this.m_frequencyHz = hz;
  }

  GetFrequency(): number {
    return this.m_frequencyHz;
  }

  /** Set/get damping ratio. */
  SetDampingRatio(ratio: number): void {
    b2CheckJointAlive(this, 'b2DistanceJoint.SetDampingRatio');
    b2CheckNonNegative('b2DistanceJoint.SetDampingRatio', 'ratio', ratio);
    this.m_dampingRatio = ratio;
  }

  GetDampingRatio(): number {
    return this.m_dampingRatio;
  }

  /** Dump joint to b2Log. */
  override Dump(): void {
    const indexA = this.m_bodyA.m_islandIndex;
    const indexB = this.m_bodyB.m_islandIndex;

    b2Log('  b2DistanceJointDef jd;\n');
    b2Log('  jd.bodyA = bodies[%d];\n', indexA);
    b2Log('  jd.bodyB = bodies[%d];\n', indexB);
    b2Log('  jd.collideConnected = bool(%d);\n', this.m_collideConnected);
    b2Log('  jd.localAnchorA.Set(%.15lef, %.15lef);\n', this.m_localAnchorA.x, this.m_localAnchorA.y);
    b2Log('  jd.localAnchorB.Set(%.15lef, %.15lef);\n', this.m_localAnchorB.x, this.m_localAnchorB.y);
    b2Log('  jd.length = %.15lef;\n', this.m_length);
    b2Log('  jd.frequencyHz = %.15lef;\n', this.m_frequencyHz);
    b2Log('  jd.dampingRatio = %.15lef;\n', this.m_dampingRatio);
    b2Log('  joints[%d] = m_world->CreateJoint(&jd);\n', this.m_index);
  }
}
