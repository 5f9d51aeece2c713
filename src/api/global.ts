/*
 * Types for the classic-script bundle: dist/box2d.js defines the global `Box2D`. A TypeScript
 * program using that script instead of the ES module references these declarations:
 *   /// <reference types="webphysics/global" />
 * and then writes Box2DWeb code: `new Box2D.Dynamics.b2World(new Box2D.Common.Math.b2Vec2(0, 10), true)`,
 * with every namespace member usable as a type (`let body: Box2D.Dynamics.b2Body`).
 */

import * as Box2DNamespace from './Box2D';

declare global {
  export import Box2D = Box2DNamespace;
}
