/*
 * Rope joint (b2RopeJoint.h, b2RopeJoint.cpp).
 *
 * Limit:
 * C = norm(pB - pA) - L
 * u = (pB - pA) / norm(pB - pA)
 * Cdot = dot(u, vB + cross(wB, rB) - vA - cross(wA, rA))
 * J = [-u -cross(rA, u) u cross(rB, u)]
 * K = J * invM * JT
 *   = invMassA + invIA * cross(rA, u)^2 + invMassB + invIB * cross(rB, u)^2
 */

import { b2Clamp, b2Min, b2MulRV, b2Rot, b2SubVV, b2Vec2 } from '../../common/b2Math';
import { b2_linearSlop, b2_maxLinearCorrection, b2Log } from '../../common/b2Settings';
import type { b2SolverData } from '../b2TimeStep';
import { b2Joint, b2JointDef, b2JointType, b2LimitState, b2CheckJointAlive } from './b2Joint';
import { b2CheckPositive } from '../../common/b2ArgumentError';

const s_qA = new b2Rot();
const s_qB = new b2Rot();
const s_rA = new b2Vec2();
const s_rB = new b2Vec2();
const s_u = new b2Vec2();

/**
 * Rope joint definition. This requires two body anchor points and a maximum lengths.
 * Note: by default the connected objects will not collide. see collideConnected in b2JointDef.
 */
export class b2RopeJointDef extends b2JointDef {
  /** The local anchor point relative to bodyA's origin. */
  localAnchorA = new b2Vec2(-1.0, 0.0);
  /** The local anchor point relative to bodyB's origin. */
  localAnchorB = new b2Vec2(1.0, 0.0);
  /**
   * The maximum length of the rope.
   * Warning: this must be larger than b2_linearSlop or the joint will have no effect.
   */
  maxLength = 0.0;

  constructor() {
    super(b2JointType.e_ropeJoint);
  }
}

/**
 * A rope joint enforces a maximum distance between two points on two bodies. It has no other
 * effect.
 * Warning: if you attempt to change the maximum length during the simulation you will get some
 * non-physical behavior. A model that would allow you to dynamically modify the length would
 * have some sponginess, so I chose not to implement it that way. See b2DistanceJoint if you
 * want to dynamically control length.
 */
export class b2RopeJoint extends b2Joint {
  // Solver shared
  readonly m_localAnchorA = new b2Vec2();
  readonly m_localAnchorB = new b2Vec2();
  m_maxLength = 0.0;
  m_length = 0.0;
  m_impulse = 0.0;

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
  m_state = b2LimitState.e_inactiveLimit;

  constructor(def: b2RopeJointDef) {
    super(def);

    this.m_localAnchorA.Assign(def.localAnchorA);
    this.m_localAnchorB.Assign(def.localAnchorB);

    this.m_maxLength = def.maxLength;

    this.m_mass = 0.0;
    this.m_impulse = 0.0;
    this.m_state = b2LimitState.e_inactiveLimit;
    this.m_length = 0.0;
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

    this.m_length = u.Length();

    const C = this.m_length - this.m_maxLength;
    if (C > 0.0) {
      this.m_state = b2LimitState.e_atUpperLimit;
    } else {
      this.m_state = b2LimitState.e_inactiveLimit;
    }

    if (this.m_length > b2_linearSlop) {
      u.Multiply(1.0 / this.m_length);
    } else {
      u.SetZero();
      this.m_mass = 0.0;
      this.m_impulse = 0.0;
      return;
    }

    // Compute effective mass.
    const crA = rA.x * u.y - rA.y * u.x;
    const crB = rB.x * u.y - rB.y * u.x;
    const invMass = this.m_invMassA + this.m_invIA * crA * crA + this.m_invMassB + this.m_invIB * crB * crB;

    this.m_mass = invMass !== 0.0 ? 1.0 / invMass : 0.0;

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
    const C = this.m_length - this.m_maxLength;
    let Cdot = u.x * (vpBx - vpAx) + u.y * (vpBy - vpAy);

    // Predictive constraint.
    if (C < 0.0) {
      Cdot += data.step.inv_dt * C;
    }

    let impulse = -this.m_mass * Cdot;
    const oldImpulse = this.m_impulse;
    this.m_impulse = b2Min(0.0, this.m_impulse + impulse);
    impulse = this.m_impulse - oldImpulse;

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
    let C = length - this.m_maxLength;

    C = b2Clamp(C, 0.0, b2_maxLinearCorrection);

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

    return length - this.m_maxLength < b2_linearSlop;
  }

  override GetAnchorA(out: b2Vec2): b2Vec2 {
    return this.m_bodyA.GetWorldPoint(this.m_localAnchorA, out);
  }

  override GetAnchorB(out: b2Vec2): b2Vec2 {
    return this.m_bodyB.GetWorldPoint(this.m_localAnchorB, out);
  }

  override GetReactionForce(inv_dt: number, out: b2Vec2): b2Vec2 {
    const s = inv_dt * this.m_impulse;
    return out.Set(s * this.m_u.x, s * this.m_u.y);
  }

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

  /** Set/Get the maximum length of the rope. */
  SetMaxLength(length: number): void {
    b2CheckJointAlive(this, 'b2RopeJoint.SetMaxLength');
    b2CheckPositive('b2RopeJoint.SetMaxLength', 'length', length);
    this.m_maxLength = length;
  }

  GetMaxLength(): number {
    return this.m_maxLength;
  }

  GetLimitState(): b2LimitState {
    return this.m_state;
  }

  /** Dump joint to b2Log. */
  override Dump(): void {
    const indexA = this.m_bodyA.m_islandIndex;
    const indexB = this.m_bodyB.m_islandIndex;

    b2Log('  b2RopeJointDef jd;\n');
    b2Log('  jd.bodyA = bodies[%d];\n', indexA);
    b2Log('  jd.bodyB = bodies[%d];\n', indexB);
    b2Log('  jd.collideConnected = bool(%d);\n', this.m_collideConnected);
    b2Log('  jd.localAnchorA.Set(%.15lef, %.15lef);\n', this.m_localAnchorA.x, this.m_localAnchorA.y);
    b2Log('  jd.localAnchorB.Set(%.15lef, %.15lef);\n', this.m_localAnchorB.x, this.m_localAnchorB.y);
    b2Log('  jd.maxLength = %.15lef;\n', this.m_maxLength);
    b2Log('  joints[%d] = m_world->CreateJoint(&jd);\n', this.m_index);
  }
}
