/*
 * Wheel joint (b2WheelJoint.h, b2WheelJoint.cpp).
 *
 * Linear constraint (point-to-line)
 * d = pB - pA = xB + rB - xA - rA
 * C = dot(ay, d)
 * Cdot = dot(d, cross(wA, ay)) + dot(ay, vB + cross(wB, rB) - vA - cross(wA, rA))
 *      = -dot(ay, vA) - dot(cross(d + rA, ay), wA) + dot(ay, vB) + dot(cross(rB, ay), vB)
 * J = [-ay, -cross(d + rA, ay), ay, cross(rB, ay)]
 *
 * Spring linear constraint
 * C = dot(ax, d)
 * Cdot = = -dot(ax, vA) - dot(cross(d + rA, ax), wA) + dot(ax, vB) + dot(cross(rB, ax), vB)
 * J = [-ax -cross(d+rA, ax) ax cross(rB, ax)]
 *
 * Motor rotational constraint
 * Cdot = wB - wA
 * J = [0 0 -1 0 0 1]
 *
 * b2WheelJoint::GetDefinition is declared by the 2.2.1 header but never defined (a C++ call fails
 * to link). The port defines it as the inverse of the constructor: it fills a def from which
 * CreateJoint would build an equivalent joint.
 */

import { b2Abs, b2Clamp, b2CrossSV, b2MulRV, b2Rot, b2SubVV, b2Vec2 } from '../../common/b2Math';
import { b2_linearSlop, b2_pi, b2Log } from '../../common/b2Settings';
import type { b2Body } from '../b2Body';
import type { b2SolverData } from '../b2TimeStep';
import { b2Joint, b2JointDef, b2JointType, b2CheckJointAlive } from './b2Joint';
import { b2CheckFinite, b2CheckNonNegative } from '../../common/b2ArgumentError';

const s_qA = new b2Rot();
const s_qB = new b2Rot();
const s_rA = new b2Vec2();
const s_rB = new b2Vec2();
const s_ay = new b2Vec2();
const s_pA = new b2Vec2();
const s_pB = new b2Vec2();
const s_axis = new b2Vec2();

/**
 * Wheel joint definition. This requires defining a line of motion using an axis and an anchor
 * point. The definition uses local anchor points and a local axis so that the initial
 * configuration can violate the constraint slightly. The joint translation is zero when the local
 * anchor points coincide in world space. Using local anchors and a local axis helps when saving
 * and loading a game.
 */
export class b2WheelJointDef extends b2JointDef {
  /** The local anchor point relative to bodyA's origin. */
  localAnchorA = new b2Vec2();
  /** The local anchor point relative to bodyB's origin. */
  localAnchorB = new b2Vec2();
  /** The local translation axis in bodyA. */
  localAxisA = new b2Vec2(1.0, 0.0);
  /** Enable/disable the joint motor. */
  enableMotor = false;
  /** The maximum motor torque, usually in N-m. */
  maxMotorTorque = 0.0;
  /** The desired motor speed in radians per second. */
  motorSpeed = 0.0;
  /** Suspension frequency, zero indicates no suspension */
  frequencyHz = 2.0;
  /** Suspension damping ratio, one indicates critical damping */
  dampingRatio = 0.7;

  constructor() {
    super(b2JointType.e_wheelJoint);
  }

  /**
   * Initialize the bodies, anchors, axis, and reference angle using the world anchor and world
   * axis.
   */
  Initialize(bA: b2Body, bB: b2Body, anchor: Readonly<b2Vec2>, axis: Readonly<b2Vec2>): void {
    this.bodyA = bA;
    this.bodyB = bB;
    bA.GetLocalPoint(anchor, this.localAnchorA);
    bB.GetLocalPoint(anchor, this.localAnchorB);
    bA.GetLocalVector(axis, this.localAxisA);
  }
}

/**
 * A wheel joint. This joint provides two degrees of freedom: translation along an axis fixed in
 * bodyA and rotation in the plane. You can use a joint limit to restrict the range of motion and
 * a joint motor to drive the rotation or to model rotational friction. This joint is designed for
 * vehicle suspensions.
 */
export class b2WheelJoint extends b2Joint {
  m_frequencyHz = 0.0;
  m_dampingRatio = 0.0;

  // Solver shared
  readonly m_localAnchorA = new b2Vec2();
  readonly m_localAnchorB = new b2Vec2();
  readonly m_localXAxisA = new b2Vec2();
  readonly m_localYAxisA = new b2Vec2();

  m_impulse = 0.0;
  m_motorImpulse = 0.0;
  m_springImpulse = 0.0;

  m_maxMotorTorque = 0.0;
  m_motorSpeed = 0.0;
  m_enableMotor = false;

  // Solver temp
  m_indexA = 0;
  m_indexB = 0;
  readonly m_localCenterA = new b2Vec2();
  readonly m_localCenterB = new b2Vec2();
  m_invMassA = 0.0;
  m_invMassB = 0.0;
  m_invIA = 0.0;
  m_invIB = 0.0;

  readonly m_ax = new b2Vec2();
  readonly m_ay = new b2Vec2();
  // The C++ constructor leaves the four lever arms uninitialised; zero is the only sane start.
  m_sAx = 0.0;
  m_sBx = 0.0;
  m_sAy = 0.0;
  m_sBy = 0.0;

  m_mass = 0.0;
  m_motorMass = 0.0;
  m_springMass = 0.0;

  m_bias = 0.0;
  m_gamma = 0.0;

  constructor(def: b2WheelJointDef) {
    super(def);

    this.m_localAnchorA.Assign(def.localAnchorA);
    this.m_localAnchorB.Assign(def.localAnchorB);
    this.m_localXAxisA.Assign(def.localAxisA);
    b2CrossSV(1.0, this.m_localXAxisA, this.m_localYAxisA);

    this.m_mass = 0.0;
    this.m_impulse = 0.0;
    this.m_motorMass = 0.0;
    this.m_motorImpulse = 0.0;
    this.m_springMass = 0.0;
    this.m_springImpulse = 0.0;

    this.m_maxMotorTorque = def.maxMotorTorque;
    this.m_motorSpeed = def.motorSpeed;
    this.m_enableMotor = def.enableMotor;

    this.m_frequencyHz = def.frequencyHz;
    this.m_dampingRatio = def.dampingRatio;

    this.m_bias = 0.0;
    this.m_gamma = 0.0;

    this.m_ax.SetZero();
    this.m_ay.SetZero();
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

    const mA = this.m_invMassA;
    const mB = this.m_invMassB;
    const iA = this.m_invIA;
    const iB = this.m_invIB;

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
    const dx = cBx + rB.x - cAx - rA.x;
    const dy = cBy + rB.y - cAy - rA.y;

    // Point to line constraint
    {
      const ay = b2MulRV(qA, this.m_localYAxisA, this.m_ay);
      this.m_sAy = (dx + rA.x) * ay.y - (dy + rA.y) * ay.x;
      this.m_sBy = rB.x * ay.y - rB.y * ay.x;

      this.m_mass = mA + mB + iA * this.m_sAy * this.m_sAy + iB * this.m_sBy * this.m_sBy;

      if (this.m_mass > 0.0) {
        this.m_mass = 1.0 / this.m_mass;
      }
    }

    // Spring constraint
    this.m_springMass = 0.0;
    this.m_bias = 0.0;
    this.m_gamma = 0.0;
    if (this.m_frequencyHz > 0.0) {
      const ax = b2MulRV(qA, this.m_localXAxisA, this.m_ax);
      this.m_sAx = (dx + rA.x) * ax.y - (dy + rA.y) * ax.x;
      this.m_sBx = rB.x * ax.y - rB.y * ax.x;

      const invMass = mA + mB + iA * this.m_sAx * this.m_sAx + iB * this.m_sBx * this.m_sBx;

      if (invMass > 0.0) {
        this.m_springMass = 1.0 / invMass;

        const C = dx * ax.x + dy * ax.y;

        // Frequency
        const omega = 2.0 * b2_pi * this.m_frequencyHz;

        // Damping coefficient
        const d = 2.0 * this.m_springMass * this.m_dampingRatio * omega;

        // Spring stiffness
        const k = this.m_springMass * omega * omega;

        // magic formulas
        const h = data.step.dt;
        this.m_gamma = h * (d + h * k);
        if (this.m_gamma > 0.0) {
          this.m_gamma = 1.0 / this.m_gamma;
        }

        this.m_bias = C * h * k * this.m_gamma;

        this.m_springMass = invMass + this.m_gamma;
        if (this.m_springMass > 0.0) {
          this.m_springMass = 1.0 / this.m_springMass;
        }
      }
    } else {
      this.m_springImpulse = 0.0;
    }

    // Rotational motor
    if (this.m_enableMotor) {
      this.m_motorMass = iA + iB;
      if (this.m_motorMass > 0.0) {
        this.m_motorMass = 1.0 / this.m_motorMass;
      }
    } else {
      this.m_motorMass = 0.0;
      this.m_motorImpulse = 0.0;
    }

    if (data.step.warmStarting) {
      // Account for variable time step.
      this.m_impulse *= data.step.dtRatio;
      this.m_springImpulse *= data.step.dtRatio;
      this.m_motorImpulse *= data.step.dtRatio;

      const Px = this.m_impulse * this.m_ay.x + this.m_springImpulse * this.m_ax.x;
      const Py = this.m_impulse * this.m_ay.y + this.m_springImpulse * this.m_ax.y;
      const LA = this.m_impulse * this.m_sAy + this.m_springImpulse * this.m_sAx + this.m_motorImpulse;
      const LB = this.m_impulse * this.m_sBy + this.m_springImpulse * this.m_sBx + this.m_motorImpulse;

      vAx -= this.m_invMassA * Px;
      vAy -= this.m_invMassA * Py;
      wA -= this.m_invIA * LA;

      vBx += this.m_invMassB * Px;
      vBy += this.m_invMassB * Py;
      wB += this.m_invIB * LB;
    } else {
      this.m_impulse = 0.0;
      this.m_springImpulse = 0.0;
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
    const mA = this.m_invMassA;
    const mB = this.m_invMassB;
    const iA = this.m_invIA;
    const iB = this.m_invIB;

    const oA = 3 * this.m_indexA;
    const velocities = data.velocities;
    const oB = 3 * this.m_indexB;
    let vAx = velocities[oA];
    let vAy = velocities[oA + 1];
    let wA = velocities[oA + 2];
    let vBx = velocities[oB];
    let vBy = velocities[oB + 1];
    let wB = velocities[oB + 2];

    const ax = this.m_ax;
    const ay = this.m_ay;

    // Solve spring constraint
    {
      const Cdot = ax.x * (vBx - vAx) + ax.y * (vBy - vAy) + this.m_sBx * wB - this.m_sAx * wA;
      const impulse = -this.m_springMass * (Cdot + this.m_bias + this.m_gamma * this.m_springImpulse);
      this.m_springImpulse += impulse;

      const Px = impulse * ax.x;
      const Py = impulse * ax.y;
      const LA = impulse * this.m_sAx;
      const LB = impulse * this.m_sBx;

      vAx -= mA * Px;
      vAy -= mA * Py;
      wA -= iA * LA;

      vBx += mB * Px;
      vBy += mB * Py;
      wB += iB * LB;
    }

    // Solve rotational motor constraint
    {
      const Cdot = wB - wA - this.m_motorSpeed;
      let impulse = -this.m_motorMass * Cdot;

      const oldImpulse = this.m_motorImpulse;
      const maxImpulse = data.step.dt * this.m_maxMotorTorque;
      this.m_motorImpulse = b2Clamp(this.m_motorImpulse + impulse, -maxImpulse, maxImpulse);
      impulse = this.m_motorImpulse - oldImpulse;

      wA -= iA * impulse;
      wB += iB * impulse;
    }

    // Solve point to line constraint
    {
      const Cdot = ay.x * (vBx - vAx) + ay.y * (vBy - vAy) + this.m_sBy * wB - this.m_sAy * wA;
      const impulse = -this.m_mass * Cdot;
      this.m_impulse += impulse;

      const Px = impulse * ay.x;
      const Py = impulse * ay.y;
      const LA = impulse * this.m_sAy;
      const LB = impulse * this.m_sBy;

      vAx -= mA * Px;
      vAy -= mA * Py;
      wA -= iA * LA;

      vBx += mB * Px;
      vBy += mB * Py;
      wB += iB * LB;
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

    const rA = b2MulRV(qA, b2SubVV(this.m_localAnchorA, this.m_localCenterA, s_rA), s_rA);
    const rB = b2MulRV(qB, b2SubVV(this.m_localAnchorB, this.m_localCenterB, s_rB), s_rB);
    const dx = cBx - cAx + rB.x - rA.x;
    const dy = cBy - cAy + rB.y - rA.y;

    const ay = b2MulRV(qA, this.m_localYAxisA, s_ay);

    const sAy = (dx + rA.x) * ay.y - (dy + rA.y) * ay.x;
    const sBy = rB.x * ay.y - rB.y * ay.x;

    const C = dx * ay.x + dy * ay.y;

    // 2.2.1 builds the effective mass from the lever arms cached by InitVelocityConstraints
    // (m_sAy, m_sBy), not from the fresh sAy/sBy used for the impulse below.
    const k = this.m_invMassA + this.m_invMassB + this.m_invIA * this.m_sAy * this.m_sAy + this.m_invIB * this.m_sBy * this.m_sBy;

    let impulse: number;
    if (k !== 0.0) {
      impulse = -C / k;
    } else {
      impulse = 0.0;
    }

    const Px = impulse * ay.x;
    const Py = impulse * ay.y;
    const LA = impulse * sAy;
    const LB = impulse * sBy;

    cAx -= this.m_invMassA * Px;
    cAy -= this.m_invMassA * Py;
    aA -= this.m_invIA * LA;
    cBx += this.m_invMassB * Px;
    cBy += this.m_invMassB * Py;
    aB += this.m_invIB * LB;

    positions[oA] = cAx;
    positions[oA + 1] = cAy;
    positions[oA + 2] = aA;
    positions[oB] = cBx;
    positions[oB + 1] = cBy;
    positions[oB + 2] = aB;

    return b2Abs(C) <= b2_linearSlop;
  }

  /**
   * Fill def with this joint's settings: bodies, user data, collideConnected, local anchors, local
   * axis, motor and spring. Declared (never defined) by the 2.2.1 header; see the file comment.
   */
  GetDefinition(def: b2WheelJointDef): void {
    def.type = this.m_type;
    def.userData = this.m_userData;
    def.bodyA = this.m_bodyA;
    def.bodyB = this.m_bodyB;
    def.collideConnected = this.m_collideConnected;
    def.localAnchorA.Assign(this.m_localAnchorA);
    def.localAnchorB.Assign(this.m_localAnchorB);
    def.localAxisA.Assign(this.m_localXAxisA);
    def.enableMotor = this.m_enableMotor;
    def.maxMotorTorque = this.m_maxMotorTorque;
    def.motorSpeed = this.m_motorSpeed;
    def.frequencyHz = this.m_frequencyHz;
    def.dampingRatio = this.m_dampingRatio;
  }

  override GetAnchorA(out: b2Vec2): b2Vec2 {
    return this.m_bodyA.GetWorldPoint(this.m_localAnchorA, out);
  }

  override GetAnchorB(out: b2Vec2): b2Vec2 {
    return this.m_bodyB.GetWorldPoint(this.m_localAnchorB, out);
  }

  override GetReactionForce(inv_dt: number, out: b2Vec2): b2Vec2 {
    const x = this.m_impulse * this.m_ay.x + this.m_springImpulse * this.m_ax.x;
    const y = this.m_impulse * this.m_ay.y + this.m_springImpulse * this.m_ax.y;
    return out.Set(inv_dt * x, inv_dt * y);
  }

  override GetReactionTorque(inv_dt: number): number {
    return inv_dt * this.m_motorImpulse;
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

  /** Get the current joint translation, usually in meters. */
  GetJointTranslation(): number {
    const bA = this.m_bodyA;
    const bB = this.m_bodyB;

    const pA = bA.GetWorldPoint(this.m_localAnchorA, s_pA);
    const pB = bB.GetWorldPoint(this.m_localAnchorB, s_pB);
    const dx = pB.x - pA.x;
    const dy = pB.y - pA.y;
    const axis = bA.GetWorldVector(this.m_localXAxisA, s_axis);

    const translation = dx * axis.x + dy * axis.y;
    return translation;
  }

  /** Get the current joint translation speed, usually in meters per second. */
  GetJointSpeed(): number {
    this.m_bodyA.PullState();
    this.m_bodyB.PullState();
    const wA = this.m_bodyA.m_angularVelocity;
    const wB = this.m_bodyB.m_angularVelocity;
    return wB - wA;
  }

  /** Is the joint motor enabled? */
  IsMotorEnabled(): boolean {
    return this.m_enableMotor;
  }

  /** Enable/disable the joint motor. */
  EnableMotor(flag: boolean): void {
    b2CheckJointAlive(this, 'b2WheelJoint.EnableMotor');
    this.m_bodyA.SetAwake(true);
    this.m_bodyB.SetAwake(true);
    this.m_enableMotor = flag;
  }

  /** Set the motor speed, usually in radians per second. */
  SetMotorSpeed(speed: number): void {
    b2CheckJointAlive(this, 'b2WheelJoint.SetMotorSpeed');
    b2CheckFinite('b2WheelJoint.SetMotorSpeed', 'speed', speed);
    this.m_bodyA.SetAwake(true);
    this.m_bodyB.SetAwake(true);
    this.m_motorSpeed = speed;
  }

  /** Get the motor speed, usually in radians per second. */
  GetMotorSpeed(): number {
    return this.m_motorSpeed;
  }

  /** Set/Get the maximum motor force, usually in N-m. */
  SetMaxMotorTorque(torque: number): void {
    b2CheckJointAlive(this, 'b2WheelJoint.SetMaxMotorTorque');
    b2CheckNonNegative('b2WheelJoint.SetMaxMotorTorque', 'torque', torque);
    this.m_bodyA.SetAwake(true);
    this.m_bodyB.SetAwake(true);
    this.m_maxMotorTorque = torque;
  }

  GetMaxMotorTorque(): number {
    return this.m_maxMotorTorque;
  }

  /** Get the current motor torque given the inverse time step, usually in N-m. */
  GetMotorTorque(inv_dt: number): number {
    return inv_dt * this.m_motorImpulse;
  }

  /** Set/Get the spring frequency in hertz. Setting the frequency to zero disables the spring. */
  SetSpringFrequencyHz(hz: number): void {
    b2CheckJointAlive(this, 'b2WheelJoint.SetSpringFrequencyHz');
    b2CheckNonNegative('b2WheelJoint.SetSpringFrequencyHz', 'hz', hz);
    this.m_frequencyHz = hz;
  }

  GetSpringFrequencyHz(): number {
    return this.m_frequencyHz;
  }

  /** Set/Get the spring damping ratio */
  SetSpringDampingRatio(ratio: number): void {
    b2CheckJointAlive(this, 'b2WheelJoint.SetSpringDampingRatio');
    b2CheckNonNegative('b2WheelJoint.SetSpringDampingRatio', 'ratio', ratio);
    this.m_dampingRatio = ratio;
  }

  GetSpringDampingRatio(): number {
    return this.m_dampingRatio;
  }

  /** Dump to b2Log. */
  override Dump(): void {
    const indexA = this.m_bodyA.m_islandIndex;
    const indexB = this.m_bodyB.m_islandIndex;

    b2Log('  b2WheelJointDef jd;\n');
    b2Log('  jd.bodyA = bodies[%d];\n', indexA);
    b2Log('  jd.bodyB = bodies[%d];\n', indexB);
    b2Log('  jd.collideConnected = bool(%d);\n', this.m_collideConnected);
    b2Log('  jd.localAnchorA.Set(%.15lef, %.15lef);\n', this.m_localAnchorA.x, this.m_localAnchorA.y);
    b2Log('  jd.localAnchorB.Set(%.15lef, %.15lef);\n', this.m_localAnchorB.x, this.m_localAnchorB.y);
    b2Log('  jd.localAxisA.Set(%.15lef, %.15lef);\n', this.m_localXAxisA.x, this.m_localXAxisA.y);
    b2Log('  jd.enableMotor = bool(%d);\n', this.m_enableMotor);
    b2Log('  jd.motorSpeed = %.15lef;\n', this.m_motorSpeed);
    b2Log('  jd.maxMotorTorque = %.15lef;\n', this.m_maxMotorTorque);
    b2Log('  jd.frequencyHz = %.15lef;\n', this.m_frequencyHz);
    b2Log('  jd.dampingRatio = %.15lef;\n', this.m_dampingRatio);
    b2Log('  joints[%d] = m_world->CreateJoint(&jd);\n', this.m_index);
  }
}
