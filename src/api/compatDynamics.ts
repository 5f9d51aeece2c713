/*
 * Box2DWeb 2.1a compatibility for Box2D.Dynamics, Box2D.Dynamics.Contacts and
 * Box2D.Dynamics.Joints: `new b2World(gravity, doSleep)`, queries and ray casts with plain
 * functions, QueryPoint/QueryShape/RayCastOne/RayCastAll, the ground body, b2Body's 2.1a setters,
 * b2FilterData, listeners with default methods, the joints' 2.1a accessors, and the line joint as
 * a wheel joint without a spring. What Box2D 2.2 removed without an equivalent throws an Error
 * naming the call and what to use instead.
 */

import { b2AABB, b2RayCastOutput } from '../collision/b2Collision';
import type { b2RayCastInput } from '../collision/b2Collision';
import { b2TestOverlapShapes } from '../collision/b2Collision';
import { b2MassData, b2Shape } from '../collision/shapes/b2Shape';
import { b2ArgumentError, b2CheckFinite, b2CheckLimits, b2CheckNonNegative, b2DescribeNumber, b2DestroyedError } from '../common/b2ArgumentError';
import { b2Color } from '../common/b2Draw';
import { b2Transform, b2Vec2 } from '../common/b2Math';
import { b2_linearSlop } from '../common/b2Settings';
import { b2Body, b2BodyDef, b2BodyType } from '../dynamics/b2Body';
import { b2Filter, b2Fixture } from '../dynamics/b2Fixture';
import type { b2FixtureDef } from '../dynamics/b2Fixture';
import { b2World } from '../dynamics/b2World';
import { b2ContactFilter, b2DestructionListener } from '../dynamics/b2WorldCallbacks';
import type { b2QueryCallback, b2RayCastCallback } from '../dynamics/b2WorldCallbacks';
import { b2Contact } from '../dynamics/contacts/b2Contact';
import { b2DistanceJoint } from '../dynamics/joints/b2DistanceJoint';
import { b2FrictionJoint } from '../dynamics/joints/b2FrictionJoint';
import { b2GearJoint } from '../dynamics/joints/b2GearJoint';
import { b2CheckJointAlive, b2Joint, b2JointType, b2LimitState } from '../dynamics/joints/b2Joint';
import type { b2JointDef } from '../dynamics/joints/b2Joint';
import { b2JointFactory } from '../dynamics/joints/b2JointFactory';
import { b2MouseJoint } from '../dynamics/joints/b2MouseJoint';
import { b2PrismaticJoint } from '../dynamics/joints/b2PrismaticJoint';
import { b2PulleyJoint, b2PulleyJointDef } from '../dynamics/joints/b2PulleyJoint';
import { b2RevoluteJoint } from '../dynamics/joints/b2RevoluteJoint';
import { b2RopeJoint } from '../dynamics/joints/b2RopeJoint';
import { b2WeldJoint } from '../dynamics/joints/b2WeldJoint';
import { b2WheelJoint, b2WheelJointDef } from '../dynamics/joints/b2WheelJoint';
import { b2DebugDraw } from './b2DebugDraw';
import { fixtureShapeFor2_1a } from './compatCollision';
import { acceptingArguments, defineMethods, defineRemovedProperty, defineStatics, removedClass, removedError, removedMethod, wrapMethod } from './patch';

/** 2.1a's query callback: return false to stop (anything falsy stops, as in 2.1a). */
export type b2QueryFunction = (fixture: b2Fixture) => boolean | void;
/** 2.1a's ray-cast callback: return -1 to ignore, 0 to stop, a fraction to clip, 1 to go on. */
export type b2RayCastFunction = (fixture: b2Fixture, point: b2Vec2, normal: b2Vec2, fraction: number) => number;

declare module '../dynamics/b2World' {
  interface b2World {
    /**
     * Query the world for all fixtures whose fat AABBs overlap the box, with a callback object
     * (2.2.1) or a function (2.1a; it receives the fixture, and a falsy return stops the query).
     */
    QueryAABB(callback: b2QueryCallback | b2QueryFunction, aabb: Readonly<b2AABB>): void;
    /**
     * Ray-cast the world, with a callback object (2.2.1) or a function (2.1a; it receives its
     * own copies of the point and the normal).
     */
    RayCast(callback: b2RayCastCallback | b2RayCastFunction, point1: Readonly<b2Vec2>, point2: Readonly<b2Vec2>): void;
    /** 2.1a: report each fixture containing the point. */
    QueryPoint(callback: b2QueryCallback | b2QueryFunction, p: Readonly<b2Vec2>): void;
    /** 2.1a: report each fixture overlapping the shape placed at the transform (default identity). */
    QueryShape(callback: b2QueryCallback | b2QueryFunction, shape: b2Shape, transform?: Readonly<b2Transform> | null): void;
    /** 2.1a: the fixture closest to point1 that the ray from point1 to point2 hits, or null. */
    RayCastOne(point1: Readonly<b2Vec2>, point2: Readonly<b2Vec2>): b2Fixture | null;
    /** 2.1a: every fixture the ray from point1 to point2 hits. */
    RayCastAll(point1: Readonly<b2Vec2>, point2: Readonly<b2Vec2>): b2Fixture[];
    /** The gravity (written to `out`, or to a new vector as 2.1a returns). */
    GetGravity(out?: b2Vec2): b2Vec2;
    /**
     * 2.1a: the world's ground body, a static body at the origin with no fixtures, often used as
     * a mouse joint's bodyA. Box2D 2.2 worlds have none: the first call creates it, and so does
     * the first call after it was destroyed.
     */
    GetGroundBody(): b2Body;
    /** 2.1a: check the broad phase's dynamic tree (throws if it is inconsistent). */
    Validate(): void;
  }
}

declare module '../dynamics/b2Body' {
  interface b2Body {
    /** 2.1a: CreateFixture(shape, density). */
    CreateFixture2(shape: b2Shape, density?: number): b2Fixture;
    /** 2.1a: SetTransform(position, angle). */
    SetPositionAndAngle(position: Readonly<b2Vec2>, angle: number): void;
    /** 2.1a: move the origin, keeping the angle. */
    SetPosition(position: Readonly<b2Vec2>): void;
    /** 2.1a: set the angle, keeping the origin. */
    SetAngle(angle: number): void;
    /** 2.1a: a body definition holding this body's current state. */
    GetDefinition(): b2BodyDef;
    /** 2.1a: ApplyLinearImpulse(impulse, point). */
    ApplyImpulse(impulse: Readonly<b2Vec2>, point: Readonly<b2Vec2>): void;
  }
  namespace b2Body {
    /** 2.1a's body type constants. */
    const b2_staticBody: b2BodyType;
    const b2_kinematicBody: b2BodyType;
    const b2_dynamicBody: b2BodyType;
  }
}

declare module '../dynamics/b2Fixture' {
  interface b2Fixture {
    /**
     * The fat AABB of a child proxy; 2.1a's GetAABB() without an index gives the box around all
     * of them (a fixture of an inactive body, which has none, gives its shape's tight box).
     */
    GetAABB(childIndex?: number): Readonly<b2AABB>;
    /** Ray-cast a child shape (2.1a passes no index: the first child). */
    RayCast(output: b2RayCastOutput, input: Readonly<b2RayCastInput>, childIndex?: number): boolean;
    /** The mass data of the fixture (2.1a also accepts no argument and returns a new one). */
    GetMassData(massData?: b2MassData): void;
  }
  interface b2Filter {
    /** 2.1a (b2FilterData): a new filter equal to this. */
    Copy(): b2Filter;
  }
}

declare module '../dynamics/contacts/b2Contact' {
  interface b2Contact {
    /** 2.1a: does either fixture of this contact belong to a sensor? */
    IsSensor(): boolean;
  }
}

declare module '../dynamics/joints/b2Joint' {
  namespace b2Joint {
    /** 2.1a's joint type and limit state constants. */
    const e_unknownJoint: b2JointType;
    const e_revoluteJoint: b2JointType;
    const e_prismaticJoint: b2JointType;
    const e_distanceJoint: b2JointType;
    const e_pulleyJoint: b2JointType;
    const e_mouseJoint: b2JointType;
    const e_gearJoint: b2JointType;
    const e_wheelJoint: b2JointType;
    /** 2.1a's line joint type: the wheel joint's, the joint a b2LineJointDef makes. */
    const e_lineJoint: b2JointType;
    const e_weldJoint: b2JointType;
    const e_frictionJoint: b2JointType;
    const e_ropeJoint: b2JointType;
    const e_inactiveLimit: b2LimitState;
    const e_atLowerLimit: b2LimitState;
    const e_atUpperLimit: b2LimitState;
    const e_equalLimits: b2LimitState;
  }
}

// Each joint's anchors and reaction force also come as new vectors when no `out` is given (2.1a).
declare module '../dynamics/joints/b2DistanceJoint' {
  interface b2DistanceJoint {
    /** The anchor on bodyA (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorA(out?: b2Vec2): b2Vec2;
    /** The anchor on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorB(out?: b2Vec2): b2Vec2;
    /** The reaction force on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetReactionForce(inv_dt: number, out?: b2Vec2): b2Vec2;
  }
}
declare module '../dynamics/joints/b2FrictionJoint' {
  interface b2FrictionJoint {
    /** The anchor on bodyA (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorA(out?: b2Vec2): b2Vec2;
    /** The anchor on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorB(out?: b2Vec2): b2Vec2;
    /** The reaction force on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetReactionForce(inv_dt: number, out?: b2Vec2): b2Vec2;
  }
}
declare module '../dynamics/joints/b2GearJoint' {
  interface b2GearJoint {
    /** The anchor on bodyA (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorA(out?: b2Vec2): b2Vec2;
    /** The anchor on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorB(out?: b2Vec2): b2Vec2;
    /** The reaction force on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetReactionForce(inv_dt: number, out?: b2Vec2): b2Vec2;
  }
}
declare module '../dynamics/joints/b2MouseJoint' {
  interface b2MouseJoint {
    /** The anchor on bodyA (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorA(out?: b2Vec2): b2Vec2;
    /** The anchor on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorB(out?: b2Vec2): b2Vec2;
    /** The reaction force on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetReactionForce(inv_dt: number, out?: b2Vec2): b2Vec2;
  }
}
declare module '../dynamics/joints/b2PrismaticJoint' {
  interface b2PrismaticJoint {
    /** The anchor on bodyA (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorA(out?: b2Vec2): b2Vec2;
    /** The anchor on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorB(out?: b2Vec2): b2Vec2;
    /** The reaction force on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetReactionForce(inv_dt: number, out?: b2Vec2): b2Vec2;
  }
}
declare module '../dynamics/joints/b2PulleyJoint' {
  interface b2PulleyJoint {
    /** The anchor on bodyA (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorA(out?: b2Vec2): b2Vec2;
    /** The anchor on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorB(out?: b2Vec2): b2Vec2;
    /** The reaction force on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetReactionForce(inv_dt: number, out?: b2Vec2): b2Vec2;
    /** The first ground anchor (written to `out`, or to a new vector as 2.1a returns). */
    GetGroundAnchorA(out?: b2Vec2): b2Vec2;
    /** The second ground anchor (written to `out`, or to a new vector as 2.1a returns). */
    GetGroundAnchorB(out?: b2Vec2): b2Vec2;
    /** 2.1a: GetLengthA, the current length of the segment on bodyA's side. */
    GetLength1(): number;
    /** 2.1a: GetLengthB, the current length of the segment on bodyB's side. */
    GetLength2(): number;
  }
}
declare module '../dynamics/joints/b2RevoluteJoint' {
  interface b2RevoluteJoint {
    /** The anchor on bodyA (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorA(out?: b2Vec2): b2Vec2;
    /** The anchor on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorB(out?: b2Vec2): b2Vec2;
    /** The reaction force on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetReactionForce(inv_dt: number, out?: b2Vec2): b2Vec2;
  }
}
declare module '../dynamics/joints/b2RopeJoint' {
  interface b2RopeJoint {
    /** The anchor on bodyA (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorA(out?: b2Vec2): b2Vec2;
    /** The anchor on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorB(out?: b2Vec2): b2Vec2;
    /** The reaction force on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetReactionForce(inv_dt: number, out?: b2Vec2): b2Vec2;
  }
}
declare module '../dynamics/joints/b2WeldJoint' {
  interface b2WeldJoint {
    /** The anchor on bodyA (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorA(out?: b2Vec2): b2Vec2;
    /** The anchor on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorB(out?: b2Vec2): b2Vec2;
    /** The reaction force on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetReactionForce(inv_dt: number, out?: b2Vec2): b2Vec2;
  }
}
declare module '../dynamics/joints/b2WheelJoint' {
  interface b2WheelJoint {
    /** The anchor on bodyA (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorA(out?: b2Vec2): b2Vec2;
    /** The anchor on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetAnchorB(out?: b2Vec2): b2Vec2;
    /** The reaction force on bodyB (written to `out`, or to a new vector as 2.1a returns). */
    GetReactionForce(inv_dt: number, out?: b2Vec2): b2Vec2;
  }
}

// The world

/** b2World also takes 2.1a's (gravity, doSleep): doSleep is SetAllowSleeping's flag. */
export const b2WorldCompat = acceptingArguments(b2World, (args, make) => {
  const world = make(args[0]);
  if (args.length > 1 && args[1] !== undefined) {
    world.SetAllowSleeping(Boolean(args[1]));
  }
  return world;
}) as typeof b2World & (new (gravity: Readonly<b2Vec2>, doSleep?: boolean) => b2World);

function queryCallbackOf(callback: b2QueryCallback | b2QueryFunction): b2QueryCallback {
  if (typeof callback === 'function') {
    return { ReportFixture: (fixture: b2Fixture) => Boolean(callback(fixture)) };
  }
  return callback;
}

/** Report a fixture to a 2.1a function or a 2.2.1 callback object; false stops the query. */
function report(callback: b2QueryCallback | b2QueryFunction, fixture: b2Fixture): boolean {
  return typeof callback === 'function' ? Boolean(callback(fixture)) : callback.ReportFixture(fixture) !== false;
}

wrapMethod(
  b2World.prototype,
  'QueryAABB',
  (queryAABB) =>
    function (this: b2World, callback: b2QueryCallback | b2QueryFunction, aabb: Readonly<b2AABB>) {
      queryAABB.call(this, queryCallbackOf(callback), aabb);
    },
);

wrapMethod(
  b2World.prototype,
  'RayCast',
  (rayCast) =>
    function (this: b2World, callback: b2RayCastCallback | b2RayCastFunction, point1: Readonly<b2Vec2>, point2: Readonly<b2Vec2>) {
      if (typeof callback === 'function') {
        // 2.1a gave each report a fresh point; callers keep them.
        const fn = callback;
        callback = {
          ReportFixture: (fixture: b2Fixture, point: b2Vec2, normal: b2Vec2, fraction: number) => fn(fixture, point.Clone(), normal.Clone(), fraction),
        };
      }
      rayCast.call(this, callback, point1, point2);
    },
);

wrapMethod(
  b2World.prototype,
  'GetGravity',
  (getGravity) =>
    function (this: b2World, out?: b2Vec2) {
      return getGravity.call(this, out ?? new b2Vec2());
    },
);

wrapMethod(
  b2World.prototype,
  'DrawDebugData',
  (drawDebugData) =>
    function (this: b2World) {
      if (this.m_debugDraw instanceof b2DebugDraw) {
        this.m_debugDraw.Clear();
      }
      drawDebugData.call(this);
    },
);

// DrawShape is 2.1a's public DrawShape(shape, xf, color); a fixture also stands for its shape (the
// C++ form). Accepted at run time only: a TypeScript overload cannot merge into the class's method.
wrapMethod(
  b2World.prototype,
  'DrawShape',
  (drawShape) =>
    function (this: b2World, shape: b2Shape | b2Fixture, xf: Readonly<b2Transform>, color: b2Color) {
      const method = 'b2World.DrawShape';
      if (this.m_debugDraw === null) {
        throw new b2ArgumentError(method, 'the world', 'has no debug draw (call SetDebugDraw first)');
      }
      if (shape instanceof b2Fixture) {
        if (shape.m_destroyed) throw b2DestroyedError(method, 'fixture');
        shape = shape.GetShape();
      } else if (!(shape instanceof b2Shape)) {
        throw new b2ArgumentError(method, 'shape', `must be a b2Shape or a b2Fixture, got ${b2DescribeNumber(shape)}`);
      }
      if (!(xf instanceof b2Transform)) {
        throw new b2ArgumentError(method, 'xf', `must be a b2Transform, got ${b2DescribeNumber(xf)}`);
      }
      if (!(color instanceof b2Color)) {
        throw new b2ArgumentError(method, 'color', `must be a b2Color, got ${b2DescribeNumber(color)}`);
      }
      drawShape.call(this, shape, xf, color);
    },
);

const s_groundBodies = new WeakMap<b2World, b2Body>();
const s_identity: Readonly<b2Transform> = new b2Transform();

defineMethods(b2World.prototype, {
  QueryPoint(callback, p) {
    const aabb = new b2AABB();
    aabb.lowerBound.Set(p.x - b2_linearSlop, p.y - b2_linearSlop);
    aabb.upperBound.Set(p.x + b2_linearSlop, p.y + b2_linearSlop);
    const reported = new Set<b2Fixture>();
    this.QueryAABB((fixture: b2Fixture) => {
      if (reported.has(fixture) || !fixture.TestPoint(p)) return true;
      reported.add(fixture);
      return report(callback, fixture);
    }, aabb);
  },
  QueryShape(callback, shape, transform) {
    const xf = transform ?? s_identity;
    const childCount = shape.GetChildCount();
    const aabb = new b2AABB();
    const childAABB = new b2AABB();
    shape.ComputeAABB(aabb, xf, 0);
    for (let i = 1; i < childCount; ++i) {
      shape.ComputeAABB(childAABB, xf, i);
      aabb.Combine(childAABB);
    }
    const reported = new Set<b2Fixture>();
    this.QueryAABB((fixture: b2Fixture) => {
      if (reported.has(fixture)) return true;
      const other = fixture.GetShape();
      const otherXf = fixture.GetBody().GetTransform();
      for (let i = 0; i < childCount; ++i) {
        for (let j = 0; j < other.GetChildCount(); ++j) {
          if (b2TestOverlapShapes(shape, i, other, j, xf, otherXf)) {
            reported.add(fixture);
            return report(callback, fixture);
          }
        }
      }
      return true;
    }, aabb);
  },
  RayCastOne(point1, point2) {
    let result: b2Fixture | null = null;
    this.RayCast(
      {
        ReportFixture: (fixture: b2Fixture, _point: b2Vec2, _normal: b2Vec2, fraction: number) => {
          result = fixture;
          return fraction;
        },
      },
      point1,
      point2,
    );
    return result;
  },
  RayCastAll(point1, point2) {
    const result: b2Fixture[] = [];
    this.RayCast(
      {
        ReportFixture: (fixture: b2Fixture) => {
          result.push(fixture);
          return 1.0;
        },
      },
      point1,
      point2,
    );
    return result;
  },
  GetGroundBody() {
    let ground = s_groundBodies.get(this);
    // 2.1a kept handing back its ground body after an app destroyed it (walking the body list
    // to clear a level), and its CreateJoint took the dead body; here a joint needs a live one.
    if (ground === undefined || ground.m_destroyed) {
      ground = this.CreateBody(new b2BodyDef());
      s_groundBodies.set(this, ground);
    }
    return ground;
  },
  Validate() {
    this.m_contactManager.m_broadPhase.m_tree.Validate();
  },
});

const controllersGone = 'There are no controllers: apply the forces yourself (b2Body.ApplyForce) before each Step.';
for (const name of ['AddController', 'RemoveController', 'CreateController', 'DestroyController']) {
  Object.defineProperty(b2World.prototype, name, {
    value: removedMethod(`b2World.${name}`, controllersGone),
    writable: true,
    configurable: true,
    enumerable: false,
  });
}
Object.defineProperty(b2World.prototype, 'SetBroadPhase', {
  value: removedMethod('b2World.SetBroadPhase', 'The world always uses its dynamic-tree broad phase (b2BroadPhase); remove the call.'),
  writable: true,
  configurable: true,
  enumerable: false,
});

// Bodies

defineStatics(b2Body, {
  b2_staticBody: b2BodyType.b2_staticBody,
  b2_kinematicBody: b2BodyType.b2_kinematicBody,
  b2_dynamicBody: b2BodyType.b2_dynamicBody,
});

wrapMethod(
  b2Body.prototype,
  'CreateFixture',
  (createFixture) =>
    function (this: b2Body, defOrShape: b2FixtureDef | b2Shape, density?: number) {
      if (defOrShape instanceof b2Shape) {
        return createFixture.call(this, fixtureShapeFor2_1a(defOrShape), density);
      }
      const shape = defOrShape.shape;
      const fixtureShape = shape === null ? null : fixtureShapeFor2_1a(shape);
      if (fixtureShape === shape) return createFixture.call(this, defOrShape);
      // The caller's definition keeps its shape.
      defOrShape.shape = fixtureShape;
      try {
        return createFixture.call(this, defOrShape);
      } finally {
        defOrShape.shape = shape;
      }
    },
);

// 2.1a's SetTransform(xf) takes a b2Transform. Accepted at run time only: a TypeScript overload
// cannot merge into SetTransform(position, angle).
wrapMethod(
  b2Body.prototype,
  'SetTransform',
  (setTransform) =>
    function (this: b2Body, position: Readonly<b2Vec2> | Readonly<b2Transform>, angle?: number) {
      if (angle === undefined && position instanceof b2Transform) {
        setTransform.call(this, position.p, position.q.GetAngle());
        return;
      }
      setTransform.call(this, position as Readonly<b2Vec2>, angle as number);
    },
);

defineMethods(b2Body.prototype, {
  CreateFixture2(shape, density) {
    return this.CreateFixture(shape, density ?? 0.0);
  },
  SetPositionAndAngle(position, angle) {
    this.SetTransform(position, angle);
  },
  SetPosition(position) {
    this.SetTransform(position, this.GetAngle());
  },
  SetAngle(angle) {
    this.SetTransform(this.GetPosition().Clone(), angle);
  },
  GetDefinition() {
    const bd = new b2BodyDef();
    bd.type = this.GetType();
    bd.allowSleep = this.IsSleepingAllowed();
    bd.angle = this.GetAngle();
    bd.angularDamping = this.GetAngularDamping();
    bd.angularVelocity = this.GetAngularVelocity();
    bd.fixedRotation = this.IsFixedRotation();
    bd.bullet = this.IsBullet();
    bd.awake = this.IsAwake();
    bd.linearDamping = this.GetLinearDamping();
    this.GetLinearVelocity(bd.linearVelocity);
    bd.position.Assign(this.GetPosition());
    bd.userData = this.GetUserData();
    bd.active = this.IsActive();
    bd.gravityScale = this.GetGravityScale();
    return bd;
  },
  ApplyImpulse(impulse, point) {
    this.ApplyLinearImpulse(impulse, point);
  },
});

for (const [name, instead] of [
  ['Split', 'Create the new body yourself and move the fixtures (DestroyFixture, then CreateFixture on it).'],
  ['Merge', 'Create the fixtures of the other body on this one (CreateFixture), then DestroyBody the other.'],
  ['GetControllerList', controllersGone],
] as const) {
  Object.defineProperty(b2Body.prototype, name, {
    value: removedMethod(`b2Body.${name}`, instead),
    writable: true,
    configurable: true,
    enumerable: false,
  });
}

// 2.1a's inertiaScale: 1 is 2.2's behaviour; anything else has no 2.2 equivalent.
Object.defineProperty(b2BodyDef.prototype, 'inertiaScale', {
  get() {
    return 1.0;
  },
  set(value: number) {
    if (value !== 1.0) {
      throw removedError('b2BodyDef.inertiaScale', 'To change the rotational inertia, call body.SetMassData({mass, center, I}) after creating the fixtures.');
    }
  },
  configurable: true,
  enumerable: false,
});

// Fixtures and filters

wrapMethod(
  b2Fixture.prototype,
  'GetAABB',
  (getAABB) =>
    function (this: b2Fixture, childIndex?: number) {
      if (childIndex !== undefined) return getAABB.call(this, childIndex);
      if (this.m_proxyCount === 1) return getAABB.call(this, 0);
      const aabb = new b2AABB();
      if (this.m_proxyCount > 1) {
        aabb.Assign(getAABB.call(this, 0));
        for (let i = 1; i < this.m_proxyCount; ++i) aabb.Combine(getAABB.call(this, i));
        return aabb;
      }
      const shape = this.GetShape();
      const xf = this.GetBody().GetTransform();
      const childAABB = new b2AABB();
      shape.ComputeAABB(aabb, xf, 0);
      for (let i = 1; i < shape.GetChildCount(); ++i) {
        shape.ComputeAABB(childAABB, xf, i);
        aabb.Combine(childAABB);
      }
      return aabb;
    },
);
wrapMethod(
  b2Fixture.prototype,
  'RayCast',
  (rayCast) =>
    function (this: b2Fixture, output: b2RayCastOutput, input: Readonly<b2RayCastInput>, childIndex?: number) {
      return rayCast.call(this, output, input, childIndex ?? 0);
    },
);
wrapMethod(
  b2Fixture.prototype,
  'GetMassData',
  (getMassData) =>
    function (this: b2Fixture, massData?: b2MassData) {
      const out = massData ?? new b2MassData();
      getMassData.call(this, out);
      return out;
    } as b2Fixture['GetMassData'],
);

defineMethods(b2Filter.prototype, {
  Copy() {
    return this.Clone();
  },
});

/** 2.1a's name for b2Filter. */
export const b2FilterData = b2Filter;
export type b2FilterData = b2Filter;

// Contacts and listeners

defineMethods(b2Contact.prototype, {
  IsSensor() {
    return this.m_fixtureA.IsSensor() || this.m_fixtureB.IsSensor();
  },
});
Object.defineProperty(b2Contact.prototype, 'SetSensor', {
  value: removedMethod('b2Contact.SetSensor', 'A contact is a sensor contact when a fixture is: call fixture.SetSensor.'),
  writable: true,
  configurable: true,
  enumerable: false,
});
Object.defineProperty(b2Contact.prototype, 'IsContinuous', {
  value: removedMethod(
    'b2Contact.IsContinuous',
    'Box2D 2.2 runs continuous collision for every contact with a static or kinematic body, and with bullets (body.IsBullet()).',
  ),
  writable: true,
  configurable: true,
  enumerable: false,
});

defineRemovedProperty(
  b2ContactFilter.prototype,
  'RayCollide',
  'b2ContactFilter.RayCollide',
  'Ray casts are not filtered by the contact filter: skip fixtures in your RayCast callback by returning -1.',
);

// 2.1a's listener methods do nothing unless replaced, so a listener may define only some.
defineMethods(b2DestructionListener.prototype as b2DestructionListener, {
  SayGoodbyeJoint() {},
  SayGoodbyeFixture() {},
});

/** b2DestructionListener with 2.1a's empty defaults, so `new b2DestructionListener()` works. */
export const b2DestructionListenerCompat = b2DestructionListener as unknown as {
  new (): b2DestructionListener;
  readonly prototype: b2DestructionListener;
};

// Joints

defineStatics(b2Joint, {
  e_unknownJoint: b2JointType.e_unknownJoint,
  e_revoluteJoint: b2JointType.e_revoluteJoint,
  e_prismaticJoint: b2JointType.e_prismaticJoint,
  e_distanceJoint: b2JointType.e_distanceJoint,
  e_pulleyJoint: b2JointType.e_pulleyJoint,
  e_mouseJoint: b2JointType.e_mouseJoint,
  e_gearJoint: b2JointType.e_gearJoint,
  e_wheelJoint: b2JointType.e_wheelJoint,
  e_weldJoint: b2JointType.e_weldJoint,
  e_frictionJoint: b2JointType.e_frictionJoint,
  e_ropeJoint: b2JointType.e_ropeJoint,
  e_inactiveLimit: b2LimitState.e_inactiveLimit,
  e_atLowerLimit: b2LimitState.e_atLowerLimit,
  e_atUpperLimit: b2LimitState.e_atUpperLimit,
  e_equalLimits: b2LimitState.e_equalLimits,
  e_lineJoint: b2JointType.e_wheelJoint,
});
/**
 * 2.1a's line joint definition. Box2D 2.2 replaced the line joint by the wheel joint: the same
 * point-on-a-line constraint with the rotation free, plus a spring along the axis, and a motor
 * that turns bodyB instead of pushing along the axis, and no translation limits. So a line joint
 * is a wheel joint without a spring (frequencyHz 0) as long as its limits and its motor stay off;
 * CreateJoint refuses the definition otherwise, naming the field. The world makes a b2LineJoint.
 */
export class b2LineJointDef extends b2WheelJointDef {
  /** 2.1a's translation limits: the wheel joint has none, so they must stay disabled. */
  enableLimit = false;
  lowerTranslation = 0.0;
  upperTranslation = 0.0;
  /** 2.1a's linear motor force: kept, but the motor must stay disabled (see the class comment). */
  maxMotorForce = 0.0;

  constructor() {
    super();
    // No spring: the body slides freely along the axis, as on 2.1a's line joint.
    this.frequencyHz = 0.0;
  }
}

const prismaticInstead = 'use b2PrismaticJointDef, which also locks the rotation';

/** What a b2LineJointDef must leave off to be a wheel joint (see b2LineJointDef). */
function checkLineJointDef(def: b2LineJointDef): void {
  const method = 'b2World.CreateJoint';
  if (def.enableLimit) {
    throw new b2ArgumentError(
      method,
      'def.enableLimit',
      "must be false for a b2LineJointDef: Box2D 2.2's wheel joint, which the line joint became, has no translation " + `limits (${prismaticInstead})`,
    );
  }
  if (def.enableMotor) {
    throw new b2ArgumentError(
      method,
      'def.enableMotor',
      "must be false for a b2LineJointDef: 2.1a's line motor pushes along the axis, Box2D 2.2's wheel joint motor turns bodyB " +
        `(for a driven wheel use b2WheelJointDef with maxMotorTorque; for a linear motor ${prismaticInstead})`,
    );
  }
  b2CheckFinite(method, 'def.lowerTranslation', def.lowerTranslation);
  b2CheckFinite(method, 'def.upperTranslation', def.upperTranslation);
  b2CheckNonNegative(method, 'def.maxMotorForce', def.maxMotorForce);
}

/**
 * The joint a b2LineJointDef makes: a wheel joint (GetType() is e_wheelJoint, which 2.1a's
 * e_lineJoint names here) with 2.1a's line joint calls. Limits and the linear motor can be set
 * but not enabled, as in the definition.
 */
export class b2LineJoint extends b2WheelJoint {
  m_lowerTranslation: number;
  m_upperTranslation: number;
  m_maxMotorForce: number;

  constructor(def: b2LineJointDef) {
    super(def);
    this.m_lowerTranslation = def.lowerTranslation;
    this.m_upperTranslation = def.upperTranslation;
    this.m_maxMotorForce = def.maxMotorForce;
  }

  /**
   * 2.1a: the speed along the axis (the wheel joint's GetJointSpeed is bodyB's rotation speed).
   * The prismatic joint's speed is the same quantity over the same anchors and axis fields.
   */
  override GetJointSpeed(): number {
    return b2PrismaticJoint.prototype.GetJointSpeed.call(this as unknown as b2PrismaticJoint);
  }

  /** 2.1a: the limits are never enabled (see b2LineJointDef). */
  IsLimitEnabled(): boolean {
    return false;
  }

  /** 2.1a: enabling the limits throws, the wheel joint has none; disabling them does nothing. */
  EnableLimit(flag: boolean): void {
    b2CheckJointAlive(this, 'b2LineJoint.EnableLimit');
    if (flag) {
      throw new b2ArgumentError(
        'b2LineJoint.EnableLimit',
        'flag',
        `must be false: Box2D 2.2's wheel joint, which the line joint became, has no translation limits (${prismaticInstead})`,
      );
    }
  }

  /** 2.1a: the lower translation limit, kept though it cannot be enabled. */
  GetLowerLimit(): number {
    return this.m_lowerTranslation;
  }

  /** 2.1a: the upper translation limit, kept though it cannot be enabled. */
  GetUpperLimit(): number {
    return this.m_upperTranslation;
  }

  /** 2.1a: set the translation limits (kept; they cannot be enabled). */
  SetLimits(lower: number, upper: number): void {
    b2CheckJointAlive(this, 'b2LineJoint.SetLimits');
    b2CheckLimits('b2LineJoint.SetLimits', 'lower', 'upper', lower, upper);
    this.m_lowerTranslation = lower;
    this.m_upperTranslation = upper;
  }

  /** 2.1a: enabling the linear motor throws (see b2LineJointDef); disabling it does nothing. */
  override EnableMotor(flag: boolean): void {
    b2CheckJointAlive(this, 'b2LineJoint.EnableMotor');
    if (flag) {
      throw new b2ArgumentError(
        'b2LineJoint.EnableMotor',
        'flag',
        "must be false: 2.1a's line motor pushes along the axis, and Box2D 2.2's wheel joint, which the line joint became, " +
          `has a motor that turns bodyB (for a linear motor ${prismaticInstead})`,
      );
    }
  }

  /** 2.1a: set the linear motor's maximum force (kept; the motor cannot be enabled). */
  SetMaxMotorForce(force: number): void {
    b2CheckJointAlive(this, 'b2LineJoint.SetMaxMotorForce');
    b2CheckNonNegative('b2LineJoint.SetMaxMotorForce', 'force', force);
    this.m_maxMotorForce = force;
  }

  /** 2.1a: the linear motor's maximum force. */
  GetMaxMotorForce(): number {
    return this.m_maxMotorForce;
  }
}

// The world makes the line joint itself; b2World.CreateJoint has checked the wheel joint's rules.
wrapMethod(b2JointFactory, 'Create', (create) => (def: b2JointDef) => {
  if (!(def instanceof b2LineJointDef)) return create(def);
  checkLineJointDef(def);
  return new b2LineJoint(def);
});

for (const joint of [
  b2DistanceJoint,
  b2FrictionJoint,
  b2GearJoint,
  b2MouseJoint,
  b2PrismaticJoint,
  b2PulleyJoint,
  b2RevoluteJoint,
  b2RopeJoint,
  b2WeldJoint,
  b2WheelJoint,
]) {
  const proto = joint.prototype as b2Joint;
  wrapMethod(
    proto,
    'GetAnchorA',
    (getAnchorA) =>
      function (this: b2Joint, out?: b2Vec2) {
        return getAnchorA.call(this, out ?? new b2Vec2());
      },
  );
  wrapMethod(
    proto,
    'GetAnchorB',
    (getAnchorB) =>
      function (this: b2Joint, out?: b2Vec2) {
        return getAnchorB.call(this, out ?? new b2Vec2());
      },
  );
  wrapMethod(
    proto,
    'GetReactionForce',
    (getReactionForce) =>
      function (this: b2Joint, inv_dt: number, out?: b2Vec2) {
        return getReactionForce.call(this, inv_dt, out ?? new b2Vec2());
      },
  );
}

/** 2.1a called these without the inverse time step, and got an impulse or the limit back. */
function requireInvDt<T extends object>(proto: T, name: keyof T & string, limitGetter: string): void {
  wrapMethod(
    proto,
    name,
    (original) =>
      function (this: T, inv_dt: number) {
        if (inv_dt === undefined) {
          throw new Error(
            `${name}() needs the inverse time step in Box2D 2.2: call ${name}(1 / timeStep) for the current value, ` + `or ${limitGetter}() for the limit.`,
          );
        }
        return (original as (inv_dt: number) => number).call(this, inv_dt);
      } as T[keyof T & string],
  );
}
requireInvDt(b2RevoluteJoint.prototype, 'GetMotorTorque', 'GetMaxMotorTorque');
requireInvDt(b2PrismaticJoint.prototype, 'GetMotorForce', 'GetMaxMotorForce');
requireInvDt(b2WheelJoint.prototype, 'GetMotorTorque', 'GetMaxMotorTorque');

wrapMethod(
  b2PulleyJoint.prototype,
  'GetGroundAnchorA',
  (getGroundAnchorA) =>
    function (this: b2PulleyJoint, out?: b2Vec2) {
      return getGroundAnchorA.call(this, out ?? new b2Vec2());
    },
);
wrapMethod(
  b2PulleyJoint.prototype,
  'GetGroundAnchorB',
  (getGroundAnchorB) =>
    function (this: b2PulleyJoint, out?: b2Vec2) {
      return getGroundAnchorB.call(this, out ?? new b2Vec2());
    },
);
defineMethods(b2PulleyJoint.prototype, {
  GetLength1() {
    return this.GetLengthA();
  },
  GetLength2() {
    return this.GetLengthB();
  },
});
for (const name of ['maxLengthA', 'maxLengthB']) {
  defineRemovedProperty(
    b2PulleyJointDef.prototype,
    name,
    `b2PulleyJointDef.${name}`,
    'The pulley has no length limits; add a b2RopeJointDef with maxLength between the ground and the body.',
  );
}

// Controllers (Box2D.Dynamics.Controllers) are gone.
export const b2Controller = removedClass('b2Controller', controllersGone);
export const b2BuoyancyController = removedClass('b2BuoyancyController', controllersGone);
export const b2ConstantAccelController = removedClass('b2ConstantAccelController', controllersGone);
export const b2ConstantForceController = removedClass('b2ConstantForceController', controllersGone);
export const b2GravityController = removedClass('b2GravityController', controllersGone);
export const b2TensorDampingController = removedClass('b2TensorDampingController', controllersGone);
