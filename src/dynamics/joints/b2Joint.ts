/*
 * The joint base class, its definition and the joint graph edges (b2Joint.h, b2Joint.cpp).
 *
 * The static factory b2Joint::Create/Destroy lives in b2JointFactory.ts: it has to import every
 * concrete joint, and a base module that imports its subclasses breaks ES module load order.
 */

import { b2Vec2 } from '../../common/b2Math';
import { b2Assert, b2Log } from '../../common/b2Settings';
import { b2DestroyedError } from '../../common/b2ArgumentError';
import { b2JointType, b2LimitState } from '../../common/b2Constants';
import type { b2Body } from '../b2Body';
import type { b2SolverData } from '../b2TimeStep';

export { b2JointType, b2LimitState };

export const e_unknownJoint = b2JointType.e_unknownJoint;
export const e_revoluteJoint = b2JointType.e_revoluteJoint;
export const e_prismaticJoint = b2JointType.e_prismaticJoint;
export const e_distanceJoint = b2JointType.e_distanceJoint;
export const e_pulleyJoint = b2JointType.e_pulleyJoint;
export const e_mouseJoint = b2JointType.e_mouseJoint;
export const e_gearJoint = b2JointType.e_gearJoint;
export const e_wheelJoint = b2JointType.e_wheelJoint;
export const e_weldJoint = b2JointType.e_weldJoint;
export const e_frictionJoint = b2JointType.e_frictionJoint;
export const e_ropeJoint = b2JointType.e_ropeJoint;

export const e_inactiveLimit = b2LimitState.e_inactiveLimit;
export const e_atLowerLimit = b2LimitState.e_atLowerLimit;
export const e_atUpperLimit = b2LimitState.e_atUpperLimit;
export const e_equalLimits = b2LimitState.e_equalLimits;

/** Declared by b2Joint.h; no joint uses it. */
export class b2Jacobian {
  readonly linear = new b2Vec2();
  angularA = 0.0;
  angularB = 0.0;

  Clone(): b2Jacobian {
    return new b2Jacobian().Assign(this);
  }

  Assign(j: Readonly<b2Jacobian>): this {
    this.linear.Assign(j.linear);
    this.angularA = j.angularA;
    this.angularB = j.angularB;
    return this;
  }
}

/**
 * A joint edge is used to connect bodies and joints together in a joint graph where each body is
 * a node and each joint is an edge. A joint edge belongs to a doubly linked list maintained in
 * each attached body. Each joint has two joint nodes, one for each attached body.
 *
 * `joint` and `other` are set when the joint is constructed (the C++ leaves them NULL until
 * b2World::CreateJoint fills them), so they are never null while the edge is in a list.
 */
export class b2JointEdge {
  /** Provides quick access to the other body attached. */
  other: b2Body;
  /** The joint. */
  joint: b2Joint;
  /** The previous joint edge in the body's joint list. */
  prev: b2JointEdge | null = null;
  /** The next joint edge in the body's joint list. */
  next: b2JointEdge | null = null;
  /**
   * Not in the C++: the joint's slot in its world's joint island flags (b2World, the C++'s
   * b2Joint::m_islandFlag), the same on both edges; -1 while the joint is in no world.
   */
  islandSlot = -1;

  constructor(joint: b2Joint, other: b2Body) {
    this.joint = joint;
    this.other = other;
  }
}

/** Joint definitions are used to construct joints. */
export class b2JointDef {
  /** The joint type is set automatically for concrete joint types. */
  type: b2JointType;
  /** Use this to attach application specific data to your joints. */
  userData: any = null;
  /** The first attached body. */
  bodyA: b2Body | null = null;
  /** The second attached body. */
  bodyB: b2Body | null = null;
  /** Set this flag to true if the attached bodies should collide. */
  collideConnected = false;

  constructor(type: b2JointType = b2JointType.e_unknownJoint) {
    this.type = type;
  }
}

/**
 * The base joint class. Joints are used to constraint two bodies together in various fashions.
 * Some joints also feature limits and motors.
 */
export abstract class b2Joint {
  m_type = b2JointType.e_unknownJoint;
  m_prev: b2Joint | null = null;
  m_next: b2Joint | null = null;
  readonly m_edgeA: b2JointEdge;
  readonly m_edgeB: b2JointEdge;
  m_bodyA: b2Body;
  m_bodyB: b2Body;

  m_index = 0;

  m_collideConnected = false;

  m_userData: any = null;

  /** Set by b2World.DestroyJoint (no C++ counterpart: the C++ frees the memory). */
  m_destroyed = false;

  /**
   * Not in the C++: where a GPU mirror of the world (src-gpu's GpuWorld) keeps this object, its
   * slot and the mirror's id (0: none), so that the mirror finds it without a map lookup.
   */
  m_mirrorSlot = -1;
  m_mirrorId = 0;

  constructor(def: b2JointDef) {
    b2Assert(def.bodyA !== def.bodyB, 'a joint needs two different bodies');
    b2Assert(def.bodyA !== null && def.bodyB !== null, 'joint bodyA and bodyB must be set');

    this.m_type = def.type;
    this.m_bodyA = def.bodyA;
    this.m_bodyB = def.bodyB;
    this.m_collideConnected = def.collideConnected;
    this.m_userData = def.userData;

    this.m_edgeA = new b2JointEdge(this, def.bodyB);
    this.m_edgeB = new b2JointEdge(this, def.bodyA);
  }

  /** Get the type of the concrete joint. */
  GetType(): b2JointType {
    return this.m_type;
  }

  /** Get the first body attached to this joint. */
  GetBodyA(): b2Body {
    return this.m_bodyA;
  }

  /** Get the second body attached to this joint. */
  GetBodyB(): b2Body {
    return this.m_bodyB;
  }

  /** Get the anchor point on bodyA in world coordinates. */
  abstract GetAnchorA(out: b2Vec2): b2Vec2;

  /** Get the anchor point on bodyB in world coordinates. */
  abstract GetAnchorB(out: b2Vec2): b2Vec2;

  /** Get the reaction force on bodyB at the joint anchor in Newtons. */
  abstract GetReactionForce(inv_dt: number, out: b2Vec2): b2Vec2;

  /** Get the reaction torque on bodyB in N*m. */
  abstract GetReactionTorque(inv_dt: number): number;

  /** Get the next joint the world joint list. */
  GetNext(): b2Joint | null {
    return this.m_next;
  }

  /** Get the user data pointer. */
  GetUserData(): any {
    return this.m_userData;
  }

  /** Set the user data pointer. */
  SetUserData(data: any): void {
    this.m_userData = data;
  }

  /** Short-cut function to determine if either body is inactive. */
  IsActive(): boolean {
    return this.m_bodyA.IsActive() && this.m_bodyB.IsActive();
  }

  /**
   * Get collide connected.
   * Note: modifying the collide connect flag won't work correctly because
   * the flag is only checked when fixture AABBs begin to overlap.
   */
  GetCollideConnected(): boolean {
    return this.m_collideConnected;
  }

  /** Dump this joint to the log file. */
  Dump(): void {
    b2Log('// Dump is not supported for this joint type.\n');
  }

  abstract InitVelocityConstraints(data: b2SolverData): void;
  abstract SolveVelocityConstraints(data: b2SolverData): void;

  /**
   * Not in the C++: b2Island.Solve calls this for every joint after the velocity iterations.
   * A joint whose solver accumulates its impulses in a record of its own (b2RevoluteJoint) writes
   * them back to its fields here, where the C++ would have had them all along; nothing reads them
   * in between. The others have nothing to do.
   */
  StoreImpulses(): void {}

  /** This returns true if the position errors are within tolerance. */
  abstract SolvePositionConstraints(data: b2SolverData): boolean;
}

/** Throws if the joint has been destroyed (b2World.DestroyJoint, or DestroyBody of one of its bodies). */
export function b2CheckJointAlive(joint: b2Joint, method: string): void {
  if (joint.m_destroyed) {
    throw b2DestroyedError(method, 'this joint');
  }
}
