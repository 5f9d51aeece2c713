/**
 * Box2D 2.2.1 for the web: the engine, a bit-exact TypeScript port of Box2D 2.2.1 under Box2D's
 * own names, with the Box2DWeb 2.1a compatibility layer loaded (`import { b2World } from 'webphysics'`).
 *
 * The same names are the classic script's (dist/box2d.js) under Box2DWeb's namespaces: see
 * {@link Box2D}.
 *
 * @module webphysics
 */

// The reference of the package entry `webphysics` (src/index.ts), read by TypeDoc (npm run docs):
// every name src/index.ts exports. Six of them src/index.ts takes from the 2.1a layer: the engine's
// classes behind a constructor proxy that also accepts 2.1a's arguments (src/api/compat.ts), a type
// and a value of the class's name. The reference documents the classes themselves.
export * from '../../src/index';
export { b2World } from '../../src/dynamics/b2World';
export { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
export { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
export { b2RayCastInput } from '../../src/collision/b2Collision';
export { b2Transform } from '../../src/common/b2Math';
export { b2DestructionListener } from '../../src/dynamics/b2WorldCallbacks';
