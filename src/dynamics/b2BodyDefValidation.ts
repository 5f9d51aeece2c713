/*
 * Checks of body and fixture definitions (no C++ counterpart; see common/b2ArgumentError.ts):
 * b2World.CreateBody and b2Body.CreateFixture run them before they change anything. Apart from the
 * joint checks (b2DefValidation.ts), which need the b2Body class, so that b2Body imports nothing
 * that imports it.
 */

import { b2ArgumentError, b2CheckFinite, b2CheckNonNegative, b2CheckObject, b2CheckVec2, b2DescribeNumber } from '../common/b2ArgumentError';
import { b2BodyType } from '../common/b2Constants';
import { b2CheckShape } from '../collision/shapes/b2ShapeValidation';
import type { b2BodyDef } from './b2Body';
import type { b2FixtureDef } from './b2Fixture';

/** `type` must be one of b2_staticBody, b2_kinematicBody, b2_dynamicBody. */
export function b2CheckBodyType(method: string, argument: string, type: b2BodyType): void {
  if (type !== b2BodyType.b2_staticBody && type !== b2BodyType.b2_kinematicBody && type !== b2BodyType.b2_dynamicBody) {
    throw new b2ArgumentError(method, argument, `must be b2_staticBody (0), b2_kinematicBody (1) or b2_dynamicBody (2), got ${b2DescribeNumber(type)}`);
  }
}

/** A body definition: valid type, finite kinematics, non-negative damping, finite gravity scale. */
export function b2CheckBodyDef(method: string, def: Readonly<b2BodyDef>): void {
  b2CheckObject(method, 'def', def);
  b2CheckBodyType(method, 'def.type', def.type);
  b2CheckVec2(method, 'def.position', def.position);
  b2CheckFinite(method, 'def.angle', def.angle);
  b2CheckVec2(method, 'def.linearVelocity', def.linearVelocity);
  b2CheckFinite(method, 'def.angularVelocity', def.angularVelocity);
  b2CheckNonNegative(method, 'def.linearDamping', def.linearDamping);
  b2CheckNonNegative(method, 'def.angularDamping', def.angularDamping);
  b2CheckFinite(method, 'def.gravityScale', def.gravityScale);
}

/** A fixture definition: a valid shape, and non-negative finite friction, restitution and density. */
export function b2CheckFixtureDef(method: string, def: Readonly<b2FixtureDef>, shapeArgument = 'def.shape'): void {
  b2CheckObject(method, 'def', def);
  if (def.shape === null || def.shape === undefined) {
    throw new b2ArgumentError(method, shapeArgument, 'must be set');
  }
  b2CheckNonNegative(method, 'def.friction', def.friction);
  b2CheckNonNegative(method, 'def.restitution', def.restitution);
  b2CheckNonNegative(method, 'def.density', def.density);
  b2CheckShape(method, shapeArgument, def.shape, def.density);
}
