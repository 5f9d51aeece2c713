/*
 * The Box2DWeb namespace layout over the 2.2.1 engine: Box2D.Common, Box2D.Common.Math,
 * Box2D.Collision, Box2D.Collision.Shapes, Box2D.Dynamics, Box2D.Dynamics.Contacts,
 * Box2D.Dynamics.Joints and Box2D.Dynamics.Controllers (whose classes Box2D 2.2 removed and
 * whose constructors throw). Each name is both the class and its type, so TypeScript code may
 * write `let body: Box2D.Dynamics.b2Body`.
 *
 * The classic-script bundle (dist/box2d.js) is this module, exposed as the global `Box2D` as
 * Box2DWeb's script is (./classic, which also defines Box2DWeb's `Vector` globals); the ES entry
 * exports it as `Box2D`. Both load the 2.1a compatibility layer (./compat), so code written for
 * Box2DWeb 2.1a runs on either.
 */

import * as collision from '../collision/b2Collision';
import * as distance from '../collision/b2Distance';
import * as dynamicTree from '../collision/b2DynamicTree';
import * as broadPhase from '../collision/b2BroadPhase';
import * as timeOfImpact from '../collision/b2TimeOfImpact';
import * as chainShape from '../collision/shapes/b2ChainShape';
import * as polygonShape from '../collision/shapes/b2PolygonShape';
import * as shape from '../collision/shapes/b2Shape';
import * as argumentError from '../common/b2ArgumentError';
import * as draw from '../common/b2Draw';
import * as math from '../common/b2Math';
import * as timer from '../common/b2Timer';
import * as body from '../dynamics/b2Body';
import * as contactManager from '../dynamics/b2ContactManager';
import * as fixture from '../dynamics/b2Fixture';
import * as island from '../dynamics/b2Island';
import * as timeStep from '../dynamics/b2TimeStep';
import * as callbacks from '../dynamics/b2WorldCallbacks';
import * as chainAndCircleContact from '../dynamics/contacts/b2ChainAndCircleContact';
import * as chainAndPolygonContact from '../dynamics/contacts/b2ChainAndPolygonContact';
import * as circleContact from '../dynamics/contacts/b2CircleContact';
import * as contact from '../dynamics/contacts/b2Contact';
import * as contactSolver from '../dynamics/contacts/b2ContactSolver';
import * as edgeAndCircleContact from '../dynamics/contacts/b2EdgeAndCircleContact';
import * as edgeAndPolygonContact from '../dynamics/contacts/b2EdgeAndPolygonContact';
import * as polygonAndCircleContact from '../dynamics/contacts/b2PolygonAndCircleContact';
import * as polygonContact from '../dynamics/contacts/b2PolygonContact';
import * as distanceJoint from '../dynamics/joints/b2DistanceJoint';
import * as frictionJoint from '../dynamics/joints/b2FrictionJoint';
import * as gearJoint from '../dynamics/joints/b2GearJoint';
import * as joint from '../dynamics/joints/b2Joint';
import * as mouseJoint from '../dynamics/joints/b2MouseJoint';
import * as prismaticJoint from '../dynamics/joints/b2PrismaticJoint';
import * as pulleyJoint from '../dynamics/joints/b2PulleyJoint';
import * as revoluteJoint from '../dynamics/joints/b2RevoluteJoint';
import * as ropeJoint from '../dynamics/joints/b2RopeJoint';
import * as weldJoint from '../dynamics/joints/b2WeldJoint';
import * as wheelJoint from '../dynamics/joints/b2WheelJoint';
import * as io from '../io/b2dJson';
import * as rope from '../rope/b2Rope';
import * as compat from './compat';

export namespace Common {
  export import b2Settings = compat.b2Settings;
  export import b2Color = draw.b2Color;
  export import b2Draw = draw.b2Draw;
  export import b2Timer = timer.b2Timer;
  /** The error the API throws for a rejected argument or call (not in Box2DWeb). */
  export import b2ArgumentError = argumentError.b2ArgumentError;

  export namespace Math {
    export import b2Vec2 = math.b2Vec2;
    export import b2Vec3 = math.b2Vec3;
    export import b2Mat22 = math.b2Mat22;
    export import b2Mat33 = math.b2Mat33;
    export import b2Rot = math.b2Rot;
    export import b2Transform = compat.b2Transform;
    export import b2Sweep = math.b2Sweep;
    export import b2Math = compat.b2Math;
  }
}

export namespace Collision {
  export import b2AABB = collision.b2AABB;
  export import b2ContactFeature = collision.b2ContactFeature;
  export import b2ContactID = collision.b2ContactID;
  export import b2Manifold = collision.b2Manifold;
  export import b2ManifoldPoint = collision.b2ManifoldPoint;
  export import b2WorldManifold = collision.b2WorldManifold;
  export import b2ClipVertex = collision.b2ClipVertex;
  export import b2RayCastInput = compat.b2RayCastInput;
  export import b2RayCastOutput = collision.b2RayCastOutput;
  export import b2Collision = compat.b2Collision;
  export import b2Segment = compat.b2Segment;
  export import b2Distance = distance.b2Distance;
  export import b2DistanceInput = distance.b2DistanceInput;
  export import b2DistanceOutput = distance.b2DistanceOutput;
  export import b2DistanceProxy = distance.b2DistanceProxy;
  export import b2SimplexCache = distance.b2SimplexCache;
  export import b2TimeOfImpact = timeOfImpact.b2TimeOfImpact;
  export import b2TOIInput = timeOfImpact.b2TOIInput;
  export import b2TOIOutput = timeOfImpact.b2TOIOutput;
  export import b2DynamicTree = dynamicTree.b2DynamicTree;
  export import b2TreeNode = dynamicTree.b2TreeNode;
  export import b2BroadPhase = broadPhase.b2BroadPhase;

  export namespace Shapes {
    export import b2Shape = shape.b2Shape;
    export import b2MassData = shape.b2MassData;
    export import b2CircleShape = compat.b2CircleShape;
    export import b2EdgeShape = compat.b2EdgeShape;
    export import b2PolygonShape = polygonShape.b2PolygonShape;
    export import b2ChainShape = chainShape.b2ChainShape;
    export import b2EdgeChainDef = compat.b2EdgeChainDef;
  }
}

export namespace Dynamics {
  export import b2World = compat.b2World;
  export import b2Body = body.b2Body;
  export import b2BodyDef = body.b2BodyDef;
  export import b2Fixture = fixture.b2Fixture;
  export import b2FixtureDef = fixture.b2FixtureDef;
  export import b2Filter = fixture.b2Filter;
  export import b2FilterData = compat.b2FilterData;
  export import b2ContactListener = callbacks.b2ContactListener;
  export import b2ContactFilter = callbacks.b2ContactFilter;
  export import b2ContactImpulse = callbacks.b2ContactImpulse;
  export import b2DestructionListener = compat.b2DestructionListener;
  export import b2QueryCallback = callbacks.b2QueryCallback;
  export import b2RayCastCallback = callbacks.b2RayCastCallback;
  export import b2DebugDraw = compat.b2DebugDraw;
  export import b2ContactManager = contactManager.b2ContactManager;
  export import b2Island = island.b2Island;
  export import b2TimeStep = timeStep.b2TimeStep;
  export import b2Profile = timeStep.b2Profile;

  export namespace Contacts {
    export import b2Contact = contact.b2Contact;
    export import b2ContactEdge = contact.b2ContactEdge;
    export import b2ContactRegister = contact.b2ContactRegister;
    export import b2CircleContact = circleContact.b2CircleContact;
    export import b2PolygonAndCircleContact = polygonAndCircleContact.b2PolygonAndCircleContact;
    export import b2PolygonContact = polygonContact.b2PolygonContact;
    export import b2EdgeAndCircleContact = edgeAndCircleContact.b2EdgeAndCircleContact;
    export import b2EdgeAndPolygonContact = edgeAndPolygonContact.b2EdgeAndPolygonContact;
    export import b2ChainAndCircleContact = chainAndCircleContact.b2ChainAndCircleContact;
    export import b2ChainAndPolygonContact = chainAndPolygonContact.b2ChainAndPolygonContact;
    export import b2ContactSolver = contactSolver.b2ContactSolver;
  }

  export namespace Joints {
    export import b2Joint = joint.b2Joint;
    export import b2JointDef = joint.b2JointDef;
    export import b2JointEdge = joint.b2JointEdge;
    export import b2Jacobian = joint.b2Jacobian;
    export import b2DistanceJoint = distanceJoint.b2DistanceJoint;
    export import b2DistanceJointDef = distanceJoint.b2DistanceJointDef;
    export import b2FrictionJoint = frictionJoint.b2FrictionJoint;
    export import b2FrictionJointDef = frictionJoint.b2FrictionJointDef;
    export import b2GearJoint = gearJoint.b2GearJoint;
    export import b2GearJointDef = gearJoint.b2GearJointDef;
    export import b2MouseJoint = mouseJoint.b2MouseJoint;
    export import b2MouseJointDef = mouseJoint.b2MouseJointDef;
    export import b2PrismaticJoint = prismaticJoint.b2PrismaticJoint;
    export import b2PrismaticJointDef = prismaticJoint.b2PrismaticJointDef;
    export import b2PulleyJoint = pulleyJoint.b2PulleyJoint;
    export import b2PulleyJointDef = pulleyJoint.b2PulleyJointDef;
    export import b2RevoluteJoint = revoluteJoint.b2RevoluteJoint;
    export import b2RevoluteJointDef = revoluteJoint.b2RevoluteJointDef;
    export import b2RopeJoint = ropeJoint.b2RopeJoint;
    export import b2RopeJointDef = ropeJoint.b2RopeJointDef;
    export import b2WeldJoint = weldJoint.b2WeldJoint;
    export import b2WeldJointDef = weldJoint.b2WeldJointDef;
    export import b2WheelJoint = wheelJoint.b2WheelJoint;
    export import b2WheelJointDef = wheelJoint.b2WheelJointDef;
    export import b2LineJoint = compat.b2LineJoint;
    export import b2LineJointDef = compat.b2LineJointDef;
  }

  export namespace Controllers {
    export import b2Controller = compat.b2Controller;
    export import b2BuoyancyController = compat.b2BuoyancyController;
    export import b2ConstantAccelController = compat.b2ConstantAccelController;
    export import b2ConstantForceController = compat.b2ConstantForceController;
    export import b2GravityController = compat.b2GravityController;
    export import b2TensorDampingController = compat.b2TensorDampingController;
  }
}

/** Box2D 2.2's rope (not in Box2DWeb). */
export namespace Rope {
  export import b2Rope = rope.b2Rope;
  export import b2RopeDef = rope.b2RopeDef;
}

/** b2dJson scene reading and writing (not in Box2DWeb). */
export namespace IO {
  export import b2dJsonRead = io.b2dJsonRead;
  export import b2dJsonWrite = io.b2dJsonWrite;
  export import b2dJsonWriteString = io.b2dJsonWriteString;
  export import b2dJsonScene = io.b2dJsonScene;
  export import b2dJsonError = io.b2dJsonError;
}
