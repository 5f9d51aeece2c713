/*
 * GpuNarrowPhase beyond single manifolds: begin/end events against the engine's contact listener
 * on a scripted scene (a body through a sensor, off a bumper and back, a body destroyed while
 * touching), byte-identical outputs run to run, the solver list, overflow of the contact (and
 * pair) capacity detected and regrown, pair-type bins that dispatch nothing when empty, and the
 * { wait: false } mode.
 */

import { expect, it } from 'vitest';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import { b2ChainShape } from '../../src/collision/shapes/b2ChainShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody, b2_staticBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import { b2FixtureDef } from '../../src/dynamics/b2Fixture';
import type { b2Contact } from '../../src/dynamics/contacts/b2Contact';
import { b2World } from '../../src/dynamics/b2World';
import { b2ContactListener } from '../../src/dynamics/b2WorldCallbacks';
import { GpuBroadPhase } from '../../src-gpu/broadphase/broadPhase';
import { BIN, EVENT_BEGIN, EVENT_END } from '../../src-gpu/device/layout';
import { GpuNarrowPhase } from '../../src-gpu/narrowphase/narrowPhase';
import { GpuPipeline } from '../../src-gpu/pipeline';
import { GpuWorld } from '../../src-gpu/world/world';
import { goldenSceneNames, loadGoldenScene } from '../support/scene';
import { describeGpu, rng } from './support';

interface Scripted {
  world: b2World;
  box: b2Body;
}

/** Zero gravity, no continuous collision: a box crosses a sensor, bounces off a circle, crosses back. */
function scriptedWorld(): Scripted {
  const world = new b2World(new b2Vec2(0, 0));
  world.SetContinuousPhysics(false);
  const ground = world.CreateBody(new b2BodyDef());
  const sensorShape = new b2PolygonShape();
  sensorShape.SetAsBox(1, 1);
  const sensorDef = new b2FixtureDef();
  sensorDef.shape = sensorShape;
  sensorDef.isSensor = true;
  ground.CreateFixture(sensorDef);
  const bumper = new b2CircleShape();
  bumper.m_radius = 0.5;
  bumper.m_p.Set(5, 0);
  const bumperDef = new b2FixtureDef();
  bumperDef.shape = bumper;
  bumperDef.restitution = 1;
  ground.CreateFixture(bumperDef);
  // A floor made of a chain and an edge, below the path (no contact unless something falls).
  const chain = new b2ChainShape();
  chain.CreateChain([new b2Vec2(-8, -3), new b2Vec2(0, -3), new b2Vec2(8, -3)]);
  ground.CreateFixture(chain, 0);
  const edge = new b2EdgeShape();
  edge.Set(new b2Vec2(-8, 3), new b2Vec2(8, 3));
  ground.CreateFixture(edge, 0);

  const def = new b2BodyDef();
  def.type = b2_dynamicBody;
  def.position.Set(-4, 0);
  def.linearVelocity.Set(12, 0);
  const box = world.CreateBody(def);
  const boxShape = new b2PolygonShape();
  boxShape.SetAsBox(0.25, 0.25);
  const boxDef = new b2FixtureDef();
  boxDef.shape = boxShape;
  boxDef.density = 1;
  boxDef.friction = 0;
  boxDef.restitution = 1;
  box.CreateFixture(boxDef);
  return { world, box };
}

type EventKey = string;

describeGpu('GpuNarrowPhase: events, determinism, capacity, bins', (ctx) => {
  it("reports the engine listener's BeginContact/EndContact, step by step, for a sensor, a bumper and a destroyed body", async () => {
    const { world, box } = scriptedWorld();
    const mirror = new GpuWorld(ctx, world);
    const broadPhase = new GpuBroadPhase(ctx);
    const narrow = new GpuNarrowPhase(ctx);
    const pipeline = new GpuPipeline(ctx, broadPhase, narrow);
    let window: EventKey[] = [];
    const listener = new b2ContactListener();
    const record = (kind: number) => (c: b2Contact) => {
      const a = mirror.proxySlot(c.m_fixtureA, c.m_indexA);
      const b = mirror.proxySlot(c.m_fixtureB, c.m_indexB);
      window.push(`${kind === EVENT_BEGIN ? 'begin' : 'end'} ${a}-${b}`);
    };
    listener.BeginContact = record(EVENT_BEGIN);
    listener.EndContact = record(EVENT_END);
    world.SetContactListener(listener);

    let sensorBegins = 0;
    let sensorEnds = 0;
    let solidBegins = 0;
    let solidEnds = 0;
    let vanished = 0;
    let ball: b2Body | null = null;
    for (let k = 0; k < 90; ++k) {
      window = [];
      // A ball put onto the bumper at k = 70, destroyed while touching at k = 80: the engine calls
      // EndContact from DestroyBody; the GPU sees the pair gone.
      if (k === 70) {
        const def = new b2BodyDef();
        def.type = b2_dynamicBody;
        def.position.Set(5, 0.95);
        def.gravityScale = 0;
        ball = world.CreateBody(def);
        const s = new b2CircleShape();
        s.m_radius = 0.5;
        ball.CreateFixture(s, 1);
      }
      if (k === 80 && ball) {
        world.DestroyBody(ball);
        ball = null;
      }
      mirror.sync();
      const result = await pipeline.step(mirror);
      const events = await narrow.readEvents();
      expect(events.length).toBe(result.eventCount);
      world.Step(1 / 60, 8, 3);
      const gpu = events.map((e) => `${e.kind === EVENT_BEGIN ? 'begin' : 'end'} ${e.proxyA}-${e.proxyB}`).sort();
      const js = window.slice().sort();
      expect(gpu, `step ${k}`).toEqual(js);
      for (const e of events) {
        const sensor = mirror.proxyAt(e.proxyA)?.fixture.m_isSensor || mirror.proxyAt(e.proxyB)?.fixture.m_isSensor;
        if (e.vanished) vanished++;
        if (e.kind === EVENT_BEGIN) {
          if (sensor) sensorBegins++;
          else solidBegins++;
        } else if (sensor) sensorEnds++;
        else solidEnds++;
      }
    }
    // In and out of the sensor twice, on and off the bumper, the ball on the bumper and gone.
    expect(sensorBegins).toBeGreaterThanOrEqual(2);
    expect(sensorEnds).toBeGreaterThanOrEqual(2);
    expect(solidBegins).toBeGreaterThanOrEqual(2);
    expect(solidEnds).toBeGreaterThanOrEqual(2);
    expect(vanished).toBe(1);
    expect(box.GetLinearVelocity().x).toBeLessThan(0);
    pipeline.destroy();
    narrow.destroy();
    broadPhase.destroy();
    mirror.destroy();
  });

  it('gives byte-identical outputs for the same inputs (two pipelines in lockstep, and a rerun)', async () => {
    const name = goldenSceneNames().includes('mixed-rain') ? 'mixed-rain' : goldenSceneNames()[0];
    const run = async () => {
      const scene = loadGoldenScene(name);
      const mirror = new GpuWorld(ctx, scene.world);
      const bp1 = new GpuBroadPhase(ctx);
      const np1 = new GpuNarrowPhase(ctx);
      const bp2 = new GpuBroadPhase(ctx);
      const np2 = new GpuNarrowPhase(ctx, { initialContactCapacity: 64 });
      const p1 = new GpuPipeline(ctx, bp1, np1);
      const p2 = new GpuPipeline(ctx, bp2, np2);
      const snapshots: Uint8Array[] = [];
      for (let k = 0; k < 60; ++k) {
        scene.step();
        if (k % 15 !== 14) continue;
        mirror.sync();
        await p1.step(mirror);
        await p2.step(mirror);
        const a = await np1.readAll();
        const b = await np2.readAll();
        expect(Buffer.from(a).equals(Buffer.from(b)), `step ${k}`).toBe(true);
        snapshots.push(a);
      }
      for (const x of [p1, p2, np1, np2, bp1, bp2, mirror]) x.destroy();
      return snapshots;
    };
    const first = await run();
    const second = await run();
    expect(first.length).toBe(4);
    first.forEach((s, i) => expect(Buffer.from(s).equals(Buffer.from(second[i])), `snapshot ${i}`).toBe(true));
    expect(first[first.length - 1].length).toBeGreaterThan(1000);
  });

  it('detects contact (and pair) capacity overflow, regrows to the exact need and loses nothing', async () => {
    // 1600 overlapping circles in a grid: thousands of pairs, from capacities of 1024 pairs and 16 contacts.
    const world = new b2World(new b2Vec2(0, 0));
    const r = rng(3);
    for (let i = 0; i < 40; ++i) {
      for (let j = 0; j < 40; ++j) {
        const def = new b2BodyDef();
        def.type = (i + j) % 7 === 0 ? b2_staticBody : b2_dynamicBody;
        def.position.Set(0.8 * i + 0.05 * r(), 0.8 * j + 0.05 * r());
        def.angle = r();
        const body = world.CreateBody(def);
        if ((i * 40 + j) % 3 === 0) {
          const s = new b2PolygonShape();
          s.SetAsBox(0.45, 0.3);
          body.CreateFixture(s, 1);
        } else {
          const s = new b2CircleShape();
          s.m_radius = 0.5;
          body.CreateFixture(s, 1);
        }
      }
    }
    const mirror = new GpuWorld(ctx, world);
    mirror.sync();
    const small = new GpuNarrowPhase(ctx, { initialContactCapacity: 16 });
    const smallBp = new GpuBroadPhase(ctx);
    const big = new GpuNarrowPhase(ctx, { initialContactCapacity: 1 << 15 });
    const bigBp = new GpuBroadPhase(ctx, { initialPairCapacity: 1 << 15 });
    const smallPipeline = new GpuPipeline(ctx, smallBp, small);
    const bigPipeline = new GpuPipeline(ctx, bigBp, big);
    const a = await smallPipeline.step(mirror);
    const b = await bigPipeline.step(mirror);
    expect(b.contactRegrows).toBe(0);
    expect(b.broad.regrows).toBe(0);
    expect(a.broad.regrows).toBeGreaterThan(0);
    expect(a.contactRegrows).toBeGreaterThan(0);
    expect(a.contactCount).toBe(b.contactCount);
    expect(a.contactCount).toBe(a.broad.pairCount);
    expect(a.contactCount).toBeGreaterThan(3000);
    expect(a.contactCapacity).toBeGreaterThanOrEqual(a.contactCount);
    expect(a.contactCapacity).toBeLessThan(2 * a.contactCount);
    expect(a.solverCount).toBe(b.solverCount);
    expect(Buffer.from(await small.readAll()).equals(Buffer.from(await big.readAll()))).toBe(true);
    // The solver list is the touching non-sensor contacts, ascending.
    const contacts = await small.readContacts();
    const list = await small.readSolverList();
    expect(Array.from(list)).toEqual(contacts.filter((c) => c.touching && !c.sensor).map((c) => c.index));
    // Only circles and polygons here: the edge, chain and sensor bins are empty (zero workgroups).
    expect(a.binCounts[BIN.EDGE_CIRCLE] + a.binCounts[BIN.EDGE_POLYGON] + a.binCounts[BIN.CHAIN_CIRCLE] + a.binCounts[BIN.CHAIN_POLYGON]).toBe(0);
    expect(a.binCounts[BIN.SENSOR]).toBe(0);
    expect(a.binCounts[BIN.CIRCLES]).toBeGreaterThan(0);
    expect(a.binCounts[BIN.POLYGON_CIRCLE]).toBeGreaterThan(0);
    expect(a.binCounts[BIN.POLYGONS]).toBeGreaterThan(0);
    expect(a.binCounts.reduce((s, x) => s + x, 0)).toBe(a.contactCount);
    // A second step warm-starts every contact.
    world.Step(1 / 60, 8, 3);
    mirror.sync();
    const a2 = await smallPipeline.step(mirror);
    expect(a2.contactRegrows).toBe(0);
    expect(a2.previousCount).toBe(a.contactCount);
    for (const x of [smallPipeline, bigPipeline, small, smallBp, big, bigBp, mirror]) x.destroy();
  });

  it('runs steps without waiting ({ wait: false }) and settles to the same contacts as waiting', async () => {
    const scene = loadGoldenScene('pyramid');
    const mirror = new GpuWorld(ctx, scene.world);
    const waitingBp = new GpuBroadPhase(ctx);
    const waiting = new GpuNarrowPhase(ctx);
    const deferredBp = new GpuBroadPhase(ctx);
    const deferred = new GpuNarrowPhase(ctx, { initialContactCapacity: 16 });
    const waitingPipeline = new GpuPipeline(ctx, waitingBp, waiting);
    const deferredPipeline = new GpuPipeline(ctx, deferredBp, deferred);
    let settled: Promise<unknown> | undefined;
    for (let k = 0; k < 8; ++k) {
      scene.step();
      mirror.sync();
      await waitingPipeline.step(mirror);
      const r = await deferredPipeline.step(mirror, { wait: false });
      expect(r.pending).toBe(true);
      settled = r.settled;
    }
    const last = await deferredPipeline.settle();
    await settled;
    // The first deferred step ran out of room (16 contacts) and said so; the buffers grew.
    expect(deferredPipeline.truncatedSteps).toBeGreaterThanOrEqual(1);
    expect(last!.overflowed).toBe(false);
    expect(last!.contactCount).toBe(waitingPipeline.lastResult!.contactCount);
    expect(Buffer.from(await deferred.readAll()).equals(Buffer.from(await waiting.readAll()))).toBe(true);
    for (const x of [waitingPipeline, deferredPipeline, waiting, waitingBp, deferred, deferredBp, mirror]) x.destroy();
  });
});
