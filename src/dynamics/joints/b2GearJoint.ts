/*
 * Gear joint (b2GearJoint.h, b2GearJoint.cpp).
 *
 * Gear Joint:
 * C0 = (coordinate1 + ratio * coordinate2)_initial
 * C = (coordinate1 + ratio * coordinate2) - C0 = 0
 * J = [J1 ratio * J2]
 * K = J * invM * JT
 *   = J1 * invM1 * J1T + ratio * ratio * J2 * invM2 * J2T
 *
 * Revolute:
 * coordinate = rotation
 * Cdot = angularVelocity
 * J = [0 0 1]
 * K = J * invM * JT = invI
 *
 * Prismatic:
 * coordinate = dot(p - pg, ug)
 * Cdot = dot(v + cross(w, r), ug)
 * J = [ug cross(r, ug)]
 * K = J * invM * JT = invMass + invI * cross(r, ug)^2
 *
 * This is a four-body constraint: the constructor replaces bodyA/bodyB with the moving bodies of
 * joint1/joint2 and keeps their grounds as bodyC/bodyD. Two of the four may be the same body, so
 * every solver step reads all four states before writing any, and writes them back in the C++
 * order A, B, C, D (the last write of a shared body wins, as in the C++).
 */

import { b2MulRV, b2MulTRV, b2Rot, b2SubVV, b2Vec2 } from '../../common/b2Math';
import { b2_linearSlop, b2Assert, b2Log } from '../../common/b2Settings';
import type { b2Body } from '../b2Body';
import type { b2SolverData } from '../b2TimeStep';
import { b2Joint, b2JointDef, b2JointType, b2CheckJointAlive } from './b2Joint';
import { b2CheckFinite } from '../../common/b2ArgumentError';
import type { b2PrismaticJoint } from './b2PrismaticJoint';
import type { b2RevoluteJoint } from './b2RevoluteJoint';

const s_qA = new b2Rot();
const s_qB = new b2Rot();
const s_qC = new b2Rot();
const s_qD = new b2Rot();
const s_u = new b2Vec2();
const s_rA = new b2Vec2();
const s_rB = new b2Vec2();
const s_rC = new b2Vec2();
const s_rD = new b2Vec2();
const s_p = new b2Vec2();
const s_JvAC = new b2Vec2();
const s_JvBD = new b2Vec2();

/**
 * Gear joint definition. This definition requires two existing revolute or prismatic joints (any
 * combination will work).
 */
export class b2GearJointDef extends b2JointDef {
  /** The first revolute/prismatic joint attached to the gear joint. */
  joint1: b2Joint | null = null;
  /** The second revolute/prismatic joint attached to the gear joint. */
  joint2: b2Joint | null = null;
  /**
   * The gear ratio.
   * @see b2GearJoint for explanation.
   */
  ratio = 1.0;

  constructor() {
    super(b2JointType.e_gearJoint);
  }
}

/**
 * A gear joint is used to connect two joints together. Either joint can be a revolute or
 * prismatic joint. You specify a gear ratio to bind the motions together:
 * coordinate1 + ratio * coordinate2 = constant
 * The ratio can be negative or positive. If one joint is a revolute joint and the other joint is
 * a prismatic joint, then the ratio will have units of length or units of 1/length.
 * @warning You have to manually destroy the gear joint if joint1 or joint2 is destroyed.
 */
export class b2GearJoint extends b2Joint {
  m_joint1: b2Joint;
  m_joint2: b2Joint;

  m_typeA = b2JointType.e_unknownJoint;
  m_typeB = b2JointType.e_unknownJoint;

  // Body A is connected to body C
  // Body B is connected to body D
  m_bodyC: b2Body;
  m_bodyD: b2Body;

  // Solver shared
  readonly m_localAnchorA = new b2Vec2();
  readonly m_localAnchorB = new b2Vec2();
  readonly m_localAnchorC = new b2Vec2();
  readonly m_localAnchorD = new b2Vec2();

  readonly m_localAxisC = new b2Vec2();
  readonly m_localAxisD = new b2Vec2();

  m_referenceAngleA = 0.0;
  m_referenceAngleB = 0.0;

  m_constant = 0.0;
  m_ratio = 0.0;

  m_impulse = 0.0;

  // Solver temp
  m_indexA = 0;
  m_indexB = 0;
  m_indexC = 0;
  m_indexD = 0;
  readonly m_lcA = new b2Vec2();
  readonly m_lcB = new b2Vec2();
  readonly m_lcC = new b2Vec2();
  readonly m_lcD = new b2Vec2();
  m_mA = 0.0;
  m_mB = 0.0;
  m_mC = 0.0;
  m_mD = 0.0;
  m_iA = 0.0;
  m_iB = 0.0;
  m_iC = 0.0;
  m_iD = 0.0;
  readonly m_JvAC = new b2Vec2();
  readonly m_JvBD = new b2Vec2();
  m_JwA = 0.0;
  m_JwB = 0.0;
  m_JwC = 0.0;
  m_JwD = 0.0;
  m_mass = 0.0;

  constructor(def: b2GearJointDef) {
    super(def);

    b2Assert(def.joint1 !== null && def.joint2 !== null, 'gear joint1 and joint2 must be set');
    this.m_joint1 = def.joint1;
    this.m_joint2 = def.joint2;

    this.m_typeA = this.m_joint1.GetType();
    this.m_typeB = this.m_joint2.GetType();

    b2Assert(this.m_typeA === b2JointType.e_revoluteJoint || this.m_typeA === b2JointType.e_prismaticJoint);
    b2Assert(this.m_typeB === b2JointType.e_revoluteJoint || this.m_typeB === b2JointType.e_prismaticJoint);

    let coordinateA: number;
    let coordinateB: number;

    // These replace the def's bodies; b2World.CreateJoint links the joint edges to them.
    this.m_bodyC = this.m_joint1.GetBodyA();
    this.m_bodyA = this.m_joint1.GetBodyB();

    // Get geometry of joint1
    this.m_bodyA.PullState();
    this.m_bodyC.PullState();
    const xfA = this.m_bodyA.m_xf;
    const aA = this.m_bodyA.m_sweep.a;
    const xfC = this.m_bodyC.m_xf;
    const aC = this.m_bodyC.m_sweep.a;

    if (this.m_typeA === b2JointType.e_revoluteJoint) {
      const revolute = def.joint1 as b2RevoluteJoint;
      this.m_localAnchorC.Assign(revolute.m_localAnchorA);
      this.m_localAnchorA.Assign(revolute.m_localAnchorB);
      this.m_referenceAngleA = revolute.m_referenceAngle;
      this.m_localAxisC.SetZero();

      coordinateA = aA - aC - this.m_referenceAngleA;
    } else {
      const prismatic = def.joint1 as b2PrismaticJoint;
      this.m_localAnchorC.Assign(prismatic.m_localAnchorA);
      this.m_localAnchorA.Assign(prismatic.m_localAnchorB);
      this.m_referenceAngleA = prismatic.m_referenceAngle;
      this.m_localAxisC.Assign(prismatic.m_localXAxisA);

      const pC = this.m_localAnchorC;
      const t = b2MulRV(xfA.q, this.m_localAnchorA, s_p);
      t.Set(t.x + (xfA.p.x - xfC.p.x), t.y + (xfA.p.y - xfC.p.y));
      const pA = b2MulTRV(xfC.q, t, s_p);
      coordinateA = (pA.x - pC.x) * this.m_localAxisC.x + (pA.y - pC.y) * this.m_localAxisC.y;
    }

    this.m_bodyD = this.m_joint2.GetBodyA();
    this.m_bodyB = this.m_joint2.GetBodyB();

    // Get geometry of joint2
    this.m_bodyB.PullState();
    this.m_bodyD.PullState();
    const xfB = this.m_bodyB.m_xf;
    const aB = this.m_bodyB.m_sweep.a;
    const xfD = this.m_bodyD.m_xf;
    const aD = this.m_bodyD.m_sweep.a;

    if (this.m_typeB === b2JointType.e_revoluteJoint) {
      const revolute = def.joint2 as b2RevoluteJoint;
      this.m_localAnchorD.Assign(revolute.m_localAnchorA);
      this.m_localAnchorB.Assign(revolute.m_localAnchorB);
      this.m_referenceAngleB = revolute.m_referenceAngle;
      this.m_localAxisD.SetZero();

      coordinateB = aB - aD - this.m_referenceAngleB;
    } else {
      const prismatic = def.joint2 as b2PrismaticJoint;
      this.m_localAnchorD.Assign(prismatic.m_localAnchorA);
      this.m_localAnchorB.Assign(prismatic.m_localAnchorB);
      this.m_referenceAngleB = prismatic.m_referenceAngle;
      this.m_localAxisD.Assign(prismatic.m_localXAxisA);

      const pD = this.m_localAnchorD;
      const t = b2MulRV(xfB.q, this.m_localAnchorB, s_p);
      t.Set(t.x + (xfB.p.x - xfD.p.x), t.y + (xfB.p.y - xfD.p.y));
      const pB = b2MulTRV(xfD.q, t, s_p);
      coordinateB = (pB.x - pD.x) * this.m_localAxisD.x + (pB.y - pD.y) * this.m_localAxisD.y;
    }

    this.m_ratio = def.ratio;

    this.m_constant = coordinateA + this.m_ratio * coordinateB;

    this.m_impulse = 0.0;
  }

  override InitVelocityConstraints(data: b2SolverData): void {
    const bA = this.m_bodyA;
    const bB = this.m_bodyB;
    const bC = this.m_bodyC;
    const bD = this.m_bodyD;
    this.m_indexA = bA.m_islandIndex;
    this.m_indexB = bB.m_islandIndex;
    this.m_indexC = bC.m_islandIndex;
    this.m_indexD = bD.m_islandIndex;
    this.m_lcA.Assign(bA.m_sweep.localCenter);
    this.m_lcB.Assign(bB.m_sweep.localCenter);
    this.m_lcC.Assign(bC.m_sweep.localCenter);
    this.m_lcD.Assign(bD.m_sweep.localCenter);
    this.m_mA = bA.m_invMass;
    this.m_mB = bB.m_invMass;
    this.m_mC = bC.m_invMass;
    this.m_mD = bD.m_invMass;
    this.m_iA = bA.m_invI;
    this.m_iB = bB.m_invI;
    this.m_iC = bC.m_invI;
    this.m_iD = bD.m_invI;

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

    const oC = 3 * this.m_indexC;
    const aC = data.positions[oC + 2];
    let vCx = velocities[oC];
    let vCy = velocities[oC + 1];
    let wC = velocities[oC + 2];

    const oD = 3 * this.m_indexD;
    const aD = data.positions[oD + 2];
    let vDx = velocities[oD];
    let vDy = velocities[oD + 1];
    let wD = velocities[oD + 2];

    this.m_mass = 0.0;

    if (this.m_typeA === b2JointType.e_revoluteJoint) {
      this.m_JvAC.SetZero();
      this.m_JwA = 1.0;
      this.m_JwC = 1.0;
      this.m_mass += this.m_iA + this.m_iC;
    } else {
      const qA = s_qA.Set(aA);
      const qC = s_qC.Set(aC);
      const u = b2MulRV(qC, this.m_localAxisC, s_u);
      const rC = b2MulRV(qC, b2SubVV(this.m_localAnchorC, this.m_lcC, s_rC), s_rC);
      const rA = b2MulRV(qA, b2SubVV(this.m_localAnchorA, this.m_lcA, s_rA), s_rA);
      this.m_JvAC.Assign(u);
      this.m_JwC = rC.x * u.y - rC.y * u.x;
      this.m_JwA = rA.x * u.y - rA.y * u.x;
      this.m_mass += this.m_mC + this.m_mA + this.m_iC * this.m_JwC * this.m_JwC + this.m_iA * this.m_JwA * this.m_JwA;
    }

    if (this.m_typeB === b2JointType.e_revoluteJoint) {
      this.m_JvBD.SetZero();
      this.m_JwB = this.m_ratio;
      this.m_JwD = this.m_ratio;
      this.m_mass += this.m_ratio * this.m_ratio * (this.m_iB + this.m_iD);
    } else {
      const qB = s_qB.Set(aB);
      const qD = s_qD.Set(aD);
      const u = b2MulRV(qD, this.m_localAxisD, s_u);
      const rD = b2MulRV(qD, b2SubVV(this.m_localAnchorD, this.m_lcD, s_rD), s_rD);
      const rB = b2MulRV(qB, b2SubVV(this.m_localAnchorB, this.m_lcB, s_rB), s_rB);
      this.m_JvBD.Set(this.m_ratio * u.x, this.m_ratio * u.y);
      this.m_JwD = this.m_ratio * (rD.x * u.y - rD.y * u.x);
      this.m_JwB = this.m_ratio * (rB.x * u.y - rB.y * u.x);
      this.m_mass += this.m_ratio * this.m_ratio * (this.m_mD + this.m_mB) + this.m_iD * this.m_JwD * this.m_JwD + this.m_iB * this.m_JwB * this.m_JwB;
    }

    // Compute effective mass.
    this.m_mass = this.m_mass > 0.0 ? 1.0 / this.m_mass : 0.0;

    if (data.step.warmStarting) {
      const impulse = this.m_impulse;
      const JvAC = this.m_JvAC;
      const JvBD = this.m_JvBD;
      const sA = this.m_mA * impulse;
      vAx += sA * JvAC.x;
      vAy += sA * JvAC.y;
      wA += this.m_iA * impulse * this.m_JwA;
      const sB = this.m_mB * impulse;
      vBx += sB * JvBD.x;
      vBy += sB * JvBD.y;
      wB += this.m_iB * impulse * this.m_JwB;
      const sC = this.m_mC * impulse;
      vCx -= sC * JvAC.x;
      vCy -= sC * JvAC.y;
      wC -= this.m_iC * impulse * this.m_JwC;
      const sD = this.m_mD * impulse;
      vDx -= sD * JvBD.x;
      vDy -= sD * JvBD.y;
      wD -= this.m_iD * impulse * this.m_JwD;
    } else {
      this.m_impulse = 0.0;
    }

    velocities[oA] = vAx;
    velocities[oA + 1] = vAy;
    velocities[oA + 2] = wA;
    velocities[oB] = vBx;
    velocities[oB + 1] = vBy;
    velocities[oB + 2] = wB;
    velocities[oC] = vCx;
    velocities[oC + 1] = vCy;
    velocities[oC + 2] = wC;
    velocities[oD] = vDx;
    velocities[oD + 1] = vDy;
    velocities[oD + 2] = wD;
  }

  override SolveVelocityConstraints(data: b2SolverData): void {
    const oA = 3 * this.m_indexA;
    const velocities = data.velocities;
    const oB = 3 * this.m_indexB;
    const oC = 3 * this.m_indexC;
    const oD = 3 * this.m_indexD;
    let vAx = velocities[oA];
    let vAy = velocities[oA + 1];
    let wA = velocities[oA + 2];
    let vBx = velocities[oB];
    let vBy = velocities[oB + 1];
    let wB = velocities[oB + 2];
    let vCx = velocities[oC];
    let vCy = velocities[oC + 1];
    let wC = velocities[oC + 2];
    let vDx = velocities[oD];
    let vDy = velocities[oD + 1];
    let wD = velocities[oD + 2];

    const JvAC = this.m_JvAC;
    const JvBD = this.m_JvBD;

    let Cdot = JvAC.x * (vAx - vCx) + JvAC.y * (vAy - vCy) + (JvBD.x * (vBx - vDx) + JvBD.y * (vBy - vDy));
    Cdot += this.m_JwA * wA - this.m_JwC * wC + (this.m_JwB * wB - this.m_JwD * wD);

    const impulse = -this.m_mass * Cdot;
    this.m_impulse += impulse;

    const sA = this.m_mA * impulse;
    vAx += sA * JvAC.x;
    vAy += sA * JvAC.y;
    wA += this.m_iA * impulse * this.m_JwA;
    const sB = this.m_mB * impulse;
    vBx += sB * JvBD.x;
    vBy += sB * JvBD.y;
    wB += this.m_iB * impulse * this.m_JwB;
    const sC = this.m_mC * impulse;
    vCx -= sC * JvAC.x;
    vCy -= sC * JvAC.y;
    wC -= this.m_iC * impulse * this.m_JwC;
    const sD = this.m_mD * impulse;
    vDx -= sD * JvBD.x;
    vDy -= sD * JvBD.y;
    wD -= this.m_iD * impulse * this.m_JwD;

    velocities[oA] = vAx;
    velocities[oA + 1] = vAy;
    velocities[oA + 2] = wA;
    velocities[oB] = vBx;
    velocities[oB + 1] = vBy;
    velocities[oB + 2] = wB;
    velocities[oC] = vCx;
    velocities[oC + 1] = vCy;
    velocities[oC + 2] = wC;
    velocities[oD] = vDx;
    velocities[oD + 1] = vDy;
    velocities[oD + 2] = wD;
  }

  override SolvePositionConstraints(data: b2SolverData): boolean {
    const oA = 3 * this.m_indexA;
    const positions = data.positions;
    const oB = 3 * this.m_indexB;
    const oC = 3 * this.m_indexC;
    const oD = 3 * this.m_indexD;
    let cAx = positions[oA];
    let cAy = positions[oA + 1];
    let aA = positions[oA + 2];
    let cBx = positions[oB];
    let cBy = positions[oB + 1];
    let aB = positions[oB + 2];
    let cCx = positions[oC];
    let cCy = positions[oC + 1];
    let aC = positions[oC + 2];
    let cDx = positions[oD];
    let cDy = positions[oD + 1];
    let aD = positions[oD + 2];

    const linearError = 0.0;

    let coordinateA: number;
    let coordinateB: number;

    const JvAC = s_JvAC;
    const JvBD = s_JvBD;
    let JwA: number;
    let JwB: number;
    let JwC: number;
    let JwD: number;
    let mass = 0.0;

    if (this.m_typeA === b2JointType.e_revoluteJoint) {
      JvAC.SetZero();
      JwA = 1.0;
      JwC = 1.0;
      mass += this.m_iA + this.m_iC;

      coordinateA = aA - aC - this.m_referenceAngleA;
    } else {
      const qA = s_qA.Set(aA);
      const qC = s_qC.Set(aC);
      const u = b2MulRV(qC, this.m_localAxisC, s_u);
      const rC = b2MulRV(qC, b2SubVV(this.m_localAnchorC, this.m_lcC, s_rC), s_rC);
      const rA = b2MulRV(qA, b2SubVV(this.m_localAnchorA, this.m_lcA, s_rA), s_rA);
      JvAC.Assign(u);
      JwC = rC.x * u.y - rC.y * u.x;
      JwA = rA.x * u.y - rA.y * u.x;
      mass += this.m_mC + this.m_mA + this.m_iC * JwC * JwC + this.m_iA * JwA * JwA;

      const pCx = this.m_localAnchorC.x - this.m_lcC.x;
      const pCy = this.m_localAnchorC.y - this.m_lcC.y;
      const pA = b2MulTRV(qC, s_p.Set(rA.x + (cAx - cCx), rA.y + (cAy - cCy)), s_p);
      coordinateA = (pA.x - pCx) * this.m_localAxisC.x + (pA.y - pCy) * this.m_localAxisC.y;
    }

    if (this.m_typeB === b2JointType.e_revoluteJoint) {
      JvBD.SetZero();
      JwB = this.m_ratio;
      JwD = this.m_ratio;
      mass += this.m_ratio * this.m_ratio * (this.m_iB + this.m_iD);

      coordinateB = aB - aD - this.m_referenceAngleB;
    } else {
      const qB = s_qB.Set(aB);
      const qD = s_qD.Set(aD);
      const u = b2MulRV(qD, this.m_localAxisD, s_u);
      const rD = b2MulRV(qD, b2SubVV(this.m_localAnchorD, this.m_lcD, s_rD), s_rD);
      const rB = b2MulRV(qB, b2SubVV(this.m_localAnchorB, this.m_lcB, s_rB), s_rB);
      JvBD.Set(this.m_ratio * u.x, this.m_ratio * u.y);
      JwD = this.m_ratio * (rD.x * u.y - rD.y * u.x);
      JwB = this.m_ratio * (rB.x * u.y - rB.y * u.x);
      mass += this.m_ratio * this.m_ratio * (this.m_mD + this.m_mB) + this.m_iD * JwD * JwD + this.m_iB * JwB * JwB;

      const pDx = this.m_localAnchorD.x - this.m_lcD.x;
      const pDy = this.m_localAnchorD.y - this.m_lcD.y;
      const pB = b2MulTRV(qD, s_p.Set(rB.x + (cBx - cDx), rB.y + (cBy - cDy)), s_p);
      coordinateB = (pB.x - pDx) * this.m_localAxisD.x + (pB.y - pDy) * this.m_localAxisD.y;
    }

    const C = coordinateA + this.m_ratio * coordinateB - this.m_constant;

    let impulse = 0.0;
    if (mass > 0.0) {
      impulse = -C / mass;
    }

    const sA = this.m_mA * impulse;
    cAx += sA * JvAC.x;
    cAy += sA * JvAC.y;
    aA += this.m_iA * impulse * JwA;
    const sB = this.m_mB * impulse;
    cBx += sB * JvBD.x;
    cBy += sB * JvBD.y;
    aB += this.m_iB * impulse * JwB;
    const sC = this.m_mC * impulse;
    cCx -= sC * JvAC.x;
    cCy -= sC * JvAC.y;
    aC -= this.m_iC * impulse * JwC;
    const sD = this.m_mD * impulse;
    cDx -= sD * JvBD.x;
    cDy -= sD * JvBD.y;
    aD -= this.m_iD * impulse * JwD;

    positions[oA] = cAx;
    positions[oA + 1] = cAy;
    positions[oA + 2] = aA;
    positions[oB] = cBx;
    positions[oB + 1] = cBy;
    positions[oB + 2] = aB;
    positions[oC] = cCx;
    positions[oC + 1] = cCy;
    positions[oC + 2] = aC;
    positions[oD] = cDx;
    positions[oD + 1] = cDy;
    positions[oD + 2] = aD;

    // 2.2.1 never measures the gear's position error, so the gear always reports success.
    return linearError < b2_linearSlop;
  }

  override GetAnchorA(out: b2Vec2): b2Vec2 {
    return this.m_bodyA.GetWorldPoint(this.m_localAnchorA, out);
  }

  override GetAnchorB(out: b2Vec2): b2Vec2 {
    return this.m_bodyB.GetWorldPoint(this.m_localAnchorB, out);
  }

  override GetReactionForce(inv_dt: number, out: b2Vec2): b2Vec2 {
    const Px = this.m_impulse * this.m_JvAC.x;
    const Py = this.m_impulse * this.m_JvAC.y;
    return out.Set(inv_dt * Px, inv_dt * Py);
  }

  override GetReactionTorque(inv_dt: number): number {
    const L = this.m_impulse * this.m_JwA;
    return inv_dt * L;
  }

  /** Get the first joint. */
  GetJoint1(): b2Joint {
    return this.m_joint1;
  }

  /** Get the second joint. */
  GetJoint2(): b2Joint {
    return this.m_joint2;
  }

  /** Set/Get the gear ratio. */
  SetRatio(ratio: number): void {
    b2CheckJointAlive(this, 'b2GearJoint.SetRatio');
    b2CheckFinite('b2GearJoint.SetRatio', 'ratio', ratio);
    this.m_ratio = ratio;
  }

  GetRatio(): number {
    return this.m_ratio;
  }

  /** Dump joint to b2Log. */
  override Dump(): void {
    const indexA = this.m_bodyA.m_islandIndex;
    const indexB = this.m_bodyB.m_islandIndex;

    const index1 = this.m_joint1.m_index;
    const index2 = this.m_joint2.m_index;

    b2Log('  b2GearJointDef jd;\n');
    b2Log('  jd.bodyA = bodies[%d];\n', indexA);
    b2Log('  jd.bodyB = bodies[%d];\n', indexB);
    b2Log('  jd.collideConnected = bool(%d);\n', this.m_collideConnected);
    b2Log('  jd.joint1 = joints[%d];\n', index1);
    b2Log('  jd.joint2 = joints[%d];\n', index2);
    b2Log('  jd.ratio = %.15lef;\n', this.m_ratio);
    b2Log('  joints[%d] = m_world->CreateJoint(&jd);\n', this.m_index);
  }
}
