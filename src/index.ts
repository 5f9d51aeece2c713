/*
 * WebPhysics: Box2D 2.2.1 in TypeScript. Every engine module, exported under Box2D's own names,
 * with the Box2DWeb 2.1a compatibility layer loaded (see the end of this file).
 */

export * from './common/b2Settings';
export * from './common/b2ArgumentError';
export * from './common/b2Math';
export * from './common/b2Trig';
export * from './common/b2Draw';
export * from './common/b2Timer';
export * from './common/b2GrowableStack';
export * from './collision/b2Collision';
export * from './collision/b2CollideCircle';
export * from './collision/b2CollidePolygon';
export * from './collision/b2CollideEdge';
export * from './collision/b2Distance';
export * from './collision/b2TimeOfImpact';
export * from './collision/b2DynamicTree';
export * from './collision/b2BroadPhase';
export * from './collision/shapes/b2Shape';
export * from './collision/shapes/b2CircleShape';
export * from './collision/shapes/b2EdgeShape';
export * from './collision/shapes/b2PolygonShape';
export * from './collision/shapes/b2ChainShape';
export * from './dynamics/b2TimeStep';
export * from './dynamics/b2WorldCallbacks';
export * from './dynamics/b2Body';
export * from './dynamics/b2Fixture';
export * from './dynamics/b2World';
export * from './dynamics/b2AccuracyTarget';
export type { b2WorldBackend, b2WorldBackendEngine, b2OverridableCallback } from './dynamics/b2WorldBackend';
export * from './dynamics/b2ContactManager';
export * from './dynamics/b2Island';
export * from './dynamics/contacts/b2Contact';
export * from './dynamics/contacts/b2ContactAllocator';
export * from './dynamics/contacts/b2ContactRegistry';
export * from './dynamics/contacts/b2CircleContact';
export * from './dynamics/contacts/b2PolygonAndCircleContact';
export * from './dynamics/contacts/b2PolygonContact';
export * from './dynamics/contacts/b2EdgeAndCircleContact';
export * from './dynamics/contacts/b2EdgeAndPolygonContact';
export * from './dynamics/contacts/b2ChainAndCircleContact';
export * from './dynamics/contacts/b2ChainAndPolygonContact';
export * from './dynamics/contacts/b2ContactSolver';
export * from './dynamics/joints/b2Joint';
export * from './dynamics/joints/b2JointFactory';
export * from './dynamics/joints/b2DistanceJoint';
export * from './dynamics/joints/b2FrictionJoint';
export * from './dynamics/joints/b2GearJoint';
export * from './dynamics/joints/b2MouseJoint';
export * from './dynamics/joints/b2PrismaticJoint';
export * from './dynamics/joints/b2PulleyJoint';
export * from './dynamics/joints/b2RevoluteJoint';
export * from './dynamics/joints/b2RopeJoint';
export * from './dynamics/joints/b2WeldJoint';
export * from './dynamics/joints/b2WheelJoint';
export * from './rope/b2Rope';
export * from './io/b2dJson';

// The Box2DWeb 2.1a compatibility layer (./api/compat). Loading it installs the 2.1a members on the
// engine classes, exactly as the classic-script bundle (dist/box2d.js) does, so code behaves the
// same through either entry. The first six names below replace the engine's exports of the same
// name: they are the same classes, whose constructors also accept 2.1a's arguments.
export {
  b2World,
  b2CircleShape,
  b2EdgeShape,
  b2RayCastInput,
  b2Transform,
  b2DestructionListener,
  b2DebugDraw,
  b2Math,
  b2Settings,
  b2Collision,
  b2Segment,
  b2FilterData,
  b2EdgeChainDef,
  b2LineJoint,
  b2LineJointDef,
  b2Controller,
  b2BuoyancyController,
  b2ConstantAccelController,
  b2ConstantForceController,
  b2GravityController,
  b2TensorDampingController,
} from './api/compat';
export type { b2DebugDrawContext, b2QueryFunction, b2RayCastFunction } from './api/compat';
/** Box2DWeb's namespaces (Box2D.Dynamics.b2World...), the object dist/box2d.js defines as a global. */
export * as Box2D from './api/Box2D';
