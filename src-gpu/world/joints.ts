/*
 * Joints into the mirror's tables and back: each of 2.2.1's ten joint types as its jointParams
 * record (anchors, limits, motor, spring; world points as cell + offset) and its jointState words
 * (impulses, limit state); and those words, read back from the GPU, into the b2Joint objects.
 *
 * In:  a b2Joint; the scratch records of the jointParams and jointState tables (layout.ts,
 *      solver/solveJoints.ts JOINT_PARAMS_VEC4).
 * Out: the scratch records filled (packJoint), or the joint's impulses and limit state
 *      (unpackJointState).
 * Invariants: unpackJointState reads exactly the state words packJoint writes; packing allocates
 *      nothing (sync() packs every joint each time).
 */

import type { b2Body } from '../../src/dynamics/b2Body';
import type { b2Joint } from '../../src/dynamics/joints/b2Joint';
import type { b2RevoluteJoint } from '../../src/dynamics/joints/b2RevoluteJoint';
import type { b2DistanceJoint } from '../../src/dynamics/joints/b2DistanceJoint';
import type { b2PrismaticJoint } from '../../src/dynamics/joints/b2PrismaticJoint';
import type { b2PulleyJoint } from '../../src/dynamics/joints/b2PulleyJoint';
import type { b2MouseJoint } from '../../src/dynamics/joints/b2MouseJoint';
import type { b2GearJoint } from '../../src/dynamics/joints/b2GearJoint';
import type { b2WheelJoint } from '../../src/dynamics/joints/b2WheelJoint';
import type { b2WeldJoint } from '../../src/dynamics/joints/b2WeldJoint';
import type { b2FrictionJoint } from '../../src/dynamics/joints/b2FrictionJoint';
import type { b2RopeJoint } from '../../src/dynamics/joints/b2RopeJoint';
import { b2JointType } from '../../src/common/b2Constants';
import type { MirrorTable } from '../device/buffers';

/** Four words into a scratch record at `at` (no array literal: packing allocates nothing). */
function put4(record: Float32Array, at: number, a: number, b: number, c: number, d: number): void {
  record[at] = a;
  record[at + 1] = b;
  record[at + 2] = c;
  record[at + 3] = d;
}

/**
 * A world point into the params' scratch record as bodies are held: its cell (i32 words at
 * `cellAt`) and the float32 offset in it (at `offsetAt`), so a stage takes it into any body's cell.
 */
function packWorldPoint(params: MirrorTable, cellSize: number, x: number, y: number, offsetAt: number, cellAt: number): void {
  const cx = Math.round(x / cellSize);
  const cy = Math.round(y / cellSize);
  params.scratchF32[offsetAt] = x - cx * cellSize;
  params.scratchF32[offsetAt + 1] = y - cy * cellSize;
  params.scratchI32[cellAt] = cx;
  params.scratchI32[cellAt + 1] = cy;
}

/** Joint `j` into the scratch records of `params` and `state`; `slots` gives the gear joint's bodies' slots. */
export function packJoint(j: b2Joint, params: MirrorTable, state: MirrorTable, cellSize: number, slots: { bodySlot(body: b2Body): number }): void {
  const p = params.scratchF32;
  p.fill(0);
  const s = state.scratchF32;
  s.fill(0);
  switch (j.m_type) {
    case b2JointType.e_revoluteJoint: {
      const r = j as b2RevoluteJoint;
      put4(p, 0, r.m_localAnchorA.x, r.m_localAnchorA.y, r.m_localAnchorB.x, r.m_localAnchorB.y);
      put4(p, 4, r.m_referenceAngle, r.m_lowerAngle, r.m_upperAngle, r.m_maxMotorTorque);
      put4(p, 8, r.m_motorSpeed, r.m_enableLimit ? 1 : 0, r.m_enableMotor ? 1 : 0, 0);
      put4(s, 0, r.m_impulse.x, r.m_impulse.y, r.m_impulse.z, r.m_motorImpulse);
      s[4] = r.m_limitState;
      break;
    }
    case b2JointType.e_prismaticJoint: {
      const r = j as b2PrismaticJoint;
      put4(p, 0, r.m_localAnchorA.x, r.m_localAnchorA.y, r.m_localAnchorB.x, r.m_localAnchorB.y);
      put4(p, 4, r.m_referenceAngle, r.m_lowerTranslation, r.m_upperTranslation, r.m_maxMotorForce);
      put4(p, 8, r.m_motorSpeed, r.m_enableLimit ? 1 : 0, r.m_enableMotor ? 1 : 0, 0);
      put4(p, 12, r.m_localXAxisA.x, r.m_localXAxisA.y, r.m_localYAxisA.x, r.m_localYAxisA.y);
      put4(s, 0, r.m_impulse.x, r.m_impulse.y, r.m_impulse.z, r.m_motorImpulse);
      s[4] = r.m_limitState;
      break;
    }
    case b2JointType.e_distanceJoint: {
      const d = j as b2DistanceJoint;
      put4(p, 0, d.m_localAnchorA.x, d.m_localAnchorA.y, d.m_localAnchorB.x, d.m_localAnchorB.y);
      put4(p, 4, d.m_length, d.m_frequencyHz, d.m_dampingRatio, 0);
      s[0] = d.m_impulse;
      break;
    }
    case b2JointType.e_pulleyJoint: {
      const q = j as b2PulleyJoint;
      put4(p, 0, q.m_localAnchorA.x, q.m_localAnchorA.y, q.m_localAnchorB.x, q.m_localAnchorB.y);
      put4(p, 4, q.m_lengthA, q.m_lengthB, q.m_ratio, q.m_constant);
      packWorldPoint(params, cellSize, q.m_groundAnchorA.x, q.m_groundAnchorA.y, 8, 12);
      packWorldPoint(params, cellSize, q.m_groundAnchorB.x, q.m_groundAnchorB.y, 10, 14);
      s[0] = q.m_impulse;
      break;
    }
    case b2JointType.e_mouseJoint: {
      const m = j as b2MouseJoint;
      put4(p, 0, 0, 0, m.m_localAnchorB.x, m.m_localAnchorB.y);
      put4(p, 4, m.m_frequencyHz, m.m_dampingRatio, m.m_maxForce, m.m_bodyB.m_mass);
      packWorldPoint(params, cellSize, m.m_targetA.x, m.m_targetA.y, 8, 12);
      s[0] = m.m_impulse.x;
      s[1] = m.m_impulse.y;
      break;
    }
    case b2JointType.e_gearJoint: {
      const g = j as b2GearJoint;
      put4(p, 0, g.m_localAnchorA.x, g.m_localAnchorA.y, g.m_localAnchorB.x, g.m_localAnchorB.y);
      put4(p, 4, g.m_referenceAngleA, g.m_referenceAngleB, g.m_ratio, g.m_constant);
      put4(p, 8, g.m_localAnchorC.x, g.m_localAnchorC.y, g.m_localAnchorD.x, g.m_localAnchorD.y);
      put4(p, 12, g.m_localAxisC.x, g.m_localAxisC.y, g.m_localAxisD.x, g.m_localAxisD.y);
      const u = params.scratchU32;
      u[16] = slots.bodySlot(g.m_bodyC);
      u[17] = slots.bodySlot(g.m_bodyD);
      u[18] = g.m_typeA;
      u[19] = g.m_typeB;
      s[0] = g.m_impulse;
      break;
    }
    case b2JointType.e_wheelJoint: {
      const w = j as b2WheelJoint;
      put4(p, 0, w.m_localAnchorA.x, w.m_localAnchorA.y, w.m_localAnchorB.x, w.m_localAnchorB.y);
      put4(p, 4, w.m_frequencyHz, w.m_dampingRatio, 0, w.m_maxMotorTorque);
      put4(p, 8, w.m_motorSpeed, 0, w.m_enableMotor ? 1 : 0, 0);
      put4(p, 12, w.m_localXAxisA.x, w.m_localXAxisA.y, w.m_localYAxisA.x, w.m_localYAxisA.y);
      put4(s, 0, w.m_impulse, w.m_springImpulse, w.m_motorImpulse, 0);
      break;
    }
    case b2JointType.e_weldJoint: {
      const w = j as b2WeldJoint;
      put4(p, 0, w.m_localAnchorA.x, w.m_localAnchorA.y, w.m_localAnchorB.x, w.m_localAnchorB.y);
      put4(p, 4, w.m_referenceAngle, w.m_frequencyHz, w.m_dampingRatio, 0);
      put4(s, 0, w.m_impulse.x, w.m_impulse.y, w.m_impulse.z, 0);
      break;
    }
    case b2JointType.e_frictionJoint: {
      const f = j as b2FrictionJoint;
      put4(p, 0, f.m_localAnchorA.x, f.m_localAnchorA.y, f.m_localAnchorB.x, f.m_localAnchorB.y);
      put4(p, 4, f.m_maxForce, f.m_maxTorque, 0, 0);
      put4(s, 0, f.m_linearImpulse.x, f.m_linearImpulse.y, f.m_angularImpulse, 0);
      break;
    }
    case b2JointType.e_ropeJoint: {
      const r = j as b2RopeJoint;
      put4(p, 0, r.m_localAnchorA.x, r.m_localAnchorA.y, r.m_localAnchorB.x, r.m_localAnchorB.y);
      p[4] = r.m_maxLength;
      s[0] = r.m_impulse;
      s[4] = r.m_state;
      break;
    }
  }
}

/** The state words of one joint (8 from `at`, as read back) into its impulses and limit state. */
export function unpackJointState(j: b2Joint, state: Float32Array, at: number): void {
  switch (j.m_type) {
    case b2JointType.e_revoluteJoint:
    case b2JointType.e_prismaticJoint: {
      const r = j as b2RevoluteJoint | b2PrismaticJoint;
      r.m_impulse.Set(state[at], state[at + 1], state[at + 2]);
      r.m_motorImpulse = state[at + 3];
      r.m_limitState = state[at + 4];
      break;
    }
    case b2JointType.e_distanceJoint:
      (j as b2DistanceJoint).m_impulse = state[at];
      break;
    case b2JointType.e_pulleyJoint:
      (j as b2PulleyJoint).m_impulse = state[at];
      break;
    case b2JointType.e_mouseJoint:
      (j as b2MouseJoint).m_impulse.Set(state[at], state[at + 1]);
      break;
    case b2JointType.e_gearJoint:
      (j as b2GearJoint).m_impulse = state[at];
      break;
    case b2JointType.e_wheelJoint: {
      const w = j as b2WheelJoint;
      w.m_impulse = state[at];
      w.m_springImpulse = state[at + 1];
      w.m_motorImpulse = state[at + 2];
      break;
    }
    case b2JointType.e_weldJoint:
      (j as b2WeldJoint).m_impulse.Set(state[at], state[at + 1], state[at + 2]);
      break;
    case b2JointType.e_frictionJoint: {
      const f = j as b2FrictionJoint;
      f.m_linearImpulse.Set(state[at], state[at + 1]);
      f.m_angularImpulse = state[at + 2];
      break;
    }
    case b2JointType.e_ropeJoint: {
      const r = j as b2RopeJoint;
      r.m_impulse = state[at];
      r.m_state = state[at + 4];
      break;
    }
  }
}
