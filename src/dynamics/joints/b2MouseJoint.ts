/*
 * Mouse joint (b2MouseJoint.h, b2MouseJoint.cpp).
 *
 * p = attached point, m = mouse point
 * C = p - m
 * Cdot = v
 *      = v + cross(w, r)
 * J = [I r_skew]
 * Identity used:
 * w k % (rx i + ry j) = w * (-ry i + rx j)
 */

import { b2IsValid, b2Mat22, b2MulMV, b2MulRV, b2MulTXV, b2Rot, b2SubVV, b2Vec2 } from '../../common/b2Math';
import { b2_epsilon, b2_pi, b2Assert, b2Log } from '../../common/b2Settings';
import type { b2SolverData } from '../b2TimeStep';
import { b2Joint, b2JointDef, b2JointType, b2CheckJointAlive } from './b2Joint';
import { b2CheckNonNegative, b2CheckPositive, b2CheckVec2 } from '../../common/b2ArgumentError';

const s_qB = new b2Rot();
const s_K = new b2Mat22();
const s_rhs = new b2Vec2();
const s_impulse = new b2Vec2();

/** Mouse joint definition. This requires a world target point, tuning parameters, and the time step. */
export class b2MouseJointDef extends b2JointDef {
  /** The initial world target point. This is assumed to coincide with the body anchor initially. */
  target = new b2Vec2(0.0, 0.0);
  /**
   * The maximum constraint force that can be exerted to move the candidate body. Usually you
   * will express as some multiple of the weight (multiplier * mass * gravity).
   */
  maxForce = 0.0;
  /** The response speed. */
  frequencyHz = 5.0;
  /** The damping ratio. 0 = no damping, 1 = critical damping. */
  dampingRatio = 0.7;

  constructor() {
    super(b2JointType.e_mouseJoint);
  }
}

/**
 * A mouse joint is used to make a point on a body track a specified world point. This a soft
 * constraint with a maximum force. This allows the constraint to stretch and without applying
 * huge forces.
 * NOTE: this joint is not documented in the manual because it was developed to be used in the
 * testbed. If you want to learn how to use the mouse joint, look at the testbed.
 */
export class b2MouseJoint extends b2Joint {
  readonly m_localAnchorB = new b2Vec2();
  readonly m_targetA = new b2Vec2();
  m_frequencyHz = 0.0;
  m_dampingRatio = 0.0;
  m_beta = 0.0;

  // Solver shared
  readonly m_impulse = new b2Vec2();
  m_maxForce = 0.0;
  m_gamma = 0.0;

  // Solver temp (the C++ also declares an m_indexA that it never sets or reads)
  m_indexB = 0;
  readonly m_rB = new b2Vec2();
  readonly m_localCenterB = new b2Vec2();
  m_invMassB = 0.0;
  m_invIB = 0.0;
  readonly m_mass = new b2Mat22();
  readonly m_C = new b2Vec2();

  constructor(def: b2MouseJointDef) {
    super(def);

    b2Assert(def.target.IsValid(), 'target must be finite');
    b2Assert(b2IsValid(def.maxForce) && def.maxForce >= 0.0, 'maxForce must be finite and non-negative');
    b2Assert(b2IsValid(def.frequencyHz) && def.frequencyHz >= 0.0, 'frequencyHz must be finite and non-negative');
    b2Assert(b2IsValid(def.dampingRatio) && def.dampingRatio >= 0.0, 'dampingRatio must be finite and non-negative');

    this.m_targetA.Assign(def.target);
    b2MulTXV(this.m_bodyB.GetTransform(), this.m_targetA, this.m_localAnchorB);

    this.m_maxForce = def.maxForce;
    this.m_impulse.SetZero();

    this.m_frequencyHz = def.frequencyHz;
    this.m_dampingRatio = def.dampingRatio;

    this.m_beta = 0.0;
    this.m_gamma = 0.0;
  }

  /** Use this to update the target point. */
  SetTarget(target: Readonly<b2Vec2>): void {
    b2CheckJointAlive(this, 'b2MouseJoint.SetTarget');
    b2CheckVec2('b2MouseJoint.SetTarget', 'target', target);
    // Unguarded, unlike the C++ (the same when awake): a change listener hears every wake.
    this.m_bodyB.SetAwake(true);
    this.m_targetA.Assign(target);
  }

  GetTarget(): Readonly<b2Vec2> {
    return this.m_targetA;
  }

  /** Set/get the maximum force in Newtons. */
  SetMaxForce(force: number): void {
    b2CheckJointAlive(this, 'b2MouseJoint.SetMaxForce');
    b2CheckNonNegative('b2MouseJoint.SetMaxForce', 'force', force);
    this.m_maxForce = force;
  }

  GetMaxForce(): number {
    return this.m_maxForce;
  }

  /** Set/get the frequency in Hertz. */
  SetFrequency(hz: number): void {
    b2CheckJointAlive(this, 'b2MouseJoint.SetFrequency');
    b2CheckPositive('b2MouseJoint.SetFrequency', 'hz', hz);
    this.m_frequencyHz = hz;
  }

  GetFrequency(): number {
    return this.m_frequencyHz;
  }

  /** Set/get the damping ratio (dimensionless). */
  SetDampingRatio(ratio: number): void {
    b2CheckJointAlive(this, 'b2MouseJoint.SetDampingRatio');
    b2CheckNonNegative('b2MouseJoint.SetDampingRatio', 'ratio', ratio);
    this.m_dampingRatio = ratio;
  }

  GetDampingRatio(): number {
    return this.m_dampingRatio;
  }

  override InitVelocityConstraints(data: b2SolverData): void {
    const bB = this.m_bodyB;
    this.m_indexB = bB.m_islandIndex;
    this.m_localCenterB.Assign(bB.m_sweep.localCenter);
    this.m_invMassB = bB.m_invMass;
    this.m_invIB = bB.m_invI;

    const oB = 3 * this.m_indexB;
    const positions = data.positions;
    const velocities = data.velocities;
    const cBx = positions[oB];
    const cBy = positions[oB + 1];
    const aB = positions[oB + 2];
    let vBx = velocities[oB];
    let vBy = velocities[oB + 1];
    let wB = velocities[oB + 2];

    const qB = s_qB.Set(aB);

    const mass = bB.GetMass();

    // Frequency
    const omega = 2.0 * b2_pi * this.m_frequencyHz;

    // Damping coefficient
    const d = 2.0 * mass * this.m_dampingRatio * omega;

    // Spring stiffness
    const k = mass * (omega * omega);

    // magic formulas
    // gamma has units of inverse mass.
    // beta has units of inverse time.
    const h = data.step.dt;
    b2Assert(d + h * k > b2_epsilon);
    this.m_gamma = h * (d + h * k);
    if (this.m_gamma !== 0.0) {
      this.m_gamma = 1.0 / this.m_gamma;
    }
    this.m_beta = h * k * this.m_gamma;

    // Compute the effective mass matrix.
    const rB = b2MulRV(qB, b2SubVV(this.m_localAnchorB, this.m_localCenterB, this.m_rB), this.m_rB);

    // K    = [(1/m1 + 1/m2) * eye(2) - skew(r1) * invI1 * skew(r1) - skew(r2) * invI2 * skew(r2)]
    //      = [1/m1+1/m2     0    ] + invI1 * [r1.y*r1.y -r1.x*r1.y] + invI2 * [r1.y*r1.y -r1.x*r1.y]
    //        [    0     1/m1+1/m2]           [-r1.x*r1.y r1.x*r1.x]           [-r1.x*r1.y r1.x*r1.x]
    const K = s_K;
    K.ex.x = this.m_invMassB + this.m_invIB * rB.y * rB.y + this.m_gamma;
    K.ex.y = -this.m_invIB * rB.x * rB.y;
    K.ey.x = K.ex.y;
    K.ey.y = this.m_invMassB + this.m_invIB * rB.x * rB.x + this.m_gamma;

    K.GetInverse(this.m_mass);

    this.m_C.Set(cBx + rB.x - this.m_targetA.x, cBy + rB.y - this.m_targetA.y);
    this.m_C.Multiply(this.m_beta);

    // Cheat with some damping
    wB *= 0.98;

    if (data.step.warmStarting) {
      this.m_impulse.Multiply(data.step.dtRatio);
      vBx += this.m_invMassB * this.m_impulse.x;
      vBy += this.m_invMassB * this.m_impulse.y;
      wB += this.m_invIB * (rB.x * this.m_impulse.y - rB.y * this.m_impulse.x);
    } else {
      this.m_impulse.SetZero();
    }

    velocities[oB] = vBx;
    velocities[oB + 1] = vBy;
    velocities[oB + 2] = wB;
  }

  override SolveVelocityConstraints(data: b2SolverData): void {
    const oB = 3 * this.m_indexB;
    const velocities = data.velocities;
    let vBx = velocities[oB];
    let vBy = velocities[oB + 1];
    let wB = velocities[oB + 2];

    const rB = this.m_rB;

    // Cdot = v + cross(w, r)
    const Cdotx = vBx - wB * rB.y;
    const Cdoty = vBy + wB * rB.x;
    const rhs = s_rhs.Set(-(Cdotx + this.m_C.x + this.m_gamma * this.m_impulse.x), -(Cdoty + this.m_C.y + this.m_gamma * this.m_impulse.y));
    const impulse = b2MulMV(this.m_mass, rhs, s_impulse);

    const oldImpulseX = this.m_impulse.x;
    const oldImpulseY = this.m_impulse.y;
    this.m_impulse.Add(impulse);
    const maxImpulse = data.step.dt * this.m_maxForce;
    if (this.m_impulse.LengthSquared() > maxImpulse * maxImpulse) {
      this.m_impulse.Multiply(maxImpulse / this.m_impulse.Length());
    }
    impulse.x = this.m_impulse.x - oldImpulseX;
    impulse.y = this.m_impulse.y - oldImpulseY;

    vBx += this.m_invMassB * impulse.x;
    vBy += this.m_invMassB * impulse.y;
    wB += this.m_invIB * (rB.x * impulse.y - rB.y * impulse.x);

    velocities[oB] = vBx;
    velocities[oB + 1] = vBy;
    velocities[oB + 2] = wB;
  }

  override SolvePositionConstraints(data: b2SolverData): boolean {
    return true;
  }

  /** Implements b2Joint. */
  override GetAnchorA(out: b2Vec2): b2Vec2 {
    return out.Assign(this.m_targetA);
  }

  /** Implements b2Joint. */
  override GetAnchorB(out: b2Vec2): b2Vec2 {
    return this.m_bodyB.GetWorldPoint(this.m_localAnchorB, out);
  }

  /** Implements b2Joint. */
  override GetReactionForce(inv_dt: number, out: b2Vec2): b2Vec2 {
    return out.Set(inv_dt * this.m_impulse.x, inv_dt * this.m_impulse.y);
  }

  /** Implements b2Joint. */
  override GetReactionTorque(inv_dt: number): number {
    return inv_dt * 0.0;
  }

  /** The mouse joint does not support dumping. */
  override Dump(): void {
    b2Log('Mouse joint dumping is not supported.\n');
  }
}
