/*
 * Pulley joint (b2PulleyJoint.h, b2PulleyJoint.cpp).
 *
 * Pulley:
 * length1 = norm(p1 - s1)
 * length2 = norm(p2 - s2)
 * C0 = (length1 + ratio * length2)_initial
 * C = C0 - (length1 + ratio * length2)
 * u1 = (p1 - s1) / norm(p1 - s1)
 * u2 = (p2 - s2) / norm(p2 - s2)
 * Cdot = -dot(u1, v1 + cross(w1, r1)) - ratio * dot(u2, v2 + cross(w2, r2))
 * J = -[u1 cross(r1, u1) ratio * u2  ratio * cross(r2, u2)]
 * K = J * invM * JT
 *   = invMass1 + invI1 * cross(r1, u1)^2 + ratio^2 * (invMass2 + invI2 * cross(r2, u2)^2)
 */

import { b2Abs, b2MulRV, b2Rot, b2SubVV, b2Vec2 } from '../../common/b2Math';
import { b2_epsilon, b2_linearSlop, b2Assert, b2Log } from '../../common/b2Settings';
import type { b2Body } from '../b2Body';
import type { b2SolverData } from '../b2TimeStep';
import { b2Joint, b2JointDef, b2JointType } from './b2Joint';

/** Declared by b2PulleyJoint.h; the 2.2.1 solver does not use it. */
export const b2_minPulleyLength = 2.0;

const s_qA = new b2Rot();
const s_qB = new b2Rot();
const s_rA = new b2Vec2();
const s_rB = new b2Vec2();
const s_uA = new b2Vec2();
const s_uB = new b2Vec2();
const s_p = new b2Vec2();

/** Pulley joint definition. This requires two ground anchors, two dynamic body anchor points, and a pulley ratio. */
export class b2PulleyJointDef extends b2JointDef {
  /** The first ground anchor in world coordinates. This point never moves. */
  groundAnchorA = new b2Vec2(-1.0, 1.0);
  /** The second ground anchor in world coordinates. This point never moves. */
  groundAnchorB = new b2Vec2(1.0, 1.0);
  /** The local anchor point relative to bodyA's origin. */
  localAnchorA = new b2Vec2(-1.0, 0.0);
  /** The local anchor point relative to bodyB's origin. */
  localAnchorB = new b2Vec2(1.0, 0.0);
  /** The a reference length for the segment attached to bodyA. */
  lengthA = 0.0;
  /** The a reference length for the segment attached to bodyB. */
  lengthB = 0.0;
  /** The pulley ratio, used to simulate a block-and-tackle. */
  ratio = 1.0;

  constructor() {
    super(b2JointType.e_pulleyJoint);
    this.collideConnected = true;
  }

  /** Initialize the bodies, anchors, lengths, max lengths, and ratio using the world anchors. */
  Initialize(
    bA: b2Body,
    bB: b2Body,
    groundA: Readonly<b2Vec2>,
    groundB: Readonly<b2Vec2>,
    anchorA: Readonly<b2Vec2>,
    anchorB: Readonly<b2Vec2>,
    r: number,
  ): void {
    this.bodyA = bA;
    this.bodyB = bB;
    this.groundAnchorA.Assign(groundA);
    this.groundAnchorB.Assign(groundB);
    bA.GetLocalPoint(anchorA, this.localAnchorA);
    bB.GetLocalPoint(anchorB, this.localAnchorB);
    const dAx = anchorA.x - groundA.x;
    const dAy = anchorA.y - groundA.y;
    this.lengthA = Math.sqrt(dAx * dAx + dAy * dAy);
    const dBx = anchorB.x - groundB.x;
    const dBy = anchorB.y - groundB.y;
    this.lengthB = Math.sqrt(dBx * dBx + dBy * dBy);
    this.ratio = r;
    b2Assert(this.ratio > b2_epsilon, 'pulley ratio must be positive');
  }
}

/**
 * The pulley joint is connected to two bodies and two fixed ground points. The pulley supports a
 * ratio such that:
 * length1 + ratio * length2 <= constant
 * Yes, the force transmitted is scaled by the ratio.
 * Warning: the pulley joint can get a bit squirrelly by itself. They often work better when
 * combined with prismatic joints. You should also cover the the anchor points with static shapes
 * to prevent one side from going to zero length.
 */
export class b2PulleyJoint extends b2Joint {
  readonly m_groundAnchorA = new b2Vec2();
  readonly m_groundAnchorB = new b2Vec2();
  m_lengthA = 0.0;
  m_lengthB = 0.0;

  // Solver shared
  readonly m_localAnchorA = new b2Vec2();
  readonly m_localAnchorB = new b2Vec2();
  m_constant = 0.0;
  m_ratio = 0.0;
  m_impulse = 0.0;

  // Solver temp
  m_indexA = 0;
  m_indexB = 0;
  readonly m_uA = new b2Vec2();
  readonly m_uB = new b2Vec2();
  readonly m_rA = new b2Vec2();
  readonly m_rB = new b2Vec2();
  readonly m_localCenterA = new b2Vec2();
  readonly m_localCenterB = new b2Vec2();
  m_invMassA = 0.0;
  m_invMassB = 0.0;
  m_invIA = 0.0;
  m_invIB = 0.0;
  m_mass = 0.0;

  constructor(def: b2PulleyJointDef) {
    super(def);

    this.m_groundAnchorA.Assign(def.groundAnchorA);
    this.m_groundAnchorB.Assign(def.groundAnchorB);
    this.m_localAnchorA.Assign(def.localAnchorA);
    this.m_localAnchorB.Assign(def.localAnchorB);

    this.m_lengthA = def.lengthA;
    this.m_lengthB = def.lengthB;

    b2Assert(def.ratio !== 0.0, 'pulley ratio must not be zero');
    this.m_ratio = def.ratio;

    this.m_constant = def.lengthA + this.m_ratio * def.lengthB;

    this.m_impulse = 0.0;
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

    // Get the pulley axes.
    const uA = this.m_uA.Set(cAx + rA.x - this.m_groundAnchorA.x, cAy + rA.y - this.m_groundAnchorA.y);
    const uB = this.m_uB.Set(cBx + rB.x - this.m_groundAnchorB.x, cBy + rB.y - this.m_groundAnchorB.y);

    const lengthA = uA.Length();
    const lengthB = uB.Length();

    if (lengthA > 10.0 * b2_linearSlop) {
      uA.Multiply(1.0 / lengthA);
    } else {
      uA.SetZero();
    }

    if (lengthB > 10.0 * b2_linearSlop) {
      uB.Multiply(1.0 / lengthB);
    } else {
      uB.SetZero();
    }

    // Compute effective mass.
    const ruA = rA.x * uA.y - rA.y * uA.x;
    const ruB = rB.x * uB.y - rB.y * uB.x;

    const mA = this.m_invMassA + this.m_invIA * ruA * ruA;
    const mB = this.m_invMassB + this.m_invIB * ruB * ruB;

    this.m_mass = mA + this.m_ratio * this.m_ratio * mB;

    if (this.m_mass > 0.0) {
      this.m_mass = 1.0 / this.m_mass;
    }

    if (data.step.warmStarting) {
      // Scale impulses to support variable time steps.
      this.m_impulse *= data.step.dtRatio;

      // Warm starting.
      const sA = -this.m_impulse;
      const PAx = sA * uA.x;
      const PAy = sA * uA.y;
      const sB = -this.m_ratio * this.m_impulse;
      const PBx = sB * uB.x;
      const PBy = sB * uB.y;

      vAx += this.m_invMassA * PAx;
      vAy += this.m_invMassA * PAy;
      wA += this.m_invIA * (rA.x * PAy - rA.y * PAx);
      vBx += this.m_invMassB * PBx;
      vBy += this.m_invMassB * PBy;
      wB += this.m_invIB * (rB.x * PBy - rB.y * PBx);
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
    const uA = this.m_uA;
    const uB = this.m_uB;

    const vpAx = vAx - wA * rA.y;
    const vpAy = vAy + wA * rA.x;
    const vpBx = vBx - wB * rB.y;
    const vpBy = vBy + wB * rB.x;

    const Cdot = -(uA.x * vpAx + uA.y * vpAy) - this.m_ratio * (uB.x * vpBx + uB.y * vpBy);
    const impulse = -this.m_mass * Cdot;
    this.m_impulse += impulse;

    const sA = -impulse;
    const PAx = sA * uA.x;
    const PAy = sA * uA.y;
    const sB = -this.m_ratio * impulse;
    const PBx = sB * uB.x;
    const PBy = sB * uB.y;
    vAx += this.m_invMassA * PAx;
    vAy += this.m_invMassA * PAy;
    wA += this.m_invIA * (rA.x * PAy - rA.y * PAx);
    vBx += this.m_invMassB * PBx;
    vBy += this.m_invMassB * PBy;
    wB += this.m_invIB * (rB.x * PBy - rB.y * PBx);

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

    const rA = b2MulRV(qA, b2SubVV(this.m_localAnchorA, this.m_localCenterA, s_rA), s_rA);
    const rB = b2MulRV(qB, b2SubVV(this.m_localAnchorB, this.m_localCenterB, s_rB), s_rB);

    // Get the pulley axes.
    const uA = s_uA.Set(cAx + rA.x - this.m_groundAnchorA.x, cAy + rA.y - this.m_groundAnchorA.y);
    const uB = s_uB.Set(cBx + rB.x - this.m_groundAnchorB.x, cBy + rB.y - this.m_groundAnchorB.y);

    const lengthA = uA.Length();
    const lengthB = uB.Length();

    if (lengthA > 10.0 * b2_linearSlop) {
      uA.Multiply(1.0 / lengthA);
    } else {
      uA.SetZero();
    }

    if (lengthB > 10.0 * b2_linearSlop) {
      uB.Multiply(1.0 / lengthB);
    } else {
      uB.SetZero();
    }

    // Compute effective mass.
    const ruA = rA.x * uA.y - rA.y * uA.x;
    const ruB = rB.x * uB.y - rB.y * uB.x;

    const mA = this.m_invMassA + this.m_invIA * ruA * ruA;
    const mB = this.m_invMassB + this.m_invIB * ruB * ruB;

    let mass = mA + this.m_ratio * this.m_ratio * mB;

    if (mass > 0.0) {
      mass = 1.0 / mass;
    }

    const C = this.m_constant - lengthA - this.m_ratio * lengthB;
    const linearError = b2Abs(C);

    const impulse = -mass * C;

    const sA = -impulse;
    const PAx = sA * uA.x;
    const PAy = sA * uA.y;
    const sB = -this.m_ratio * impulse;
    const PBx = sB * uB.x;
    const PBy = sB * uB.y;

    cAx += this.m_invMassA * PAx;
    cAy += this.m_invMassA * PAy;
    aA += this.m_invIA * (rA.x * PAy - rA.y * PAx);
    cBx += this.m_invMassB * PBx;
    cBy += this.m_invMassB * PBy;
    aB += this.m_invIB * (rB.x * PBy - rB.y * PBx);

    positions[oA] = cAx;
    positions[oA + 1] = cAy;
    positions[oA + 2] = aA;
    positions[oB] = cBx;
    positions[oB + 1] = cBy;
    positions[oB + 2] = aB;

    return linearError < b2_linearSlop;
  }

  override GetAnchorA(out: b2Vec2): b2Vec2 {
    return this.m_bodyA.GetWorldPoint(this.m_localAnchorA, out);
  }

  override GetAnchorB(out: b2Vec2): b2Vec2 {
    return this.m_bodyB.GetWorldPoint(this.m_localAnchorB, out);
  }

  override GetReactionForce(inv_dt: number, out: b2Vec2): b2Vec2 {
    const Px = this.m_impulse * this.m_uB.x;
    const Py = this.m_impulse * this.m_uB.y;
    return out.Set(inv_dt * Px, inv_dt * Py);
  }

  override GetReactionTorque(inv_dt: number): number {
    return 0.0;
  }

  /** Get the first ground anchor. */
  GetGroundAnchorA(out: b2Vec2): b2Vec2 {
    return out.Assign(this.m_groundAnchorA);
  }

  /** Get the second ground anchor. */
  GetGroundAnchorB(out: b2Vec2): b2Vec2 {
    return out.Assign(this.m_groundAnchorB);
  }

  /** Get the current length of the segment attached to bodyA. */
  GetLengthA(): number {
    const p = this.m_bodyA.GetWorldPoint(this.m_localAnchorA, s_p);
    const s = this.m_groundAnchorA;
    const dx = p.x - s.x;
    const dy = p.y - s.y;
    return Math.sqrt(dx * dx + dy * dy);
  }

  /** Get the current length of the segment attached to bodyB. */
  GetLengthB(): number {
    const p = this.m_bodyB.GetWorldPoint(this.m_localAnchorB, s_p);
    const s = this.m_groundAnchorB;
    const dx = p.x - s.x;
    const dy = p.y - s.y;
    return Math.sqrt(dx * dx + dy * dy);
  }

  /** Get the pulley ratio. */
  GetRatio(): number {
    return this.m_ratio;
  }

  /** Dump joint to b2Log. */
  override Dump(): void {
    const indexA = this.m_bodyA.m_islandIndex;
    const indexB = this.m_bodyB.m_islandIndex;

    b2Log('  b2PulleyJointDef jd;\n');
    b2Log('  jd.bodyA = bodies[%d];\n', indexA);
    b2Log('  jd.bodyB = bodies[%d];\n', indexB);
    b2Log('  jd.collideConnected = bool(%d);\n', this.m_collideConnected);
    b2Log('  jd.groundAnchorA.Set(%.15lef, %.15lef);\n', this.m_groundAnchorA.x, this.m_groundAnchorA.y);
    b2Log('  jd.groundAnchorB.Set(%.15lef, %.15lef);\n', this.m_groundAnchorB.x, this.m_groundAnchorB.y);
    b2Log('  jd.localAnchorA.Set(%.15lef, %.15lef);\n', this.m_localAnchorA.x, this.m_localAnchorA.y);
    b2Log('  jd.localAnchorB.Set(%.15lef, %.15lef);\n', this.m_localAnchorB.x, this.m_localAnchorB.y);
    b2Log('  jd.lengthA = %.15lef;\n', this.m_lengthA);
    b2Log('  jd.lengthB = %.15lef;\n', this.m_lengthB);
    b2Log('  jd.ratio = %.15lef;\n', this.m_ratio);
    b2Log('  joints[%d] = m_world->CreateJoint(&jd);\n', this.m_index);
  }
}
