/*
 * The Box2DWeb 2.1a compatibility layer. Importing this module installs the 2.1a members on the
 * engine's classes (see compatMath, compatCollision, compatDynamics) and gives the names the ES
 * entry and the Box2D namespace export in place of, or beside, the engine's:
 * - the classes whose constructors also take 2.1a's arguments (b2World(gravity, doSleep),
 *   b2CircleShape(radius), b2EdgeShape(v1, v2), b2RayCastInput(p1, p2, maxFraction),
 *   b2Transform(position, R)). They are the engine classes behind a constructor proxy:
 *   `instanceof`, statics and subclassing are the engine class's;
 * - 2.1a's own names: b2Math, b2Settings, b2Collision, b2Segment, b2FilterData, b2DebugDraw;
 * - 2.1a's line joint, which becomes a wheel joint (b2LineJointDef, b2LineJoint);
 * - 2.1a classes Box2D 2.2 removed, whose constructors throw (the controllers...).
 */

import type { b2RayCastInput as b2RayCastInputEngine } from '../collision/b2Collision';
import type { b2CircleShape as b2CircleShapeEngine } from '../collision/shapes/b2CircleShape';
import type { b2EdgeShape as b2EdgeShapeEngine } from '../collision/shapes/b2EdgeShape';
import type { b2Transform as b2TransformEngine } from '../common/b2Math';
import type { b2World as b2WorldEngine } from '../dynamics/b2World';
import type { b2DestructionListener as b2DestructionListenerEngine } from '../dynamics/b2WorldCallbacks';
import { b2CircleShapeCompat, b2EdgeShapeCompat, b2RayCastInputCompat } from './compatCollision';
import { b2DestructionListenerCompat, b2WorldCompat } from './compatDynamics';
import { b2TransformCompat } from './compatMath';

export { b2DebugDraw } from './b2DebugDraw';
export type { b2DebugDrawContext } from './b2DebugDraw';
export { b2Math } from './compatMath';
export { b2Settings } from './compatSettings';
export { b2Collision, b2EdgeChainDef, b2Segment } from './compatCollision';
export {
  b2BuoyancyController,
  b2ConstantAccelController,
  b2ConstantForceController,
  b2Controller,
  b2FilterData,
  b2GravityController,
  b2LineJoint,
  b2LineJointDef,
  b2TensorDampingController,
} from './compatDynamics';
export type { b2QueryFunction, b2RayCastFunction } from './compatDynamics';

export type b2World = b2WorldEngine;
export const b2World = b2WorldCompat;
export type b2CircleShape = b2CircleShapeEngine;
export const b2CircleShape = b2CircleShapeCompat;
export type b2EdgeShape = b2EdgeShapeEngine;
export const b2EdgeShape = b2EdgeShapeCompat;
export type b2RayCastInput = b2RayCastInputEngine;
export const b2RayCastInput = b2RayCastInputCompat;
export type b2Transform = b2TransformEngine;
export const b2Transform = b2TransformCompat;
export type b2DestructionListener = b2DestructionListenerEngine;
export const b2DestructionListener = b2DestructionListenerCompat;
