/*
 * Prismatic joint (b2PrismaticJoint.h, b2PrismaticJoint.cpp).
 *
 * Linear constraint (point-to-line)
 * d = p2 - p1 = x2 + r2 - x1 - r1
 * C = dot(perp, d)
 * Cdot = dot(d, cross(w1, perp)) + dot(perp, v2 + cross(w2, r2) - v1 - cross(w1, r1))
 *      = -dot(perp, v1) - dot(cross(d + r1, perp), w1) + dot(perp, v2) + dot(cross(r2, perp), v2)
 * J = [-perp, -cross(d + r1, perp), perp, cross(r2,perp)]
 *
 * Angular constraint
 * C = a2 - a1 + a_initial
 * Cdot = w2 - w1
 * J = [0 0 -1 0 0 1]
 *
 * K = J * invM * JT
 *
 * J = [-a -s1 a s2]
 *     [0  -1  0  1]
 * a = perp
 * s1 = cross(d + r1, a) = cross(p2 - x1, a)
 * s2 = cross(r2, a) = cross(p2 - x2, a)
 *
 * Motor/Limit linear constraint
 * C = dot(ax1, d)
 * Cdot = = -dot(ax1, v1) - dot(cross(d + r1, ax1), w1) + dot(ax1, v2) + dot(cross(r2, ax1), v2)
 * J = [-ax1 -cross(d+r1,ax1) ax1 cross(r2,ax1)]
 *
 * Block Solver
 * We develop a block solver that includes the joint limit. This makes the limit stiff (inelastic)
 * even when the mass has poor distribution (leading to large torques about the joint anchor
 * points).
 *
 * The Jacobian has 3 rows:
 * J = [-uT -s1 uT s2] // linear
 *     [0   -1   0  1] // angular
 *     [-vT -a1 vT a2] // limit
 *
 * u = perp
 * v = axis
 * s1 = cross(d + r1, u), s2 = cross(r2, u)
 * a1 = cross(d + r1, v), a2 = cross(r2, v)
 *
 * M * (v2 - v1) = JT * df
 * J * v2 = bias
 *
 * v2 = v1 + invM * JT * df
 * J * (v1 + invM * JT * df) = bias
 * K * df = bias - J * v1 = -Cdot
 * K = J * invM * JT
 * Cdot = J * v1 - bias
 *
 * Now solve for f2.
 * df = f2 - f1
 * K * (f2 - f1) = -Cdot
 * f2 = invK * (-Cdot) + f1
 *
 * Clamp accumulated limit impulse.
 * lower: f2(3) = max(f2(3), 0)
 * upper: f2(3) = min(f2(3), 0)
 *
 * Solve for correct f2(1:2)
 * K(1:2, 1:2) * f2(1:2) = -Cdot(1:2) - K(1:2,3) * f2(3) + K(1:2,1:3) * f1
 *                       = -Cdot(1:2) - K(1:2,3) * f2(3) + K(1:2,1:2) * f1(1:2) + K(1:2,3) * f1(3)
 * K(1:2, 1:2) * f2(1:2) = -Cdot(1:2) - K(1:2,3) * (f2(3) - f1(3)) + K(1:2,1:2) * f1(1:2)
 * f2(1:2) = invK(1:2,1:2) * (-Cdot(1:2) - K(1:2,3) * (f2(3) - f1(3))) + f1(1:2)
 *
 * Now compute impulse to be applied:
 * df = f2 - f1
 */

import { b2Abs, b2Clamp, b2CrossSV, b2Mat22, b2Mat33, b2Max, b2Min, b2MulRV, b2Rot, b2SubVV, b2Vec2, b2Vec3 } from '../../common/b2Math';
import { b2_linearSlop, b2_angularSlop, b2_maxLinearCorrection, b2Log } from '../../common/b2Settings';
import type { b2Body } from '../b2Body';
import type { b2SolverData } from '../b2TimeStep';
import { b2Joint, b2JointDef, b2JointType, b2LimitState, b2CheckJointAlive } from './b2Joint';
import { b2CheckFinite, b2CheckLimits, b2CheckNonNegative } from '../../common/b2ArgumentError';

const s_qA = new b2Rot();
const s_qB = new b2Rot();
const s_rA = new b2Vec2();
const s_rB = new b2Vec2();
const s_axis = new b2Vec2();
const s_perp = new b2Vec2();
const s_v2 = new b2Vec2();
const s_df2 = new b2Vec2();
const s_v3 = new b2Vec3();
const s_df3 = new b2Vec3();
const s_K22 = new b2Mat22();
const s_K33 = new b2Mat33();
const s_pA = new b2Vec2();
const s_pB = new b2Vec2();

/**
 * Prismatic joint definition. This requires defining a line of motion using an axis and an
 * anchor point. The definition uses local anchor points and a local axis so that the initial
 * configuration can violate the constraint slightly. The joint translation is zero when the
 * local anchor points coincide in world space. Using local anchors and a local axis helps when
 * saving and loading a game.
 */
export class b2PrismaticJointDef extends b2JointDef {
  /** The local anchor point relative to bodyA's origin. */
  localAnchorA = new b2Vec2();
  /** The local anchor point relative to bodyB's origin. */
  localAnchorB = new b2Vec2();
  /** The local translation unit axis in bodyA. */
  localAxisA = new b2Vec2(1.0, 0.0);
  /** The constrained angle between the bodies: bodyB_angle - bodyA_angle. */
  referenceAngle = 0.0;
  /** Enable/disable the joint limit. */
  enableLimit = false;
  /** The lower translation limit, usually in meters. */
  lowerTranslation = 0.0;
  /** The upper translation limit, usually in meters. */
  upperTranslation = 0.0;
  /** Enable/disable the joint motor. */
  enableMotor = false;
  /** The maximum motor torque, usually in N-m. */
  maxMotorForce = 0.0;
  /** The desired motor speed in radians per second. */
  motorSpeed = 0.0;

  constructor() {
    super(b2JointType.e_prismaticJoint);
  }

  /**
   * Initialize the bodies, anchors, axis, and reference angle using the world anchor and unit
   * world axis.
   */
  Initialize(bA: b2Body, bB: b2Body, anchor: Readonly<b2Vec2>, axis: Readonly<b2Vec2>): void {
    this.bodyA = bA;
    this.bodyB = bB;
    bA.GetLocalPoint(anchor, this.localAnchorA);
    bB.GetLocalPoint(anchor, this.localAnchorB);
    bA.GetLocalVector(axis, this.localAxisA);
    this.referenceAngle = bB.GetAngle() - bA.GetAngle();
  }
}

/**
 * A prismatic joint. This joint provides one degree of freedom: translation along an axis fixed
 * in bodyA. Relative rotation is prevented. You can use a joint limit to restrict the range of
 * motion and a joint motor to drive the motion or to model joint friction.
 */
export class b2PrismaticJoint extends b2Joint {
  // Solver shared
  readonly m_localAnchorA = new b2Vec2();
  readonly m_localAnchorB = new b2Vec2();
  readonly m_localXAxisA = new b2Vec2();
  readonly m_localYAxisA = new b2Vec2();
  m_referenceAngle = 0.0;
  readonly m_impulse = new b2Vec3();
  m_motorImpulse = 0.0;
  m_lowerTranslation = 0.0;
  m_upperTranslation = 0.0;
  m_maxMotorForce = 0.0;
  m_motorSpeed = 0.0;
  m_enableLimit = false;
  m_enableMotor = false;
  m_limitState = b2LimitState.e_inactiveLimit;

  // Solver temp
  m_indexA = 0;
  m_indexB = 0;
  readonly m_localCenterA = new b2Vec2();
  readonly m_localCenterB = new b2Vec2();
  m_invMassA = 0.0;
  m_invMassB = 0.0;
  m_invIA = 0.0;
  m_invIB = 0.0;
  readonly m_axis = new b2Vec2();
  readonly m_perp = new b2Vec2();
  m_s1 = 0.0;
  m_s2 = 0.0;
  m_a1 = 0.0;
  m_a2 = 0.0;
  readonly m_K = new b2Mat33();
  m_motorMass = 0.0;

  constructor(def: b2PrismaticJointDef) {
    super(def);

    this.m_localAnchorA.Assign(def.localAnchorA);
    this.m_localAnchorB.Assign(def.localAnchorB);
    this.m_localXAxisA.Assign(def.localAxisA);
    this.m_localXAxisA.Normalize();
    b2CrossSV(1.0, this.m_localXAxisA, this.m_localYAxisA);
    this.m_referenceAngle = def.referenceAngle;

    this.m_impulse.SetZero();
    this.m_motorMass = 0.0;
    this.m_motorImpulse = 0.0;

    this.m_lowerTranslation = def.lowerTranslation;
    this.m_upperTranslation = def.upperTranslation;
    this.m_maxMotorForce = def.maxMotorForce;
    this.m_motorSpeed = def.motorSpeed;
    this.m_enableLimit = def.enableLimit;
    this.m_enableMotor = def.enableMotor;
    this.m_limitState = b2LimitState.e_inactiveLimit;

    this.m_axis.SetZero();
    this.m_perp.SetZero();
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

    // Compute the effective masses.
    const rA = b2MulRV(qA, b2SubVV(this.m_localAnchorA, this.m_localCenterA, s_rA), s_rA);
    const rB = b2MulRV(qB, b2SubVV(this.m_localAnchorB, this.m_localCenterB, s_rB), s_rB);
    const dx = cBx - cAx + rB.x - rA.x;
    const dy = cBy - cAy + rB.y - rA.y;

    const mA = this.m_invMassA;
    const mB = this.m_invMassB;
    const iA = this.m_invIA;
    const iB = this.m_invIB;

    // Compute motor Jacobian and effective mass.
    {
      const axis = b2MulRV(qA, this.m_localXAxisA, this.m_axis);
      this.m_a1 = (dx + rA.x) * axis.y - (dy + rA.y) * axis.x;
      this.m_a2 = rB.x * axis.y - rB.y * axis.x;

      this.m_motorMass = mA + mB + iA * this.m_a1 * this.m_a1 + iB * this.m_a2 * this.m_a2;
      if (this.m_motorMass > 0.0) {
        this.m_motorMass = 1.0 / this.m_motorMass;
      }
    }

    // Prismatic constraint.
    {
      const perp = b2MulRV(qA, this.m_localYAxisA, this.m_perp);

      this.m_s1 = (dx + rA.x) * perp.y - (dy + rA.y) * perp.x;
      this.m_s2 = rB.x * perp.y - rB.y * perp.x;

      const s1 = this.m_s1;
      const s2 = this.m_s2;
      const a1 = this.m_a1;
      const a2 = this.m_a2;
      const k11 = mA + mB + iA * s1 * s1 + iB * s2 * s2;
      const k12 = iA * s1 + iB * s2;
      const k13 = iA * s1 * a1 + iB * s2 * a2;
      let k22 = iA + iB;
      if (k22 === 0.0) {
        // For bodies with fixed rotation.
        k22 = 1.0;
      }
      const k23 = iA * a1 + iB * a2;
      const k33 = mA + mB + iA * a1 * a1 + iB * a2 * a2;

      this.m_K.ex.Set(k11, k12, k13);
      this.m_K.ey.Set(k12, k22, k23);
      this.m_K.ez.Set(k13, k23, k33);
    }

    // Compute motor and limit terms.
    if (this.m_enableLimit) {
      const jointTranslation = this.m_axis.x * dx + this.m_axis.y * dy;
      if (b2Abs(this.m_upperTranslation - this.m_lowerTranslation) < 2.0 * b2_linearSlop) {
        this.m_limitState = b2LimitState.e_equalLimits;
      } else if (jointTranslation <= this.m_lowerTranslation) {
        if (this.m_limitState !== b2LimitState.e_atLowerLimit) {
          this.m_limitState = b2LimitState.e_atLowerLimit;
          this.m_impulse.z = 0.0;
        }
      } else if (jointTranslation >= this.m_upperTranslation) {
        if (this.m_limitState !== b2LimitState.e_atUpperLimit) {
          this.m_limitState = b2LimitState.e_atUpperLimit;
          this.m_impulse.z = 0.0;
        }
      } else {
        this.m_limitState = b2LimitState.e_inactiveLimit;
        this.m_impulse.z = 0.0;
      }
    } else {
      this.m_limitState = b2LimitState.e_inactiveLimit;
      this.m_impulse.z = 0.0;
    }

    if (this.m_enableMotor === false) {
      this.m_motorImpulse = 0.0;
    }

    if (data.step.warmStarting) {
      // Account for variable time step.
      this.m_impulse.Multiply(data.step.dtRatio);
      this.m_motorImpulse *= data.step.dtRatio;

      const imp = this.m_impulse;
      const axial = this.m_motorImpulse + imp.z;
      const Px = imp.x * this.m_perp.x + axial * this.m_axis.x;
      const Py = imp.x * this.m_perp.y + axial * this.m_axis.y;
      const LA = imp.x * this.m_s1 + imp.y + axial * this.m_a1;
      const LB = imp.x * this.m_s2 + imp.y + axial * this.m_a2;

      vAx -= mA * Px;
      vAy -= mA * Py;
      wA -= iA * LA;

      vBx += mB * Px;
      vBy += mB * Py;
      wB += iB * LB;
    } else {
      this.m_impulse.SetZero();
      this.m_motorImpulse = 0.0;
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
    const axis = this.m_axis;
    const perp = this.m_perp;

    // Solve linear motor constraint.
    if (this.m_enableMotor && this.m_limitState !== b2LimitState.e_equalLimits) {
      const Cdot = axis.x * (vBx - vAx) + axis.y * (vBy - vAy) + this.m_a2 * wB - this.m_a1 * wA;
      let impulse = this.m_motorMass * (this.m_motorSpeed - Cdot);
      const oldImpulse = this.m_motorImpulse;
      const maxImpulse = data.step.dt * this.m_maxMotorForce;
      this.m_motorImpulse = b2Clamp(this.m_motorImpulse + impulse, -maxImpulse, maxImpulse);
      impulse = this.m_motorImpulse - oldImpulse;

      const Px = impulse * axis.x;
      const Py = impulse * axis.y;
      const LA = impulse * this.m_a1;
      const LB = impulse * this.m_a2;

      vAx -= mA * Px;
      vAy -= mA * Py;
      wA -= iA * LA;

      vBx += mB * Px;
      vBy += mB * Py;
      wB += iB * LB;
    }

    const Cdot1x = perp.x * (vBx - vAx) + perp.y * (vBy - vAy) + this.m_s2 * wB - this.m_s1 * wA;
    const Cdot1y = wB - wA;

    if (this.m_enableLimit && this.m_limitState !== b2LimitState.e_inactiveLimit) {
      // Solve prismatic and limit constraint in block form.
      const Cdot2 = axis.x * (vBx - vAx) + axis.y * (vBy - vAy) + this.m_a2 * wB - this.m_a1 * wA;

      const f1x = this.m_impulse.x;
      const f1y = this.m_impulse.y;
      const f1z = this.m_impulse.z;
      const df = this.m_K.Solve33(s_v3.Set(-Cdot1x, -Cdot1y, -Cdot2), s_df3);
      this.m_impulse.Add(df);

      if (this.m_limitState === b2LimitState.e_atLowerLimit) {
        this.m_impulse.z = b2Max(this.m_impulse.z, 0.0);
      } else if (this.m_limitState === b2LimitState.e_atUpperLimit) {
        this.m_impulse.z = b2Min(this.m_impulse.z, 0.0);
      }

      // f2(1:2) = invK(1:2,1:2) * (-Cdot(1:2) - K(1:2,3) * (f2(3) - f1(3))) + f1(1:2)
      const dz = this.m_impulse.z - f1z;
      const b = s_v2.Set(-Cdot1x - dz * this.m_K.ez.x, -Cdot1y - dz * this.m_K.ez.y);
      const f2r = this.m_K.Solve22(b, s_df2);
      this.m_impulse.x = f2r.x + f1x;
      this.m_impulse.y = f2r.y + f1y;

      df.x = this.m_impulse.x - f1x;
      df.y = this.m_impulse.y - f1y;
      df.z = this.m_impulse.z - f1z;

      const Px = df.x * perp.x + df.z * axis.x;
      const Py = df.x * perp.y + df.z * axis.y;
      const LA = df.x * this.m_s1 + df.y + df.z * this.m_a1;
      const LB = df.x * this.m_s2 + df.y + df.z * this.m_a2;

      vAx -= mA * Px;
      vAy -= mA * Py;
      wA -= iA * LA;

      vBx += mB * Px;
      vBy += mB * Py;
      wB += iB * LB;
    } else {
      // Limit is inactive, just solve the prismatic constraint in block form.
      const df = this.m_K.Solve22(s_v2.Set(-Cdot1x, -Cdot1y), s_df2);
      this.m_impulse.x += df.x;
      this.m_impulse.y += df.y;

      const Px = df.x * perp.x;
      const Py = df.x * perp.y;
      const LA = df.x * this.m_s1 + df.y;
      const LB = df.x * this.m_s2 + df.y;

      vAx -= mA * Px;
      vAy -= mA * Py;
      wA -= iA * LA;

      vBx += mB * Px;
      vBy += mB * Py;
      wB += iB * LB;

      // The C++ recomputes Cdot1 here for a debugging check whose result is never used.
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

    // Compute fresh Jacobians
    const rA = b2MulRV(qA, b2SubVV(this.m_localAnchorA, this.m_localCenterA, s_rA), s_rA);
    const rB = b2MulRV(qB, b2SubVV(this.m_localAnchorB, this.m_localCenterB, s_rB), s_rB);
    const dx = cBx + rB.x - cAx - rA.x;
    const dy = cBy + rB.y - cAy - rA.y;

    const axis = b2MulRV(qA, this.m_localXAxisA, s_axis);
    const a1 = (dx + rA.x) * axis.y - (dy + rA.y) * axis.x;
    const a2 = rB.x * axis.y - rB.y * axis.x;
    const perp = b2MulRV(qA, this.m_localYAxisA, s_perp);

    const s1 = (dx + rA.x) * perp.y - (dy + rA.y) * perp.x;
    const s2 = rB.x * perp.y - rB.y * perp.x;

    const C1x = perp.x * dx + perp.y * dy;
    const C1y = aB - aA - this.m_referenceAngle;

    let linearError = b2Abs(C1x);
    const angularError = b2Abs(C1y);

    let active = false;
    let C2 = 0.0;
    if (this.m_enableLimit) {
      const translation = axis.x * dx + axis.y * dy;
      if (b2Abs(this.m_upperTranslation - this.m_lowerTranslation) < 2.0 * b2_linearSlop) {
        // Prevent large angular corrections
        C2 = b2Clamp(translation, -b2_maxLinearCorrection, b2_maxLinearCorrection);
        linearError = b2Max(linearError, b2Abs(translation));
        active = true;
      } else if (translation <= this.m_lowerTranslation) {
        // Prevent large linear corrections and allow some slop.
        C2 = b2Clamp(translation - this.m_lowerTranslation + b2_linearSlop, -b2_maxLinearCorrection, 0.0);
        linearError = b2Max(linearError, this.m_lowerTranslation - translation);
        active = true;
      } else if (translation >= this.m_upperTranslation) {
        // Prevent large linear corrections and allow some slop.
        C2 = b2Clamp(translation - this.m_upperTranslation - b2_linearSlop, 0.0, b2_maxLinearCorrection);
        linearError = b2Max(linearError, translation - this.m_upperTranslation);
        active = true;
      }
    }

    let impulseX: number;
    let impulseY: number;
    let impulseZ: number;
    if (active) {
      const k11 = mA + mB + iA * s1 * s1 + iB * s2 * s2;
      const k12 = iA * s1 + iB * s2;
      const k13 = iA * s1 * a1 + iB * s2 * a2;
      let k22 = iA + iB;
      if (k22 === 0.0) {
        // For fixed rotation
        k22 = 1.0;
      }
      const k23 = iA * a1 + iB * a2;
      const k33 = mA + mB + iA * a1 * a1 + iB * a2 * a2;

      const K = s_K33;
      K.ex.Set(k11, k12, k13);
      K.ey.Set(k12, k22, k23);
      K.ez.Set(k13, k23, k33);

      const impulse = K.Solve33(s_v3.Set(-C1x, -C1y, -C2), s_df3);
      impulseX = impulse.x;
      impulseY = impulse.y;
      impulseZ = impulse.z;
    } else {
      const k11 = mA + mB + iA * s1 * s1 + iB * s2 * s2;
      const k12 = iA * s1 + iB * s2;
      let k22 = iA + iB;
      if (k22 === 0.0) {
        k22 = 1.0;
      }

      const K = s_K22;
      K.ex.Set(k11, k12);
      K.ey.Set(k12, k22);

      const impulse1 = K.Solve(s_v2.Set(-C1x, -C1y), s_df2);
      impulseX = impulse1.x;
      impulseY = impulse1.y;
      impulseZ = 0.0;
    }

    const Px = impulseX * perp.x + impulseZ * axis.x;
    const Py = impulseX * perp.y + impulseZ * axis.y;
    const LA = impulseX * s1 + impulseY + impulseZ * a1;
    const LB = impulseX * s2 + impulseY + impulseZ * a2;

    cAx -= mA * Px;
    cAy -= mA * Py;
    aA -= iA * LA;
    cBx += mB * Px;
    cBy += mB * Py;
    aB += iB * LB;

    positions[oA] = cAx;
    positions[oA + 1] = cAy;
    positions[oA + 2] = aA;
    positions[oB] = cBx;
    positions[oB + 1] = cBy;
    positions[oB + 2] = aB;

    return linearError <= b2_linearSlop && angularError <= b2_angularSlop;
  }

  override GetAnchorA(out: b2Vec2): b2Vec2 {
    return this.m_bodyA.GetWorldPoint(this.m_localAnchorA, out);
  }

  override GetAnchorB(out: b2Vec2): b2Vec2 {
    return this.m_bodyB.GetWorldPoint(this.m_localAnchorB, out);
  }

  override GetReactionForce(inv_dt: number, out: b2Vec2): b2Vec2 {
    const axial = this.m_motorImpulse + this.m_impulse.z;
    const x = this.m_impulse.x * this.m_perp.x + axial * this.m_axis.x;
    const y = this.m_impulse.x * this.m_perp.y + axial * this.m_axis.y;
    return out.Set(inv_dt * x, inv_dt * y);
  }

  override GetReactionTorque(inv_dt: number): number {
    return inv_dt * this.m_impulse.y;
  }

  /** The local anchor point relative to bodyA's origin. */
  GetLocalAnchorA(): Readonly<b2Vec2> {
    return this.m_localAnchorA;
  }

  /** The local anchor point relative to bodyB's origin. */
  GetLocalAnchorB(): Readonly<b2Vec2> {
    return this.m_localAnchorB;
  }

  /** The local joint axis relative to bodyA. */
  GetLocalAxisA(): Readonly<b2Vec2> {
    return this.m_localXAxisA;
  }

  /** Get the reference angle. */
  GetReferenceAngle(): number {
    return this.m_referenceAngle;
  }

  /** Get the current joint translation, usually in meters. */
  GetJointTranslation(): number {
    const pA = this.m_bodyA.GetWorldPoint(this.m_localAnchorA, s_pA);
    const pB = this.m_bodyB.GetWorldPoint(this.m_localAnchorB, s_pB);
    const dx = pB.x - pA.x;
    const dy = pB.y - pA.y;
    const axis = this.m_bodyA.GetWorldVector(this.m_localXAxisA, s_axis);

    const translation = dx * axis.x + dy * axis.y;
    return translation;
  }

  /** Get the current joint translation speed, usually in meters per second. */
  GetJointSpeed(): number {
    const bA = this.m_bodyA;
    const bB = this.m_bodyB;
    bA.PullState();
    bB.PullState();

    const rA = b2MulRV(bA.m_xf.q, b2SubVV(this.m_localAnchorA, bA.m_sweep.localCenter, s_rA), s_rA);
    const rB = b2MulRV(bB.m_xf.q, b2SubVV(this.m_localAnchorB, bB.m_sweep.localCenter, s_rB), s_rB);
    const p1x = bA.m_sweep.c.x + rA.x;
    const p1y = bA.m_sweep.c.y + rA.y;
    const p2x = bB.m_sweep.c.x + rB.x;
    const p2y = bB.m_sweep.c.y + rB.y;
    const dx = p2x - p1x;
    const dy = p2y - p1y;
    const axis = b2MulRV(bA.m_xf.q, this.m_localXAxisA, s_axis);

    const vA = bA.m_linearVelocity;
    const vB = bB.m_linearVelocity;
    const wA = bA.m_angularVelocity;
    const wB = bB.m_angularVelocity;

    // dot(d, cross(wA, axis)) + dot(axis, vB + cross(wB, rB) - vA - cross(wA, rA))
    const relx = vB.x - wB * rB.y - vA.x + wA * rA.y;
    const rely = vB.y + wB * rB.x - vA.y - wA * rA.x;
    const speed = dx * (-wA * axis.y) + dy * (wA * axis.x) + (axis.x * relx + axis.y * rely);
    return speed;
  }

  /** Is the joint limit enabled? */
  IsLimitEnabled(): boolean {
    return this.m_enableLimit;
  }

  /** Enable/disable the joint limit. */
  EnableLimit(flag: boolean): void {
    b2CheckJointAlive(this, 'b2PrismaticJoint.EnableLimit');
    if (flag !== this.m_enableLimit) {
      this.m_bodyA.SetAwake(true);
      this.m_bodyB.SetAwake(true);
      this.m_enableLimit = flag;
      this.m_impulse.z = 0.0;
    }
  }

  /** Get the lower joint limit, usually in meters. */
  GetLowerLimit(): number {
    return this.m_lowerTranslation;
  }

  /** Get the upper joint limit, usually in meters. */
  GetUpperLimit(): number {
    return this.m_upperTranslation;
  }

  /** Set the joint limits, usually in meters. */
  SetLimits(lower: number, upper: number): void {
    b2CheckJointAlive(this, 'b2PrismaticJoint.SetLimits');
    b2CheckLimits('b2PrismaticJoint.SetLimits', 'lower', 'upper', lower, upper);
    if (lower !== this.m_lowerTranslation || upper !== this.m_upperTranslation) {
      this.m_bodyA.SetAwake(true);
      this.m_bodyB.SetAwake(true);
      this.m_lowerTranslation = lower;
      this.m_upperTranslation = upper;
      this.m_impulse.z = 0.0;
    }
  }

  /** Is the joint motor enabled? */
  IsMotorEnabled(): boolean {
    return this.m_enableMotor;
  }

  /** Enable/disable the joint motor. */
  EnableMotor(flag: boolean): void {
    b2CheckJointAlive(this, 'b2PrismaticJoint.EnableMotor');
    this.m_bodyA.SetAwake(true);
    this.m_bodyB.SetAwake(true);
    this.m_enableMotor = flag;
  }

  /** Set the motor speed, usually in meters per second. */
  SetMotorSpeed(speed: number): void {
    b2CheckJointAlive(this, 'b2PrismaticJoint.SetMotorSpeed');
    b2CheckFinite('b2PrismaticJoint.SetMotorSpeed', 'speed', speed);
    this.m_bodyA.SetAwake(true);
    this.m_bodyB.SetAwake(true);
    this.m_motorSpeed = speed;
  }

  /** Get the motor speed, usually in meters per second. */
  GetMotorSpeed(): number {
    return this.m_motorSpeed;
  }

  /** Set the maximum motor force, usually in N. */
  SetMaxMotorForce(force: number): void {
    b2CheckJointAlive(this, 'b2PrismaticJoint.SetMaxMotorForce');
    b2CheckNonNegative('b2PrismaticJoint.SetMaxMotorForce', 'force', force);
    this.m_bodyA.SetAwake(true);
    this.m_bodyB.SetAwake(true);
    this.m_maxMotorForce = force;
  }

  GetMaxMotorForce(): number {
    return this.m_maxMotorForce;
  }

  /** Get the current motor force given the inverse time step, usually in N. */
  GetMotorForce(inv_dt: number): number {
    return inv_dt * this.m_motorImpulse;
  }

  /** Dump to b2Log. */
  override Dump(): void {
    const indexA = this.m_bodyA.m_islandIndex;
    const indexB = this.m_bodyB.m_islandIndex;

    b2Log('  b2PrismaticJointDef jd;\n');
    b2Log('  jd.bodyA = bodies[%d];\n', indexA);
    b2Log('  jd.bodyB = bodies[%d];\n', indexB);
    b2Log('  jd.collideConnected = bool(%d);\n', this.m_collideConnected);
    b2Log('  jd.localAnchorA.Set(%.15lef, %.15lef);\n', this.m_localAnchorA.x, this.m_localAnchorA.y);
    b2Log('  jd.localAnchorB.Set(%.15lef, %.15lef);\n', this.m_localAnchorB.x, this.m_localAnchorB.y);
    b2Log('  jd.localAxisA.Set(%.15lef, %.15lef);\n', this.m_localXAxisA.x, this.m_localXAxisA.y);
    b2Log('  jd.referenceAngle = %.15lef;\n', this.m_referenceAngle);
    b2Log('  jd.enableLimit = bool(%d);\n', this.m_enableLimit);
    b2Log('  jd.lowerTranslation = %.15lef;\n', this.m_lowerTranslation);
    b2Log('  jd.upperTranslation = %.15lef;\n', this.m_upperTranslation);
    b2Log('  jd.enableMotor = bool(%d);\n', this.m_enableMotor);
    b2Log('  jd.motorSpeed = %.15lef;\n', this.m_motorSpeed);
    b2Log('  jd.maxMotorForce = %.15lef;\n', this.m_maxMotorForce);
    b2Log('  joints[%d] = m_world->CreateJoint(&jd);\n', this.m_index);
  }
}
