/*
 * GpuPointQuery (src-gpu/query/pointQuery.ts): the dynamic body under a world point, found on the
 * GPU after the steps called so far with one 16-byte read-back, as the Testbed's MouseDown picks
 * one (circles and polygons hold points; static bodies and edges are never picked).
 */

import { expect, it } from 'vitest';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import { b2World } from '../../src/dynamics/b2World';
import { WebGPUBackend } from '../../src-gpu/backend/backend';
import { GpuPointQuery } from '../../src-gpu/query/pointQuery';
import { describeGpu } from './support';

describeGpu('GpuPointQuery: the body under a point, from the GPU', (ctx) => {
  it('finds the dynamic body whose shape holds the point where the GPU has it, and nothing on static bodies, edges or empty space', async () => {
    const world = new b2World(new b2Vec2(0, -10));
    world.SetAllowSleeping(false);
    const ground = world.CreateBody(new b2BodyDef());
    const floor = new b2PolygonShape();
    floor.SetAsBox(10, 0.5, new b2Vec2(0, -10), 0);
    ground.CreateFixture(floor, 0);
    const ledge = new b2EdgeShape();
    ledge.Set(new b2Vec2(4, 0), new b2Vec2(10, 0));
    ground.CreateFixture(ledge, 0);
    const dynamic = (x: number, y: number, angle: number): b2Body => {
      const def = new b2BodyDef();
      def.type = b2_dynamicBody;
      def.position.Set(x, y);
      def.angle = angle;
      return world.CreateBody(def);
    };
    const box = dynamic(-5, 4, 0.5);
    const square = new b2PolygonShape();
    square.SetAsBox(1, 0.5);
    box.CreateFixture(square, 1);
    const ball = dynamic(7, 1, 0);
    const disc = new b2CircleShape();
    disc.m_radius = 1;
    ball.CreateFixture(disc, 1);

    const backend = await WebGPUBackend.create({ context: ctx });
    await world.SetBackend(backend);
    const query = new GpuPointQuery(backend);
    const maps: number[] = [];
    const proto = Object.getPrototypeOf(ctx.createBuffer('probe', 16, 0x8)) as { mapAsync: (...args: unknown[]) => Promise<void>; size: number };
    const mapAsync = proto.mapAsync;
    try {
      for (let i = 0; i < 30; ++i) await world.StepAsync(1 / 60, 8, 3);
      proto.mapAsync = function (this: GPUBuffer, ...args: unknown[]) {
        maps.push(this.size);
        return mapAsync.apply(this, args);
      };
      // The box has fallen 1.3 m by now: it is found where the GPU has it, not where it started.
      const fallen = 4 - (10 * (30 * 31)) / (2 * 3600);
      const hit = await query.bodyAt(-5, fallen + 0.3);
      proto.mapAsync = mapAsync;
      expect(maps, 'bytes of each buffer mapped by the query').toEqual([16]);
      expect(hit?.body).toBe(box);
      // The point 0.3 m above the centre, in the frame of a box turned by 0.5 rad.
      expect(hit!.localPoint.x).toBeCloseTo(0.3 * Math.sin(0.5), 4);
      expect(hit!.localPoint.y).toBeCloseTo(0.3 * Math.cos(0.5), 4);
      expect(await query.bodyAt(-5, 4)).toBeNull(); // where the box started: empty now
      expect((await query.bodyAt(7.5, 1.5))?.body).toBe(ball);
      expect(await query.bodyAt(7.9, 1.9)).toBeNull(); // inside the ball's square, outside the disc
      expect(await query.bodyAt(0, -10)).toBeNull(); // the static floor
      expect(await query.bodyAt(6, 0)).toBeNull(); // on the edge
      await expect(query.bodyAt(Number.NaN, 0)).rejects.toThrow(/x and y must be finite, got \(NaN, 0\)/);
      expect((await query.bodyAt(7, 1))?.body).toBe(ball); // the query still works after a refusal
    } finally {
      proto.mapAsync = mapAsync;
      query.destroy();
      await world.SetBackend(null);
    }
  }, 120_000);
});
