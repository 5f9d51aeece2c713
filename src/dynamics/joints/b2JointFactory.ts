/*
 * b2Joint::Create and b2Joint::Destroy (b2Joint.cpp). They live here rather than in b2Joint.ts
 * because they import every concrete joint, and the joints import b2Joint: a base module that
 * imports its subclasses breaks ES module load order.
 */

import { b2Assert } from '../../common/b2Settings';
import { b2DistanceJoint, type b2DistanceJointDef } from './b2DistanceJoint';
import { b2FrictionJoint, type b2FrictionJointDef } from './b2FrictionJoint';
import { b2GearJoint, type b2GearJointDef } from './b2GearJoint';
import { b2JointType, type b2Joint, type b2JointDef } from './b2Joint';
import { b2MouseJoint, type b2MouseJointDef } from './b2MouseJoint';
import { b2PrismaticJoint, type b2PrismaticJointDef } from './b2PrismaticJoint';
import { b2PulleyJoint, type b2PulleyJointDef } from './b2PulleyJoint';
import { b2RevoluteJoint, type b2RevoluteJointDef } from './b2RevoluteJoint';
import { b2RopeJoint, type b2RopeJointDef } from './b2RopeJoint';
import { b2WeldJoint, type b2WeldJointDef } from './b2WeldJoint';
import { b2WheelJoint, type b2WheelJointDef } from './b2WheelJoint';

export class b2JointFactory {
  /** Construct the concrete joint named by def.type (the def must be of the matching class). */
  static Create(def: b2JointDef): b2Joint {
    switch (def.type) {
      case b2JointType.e_distanceJoint:
        return new b2DistanceJoint(def as b2DistanceJointDef);
      case b2JointType.e_mouseJoint:
        return new b2MouseJoint(def as b2MouseJointDef);
      case b2JointType.e_prismaticJoint:
        return new b2PrismaticJoint(def as b2PrismaticJointDef);
      case b2JointType.e_revoluteJoint:
        return new b2RevoluteJoint(def as b2RevoluteJointDef);
      case b2JointType.e_pulleyJoint:
        return new b2PulleyJoint(def as b2PulleyJointDef);
      case b2JointType.e_gearJoint:
        return new b2GearJoint(def as b2GearJointDef);
      case b2JointType.e_wheelJoint:
        return new b2WheelJoint(def as b2WheelJointDef);
      case b2JointType.e_weldJoint:
        return new b2WeldJoint(def as b2WeldJointDef);
      case b2JointType.e_frictionJoint:
        return new b2FrictionJoint(def as b2FrictionJointDef);
      case b2JointType.e_ropeJoint:
        return new b2RopeJoint(def as b2RopeJointDef);
      default:
        throw new Error(`Box2D: unknown joint type ${def.type}`);
    }
  }

  /**
   * The C++ runs the joint's (trivial) destructor and returns its memory to the block allocator;
   * the garbage collector does both here, so only the type check of the C++ switch remains.
   */
  static Destroy(joint: b2Joint): void {
    b2Assert(joint.m_type > b2JointType.e_unknownJoint && joint.m_type <= b2JointType.e_ropeJoint, `unknown joint type ${joint.m_type}`);
  }
}
