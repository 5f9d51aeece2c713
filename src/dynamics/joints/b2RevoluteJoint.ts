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

import { b2Abs, b2Clamp, b2Mat22, b2Mat33, b2MulRV, b2Rot, b2SubVV, b2Vec2, b2Vec3 } from '../../common/b2Math';
import {
  b2_angularSlop,
  b2_linearSlop,
  b2_maxAngularCorrection,
  b2Log,
} from '../../common/b2Settings';
import type { b2Body } from '../b2Body';
import type { b2SolverData } from '../b2TimeStep';
import { b2Joint, b2JointDef, b2JointType, b2LimitState, b2CheckJointAlive } from './b2Joint';
import { b2CheckFinite, b2CheckLimits, b2CheckNonNegative } from '../../common/b2ArgumentError';

const s_qA = new b2Rot();
const s_qB = new b2Rot();
const s_rA = new b2Vec2();
const s_rB = new b2Vec2();
const s_Cdot = new b2Vec3();
const s_impulse3 = new b2Vec3();
const s_rhs = new b2Vec2();
const s_reduced = new b2Vec2();
const s_impulse2 = new b2Vec2();
const s_K = new b2Mat22();

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
  // Solver shared
  readonly m_localAnchorA = new b2Vec2();
  readonly m_localAnchorB = new b2Vec2();
  readonly m_impulse = new b2Vec3();
  m_motorImpulse = 0.0;

  m_enableMotor = false;
  m_maxMotorTorque = 0.0;
  m_motorSpeed = 0.0;

  m_enableLimit = false;
  m_referenceAngle = 0.0;
  m_lowerAngle = 0.0;
  m_upperAngle = 0.0;

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
  /** Effective mass for point-to-point constraint. */
  readonly m_mass = new b2Mat33();
  /** Effective mass for motor/limit angular constraint. */
  m_motorMass = 0.0;
  m_limitState = b2LimitState.e_inactiveLimit;

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
    this.m_localCenterA.Assign(bA.m_sweep.localCenter);
    this.m_localCenterB.Assign(bB.m_sweep.localCenter);
    this.m_invMassA = bA.m_invMass;
    this.m_invMassB = bB.m_invMass;
    this.m_invIA = bA.m_invI;
    this.m_invIB = bB.m_invI;

    const aA = data.positions[this.m_indexA].a;
    const velA = data.velocities[this.m_indexA];
    let vAx = velA.v.x;
    let vAy = velA.v.y;
    let wA = velA.w;

    const aB = data.positions[this.m_indexB].a;
    const velB = data.velocities[this.m_indexB];
    let vBx = velB.v.x;
    let vBy = velB.v.y;
    let wB = velB.w;

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

    const fixedRotation = iA + iB === 0.0;

    const K = this.m_mass;
    K.ex.x = mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB;
    K.ey.x = -rA.y * rA.x * iA - rB.y * rB.x * iB;
    K.ez.x = -rA.y * iA - rB.y * iB;
    K.ex.y = K.ey.x;
    K.ey.y = mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB;
    K.ez.y = rA.x * iA + rB.x * iB;
    K.ex.z = K.ez.x;
    K.ey.z = K.ez.y;
    K.ez.z = iA + iB;

    this.m_motorMass = iA + iB;
    if (this.m_motorMass > 0.0) {
      this.m_motorMass = 1.0 / this.m_motorMass;
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
      wA -= iA * (rA.x * Py - rA.y * Px + this.m_motorImpulse + this.m_impulse.z);

      vBx += mB * Px;
      vBy += mB * Py;
      wB += iB * (rB.x * Py - rB.y * Px + this.m_motorImpulse + this.m_impulse.z);
    } else {
      this.m_impulse.SetZero();
      this.m_motorImpulse = 0.0;
    }

    velA.v.x = vAx;
    velA.v.y = vAy;
    velA.w = wA;
    velB.v.x = vBx;
    velB.v.y = vBy;
    velB.w = wB;
  }

  override SolveVelocityConstraints(data: b2SolverData): void {
    const velA = data.velocities[this.m_indexA];
    const velB = data.velocities[this.m_indexB];
    let vAx = velA.v.x;
    let vAy = velA.v.y;
    let wA = velA.w;
    let vBx = velB.v.x;
    let vBy = velB.v.y;
    let wB = velB.w;

    const mA = this.m_invMassA;
    const mB = this.m_invMassB;
    const iA = this.m_invIA;
    const iB = this.m_invIB;
    const rA = this.m_rA;
    const rB = this.m_rB;

    const fixedRotation = iA + iB === 0.0;

    // Solve motor constraint.
    if (this.m_enableMotor && this.m_limitState !== b2LimitState.e_equalLimits && fixedRotation === false) {
      const Cdot = wB - wA - this.m_motorSpeed;
      let impulse = -this.m_motorMass * Cdot;
      const oldImpulse = this.m_motorImpulse;
      const maxImpulse = data.step.dt * this.m_maxMotorTorque;
      this.m_motorImpulse = b2Clamp(this.m_motorImpulse + impulse, -maxImpulse, maxImpulse);
      impulse = this.m_motorImpulse - oldImpulse;

      wA -= iA * impulse;
      wB += iB * impulse;
    }

    // Solve limit constraint.
    if (this.m_enableLimit && this.m_limitState !== b2LimitState.e_inactiveLimit && fixedRotation === false) {
      const Cdot1x = vBx - wB * rB.y - vAx + wA * rA.y;
      const Cdot1y = vBy + wB * rB.x - vAy - wA * rA.x;
      const Cdot2 = wB - wA;
      const Cdot = s_Cdot.Set(Cdot1x, Cdot1y, Cdot2);

      const impulse = this.m_mass.Solve33(Cdot, s_impulse3);
      impulse.x = -impulse.x;
      impulse.y = -impulse.y;
      impulse.z = -impulse.z;

      if (this.m_limitState === b2LimitState.e_equalLimits) {
        this.m_impulse.Add(impulse);
      } else if (this.m_limitState === b2LimitState.e_atLowerLimit) {
        const newImpulse = this.m_impulse.z + impulse.z;
        if (newImpulse < 0.0) {
          this.SolveReducedLimit(Cdot1x, Cdot1y, impulse);
        } else {
          this.m_impulse.Add(impulse);
        }
      } else if (this.m_limitState === b2LimitState.e_atUpperLimit) {
        const newImpulse = this.m_impulse.z + impulse.z;
        if (newImpulse > 0.0) {
          this.SolveReducedLimit(Cdot1x, Cdot1y, impulse);
        } else {
          this.m_impulse.Add(impulse);
        }
      }

      const Px = impulse.x;
      const Py = impulse.y;

      vAx -= mA * Px;
      vAy -= mA * Py;
      wA -= iA * (rA.x * Py - rA.y * Px + impulse.z);

      vBx += mB * Px;
      vBy += mB * Py;
      wB += iB * (rB.x * Py - rB.y * Px + impulse.z);
    } else {
      // Solve point-to-point constraint
      const Cdotx = vBx - wB * rB.y - vAx + wA * rA.y;
      const Cdoty = vBy + wB * rB.x - vAy - wA * rA.x;
      const impulse = this.m_mass.Solve22(s_rhs.Set(-Cdotx, -Cdoty), s_impulse2);

      this.m_impulse.x += impulse.x;
      this.m_impulse.y += impulse.y;

      vAx -= mA * impulse.x;
      vAy -= mA * impulse.y;
      wA -= iA * (rA.x * impulse.y - rA.y * impulse.x);

      vBx += mB * impulse.x;
      vBy += mB * impulse.y;
      wB += iB * (rB.x * impulse.y - rB.y * impulse.x);
    }

    velA.v.x = vAx;
    velA.v.y = vAy;
    velA.w = wA;
    velB.v.x = vBx;
    velB.v.y = vBy;
    velB.w = wB;
  }

  /**
   * The limit impulse would change sign: solve the point constraint alone with the limit impulse
   * removed (shared by the lower and upper limit branches of the C++).
   */
  private SolveReducedLimit(Cdot1x: number, Cdot1y: number, impulse: b2Vec3): void {
    const rhs = s_rhs.Set(-Cdot1x + this.m_impulse.z * this.m_mass.ez.x, -Cdot1y + this.m_impulse.z * this.m_mass.ez.y);
    const reduced = this.m_mass.Solve22(rhs, s_reduced);
    impulse.x = reduced.x;
    impulse.y = reduced.y;
    impulse.z = -this.m_impulse.z;
    this.m_impulse.x += reduced.x;
    this.m_impulse.y += reduced.y;
    this.m_impulse.z = 0.0;
  }

  override SolvePositionConstraints(data: b2SolverData): boolean {
    const posA = data.positions[this.m_indexA];
    const posB = data.positions[this.m_indexB];
    let cAx = posA.c.x;
    let cAy = posA.c.y;
    let aA = posA.a;
    let cBx = posB.c.x;
    let cBy = posB.c.y;
    let aB = posB.a;

    let angularError = 0.0;
    let positionError = 0.0;

    const fixedRotation = this.m_invIA + this.m_invIB === 0.0;

    // Solve angular limit constraint.
    if (this.m_enableLimit && this.m_limitState !== b2LimitState.e_inactiveLimit && fixedRotation === false) {
      const angle = aB - aA - this.m_referenceAngle;
      let limitImpulse = 0.0;

      if (this.m_limitState === b2LimitState.e_equalLimits) {
        // Prevent large angular corrections
        const C = b2Clamp(angle - this.m_lowerAngle, -b2_maxAngularCorrection, b2_maxAngularCorrection);
        limitImpulse = -this.m_motorMass * C;
        angularError = b2Abs(C);
      } else if (this.m_limitState === b2LimitState.e_atLowerLimit) {
        let C = angle - this.m_lowerAngle;
        angularError = -C;

        // Prevent large angular corrections and allow some slop.
        C = b2Clamp(C + b2_angularSlop, -b2_maxAngularCorrection, 0.0);
        limitImpulse = -this.m_motorMass * C;
      } else if (this.m_limitState === b2LimitState.e_atUpperLimit) {
        let C = angle - this.m_upperAngle;
        angularError = C;

        // Prevent large angular corrections and allow some slop.
        C = b2Clamp(C - b2_angularSlop, 0.0, b2_maxAngularCorrection);
        limitImpulse = -this.m_motorMass * C;
      }

      aA -= this.m_invIA * limitImpulse;
      aB += this.m_invIB * limitImpulse;
    }

    // Solve point-to-point constraint.
    {
      // The C++ also builds qA/qB from the initial angles; only these rotations are ever read.
      const qA = s_qA.Set(aA);
      const qB = s_qB.Set(aB);
      const rA = b2MulRV(qA, b2SubVV(this.m_localAnchorA, this.m_localCenterA, s_rA), s_rA);
      const rB = b2MulRV(qB, b2SubVV(this.m_localAnchorB, this.m_localCenterB, s_rB), s_rB);

      const Cx = cBx + rB.x - cAx - rA.x;
      const Cy = cBy + rB.y - cAy - rA.y;
      positionError = Math.sqrt(Cx * Cx + Cy * Cy);

      const mA = this.m_invMassA;
      const mB = this.m_invMassB;
      const iA = this.m_invIA;
      const iB = this.m_invIB;

      const K = s_K;
      K.ex.x = mA + mB + iA * rA.y * rA.y + iB * rB.y * rB.y;
      K.ex.y = -iA * rA.x * rA.y - iB * rB.x * rB.y;
      K.ey.x = K.ex.y;
      K.ey.y = mA + mB + iA * rA.x * rA.x + iB * rB.x * rB.x;

      const impulse = K.Solve(s_rhs.Set(Cx, Cy), s_impulse2);
      impulse.x = -impulse.x;
      impulse.y = -impulse.y;

      cAx -= mA * impulse.x;
      cAy -= mA * impulse.y;
      aA -= iA * (rA.x * impulse.y - rA.y * impulse.x);

      cBx += mB * impulse.x;
      cBy += mB * impulse.y;
      aB += iB * (rB.x * impulse.y - rB.y * impulse.x);
    }

    posA.c.x = cAx;
    posA.c.y = cAy;
    posA.a = aA;
    posB.c.x = cBx;
    posB.c.y = cBy;
    posB.a = aB;

    return positionError <= b2_linearSlop && angularError <= b2_angularSlop;
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
    return bB.m_sweep.a - bA.m_sweep.a - this.m_referenceAngle;
  }

  /** Get the current joint angle speed in radians per second. */
  GetJointSpeed(): number {
    const bA = this.m_bodyA;
    const bB = this.m_bodyB;
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
