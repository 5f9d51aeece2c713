/*
 * The island solver (b2Island.h, b2Island.cpp).
 *
 * The C++ builds an island and a contact solver from the stack allocator for every solve. Here
 * the world keeps one island and re-initialises it with Initialize(), and the island keeps one
 * contact solver: the capacities are the C++ ones (SolveTOI stops growing its mini island when
 * they are reached), while the backing arrays only grow, so steady-state steps do not allocate.
 */

import { b2Abs, b2Clamp, b2Max, b2Min, type b2Vec2 } from '../common/b2Math';
import {
  b2Assert,
  b2_angularSleepTolerance,
  b2_linearSleepTolerance,
  b2_maxFloat,
  b2_maxRotation,
  b2_maxRotationSquared,
  b2_maxTranslation,
  b2_maxTranslationSquared,
  b2_timeToSleep,
} from '../common/b2Settings';
import { b2Timer } from '../common/b2Timer';
import { b2BodyFlags, b2BodyType, b2JointType } from '../common/b2Constants';
import type { b2Body } from './b2Body';
import { b2SolverData, type b2Profile, type b2TimeStep } from './b2TimeStep';
import { b2ContactImpulse, b2ContactListener } from './b2WorldCallbacks';
import type { b2Contact } from './contacts/b2Contact';
import { b2ContactSolver, b2ContactSolverDef, type b2ContactVelocityConstraint } from './contacts/b2ContactSolver';
import type { b2Joint } from './joints/b2Joint';
import { b2RevoluteSolvePosition, b2RevoluteSolveVelocity, type b2RevoluteJoint } from './joints/b2RevoluteJoint';

/** This is an internal class. */
export class b2Island {
  m_listener: b2ContactListener | null = null;

  // Never replaced: the contact solver def shares these arrays.
  readonly m_bodies: b2Body[] = [];
  readonly m_contacts: b2Contact[] = [];
  readonly m_joints: b2Joint[] = [];

  /**
   * The b2Position and b2Velocity records of the island's bodies, three doubles each (see
   * b2SolverData). Replaced by larger ones when the island grows; the solver data and the contact
   * solver def are pointed at the new ones.
   */
  m_positions = new Float64Array(0);
  m_velocities = new Float64Array(0);

  /**
   * Not in the C++: the solver record of joint i (a revolute joint's m_solverRecord, null for the
   * other kinds) and its offset, noted after the joint's InitVelocityConstraints. The velocity and
   * position passes run the revolute joints on their records (b2RevoluteSolveVelocity,
   * b2RevoluteSolvePosition) without loading the joint objects, scattered over the heap.
   */
  private readonly m_jointRecords: (Float64Array | null)[] = [];
  private m_jointRecordOffsets = new Int32Array(0);

  m_bodyCount = 0;
  m_jointCount = 0;
  m_contactCount = 0;

  m_bodyCapacity = 0;
  m_contactCapacity = 0;
  m_jointCapacity = 0;

  private readonly m_timer = new b2Timer();
  private readonly m_solverData = new b2SolverData();
  private readonly m_contactSolverDef = new b2ContactSolverDef();
  private readonly m_contactSolver = new b2ContactSolver();
  private readonly m_impulse = new b2ContactImpulse();

  constructor(bodyCapacity: number, contactCapacity: number, jointCapacity: number, listener: b2ContactListener | null) {
    this.m_contactSolverDef.contacts = this.m_contacts;
    this.Initialize(bodyCapacity, contactCapacity, jointCapacity, listener);
  }

  /**
   * Make this island the one the C++ constructor would build: empty, with these capacities and
   * this listener. The position and velocity buffers grow geometrically and are never shrunk.
   */
  Initialize(bodyCapacity: number, contactCapacity: number, jointCapacity: number, listener: b2ContactListener | null): void {
    this.m_bodyCapacity = bodyCapacity;
    this.m_contactCapacity = contactCapacity;
    this.m_jointCapacity = jointCapacity;
    this.m_bodyCount = 0;
    this.m_contactCount = 0;
    this.m_jointCount = 0;

    this.m_listener = listener;

    const length = this.m_positions.length / 3;
    if (length < bodyCapacity) {
      // Every solve writes the records of its bodies before reading them: nothing to copy.
      const newLength = b2Max(bodyCapacity, 2 * length);
      this.m_positions = new Float64Array(3 * newLength);
      this.m_velocities = new Float64Array(3 * newLength);
      this.m_solverData.positions = this.m_positions;
      this.m_solverData.velocities = this.m_velocities;
      this.m_contactSolverDef.positions = this.m_positions;
      this.m_contactSolverDef.velocities = this.m_velocities;
    }
  }

  Clear(): void {
    this.m_bodyCount = 0;
    this.m_contactCount = 0;
    this.m_jointCount = 0;
  }

  /** profile: null when the world is not timing its steps (b2World.SetProfiling). */
  Solve(profile: b2Profile | null, step: Readonly<b2TimeStep>, gravity: Readonly<b2Vec2>, allowSleep: boolean): void {
    const timer = this.m_timer;
    if (profile !== null) timer.Reset();

    const h = step.dt;
    const positions = this.m_positions;
    const velocities = this.m_velocities;

    // Integrate velocities and apply damping. Initialize the body state.
    for (let i = 0; i < this.m_bodyCount; ++i) {
      const b = this.m_bodies[i];
      const sweep = b.m_sweep;

      const cx = sweep.c.x;
      const cy = sweep.c.y;
      const a = sweep.a;
      let vx = b.m_linearVelocity.x;
      let vy = b.m_linearVelocity.y;
      let w = b.m_angularVelocity;

      // Store positions for continuous collision.
      sweep.c0.Assign(sweep.c);
      sweep.a0 = sweep.a;

      if (b.m_type === b2BodyType.b2_dynamicBody) {
        // Integrate velocities.
        vx += h * (b.m_gravityScale * gravity.x + b.m_invMass * b.m_force.x);
        vy += h * (b.m_gravityScale * gravity.y + b.m_invMass * b.m_force.y);
        w += h * b.m_invI * b.m_torque;

        // Apply damping.
        // ODE: dv/dt + c * v = 0
        // Solution: v(t) = v0 * exp(-c * t)
        // Time step: v(t + dt) = v0 * exp(-c * (t + dt)) = v0 * exp(-c * t) * exp(-c * dt) = v * exp(-c * dt)
        // v2 = exp(-c * dt) * v1
        // Taylor expansion:
        // v2 = (1.0f - c * dt) * v1
        const linearScale = b2Clamp(1.0 - h * b.m_linearDamping, 0.0, 1.0);
        vx *= linearScale;
        vy *= linearScale;
        w *= b2Clamp(1.0 - h * b.m_angularDamping, 0.0, 1.0);
      }

      positions[3 * i] = cx;
      positions[3 * i + 1] = cy;
      positions[3 * i + 2] = a;
      velocities[3 * i] = vx;
      velocities[3 * i + 1] = vy;
      velocities[3 * i + 2] = w;
    }

    if (profile !== null) timer.Reset();

    // Solver data
    const solverData = this.m_solverData;
    solverData.step.Assign(step);

    // Initialize velocity constraints.
    const contactSolver = this.CreateContactSolver(step);
    contactSolver.InitializeVelocityConstraints();

    if (step.warmStarting) {
      contactSolver.WarmStart();
    }

    solverData.jointRecordCount = 0;
    if (this.m_jointRecordOffsets.length < this.m_jointCount) {
      this.m_jointRecordOffsets = new Int32Array(b2Max(this.m_jointCount, 2 * this.m_jointRecordOffsets.length));
    }
    const jointRecords = this.m_jointRecords;
    const jointRecordOffsets = this.m_jointRecordOffsets;
    for (let i = 0; i < this.m_jointCount; ++i) {
      const joint = this.m_joints[i];
      joint.InitVelocityConstraints(solverData);
      if (joint.m_type === b2JointType.e_revoluteJoint) {
        jointRecords[i] = (joint as b2RevoluteJoint).m_solverRecord;
        jointRecordOffsets[i] = (joint as b2RevoluteJoint).m_recordOffset;
      } else {
        jointRecords[i] = null;
      }
    }

    if (profile !== null) profile.solveInit = timer.GetMilliseconds();

    // Solve velocity constraints
    if (profile !== null) timer.Reset();
    for (let i = 0; i < step.velocityIterations; ++i) {
      for (let j = 0; j < this.m_jointCount; ++j) {
        const record = jointRecords[j];
        if (record !== null) {
          b2RevoluteSolveVelocity(record, jointRecordOffsets[j], solverData);
        } else {
          this.m_joints[j].SolveVelocityConstraints(solverData);
        }
      }

      contactSolver.SolveVelocityConstraints();
    }

    // Store impulses for warm starting
    for (let j = 0; j < this.m_jointCount; ++j) {
      this.m_joints[j].StoreImpulses();
    }
    contactSolver.StoreImpulses();
    if (profile !== null) profile.solveVelocity = timer.GetMilliseconds();

    // Integrate positions
    for (let i = 0; i < this.m_bodyCount; ++i) {
      this.IntegratePosition(i, h);
    }

    // Solve position constraints
    if (profile !== null) timer.Reset();
    let positionSolved = false;
    for (let i = 0; i < step.positionIterations; ++i) {
      const contactsOkay = contactSolver.SolvePositionConstraints();

      let jointsOkay = true;
      for (let j = 0; j < this.m_jointCount; ++j) {
        const record = jointRecords[j];
        const jointOkay =
          record !== null ? b2RevoluteSolvePosition(record, jointRecordOffsets[j], solverData) : this.m_joints[j].SolvePositionConstraints(solverData);
        jointsOkay = jointsOkay && jointOkay;
      }

      if (contactsOkay && jointsOkay) {
        // Exit early if the position errors are small.
        positionSolved = true;
        break;
      }
    }

    // Copy state buffers back to the bodies
    for (let i = 0; i < this.m_bodyCount; ++i) {
      const body = this.m_bodies[i];
      body.m_sweep.c.x = positions[3 * i];
      body.m_sweep.c.y = positions[3 * i + 1];
      body.m_sweep.a = positions[3 * i + 2];
      body.m_linearVelocity.x = velocities[3 * i];
      body.m_linearVelocity.y = velocities[3 * i + 1];
      body.m_angularVelocity = velocities[3 * i + 2];
      body.SynchronizeTransform();
    }

    if (profile !== null) profile.solvePosition = timer.GetMilliseconds();

    this.ReportSolver(contactSolver);

    if (allowSleep) {
      let minSleepTime = +b2_maxFloat; // unary plus: docs/PORTING.md

      const linTolSqr = b2_linearSleepTolerance * b2_linearSleepTolerance;
      const angTolSqr = b2_angularSleepTolerance * b2_angularSleepTolerance;

      for (let i = 0; i < this.m_bodyCount; ++i) {
        const b = this.m_bodies[i];
        if (b.GetType() === b2BodyType.b2_staticBody) {
          continue;
        }

        const v = b.m_linearVelocity;
        if ((b.m_flags & b2BodyFlags.e_autoSleepFlag) === 0 || b.m_angularVelocity * b.m_angularVelocity > angTolSqr || v.x * v.x + v.y * v.y > linTolSqr) {
          b.m_sleepTime = 0.0;
          minSleepTime = 0.0;
        } else {
          b.m_sleepTime += h;
          minSleepTime = b2Min(minSleepTime, b.m_sleepTime);
        }
      }

      if (minSleepTime >= b2_timeToSleep && positionSolved) {
        for (let i = 0; i < this.m_bodyCount; ++i) {
          const b = this.m_bodies[i];
          b.SetAwake(false);
        }
      }
    }
  }

  SolveTOI(subStep: Readonly<b2TimeStep>, toiIndexA: number, toiIndexB: number): void {
    b2Assert(toiIndexA < this.m_bodyCount);
    b2Assert(toiIndexB < this.m_bodyCount);

    const positions = this.m_positions;
    const velocities = this.m_velocities;

    // Initialize the body state.
    for (let i = 0; i < this.m_bodyCount; ++i) {
      const b = this.m_bodies[i];
      positions[3 * i] = b.m_sweep.c.x;
      positions[3 * i + 1] = b.m_sweep.c.y;
      positions[3 * i + 2] = b.m_sweep.a;
      velocities[3 * i] = b.m_linearVelocity.x;
      velocities[3 * i + 1] = b.m_linearVelocity.y;
      velocities[3 * i + 2] = b.m_angularVelocity;
    }

    const contactSolver = this.CreateContactSolver(subStep);

    // Solve position constraints.
    for (let i = 0; i < subStep.positionIterations; ++i) {
      const contactsOkay = contactSolver.SolveTOIPositionConstraints(toiIndexA, toiIndexB);
      if (contactsOkay) {
        break;
      }
    }

    // Leap of faith to new safe state.
    const sweepA = this.m_bodies[toiIndexA].m_sweep;
    sweepA.c0.x = positions[3 * toiIndexA];
    sweepA.c0.y = positions[3 * toiIndexA + 1];
    sweepA.a0 = positions[3 * toiIndexA + 2];
    const sweepB = this.m_bodies[toiIndexB].m_sweep;
    sweepB.c0.x = positions[3 * toiIndexB];
    sweepB.c0.y = positions[3 * toiIndexB + 1];
    sweepB.a0 = positions[3 * toiIndexB + 2];

    // No warm starting is needed for TOI events because warm
    // starting impulses were applied in the discrete solver.
    contactSolver.InitializeVelocityConstraints();

    // Solve velocity constraints.
    for (let i = 0; i < subStep.velocityIterations; ++i) {
      contactSolver.SolveVelocityConstraints();
    }

    // Don't store the TOI contact forces for warm starting
    // because they can be quite large.

    const h = subStep.dt;

    // Integrate positions
    for (let i = 0; i < this.m_bodyCount; ++i) {
      this.IntegratePosition(i, h);

      // Sync bodies
      const body = this.m_bodies[i];
      body.m_sweep.c.x = positions[3 * i];
      body.m_sweep.c.y = positions[3 * i + 1];
      body.m_sweep.a = positions[3 * i + 2];
      body.m_linearVelocity.x = velocities[3 * i];
      body.m_linearVelocity.y = velocities[3 * i + 1];
      body.m_angularVelocity = velocities[3 * i + 2];
      body.SynchronizeTransform();
    }

    this.ReportSolver(contactSolver);
  }

  Add(body: b2Body): void {
    b2Assert(this.m_bodyCount < this.m_bodyCapacity);
    body.m_islandIndex = this.m_bodyCount;
    this.m_bodies[this.m_bodyCount] = body;
    ++this.m_bodyCount;
  }

  AddContact(contact: b2Contact): void {
    b2Assert(this.m_contactCount < this.m_contactCapacity);
    this.m_contacts[this.m_contactCount++] = contact;
  }

  AddJoint(joint: b2Joint): void {
    b2Assert(this.m_jointCount < this.m_jointCapacity);
    this.m_joints[this.m_jointCount++] = joint;
  }

  Report(constraints: readonly b2ContactVelocityConstraint[]): void {
    const listener = this.m_listener;
    if (listener === null) {
      return;
    }

    const impulse = this.m_impulse;
    for (let i = 0; i < this.m_contactCount; ++i) {
      const c = this.m_contacts[i];

      const vc = constraints[i];

      impulse.count = vc.pointCount;
      for (let j = 0; j < vc.pointCount; ++j) {
        impulse.normalImpulses[j] = vc.points[j].normalImpulse;
        impulse.tangentImpulses[j] = vc.points[j].tangentImpulse;
      }

      listener.PostSolve(c, impulse);
    }
  }

  /**
   * Report as the C++ Report(contactSolver.m_velocityConstraints) does, reading the impulses
   * straight from the solver's constraint records.
   */
  private ReportSolver(contactSolver: b2ContactSolver): void {
    const listener = this.m_listener;
    // A listener without a PostSolve of its own (the world's default one) would get only calls
    // to the empty base method: skipping them changes nothing.
    if (listener === null || listener.PostSolve === b2ContactListener.prototype.PostSolve) {
      return;
    }

    const impulse = this.m_impulse;
    for (let i = 0; i < this.m_contactCount; ++i) {
      const c = this.m_contacts[i];
      contactSolver.GetImpulses(i, impulse);
      listener.PostSolve(c, impulse);
    }
  }

  /** The C++ constructs a b2ContactSolver here; the island re-initialises its own. */
  private CreateContactSolver(step: Readonly<b2TimeStep>): b2ContactSolver {
    const def = this.m_contactSolverDef;
    def.step.Assign(step);
    def.count = this.m_contactCount;
    return this.m_contactSolver.Initialize(def);
  }

  /**
   * The position integration of one body, shared by Solve and SolveTOI: clamp the velocity to
   * b2_maxTranslation and b2_maxRotation per step, then c += h * v and a += h * w, in the
   * island's buffers.
   */
  private IntegratePosition(i: number, h: number): void {
    const positions = this.m_positions;
    const velocities = this.m_velocities;
    let vx = velocities[3 * i];
    let vy = velocities[3 * i + 1];
    let w = velocities[3 * i + 2];

    // Check for large velocities
    const translationX = h * vx;
    const translationY = h * vy;
    const translationSquared = translationX * translationX + translationY * translationY;
    if (translationSquared > b2_maxTranslationSquared) {
      const ratio = b2_maxTranslation / Math.sqrt(translationSquared);
      vx *= ratio;
      vy *= ratio;
    }

    const rotation = h * w;
    if (rotation * rotation > b2_maxRotationSquared) {
      const ratio = b2_maxRotation / b2Abs(rotation);
      w *= ratio;
    }

    // Integrate
    positions[3 * i] += h * vx;
    positions[3 * i + 1] += h * vy;
    positions[3 * i + 2] += h * w;
    velocities[3 * i] = vx;
    velocities[3 * i + 1] = vy;
    velocities[3 * i + 2] = w;
  }
}
