/*
 * Small scene builders shared by the joint tests: a world, static ground, boxes and circles,
 * and a log capture for Dump().
 */

import { b2CircleShape } from '../../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../../src/common/b2Math';
import { b2LogSink, b2SetLogSink } from '../../../src/common/b2Settings';
import { b2Body, b2BodyDef, b2BodyType } from '../../../src/dynamics/b2Body';
import { b2FixtureDef } from '../../../src/dynamics/b2Fixture';
import { b2World } from '../../../src/dynamics/b2World';

export const h = 1.0 / 60.0;
export const inv_h = 60.0;

export function makeWorld(gx = 0.0, gy = -10.0): b2World {
  return new b2World(new b2Vec2(gx, gy));
}

/** A static body without fixtures (the Testbed's m_groundBody). */
export function makeGround(world: b2World, x = 0.0, y = 0.0): b2Body {
  const bd = new b2BodyDef();
  bd.position.Set(x, y);
  return world.CreateBody(bd);
}

export interface BodyOptions {
  angle?: number;
  type?: b2BodyType;
  density?: number;
  allowSleep?: boolean;
  /** A collision category of 0 keeps the body out of every contact. */
  categoryBits?: number;
}

function makeBody(world: b2World, x: number, y: number, opts: BodyOptions): b2Body {
  const bd = new b2BodyDef();
  bd.type = opts.type ?? b2BodyType.b2_dynamicBody;
  bd.position.Set(x, y);
  bd.angle = opts.angle ?? 0.0;
  bd.allowSleep = opts.allowSleep ?? false;
  return world.CreateBody(bd);
}

function fixtureDef(opts: BodyOptions): b2FixtureDef {
  const fd = new b2FixtureDef();
  fd.density = opts.density ?? 1.0;
  fd.filter.categoryBits = opts.categoryBits ?? 0x0001;
  return fd;
}

/** A box body (half extents hx, hy) whose fixtures collide with nothing unless asked to. */
export function makeBox(world: b2World, x: number, y: number, hx: number, hy: number, opts: BodyOptions = {}): b2Body {
  const body = makeBody(world, x, y, opts);
  const shape = new b2PolygonShape();
  shape.SetAsBox(hx, hy);
  const fd = fixtureDef({ categoryBits: 0, ...opts });
  fd.shape = shape;
  body.CreateFixture(fd);
  return body;
}

/** A circle body whose fixture collides with nothing unless asked to. */
export function makeCircle(world: b2World, x: number, y: number, radius: number, opts: BodyOptions = {}): b2Body {
  const body = makeBody(world, x, y, opts);
  const shape = new b2CircleShape();
  shape.m_radius = radius;
  const fd = fixtureDef({ categoryBits: 0, ...opts });
  fd.shape = shape;
  body.CreateFixture(fd);
  return body;
}

export function step(world: b2World, count: number, each?: (k: number) => void): void {
  for (let k = 1; k <= count; ++k) {
    world.Step(h, 8, 3);
    each?.(k);
  }
}

/** Run fn with b2Log captured; returns the text it logged. */
export function captureLog(fn: () => void): string {
  const previous = b2LogSink;
  let text = '';
  b2SetLogSink((s) => {
    text += s;
  });
  try {
    fn();
  } finally {
    b2SetLogSink(previous);
  }
  return text;
}
