/*
 * Revolute joint (b2RevoluteJoint.h, b2RevoluteJoint.cpp).
 *
 * Point-to-point constraint
 * C = p2 - p1
 * Cdot = v2 - v1
 *      = v2 + cross(w2, r2) - v1 - cross(w1, r1)
 * J = [-I -r1_skew I r2_skew ]
 * Identity used:
 * w k % (rx i + ry j) = w * (-ry i + rx j)
 *
 * Motor constraint
 * Cdot = w2 - w1
 * J = [0 0 -1 0 0 1]
 * K = invI1 + invI2
 *
 * The solver keeps body state in scalar locals: `vB + b2Cross(wB, rB)` is `vB.x - wB * rB.y`,
 * `vB.y + wB * rB.x`, the same IEEE operations as the C++ vector code.
 */

import { b2Abs, b2Clamp, b2Rot, b2Vec2, b2Vec3 } from '../../common/b2Math';
import { b2_angularSlop, b2_linearSlop, b2_maxAngularCorrection, b2Log } from '../../common/b2Settings';
import type { b2Body } from '../b2Body';
import type { b2SolverData } from '../b2TimeStep';
import { b2Joint, b2JointDef, b2JointType, b2LimitState, b2CheckJointAlive } from './b2Joint';
import { b2CheckFinite, b2CheckLimits, b2CheckNonNegative } from '../../common/b2ArgumentError';

const s_qA = new b2Rot();
const s_qB = new b2Rot();
/** m_solverRecord before the joint's first InitVelocityConstraints. */
const s_noRecord = new Float64Array(0);

/**
 * The joint's solver record (m_solverRecord): what SolveVelocityConstraints and
 * SolvePositionConstraints read, copied by InitVelocityConstraints into the island's joint records
 * (one Float64Array, the joints' records one after the other in solver order), and the impulses
 * they accumulate (StoreImpulses writes m_impulse and m_motorImpulse back after the velocity
 * iterations). It spares the solver's eight velocity and three position passes the twenty-odd
 * small heap objects the C++'s fields would be (V8 boxes every double in an object field), and
 * holds the C++'s solver temporaries outright. In a 10,000-body joint grid those passes were
 * bound by memory latency. The record holds all the
 * passes read, so b2Island runs them (b2RevoluteSolveVelocity, b2RevoluteSolvePosition) without
 * loading the joint objects either: with 19,800 joints that took a quarter to a third off a
 * velocity pass (docs/PORTING.md).
 */
const enum RJ {
  // m_indexA, m_indexB and the flags the passes test (RJFlag), first: every pass reads them
  indexA = 0,
  indexB = 1,
  flags = 2,
  rAx = 3,
  rAy = 4,
  rBx = 5,
  rBy = 6,
  invMassA = 7,
  invMassB = 8,
  invIA = 9,
  invIB = 10,
  // m_mass, column by column as b2Mat33: ex.x, ex.y, ex.z, ey.x...
  massExX = 11,
  massExY = 12,
  massExZ = 13,
  massEyX = 14,
  massEyY = 15,
  massEyZ = 16,
  massEzX = 17,
  massEzY = 18,
  massEzZ = 19,
  motorMass = 20,
  impulseX = 21,
  impulseY = 22,
  impulseZ = 23,
  motorImpulse = 24,
  motorSpeed = 25,
  maxMotorTorque = 26,
  referenceAngle = 27,
  lowerAngle = 28,
  upperAngle = 29,
  // m_localAnchorA - m_localCenterA and the same for B, as SolvePositionConstraints computes them
  localAnchorAX = 30,
  localAnchorAY = 31,
  localAnchorBX = 32,
  localAnchorBY = 33,
  size = 34,
}

/** Bits of a solver record's RJ.flags: m_enableMotor, m_enableLimit and m_limitState above them. */
const enum RJFlag {
  enableMotor = 1,
  enableLimit = 2,
  limitStateShift = 2,
}

/**
 * Revolute joint definition. This requires defining an anchor point where the bodies are joined.
 * The definition uses local anchor points so that the initial configuration can violate the
 * constraint slightly. You also need to specify the initial relative angle for joint limits.
 * This helps when saving and loading a game.
 * The local anchor points are measured from the body's origin rather than the center of mass
 * because:
 * 1. you might not know where the center of mass will be.
 * 2. if you add/remove shapes from a body and recompute the mass, the joints will be broken.
 */
export class b2RevoluteJointDef extends b2JointDef {
  /** The local anchor point relative to bodyA's origin. */
  localAnchorA = new b2Vec2(0.0, 0.0);
  /** The local anchor point relative to bodyB's origin. */
  localAnchorB = new b2Vec2(0.0, 0.0);
  /** The bodyB angle minus bodyA angle in the reference state (radians). */
  referenceAngle = 0.0;
  /** A flag to enable joint limits. */
  enableLimit = false;
  /** The lower angle for the joint limit (radians). */
  lowerAngle = 0.0;
  /** The upper angle for the joint limit (radians). */
  upperAngle = 0.0;
  /** A flag to enable the joint motor. */
  enableMotor = false;
  /** The desired motor speed. Usually in radians per second. */
  motorSpeed = 0.0;
  /** The maximum motor torque used to achieve the desired motor speed. Usually in N-m. */
  maxMotorTorque = 0.0;

  constructor() {
    super(b2JointType.e_revoluteJoint);
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
 * A revolute joint constrains two bodies to share a common point while they are free to rotate
 * about the point. The relative rotation about the shared point is the joint angle. You can
 * limit the relative rotation with a joint limit that specifies a lower and upper angle. You can
 * use a motor to drive the relative rotation about the shared point. A maximum motor torque is
 * provided so that infinite forces are not generated.
 */
export class b2RevoluteJoint extends b2Joint {
  // Out of the C++ order: the fields InitVelocityConstraints copies into the solver record for the
  // passes (which read only the record; b2Island), and where that record is.
  m_indexA = 0;
  m_indexB = 0;
  m_enableMotor = false;
  m_enableLimit = false;
  m_limitState = b2LimitState.e_inactiveLimit;
  /**
   * The solver record (see RJ): RJ.size doubles from m_recordOffset in m_solverRecord, the island's
   * joint records (b2SolverData.jointRecords); valid from InitVelocityConstraints to the end of the
   * island's solve.
   */
  m_solverRecord = s_noRecord;
  m_recordOffset = 0;

  // Solver shared
  readonly m_localAnchorA = new b2Vec2();
  readonly m_localAnchorB = new b2Vec2();
  readonly m_impulse = new b2Vec3();
  m_motorImpulse = 0.0;

  m_maxMotorTorque = 0.0;
  m_motorSpeed = 0.0;

  m_referenceAngle = 0.0;
  m_lowerAngle = 0.0;
  m_upperAngle = 0.0;

  // The C++'s solver temporaries (m_rA, m_rB, m_localCenterA/B, m_invMassA/B, m_invIA/B, m_mass,
  // m_motorMass) live only in the solver record (RJ): InitVelocityConstraints computes them in
  // locals and writes them there.

  constructor(def: b2RevoluteJointDef) {
    super(def);

    this.m_localAnchorA.Assign(def.localAnchorA);
    this.m_localAnchorB.Assign(def.localAnchorB);
    this.m_referenceAngle = def.referenceAngle;

    this.m_impulse.SetZero();
    this.m_motorImpulse = 0.0;

    this.m_lowerAngle = def.lowerAngle;
    this.m_upperAngle = def.upperAngle;
    this.m_maxMotorTorque = def.maxMotorTorque;
    this.m_motorSpeed = def.motorSpeed;
    this.m_enableLimit = def.enableLimit;
    this.m_enableMotor = def.enableMotor;
    this.m_limitState = b2LimitState.e_inactiveLimit;
  }

  override InitVelocityConstraints(data: b2SolverData): void {
    const bA = this.m_bodyA;
    const bB = this.m_bodyB;
    this.m_indexA = bA.m_islandIndex;
    this.m_indexB = bB.m_islandIndex;
    const localCenterA = bA.m_sweep.localCenter;
    const localCenterB = bB.m_sweep.localCenter;
    const mA = bA.m_invMass;
    const mB = bB.m_invMass;
    const iA = bA.m_invI;
    const iB = bB.m_invI;

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

    // rA = b2Mul(qA, m_localAnchorA - m_localCenterA), likewise rB, as b2MulRV computes them.
    const dAx = this.m_localAnchorA.x - localCenterA.x;
    const dAy = this.m_localAnchorA.y - localCenterA.y;
    const dBx = this.m_localAnchorB.x - localCenterB.x;
    const dBy = this.m_localAnchorB.y - localCenterB.y;
    const rAx = qA.c * dAx - qA.s * dAy;
    const rAy = qA.s * dAx + qA.c * dAy;
    const rBx = qB.c * dBx - qB.s * dBy;
    const rBy = qB.s * dBx + qB.c * dBy;

    // J = [-I -r1_skew I r2_skew]
    //     [ 0       -1 0       1]
    // r_skew = [-ry; rx]

    // Matlab
    // K = [ mA+r1y^2*iA+mB+r2y^2*iB,  -r1y*iA*r1x-r2y*iB*r2x,          -r1y*iA-r2y*iB]
    //     [  -r1y*iA*r1x-r2y*iB*r2x, mA+r1x^2*iA+mB+r2x^2*iB,           r1x*iA+r2x*iB]
    //     [          -r1y*iA-r2y*iB,           r1x*iA+r2x*iB,                   iA+iB]

    const fixedRotation = iA + iB === 0.0;

    // m_mass = K, column by column.
    const exx = mA + mB + rAy * rAy * iA + rBy * rBy * iB;
    const eyx = -rAy * rAx * iA - rBy * rBx * iB;
    const ezx = -rAy * iA - rBy * iB;
    const eyy = mA + mB + rAx * rAx * iA + rBx * rBx * iB;
    const ezy = rAx * iA + rBx * iB;
    const ezz = iA + iB;

    let motorMass = iA + iB;
    if (motorMass > 0.0) {
      motorMass = 1.0 / motorMass;
    }

    if (this.m_enableMotor === false || fixedRotation) {
      this.m_motorImpulse = 0.0;
    }

    if (this.m_enableLimit && fixedRotation === false) {
      const jointAngle = aB - aA - this.m_referenceAngle;
      if (b2Abs(this.m_upperAngle - this.m_lowerAngle) < 2.0 * b2_angularSlop) {
        this.m_limitState = b2LimitState.e_equalLimits;
      } else if (jointAngle <= this.m_lowerAngle) {
        if (this.m_limitState !== b2LimitState.e_atLowerLimit) {
          this.m_impulse.z = 0.0;
        }
        this.m_limitState = b2LimitState.e_atLowerLimit;
      } else if (jointAngle >= this.m_upperAngle) {
        if (this.m_limitState !== b2LimitState.e_atUpperLimit) {
          this.m_impulse.z = 0.0;
        }
        this.m_limitState = b2LimitState.e_atUpperLimit;
      } else {
        this.m_limitState = b2LimitState.e_inactiveLimit;
        this.m_impulse.z = 0.0;
      }
    } else {
      this.m_limitState = b2LimitState.e_inactiveLimit;
    }

    if (data.step.warmStarting) {
      // Scale impulses to support a variable time step.
      this.m_impulse.Multiply(data.step.dtRatio);
      this.m_motorImpulse *= data.step.dtRatio;

      const Px = this.m_impulse.x;
      const Py = this.m_impulse.y;

      vAx -= mA * Px;
      vAy -= mA * Py;
      wA -= iA * (rAx * Py - rAy * Px + this.m_motorImpulse + this.m_impulse.z);

      vBx += mB * Px;
      vBy += mB * Py;
      wB += iB * (rBx * Py - rBy * Px + this.m_motorImpulse + this.m_impulse.z);
    } else {
      this.m_impulse.SetZero();
      this.m_motorImpulse = 0.0;
    }

    // This joint's record, next to the island's other joint records (b2SolverData.AllocateJointRecord).
    const rec = data.AllocateJointRecord(RJ.size);
    const t = data.jointRecords;
    this.m_solverRecord = t;
    this.m_recordOffset = rec;
    t[rec + RJ.indexA] = this.m_indexA;
    t[rec + RJ.indexB] = this.m_indexB;
    t[rec + RJ.flags] =
      (this.m_enableMotor ? RJFlag.enableMotor : 0) | (this.m_enableLimit ? RJFlag.enableLimit : 0) | (this.m_limitState << RJFlag.limitStateShift);
    t[rec + RJ.rAx] = rAx;
    t[rec + RJ.rAy] = rAy;
    t[rec + RJ.rBx] = rBx;
    t[rec + RJ.rBy] = rBy;
    t[rec + RJ.invMassA] = mA;
    t[rec + RJ.invMassB] = mB;
    t[rec + RJ.invIA] = iA;
    t[rec + RJ.invIB] = iB;
    // K is symmetric: ex.y = ey.x, ex.z = ez.x, ey.z = ez.y.
    t[rec + RJ.massExX] = exx;
    t[rec + RJ.massExY] = eyx;
    t[rec + RJ.massExZ] = ezx;
    t[rec + RJ.massEyX] = eyx;
    t[rec + RJ.massEyY] = eyy;
    t[rec + RJ.massEyZ] = ezy;
    t[rec + RJ.massEzX] = ezx;
    t[rec + RJ.massEzY] = ezy;
    t[rec + RJ.massEzZ] = ezz;
    t[rec + RJ.motorMass] = motorMass;
    t[rec + RJ.impulseX] = this.m_impulse.x;
    t[rec + RJ.impulseY] = this.m_impulse.y;
    t[rec + RJ.impulseZ] = this.m_impulse.z;
    t[rec + RJ.motorImpulse] = this.m_motorImpulse;
    t[rec + RJ.motorSpeed] = this.m_motorSpeed;
    t[rec + RJ.maxMotorTorque] = this.m_maxMotorTorque;
    t[rec + RJ.referenceAngle] = this.m_referenceAngle;
    t[rec + RJ.lowerAngle] = this.m_lowerAngle;
    t[rec + RJ.upperAngle] = this.m_upperAngle;
    t[rec + RJ.localAnchorAX] = dAx;
    t[rec + RJ.localAnchorAY] = dAy;
    t[rec + RJ.localAnchorBX] = dBx;
    t[rec + RJ.localAnchorBY] = dBy;

    velocities[oA] = vAx;
    velocities[oA + 1] = vAy;
    velocities[oA + 2] = wA;
    velocities[oB] = vBx;
    velocities[oB + 1] = vBy;
    velocities[oB + 2] = wB;
  }

  override SolveVelocityConstraints(data: b2SolverData): void {
    b2RevoluteSolveVelocity(this.m_solverRecord, this.m_recordOffset, data);
  }

  /** The impulses the velocity iterations accumulated in the solver record, back to the fields. */
  override StoreImpulses(): void {
    const t = this.m_solverRecord;
    const rec = this.m_recordOffset;
    this.m_impulse.x = t[rec + RJ.impulseX];
    this.m_impulse.y = t[rec + RJ.impulseY];
    this.m_impulse.z = t[rec + RJ.impulseZ];
    this.m_motorImpulse = t[rec + RJ.motorImpulse];
  }

  override SolvePositionConstraints(data: b2SolverData): boolean {
    return b2RevoluteSolvePosition(this.m_solverRecord, this.m_recordOffset, data);
  }

  override GetAnchorA(out: b2Vec2): b2Vec2 {
    return this.m_bodyA.GetWorldPoint(this.m_localAnchorA, out);
  }

  override GetAnchorB(out: b2Vec2): b2Vec2 {
    return this.m_bodyB.GetWorldPoint(this.m_localAnchorB, out);
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

  /** Get the current joint angle in radians. */
  GetJointAngle(): number {
    const bA = this.m_bodyA;
    const bB = this.m_bodyB;
    bA.PullState();
    bB.PullState();
    return bB.m_sweep.a - bA.m_sweep.a - this.m_referenceAngle;
  }

  /** Get the current joint angle speed in radians per second. */
  GetJointSpeed(): number {
    const bA = this.m_bodyA;
    const bB = this.m_bodyB;
    bA.PullState();
    bB.PullState();
    return bB.m_angularVelocity - bA.m_angularVelocity;
  }

  /** Is the joint limit enabled? */
  IsLimitEnabled(): boolean {
    return this.m_enableLimit;
  }

  /** Enable/disable the joint limit. */
  EnableLimit(flag: boolean): void {
    b2CheckJointAlive(this, 'b2RevoluteJoint.EnableLimit');
    if (flag !== this.m_enableLimit) {
      this.m_bodyA.SetAwake(true);
      this.m_bodyB.SetAwake(true);
      this.m_enableLimit = flag;
      this.m_impulse.z = 0.0;
    }
  }

  /** Get the lower joint limit in radians. */
  GetLowerLimit(): number {
    return this.m_lowerAngle;
  }

  /** Get the upper joint limit in radians. */
  GetUpperLimit(): number {
    return this.m_upperAngle;
  }

  /** Set the joint limits in radians. */
  SetLimits(lower: number, upper: number): void {
    b2CheckJointAlive(this, 'b2RevoluteJoint.SetLimits');
    b2CheckLimits('b2RevoluteJoint.SetLimits', 'lower', 'upper', lower, upper);
    if (lower !== this.m_lowerAngle || upper !== this.m_upperAngle) {
      this.m_bodyA.SetAwake(true);
      this.m_bodyB.SetAwake(true);
      this.m_impulse.z = 0.0;
      this.m_lowerAngle = lower;
      this.m_upperAngle = upper;
    }
  }

  /** Is the joint motor enabled? */
  IsMotorEnabled(): boolean {
    return this.m_enableMotor;
  }

  /** Enable/disable the joint motor. */
  EnableMotor(flag: boolean): void {
    b2CheckJointAlive(this, 'b2RevoluteJoint.EnableMotor');
    this.m_bodyA.SetAwake(true);
    this.m_bodyB.SetAwake(true);
    this.m_enableMotor = flag;
  }

  /** Set the motor speed in radians per second. */
  SetMotorSpeed(speed: number): void {
    b2CheckJointAlive(this, 'b2RevoluteJoint.SetMotorSpeed');
    b2CheckFinite('b2RevoluteJoint.SetMotorSpeed', 'speed', speed);
    this.m_bodyA.SetAwake(true);
    this.m_bodyB.SetAwake(true);
    this.m_motorSpeed = speed;
  }

  /** Get the motor speed in radians per second. */
  GetMotorSpeed(): number {
    return this.m_motorSpeed;
  }

  /** Set the maximum motor torque, usually in N-m. */
  SetMaxMotorTorque(torque: number): void {
    b2CheckJointAlive(this, 'b2RevoluteJoint.SetMaxMotorTorque');
    b2CheckNonNegative('b2RevoluteJoint.SetMaxMotorTorque', 'torque', torque);
    this.m_bodyA.SetAwake(true);
    this.m_bodyB.SetAwake(true);
    this.m_maxMotorTorque = torque;
  }

  GetMaxMotorTorque(): number {
    return this.m_maxMotorTorque;
  }

  /** Get the reaction force given the inverse time step. Unit is N. */
  override GetReactionForce(inv_dt: number, out: b2Vec2): b2Vec2 {
    return out.Set(inv_dt * this.m_impulse.x, inv_dt * this.m_impulse.y);
  }

  /** Get the reaction torque due to the joint limit given the inverse time step. Unit is N*m. */
  override GetReactionTorque(inv_dt: number): number {
    return inv_dt * this.m_impulse.z;
  }

  /** Get the current motor torque given the inverse time step. Unit is N*m. */
  GetMotorTorque(inv_dt: number): number {
    return inv_dt * this.m_motorImpulse;
  }

  /** Dump to b2Log. */
  override Dump(): void {
    const indexA = this.m_bodyA.m_islandIndex;
    const indexB = this.m_bodyB.m_islandIndex;

    b2Log('  b2RevoluteJointDef jd;\n');
    b2Log('  jd.bodyA = bodies[%d];\n', indexA);
    b2Log('  jd.bodyB = bodies[%d];\n', indexB);
    b2Log('  jd.collideConnected = bool(%d);\n', this.m_collideConnected);
    b2Log('  jd.localAnchorA.Set(%.15lef, %.15lef);\n', this.m_localAnchorA.x, this.m_localAnchorA.y);
    b2Log('  jd.localAnchorB.Set(%.15lef, %.15lef);\n', this.m_localAnchorB.x, this.m_localAnchorB.y);
    b2Log('  jd.referenceAngle = %.15lef;\n', this.m_referenceAngle);
    b2Log('  jd.enableLimit = bool(%d);\n', this.m_enableLimit);
    b2Log('  jd.lowerAngle = %.15lef;\n', this.m_lowerAngle);
    b2Log('  jd.upperAngle = %.15lef;\n', this.m_upperAngle);
    b2Log('  jd.enableMotor = bool(%d);\n', this.m_enableMotor);
    b2Log('  jd.motorSpeed = %.15lef;\n', this.m_motorSpeed);
    b2Log('  jd.maxMotorTorque = %.15lef;\n', this.m_maxMotorTorque);
    b2Log('  joints[%d] = m_world->CreateJoint(&jd);\n', this.m_index);
  }
}

/** b2RevoluteJoint.SolveVelocityConstraints on the joint's solver record (RJ) at rec in t. */
export function b2RevoluteSolveVelocity(t: Float64Array, rec: number, data: b2SolverData): void {
  const oA = 3 * t[rec + RJ.indexA];
  const velocities = data.velocities;
  const oB = 3 * t[rec + RJ.indexB];
  const flags = t[rec + RJ.flags];
  const limitState = flags >> RJFlag.limitStateShift;
  let vAx = velocities[oA];
  let vAy = velocities[oA + 1];
  let wA = velocities[oA + 2];
  let vBx = velocities[oB];
  let vBy = velocities[oB + 1];
  let wB = velocities[oB + 2];

  const mA = t[rec + RJ.invMassA];
  const mB = t[rec + RJ.invMassB];
  const iA = t[rec + RJ.invIA];
  const iB = t[rec + RJ.invIB];
  const rAx = t[rec + RJ.rAx];
  const rAy = t[rec + RJ.rAy];
  const rBx = t[rec + RJ.rBx];
  const rBy = t[rec + RJ.rBy];

  const fixedRotation = iA + iB === 0.0;

  // Solve motor constraint.
  if ((flags & RJFlag.enableMotor) !== 0 && limitState !== b2LimitState.e_equalLimits && fixedRotation === false) {
    const Cdot = wB - wA - t[rec + RJ.motorSpeed];
    let impulse = -t[rec + RJ.motorMass] * Cdot;
    const oldImpulse = t[rec + RJ.motorImpulse];
    const maxImpulse = data.step.dt * t[rec + RJ.maxMotorTorque];
    const motorImpulse = b2Clamp(oldImpulse + impulse, -maxImpulse, maxImpulse);
    t[rec + RJ.motorImpulse] = motorImpulse;
    impulse = motorImpulse - oldImpulse;

    wA -= iA * impulse;
    wB += iB * impulse;
  }

  // Solve limit constraint.
  if ((flags & RJFlag.enableLimit) !== 0 && limitState !== b2LimitState.e_inactiveLimit && fixedRotation === false) {
    const Cdot1x = vBx - wB * rBy - vAx + wA * rAy;
    const Cdot1y = vBy + wB * rBx - vAy - wA * rAx;
    const Cdot2 = wB - wA;

    // impulse = -m_mass.Solve33(Cdot), as b2Mat33.Solve33 computes it
    const exx = t[rec + RJ.massExX];
    const exy = t[rec + RJ.massExY];
    const exz = t[rec + RJ.massExZ];
    const eyx = t[rec + RJ.massEyX];
    const eyy = t[rec + RJ.massEyY];
    const eyz = t[rec + RJ.massEyZ];
    const ezx = t[rec + RJ.massEzX];
    const ezy = t[rec + RJ.massEzY];
    const ezz = t[rec + RJ.massEzZ];
    let det = exx * (eyy * ezz - eyz * ezy) + exy * (eyz * ezx - eyx * ezz) + exz * (eyx * ezy - eyy * ezx);
    if (det !== 0.0) {
      det = 1.0 / det;
    }
    let impulseX = -(det * (Cdot1x * (eyy * ezz - eyz * ezy) + Cdot1y * (eyz * ezx - eyx * ezz) + Cdot2 * (eyx * ezy - eyy * ezx)));
    let impulseY = -(det * (exx * (Cdot1y * ezz - Cdot2 * ezy) + exy * (Cdot2 * ezx - Cdot1x * ezz) + exz * (Cdot1x * ezy - Cdot1y * ezx)));
    let impulseZ = -(det * (exx * (eyy * Cdot2 - eyz * Cdot1y) + exy * (eyz * Cdot1x - eyx * Cdot2) + exz * (eyx * Cdot1y - eyy * Cdot1x)));

    let reduced = false;
    if (limitState === b2LimitState.e_atLowerLimit) {
      reduced = t[rec + RJ.impulseZ] + impulseZ < 0.0;
    } else if (limitState === b2LimitState.e_atUpperLimit) {
      reduced = t[rec + RJ.impulseZ] + impulseZ > 0.0;
    }

    if (reduced) {
      // The limit impulse would change sign: solve the point constraint alone with the limit
      // impulse removed. reduced = m_mass.Solve22(rhs), as b2Mat33.Solve22 computes it.
      const oldImpulseZ = t[rec + RJ.impulseZ];
      const rhsX = -Cdot1x + oldImpulseZ * ezx;
      const rhsY = -Cdot1y + oldImpulseZ * ezy;
      let det2 = exx * eyy - eyx * exy;
      if (det2 !== 0.0) {
        det2 = 1.0 / det2;
      }
      const reducedX = det2 * (eyy * rhsX - eyx * rhsY);
      const reducedY = det2 * (exx * rhsY - exy * rhsX);
      impulseX = reducedX;
      impulseY = reducedY;
      impulseZ = -oldImpulseZ;
      t[rec + RJ.impulseX] += reducedX;
      t[rec + RJ.impulseY] += reducedY;
      t[rec + RJ.impulseZ] = 0.0;
    } else {
      // m_impulse += impulse (e_equalLimits, or a limit impulse that keeps its sign)
      t[rec + RJ.impulseX] += impulseX;
      t[rec + RJ.impulseY] += impulseY;
      t[rec + RJ.impulseZ] += impulseZ;
    }

    const Px = impulseX;
    const Py = impulseY;

    vAx -= mA * Px;
    vAy -= mA * Py;
    wA -= iA * (rAx * Py - rAy * Px + impulseZ);

    vBx += mB * Px;
    vBy += mB * Py;
    wB += iB * (rBx * Py - rBy * Px + impulseZ);
  } else {
    // Solve point-to-point constraint
    const Cdotx = vBx - wB * rBy - vAx + wA * rAy;
    const Cdoty = vBy + wB * rBx - vAy - wA * rAx;

    // impulse = m_mass.Solve22(-Cdot), as b2Mat33.Solve22 computes it
    const a11 = t[rec + RJ.massExX];
    const a12 = t[rec + RJ.massEyX];
    const a21 = t[rec + RJ.massExY];
    const a22 = t[rec + RJ.massEyY];
    let det = a11 * a22 - a12 * a21;
    if (det !== 0.0) {
      det = 1.0 / det;
    }
    const bx = -Cdotx;
    const by = -Cdoty;
    const impulseX = det * (a22 * bx - a12 * by);
    const impulseY = det * (a11 * by - a21 * bx);

    t[rec + RJ.impulseX] += impulseX;
    t[rec + RJ.impulseY] += impulseY;

    vAx -= mA * impulseX;
    vAy -= mA * impulseY;
    wA -= iA * (rAx * impulseY - rAy * impulseX);

    vBx += mB * impulseX;
    vBy += mB * impulseY;
    wB += iB * (rBx * impulseY - rBy * impulseX);
  }

  velocities[oA] = vAx;
  velocities[oA + 1] = vAy;
  velocities[oA + 2] = wA;
  velocities[oB] = vBx;
  velocities[oB + 1] = vBy;
  velocities[oB + 2] = wB;
}

/** b2RevoluteJoint.SolvePositionConstraints on the joint's solver record (RJ) at rec in t. */
export function b2RevoluteSolvePosition(t: Float64Array, rec: number, data: b2SolverData): boolean {
  const oA = 3 * t[rec + RJ.indexA];
  const positions = data.positions;
  const oB = 3 * t[rec + RJ.indexB];
  const flags = t[rec + RJ.flags];
  const limitState = flags >> RJFlag.limitStateShift;
  let cAx = positions[oA];
  let cAy = positions[oA + 1];
  let aA = positions[oA + 2];
  let cBx = positions[oB];
  let cBy = positions[oB + 1];
  let aB = positions[oB + 2];

  let angularError = 0.0;
  let positionError = 0.0;

  const mA = t[rec + RJ.invMassA];
  const mB = t[rec + RJ.invMassB];
  const iA = t[rec + RJ.invIA];
  const iB = t[rec + RJ.invIB];

  const fixedRotation = iA + iB === 0.0;

  // Solve angular limit constraint.
  if ((flags & RJFlag.enableLimit) !== 0 && limitState !== b2LimitState.e_inactiveLimit && fixedRotation === false) {
    const angle = aB - aA - t[rec + RJ.referenceAngle];
    let limitImpulse = 0.0;

    if (limitState === b2LimitState.e_equalLimits) {
      // Prevent large angular corrections
      const C = b2Clamp(angle - t[rec + RJ.lowerAngle], -b2_maxAngularCorrection, b2_maxAngularCorrection);
      limitImpulse = -t[rec + RJ.motorMass] * C;
      angularError = b2Abs(C);
    } else if (limitState === b2LimitState.e_atLowerLimit) {
      let C = angle - t[rec + RJ.lowerAngle];
      angularError = -C;

      // Prevent large angular corrections and allow some slop.
      C = b2Clamp(C + b2_angularSlop, -b2_maxAngularCorrection, 0.0);
      limitImpulse = -t[rec + RJ.motorMass] * C;
    } else if (limitState === b2LimitState.e_atUpperLimit) {
      let C = angle - t[rec + RJ.upperAngle];
      angularError = C;

      // Prevent large angular corrections and allow some slop.
      C = b2Clamp(C - b2_angularSlop, 0.0, b2_maxAngularCorrection);
      limitImpulse = -t[rec + RJ.motorMass] * C;
    }

    aA -= iA * limitImpulse;
    aB += iB * limitImpulse;
  }

  // Solve point-to-point constraint.
  {
    // The C++ also builds qA/qB from the initial angles; only these rotations are ever read.
    const qA = s_qA.Set(aA);
    const qB = s_qB.Set(aB);
    // rA = b2Mul(qA, m_localAnchorA - m_localCenterA); likewise rB.
    const lAx = t[rec + RJ.localAnchorAX];
    const lAy = t[rec + RJ.localAnchorAY];
    const lBx = t[rec + RJ.localAnchorBX];
    const lBy = t[rec + RJ.localAnchorBY];
    const rAx = qA.c * lAx - qA.s * lAy;
    const rAy = qA.s * lAx + qA.c * lAy;
    const rBx = qB.c * lBx - qB.s * lBy;
    const rBy = qB.s * lBx + qB.c * lBy;

    const Cx = cBx + rBx - cAx - rAx;
    const Cy = cBy + rBy - cAy - rAy;
    positionError = Math.sqrt(Cx * Cx + Cy * Cy);

    // K = [[k11, k12], [k12, k22]]; impulse = -K.Solve(C), as b2Mat22.Solve computes it
    const k11 = mA + mB + iA * rAy * rAy + iB * rBy * rBy;
    const k12 = -iA * rAx * rAy - iB * rBx * rBy;
    const k22 = mA + mB + iA * rAx * rAx + iB * rBx * rBx;
    let det = k11 * k22 - k12 * k12;
    if (det !== 0.0) {
      det = 1.0 / det;
    }
    const impulseX = -(det * (k22 * Cx - k12 * Cy));
    const impulseY = -(det * (k11 * Cy - k12 * Cx));

    cAx -= mA * impulseX;
    cAy -= mA * impulseY;
    aA -= iA * (rAx * impulseY - rAy * impulseX);

    cBx += mB * impulseX;
    cBy += mB * impulseY;
    aB += iB * (rBx * impulseY - rBy * impulseX);
  }

  positions[oA] = cAx;
  positions[oA + 1] = cAy;
  positions[oA + 2] = aA;
  positions[oB] = cBx;
  positions[oB + 1] = cBy;
  positions[oB + 2] = aB;

  return positionError <= b2_linearSlop && angularError <= b2_angularSlop;
}
