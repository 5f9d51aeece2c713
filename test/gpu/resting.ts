/*
 * Stacks of boxes placed at rest on a ground, and stepping them until they sleep: what the GPU
 * tests of islands and sleeping (solverIslands.test.ts) and of contacts kept while asleep
 * (narrowPhaseSleep.test.ts) share.
 */

import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import { b2World } from '../../src/dynamics/b2World';
import type { GpuStepper } from '../../src-gpu/stepper';

export const DT = 1 / 60;
export const VELOCITY_ITERATIONS = 8;
export const POSITION_ITERATIONS = 3;

/** A ground box (top at y = 0) and boxes of half size 0.5 at `at`, exactly touching, at rest. */
export function restingWorld(at: number[][], allowSleep = true): { world: b2World; boxes: b2Body[] } {
  const world = new b2World(new b2Vec2(0, -10));
  world.SetAllowSleeping(allowSleep);
  const ground = world.CreateBody(new b2BodyDef());
  const groundShape = new b2PolygonShape();
  groundShape.SetAsBox(40, 1, new b2Vec2(0, -1), 0);
  ground.CreateFixture(groundShape, 0);
  const box = new b2PolygonShape();
  box.SetAsBox(0.5, 0.5);
  const boxes = at.map(([x, y]) => {
    const def = new b2BodyDef();
    def.type = b2_dynamicBody;
    def.position.Set(x, y);
    const body = world.CreateBody(def);
    body.CreateFixture(box, 1);
    return body;
  });
  return { world, boxes };
}

export const column = (x: number, n: number) => Array.from({ length: n }, (_, i) => [x, 0.5 + i]);
export const pyramid = (rows: number) => {
  const at: number[][] = [];
  for (let row = 0; row < rows; ++row) for (let i = 0; i < rows - row; ++i) at.push([-rows / 2 + i + 0.5 * row + 0.5, 0.5 + row]);
  return at;
};

export const allAsleep = (bodies: b2Body[]) => bodies.every((b) => !b.IsAwake());
export const allAwake = (bodies: b2Body[]) => bodies.every((b) => b.IsAwake());

/** Transform, sweep, velocities and sleep time of the bodies as float64 values (float32 on the GPU side). */
export const motion = (bodies: b2Body[]) =>
  bodies.map((b) => [
    b.m_xf.p.x,
    b.m_xf.p.y,
    b.m_xf.q.c,
    b.m_xf.q.s,
    b.m_sweep.c.x,
    b.m_sweep.c.y,
    b.m_sweep.a,
    b.m_linearVelocity.x,
    b.m_linearVelocity.y,
    b.m_angularVelocity,
    b.m_sleepTime,
  ]);

/** Steps until every body of `bodies` reads back asleep (at most `limit` steps); returns the steps taken. */
export async function stepUntilAsleep(stepper: GpuStepper, bodies: b2Body[], limit = 200): Promise<number> {
  for (let step = 1; step <= limit; ++step) {
    await stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    await stepper.readBodies();
    if (allAsleep(bodies)) return step;
  }
  throw new Error(`not asleep after ${limit} steps`);
}
