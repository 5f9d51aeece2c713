/*
 * Checks of joint definitions and of the bodies and joints a world call refers to (no C++
 * counterpart; see common/b2ArgumentError.ts; body and fixture definitions: b2BodyDefValidation.ts).
 * b2World.CreateJoint, DestroyBody and DestroyJoint run them before they change anything.
 *
 * The joint rules are those of Box2D 2.2.1's asserts and documentation, plus what keeps the solver
 * free of NaN: finite numbers everywhere, non-negative forces, torques, frequencies and damping
 * ratios, non-zero axes, a non-zero pulley ratio, a non-negative rope length, a
 * positive mouse frequency on a dynamic body B (b2MouseJoint asserts d + h * k > epsilon in the time
 * step, with d and k proportional to body B's mass).
 */

import {
  b2ArgumentError,
  b2CheckFinite,
  b2CheckNonNegative,
  b2CheckObject,
  b2CheckPositive,
  b2CheckVec2,
  b2DescribeNumber,
  b2DestroyedError,
} from '../common/b2ArgumentError';
import type { b2Vec2 } from '../common/b2Math';
import { b2BodyType, b2JointType } from '../common/b2Constants';
import { b2Body } from './b2Body';
import type { b2World } from './b2World';
import type { b2DistanceJointDef } from './joints/b2DistanceJoint';
import type { b2FrictionJointDef } from './joints/b2FrictionJoint';
import type { b2GearJointDef } from './joints/b2GearJoint';
import { b2Joint } from './joints/b2Joint';
import type { b2JointDef } from './joints/b2Joint';
import type { b2MouseJointDef } from './joints/b2MouseJoint';
import type { b2PrismaticJointDef } from './joints/b2PrismaticJoint';
import type { b2PulleyJointDef } from './joints/b2PulleyJoint';
import type { b2RevoluteJointDef } from './joints/b2RevoluteJoint';
import type { b2RopeJointDef } from './joints/b2RopeJoint';
import type { b2WeldJointDef } from './joints/b2WeldJoint';
import type { b2WheelJointDef } from './joints/b2WheelJoint';

/** `body` must be a live body of `world`. */
export function b2CheckBodyOf(method: string, argument: string, body: b2Body | null, world: b2World): void {
  if (!(body instanceof b2Body)) {
    throw new b2ArgumentError(method, argument, `must be a b2Body, got ${b2DescribeNumber(body)}`);
  }
  if (body.m_destroyed) throw b2DestroyedError(method, argument);
  if (body.m_world !== world) throw new b2ArgumentError(method, argument, 'belongs to another world');
}

/** `joint` must be a live joint of `world`. */
export function b2CheckJointOf(method: string, argument: string, joint: b2Joint | null, world: b2World): void {
  if (!(joint instanceof b2Joint)) {
    throw new b2ArgumentError(method, argument, `must be a b2Joint, got ${b2DescribeNumber(joint)}`);
  }
  if (joint.m_destroyed) throw b2DestroyedError(method, argument);
  if (joint.m_bodyA.m_world !== world) throw new b2ArgumentError(method, argument, 'belongs to another world');
}

function checkAnchors(method: string, def: { localAnchorA: b2Vec2; localAnchorB: b2Vec2 }): void {
  b2CheckVec2(method, 'def.localAnchorA', def.localAnchorA);
  b2CheckVec2(method, 'def.localAnchorB', def.localAnchorB);
}

/** An axis must be finite and not zero (the joint normalizes it). */
export function b2CheckAxis(method: string, argument: string, axis: Readonly<b2Vec2>): void {
  b2CheckVec2(method, argument, axis);
  if (!(axis.x * axis.x + axis.y * axis.y > 0.0)) {
    throw new b2ArgumentError(method, argument, 'must not be the zero vector (it is the joint axis)');
  }
}

function checkGearJoint(method: string, argument: string, joint: b2Joint | null, world: b2World): void {
  b2CheckJointOf(method, argument, joint, world);
  const type = (joint as b2Joint).m_type;
  if (type !== b2JointType.e_revoluteJoint && type !== b2JointType.e_prismaticJoint) {
    throw new b2ArgumentError(method, argument, `must be a revolute or prismatic joint, got a ${b2JointType[type] ?? b2DescribeNumber(type)}`);
  }
}

/** A joint definition for `world`: two distinct live bodies of the world and the type's rules. */
export function b2CheckJointDef(method: string, def: Readonly<b2JointDef>, world: b2World): void {
  b2CheckObject(method, 'def', def);
  b2CheckBodyOf(method, 'def.bodyA', def.bodyA, world);
  b2CheckBodyOf(method, 'def.bodyB', def.bodyB, world);
  if (def.bodyA === def.bodyB) {
    throw new b2ArgumentError(method, 'def.bodyB', 'is def.bodyA (a joint connects two different bodies)');
  }

  switch (def.type) {
    case b2JointType.e_revoluteJoint: {
      const d = def as b2RevoluteJointDef;
      checkAnchors(method, d);
      b2CheckFinite(method, 'def.referenceAngle', d.referenceAngle);
      // 2.2.1 asserts lower <= upper only in SetLimits: a def may carry any finite pair.
      b2CheckFinite(method, 'def.lowerAngle', d.lowerAngle);
      b2CheckFinite(method, 'def.upperAngle', d.upperAngle);
      b2CheckFinite(method, 'def.motorSpeed', d.motorSpeed);
      b2CheckNonNegative(method, 'def.maxMotorTorque', d.maxMotorTorque);
      return;
    }
    case b2JointType.e_prismaticJoint: {
      const d = def as b2PrismaticJointDef;
      checkAnchors(method, d);
      b2CheckAxis(method, 'def.localAxisA', d.localAxisA);
      b2CheckFinite(method, 'def.referenceAngle', d.referenceAngle);
      b2CheckFinite(method, 'def.lowerTranslation', d.lowerTranslation);
      b2CheckFinite(method, 'def.upperTranslation', d.upperTranslation);
      b2CheckFinite(method, 'def.motorSpeed', d.motorSpeed);
      b2CheckNonNegative(method, 'def.maxMotorForce', d.maxMotorForce);
      return;
    }
    case b2JointType.e_distanceJoint: {
      const d = def as b2DistanceJointDef;
      checkAnchors(method, d);
      b2CheckNonNegative(method, 'def.length', d.length);
      b2CheckNonNegative(method, 'def.frequencyHz', d.frequencyHz);
      b2CheckNonNegative(method, 'def.dampingRatio', d.dampingRatio);
      return;
    }
    case b2JointType.e_pulleyJoint: {
      const d = def as b2PulleyJointDef;
      b2CheckVec2(method, 'def.groundAnchorA', d.groundAnchorA);
      b2CheckVec2(method, 'def.groundAnchorB', d.groundAnchorB);
      checkAnchors(method, d);
      b2CheckNonNegative(method, 'def.lengthA', d.lengthA);
      b2CheckNonNegative(method, 'def.lengthB', d.lengthB);
      b2CheckFinite(method, 'def.ratio', d.ratio);
      if (d.ratio === 0.0) {
        // b2PulleyJoint divides by the ratio (2.2.1 asserts ratio != 0); a negative one is allowed.
        throw new b2ArgumentError(method, 'def.ratio', 'must not be 0');
      }
      return;
    }
    case b2JointType.e_mouseJoint: {
      const d = def as b2MouseJointDef;
      if ((d.bodyB as b2Body).m_type !== b2BodyType.b2_dynamicBody) {
        // The joint's spring is built from body B's mass: without one, b2MouseJoint asserts in the time step.
        throw new b2ArgumentError(method, 'def.bodyB', 'must be a dynamic body (the mouse joint drags body B by its mass)');
      }
      b2CheckVec2(method, 'def.target', d.target);
      b2CheckNonNegative(method, 'def.maxForce', d.maxForce);
      b2CheckPositive(method, 'def.frequencyHz', d.frequencyHz);
      b2CheckNonNegative(method, 'def.dampingRatio', d.dampingRatio);
      return;
    }
    case b2JointType.e_gearJoint: {
      const d = def as b2GearJointDef;
      checkGearJoint(method, 'def.joint1', d.joint1, world);
      checkGearJoint(method, 'def.joint2', d.joint2, world);
      if (d.joint1 === d.joint2) {
        throw new b2ArgumentError(method, 'def.joint2', 'is def.joint1 (a gear couples two different joints)');
      }
      b2CheckFinite(method, 'def.ratio', d.ratio);
      return;
    }
    case b2JointType.e_wheelJoint: {
      const d = def as b2WheelJointDef;
      checkAnchors(method, d);
      b2CheckAxis(method, 'def.localAxisA', d.localAxisA);
      b2CheckFinite(method, 'def.motorSpeed', d.motorSpeed);
      b2CheckNonNegative(method, 'def.maxMotorTorque', d.maxMotorTorque);
      b2CheckNonNegative(method, 'def.frequencyHz', d.frequencyHz);
      b2CheckNonNegative(method, 'def.dampingRatio', d.dampingRatio);
      return;
    }
    case b2JointType.e_weldJoint: {
      const d = def as b2WeldJointDef;
      checkAnchors(method, d);
      b2CheckFinite(method, 'def.referenceAngle', d.referenceAngle);
      b2CheckNonNegative(method, 'def.frequencyHz', d.frequencyHz);
      b2CheckNonNegative(method, 'def.dampingRatio', d.dampingRatio);
      return;
    }
    case b2JointType.e_frictionJoint: {
      const d = def as b2FrictionJointDef;
      checkAnchors(method, d);
      b2CheckNonNegative(method, 'def.maxForce', d.maxForce);
      b2CheckNonNegative(method, 'def.maxTorque', d.maxTorque);
      return;
    }
    case b2JointType.e_ropeJoint: {
      const d = def as b2RopeJointDef;
      checkAnchors(method, d);
      b2CheckNonNegative(method, 'def.maxLength', d.maxLength);
      return;
    }
    default:
      throw new b2ArgumentError(method, 'def.type', `must be a joint type (use a b2XxxJointDef), got ${b2JointType[def.type] ?? b2DescribeNumber(def.type)}`);
  }
}
