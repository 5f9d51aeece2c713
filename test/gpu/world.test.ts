/*
 * GpuWorld, the world mirrored on the GPU: the mapping between engine objects and GPU slots
 * (including reuse after destroy), incremental uploads, what the buffers hold (read back from the
 * GPU), growth, and the precision of positions and AABBs far from the origin.
 */

import { expect, it } from 'vitest';
import { b2AABB } from '../../src/collision/b2Collision';
import { b2ChainShape } from '../../src/collision/shapes/b2ChainShape';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2_aabbExtension } from '../../src/common/b2Settings';
import { b2BodyDef, b2_dynamicBody, b2_kinematicBody, b2_staticBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import { b2Filter, b2FixtureDef } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { b2ContactFilter } from '../../src/dynamics/b2WorldCallbacks';
import { b2RevoluteJointDef } from '../../src/dynamics/joints/b2RevoluteJoint';
import { GpuBroadPhase } from '../../src-gpu/broadphase/broadPhase';
import type { GpuContext } from '../../src-gpu/device/device';
import { BODY_LIVE, MAP_READ, PROXY_JOINTED, PROXY_LIVE, USAGE } from '../../src-gpu/device/layout';
import { GpuWorld } from '../../src-gpu/world/world';
import { describeGpu } from './support';

async function readBack(ctx: GpuContext, buffer: GPUBuffer, bytes: number): Promise<ArrayBuffer> {
  const size = Math.max(16, Math.ceil(bytes / 16) * 16);
  const staging = ctx.createBuffer('test read', size, USAGE.MAP_READ | USAGE.COPY_DST);
  const enc = ctx.device.createCommandEncoder();
  enc.copyBufferToBuffer(buffer, 0, staging, 0, size);
  ctx.device.queue.submit([enc.finish()]);
  await staging.mapAsync(MAP_READ);
  const out = staging.getMappedRange().slice(0, bytes);
  staging.unmap();
  staging.destroy();
  return out;
}

function box(world: b2World, x: number, y: number, type = b2_dynamicBody, half = 0.5): b2Body {
  const def = new b2BodyDef();
  def.type = type;
  def.position.Set(x, y);
  const body = world.CreateBody(def);
  const shape = new b2PolygonShape();
  shape.SetAsBox(half, half);
  body.CreateFixture(shape, 1);
  return body;
}

describeGpu('GpuWorld: the world mirrored on the GPU', (ctx) => {
  it('maps bodies, fixtures and proxies (one per chain edge) to slots both ways', () => {
    const world = new b2World(new b2Vec2(0, -10));
    const ground = world.CreateBody(new b2BodyDef());
    const chain = new b2ChainShape();
    chain.CreateChain([new b2Vec2(-20, 0), new b2Vec2(-10, 1), new b2Vec2(0, 0), new b2Vec2(10, 2), new b2Vec2(20, 0)]);
    const chainFixture = ground.CreateFixture(chain, 0);
    const edge = new b2EdgeShape();
    edge.Set(new b2Vec2(-5, 5), new b2Vec2(5, 5));
    const edgeFixture = ground.CreateFixture(edge, 0);
    const body = box(world, 0, 3);
    const boxFixture = body.GetFixtureList()!;
    const circle = new b2CircleShape();
    circle.m_radius = 0.25;
    circle.m_p.Set(0.5, 0);
    const circleFixture = body.CreateFixture(circle, 1);

    const mirror = new GpuWorld(ctx, world);
    const stats = mirror.sync();
    expect(stats.bodies).toEqual({ live: 2, created: 2, released: 0 });
    expect(stats.fixtures.live).toBe(4);
    expect(stats.proxies.live).toBe(4 + 1 + 2);
    for (const b of [ground, body]) expect(mirror.bodyAt(mirror.bodySlot(b))).toBe(b);
    for (const f of [chainFixture, edgeFixture, circleFixture, boxFixture]) {
      expect(mirror.fixtureAt(mirror.fixtureSlot(f))).toBe(f);
    }
    const slots = new Set<number>();
    for (let child = 0; child < 4; ++child) {
      const slot = mirror.proxySlot(chainFixture, child);
      expect(mirror.proxyAt(slot)).toEqual({ fixture: chainFixture, childIndex: child });
      slots.add(slot);
    }
    slots.add(mirror.proxySlot(edgeFixture, 0));
    slots.add(mirror.proxySlot(circleFixture, 0));
    slots.add(mirror.proxySlot(boxFixture, 0));
    expect([...slots].sort((a, b) => a - b)).toEqual([0, 1, 2, 3, 4, 5, 6]);
    expect(mirror.proxySlot(chainFixture, 4)).toBe(-1);
    mirror.destroy();
  });

  it('two mirrors of one world each find every body, fixture and joint; a mirror destroyed gives its objects up to the next', () => {
    const world = new b2World(new b2Vec2(0, 0));
    const bodies = [0, 1, 2].map((i) => box(world, 3 * i, 0));
    const jd = new b2RevoluteJointDef();
    jd.Initialize(bodies[0], bodies[1], new b2Vec2(1.5, 0));
    const joint = world.CreateJoint(jd);
    const first = new GpuWorld(ctx, world);
    first.sync();
    // The second mirror sees objects the first has tagged, and keeps its own slots for them.
    const extra = box(world, 20, 0);
    const second = new GpuWorld(ctx, world);
    second.sync();
    first.sync();
    for (const mirror of [first, second]) {
      for (const b of [...bodies, extra]) {
        expect(mirror.bodyAt(mirror.bodySlot(b))).toBe(b);
        expect(mirror.fixtureAt(mirror.fixtureSlot(b.GetFixtureList()!))).toBe(b.GetFixtureList());
      }
      expect(mirror.jointAt(mirror.jointSlot(joint))).toBe(joint);
    }
    world.DestroyBody(bodies[2]);
    first.sync();
    second.sync();
    expect(first.bodySlot(bodies[2])).toBe(-1);
    expect(second.bodySlot(bodies[2])).toBe(-1);
    first.destroy();
    const third = new GpuWorld(ctx, world);
    third.sync();
    second.sync();
    for (const mirror of [second, third]) {
      for (const b of [bodies[0], bodies[1], extra]) expect(mirror.bodyAt(mirror.bodySlot(b))).toBe(b);
    }
    second.destroy();
    third.destroy();
  });

  it('releases the slots of destroyed objects and hands them to new ones, lowest first', () => {
    const world = new b2World(new b2Vec2(0, 0));
    const bodies = [0, 1, 2, 3].map((i) => box(world, 3 * i, 0));
    const mirror = new GpuWorld(ctx, world);
    mirror.sync();
    const slotOf = bodies.map((b) => mirror.bodySlot(b));
    const proxyOf = bodies.map((b) => mirror.proxySlot(b.GetFixtureList()!, 0));

    world.DestroyBody(bodies[2]);
    world.DestroyBody(bodies[0]);
    const after = mirror.sync();
    expect(after.bodies).toEqual({ live: 2, created: 0, released: 2 });
    expect(after.proxies.released).toBe(2);
    expect(mirror.bodyAt(slotOf[0])).toBe(null);
    expect(mirror.bodyAt(slotOf[2])).toBe(null);
    expect(mirror.proxyAt(proxyOf[0])).toBe(null);
    expect(mirror.bodyFlags.u32[slotOf[2]]).toBe(0);
    expect(mirror.proxyRef.u32[4 * proxyOf[2] + 3] & PROXY_LIVE).toBe(0);
    // survivors keep their slots
    expect(mirror.bodySlot(bodies[1])).toBe(slotOf[1]);
    expect(mirror.bodySlot(bodies[3])).toBe(slotOf[3]);

    const fresh = [box(world, 20, 0), box(world, 25, 0)];
    mirror.sync();
    const freshSlots = fresh.map((b) => mirror.bodySlot(b)).sort((a, b) => a - b);
    expect(freshSlots).toEqual([slotOf[0], slotOf[2]].sort((a, b) => a - b));
    const freshProxies = fresh.map((b) => mirror.proxySlot(b.GetFixtureList()!, 0)).sort((a, b) => a - b);
    expect(freshProxies).toEqual([proxyOf[0], proxyOf[2]].sort((a, b) => a - b));
    expect(mirror.bodySlotCount).toBe(4);

    // a destroyed fixture frees its proxy; an inactive body keeps its slot but loses its proxies
    const f = bodies[1].GetFixtureList()!;
    bodies[1].DestroyFixture(f);
    bodies[3].SetActive(false);
    const s = mirror.sync();
    expect(s.fixtures.released).toBe(1);
    expect(s.proxies.released).toBe(2);
    expect(mirror.bodySlot(bodies[3])).toBe(slotOf[3]);
    expect(mirror.proxySlot(bodies[3].GetFixtureList()!, 0)).toBe(-1);
    expect(mirror.liveProxyCount).toBe(2);
    bodies[3].SetActive(true);
    mirror.sync();
    expect(mirror.proxySlot(bodies[3].GetFixtureList()!, 0)).toBeGreaterThanOrEqual(0);
    expect(mirror.liveProxyCount).toBe(3);
    mirror.destroy();
  });

  it('uploads only what changed since the last sync', () => {
    const world = new b2World(new b2Vec2(0, 0));
    const bodies = Array.from({ length: 200 }, (_, i) => box(world, (i % 20) * 2, Math.floor(i / 20) * 2, b2_staticBody));
    const mirror = new GpuWorld(ctx, world);
    const first = mirror.sync();
    expect(first.upload.bytes).toBeGreaterThan(200 * 64);

    const idle = mirror.sync();
    expect(idle.upload).toEqual({ bytes: 0, writes: 0, elements: 0 });

    bodies[37].SetTransform(new b2Vec2(100, 100), 0.5);
    const moved = mirror.sync();
    // the body's transform, cell and sweep, and nothing else
    expect(moved.upload.elements).toBe(3);
    expect(moved.upload.writes).toBe(3);
    expect(moved.upload.bytes).toBe(16 + 8 + 32);

    const filter = new b2Filter();
    filter.categoryBits = 4;
    bodies[5].GetFixtureList()!.SetFilterData(filter);
    const filtered = mirror.sync();
    expect(filtered.upload.elements).toBe(1);
    expect(filtered.upload.bytes).toBe(8);

    bodies[9].SetType(b2_kinematicBody);
    const retyped = mirror.sync();
    // flags, proxyRef (body type bits), mass; the sweep is untouched here
    expect(retyped.upload.elements).toBeLessThanOrEqual(4);
    expect(mirror.proxyRef.u32[4 * mirror.proxySlot(bodies[9].GetFixtureList()!, 0) + 3] & 0xc).toBe(1 << 2);
    mirror.destroy();
  });

  it('packs a shape when its fixture is created, and again only after invalidateShape()', () => {
    const world = new b2World(new b2Vec2(0, 0));
    const body = box(world, 0, 0);
    const fixture = body.GetFixtureList()!;
    const mirror = new GpuWorld(ctx, world);
    mirror.sync();
    const slot = mirror.fixtureSlot(fixture);
    const offset = mirror.fixtureShape.u32[4 * slot + 1];
    const x0 = () => mirror.shapePool.f32[2 * offset];
    expect(x0()).toBe(-0.5);

    (fixture.m_shape as b2PolygonShape).SetAsBox(0.75, 0.25);
    const unseen = mirror.sync();
    expect(unseen.upload.elements).toBe(0);
    expect(x0()).toBe(-0.5);

    mirror.invalidateShape(fixture);
    const seen = mirror.sync();
    expect(x0()).toBe(-0.75);
    // the vertices and normals that changed (four vertices; the normals of a box stay), nothing else
    expect(seen.upload.elements).toBe(4);
    mirror.destroy();
  });

  it('clearForces zeroes every force and torque uploaded since the last clear, in the world and the mirror, and no other body', () => {
    const world = new b2World(new b2Vec2(0, -10));
    const bodies = Array.from({ length: 20 }, (_, i) => box(world, (i % 5) * 2, Math.floor(i / 5) * 2));
    // A force present at the first (full) sync, before the GPU owns the motion.
    bodies[0].ApplyForceToCenter(new b2Vec2(1, 2));
    const mirror = new GpuWorld(ctx, world);
    mirror.sync();
    mirror.gpuOwnsMotion = true;
    // A torque alone, a force applied in two syncs, and a force on a body created later.
    bodies[4].ApplyTorque(3);
    mirror.sync();
    bodies[9].ApplyForceToCenter(new b2Vec2(-4, 0));
    mirror.sync();
    bodies[9].ApplyForceToCenter(new b2Vec2(-4, 0));
    const late = box(world, 30, 0);
    late.ApplyForceToCenter(new b2Vec2(0, 7));
    mirror.sync();
    const force = (b: b2Body) => Array.from(mirror.bodyForce.f32.subarray(4 * mirror.bodySlot(b), 4 * mirror.bodySlot(b) + 3));
    expect(force(bodies[0])).toEqual([1, 2, 0]);
    expect(force(bodies[4])).toEqual([0, 0, 3]);
    expect(force(bodies[9])).toEqual([-8, 0, 0]);
    expect(force(late)).toEqual([0, 7, 0]);
    mirror.clearForces();
    for (const b of [...bodies, late]) {
      expect(b.m_force.x === 0 && b.m_force.y === 0 && b.m_torque === 0).toBe(true);
      expect(force(b)).toEqual([0, 0, 0]);
    }
    // The four cleared records are uploaded; a second clear finds nothing to do.
    expect(mirror.sync().upload.elements).toBe(4);
    mirror.clearForces();
    expect(mirror.sync().upload.elements).toBe(0);
    mirror.destroy();
  });

  it('once the GPU owns the motion, uploads only what the API changed (b2ChangeListener), and everything after a structural change', () => {
    const world = new b2World(new b2Vec2(0, -10));
    const bodies = Array.from({ length: 50 }, (_, i) => box(world, (i % 10) * 2, Math.floor(i / 10) * 2));
    const mirror = new GpuWorld(ctx, world);
    mirror.sync();
    mirror.gpuOwnsMotion = true;
    expect(mirror.sync().upload.elements).toBe(0);

    // A force: the body's force record, and its awake word (a force wakes the body, and the GPU
    // may have put it to sleep since the world's flag was read back); its motion stays the GPU's.
    bodies[3].ApplyForceToCenter(new b2Vec2(5, 0));
    const forced = mirror.sync();
    expect(forced.upload.elements).toBe(2);
    expect(mirror.bodyForce.f32[4 * mirror.bodySlot(bodies[3])]).toBe(5);
    expect(mirror.bodyAwake.u32[mirror.bodySlot(bodies[3])]).toBe(1);

    // clearForces (b2World::ClearForces for the stepper) zeroes it in the world and on the GPU.
    mirror.clearForces();
    expect(bodies[3].m_force.x).toBe(0);
    expect(mirror.sync().upload.elements).toBe(1);
    expect(mirror.bodyForce.f32[4 * mirror.bodySlot(bodies[3])]).toBe(0);

    // A velocity set through the API overrides the GPU's motion for that body: cell, xf, sweep,
    // velocity, and it wakes the body.
    bodies[7].SetLinearVelocity(new b2Vec2(0, 3));
    const moved = mirror.sync();
    expect(moved.upload.elements).toBe(5);
    expect(mirror.bodyVel.f32[4 * mirror.bodySlot(bodies[7]) + 1]).toBe(3);

    // A fixture's material.
    bodies[9].GetFixtureList()!.SetFriction(0.25);
    expect(mirror.sync().upload.elements).toBe(1);
    expect(mirror.fixtureMaterial.f32[4 * mirror.fixtureSlot(bodies[9].GetFixtureList()!)]).toBe(0.25);

    // A field written directly is not reported, so not seen until the next structural change.
    bodies[11].m_linearDamping = 0.5;
    expect(mirror.sync().upload.elements).toBe(0);
    const added = box(world, 100, 0);
    const full = mirror.sync();
    expect(full.bodies.created).toBe(1);
    expect(mirror.bodyParams.f32[4 * mirror.bodySlot(bodies[11])]).toBe(0.5);
    expect(mirror.bodySlot(added)).toBeGreaterThanOrEqual(0);
    mirror.destroy();
    expect(world.m_changeListener).toBeNull();
  });

  it('holds on the GPU what the engine holds: transforms, cells, shapes, filters, joints', async () => {
    const world = new b2World(new b2Vec2(0, -10));
    const a = box(world, 1.5, 2.25);
    const b = box(world, 40.75, -70.5, b2_dynamicBody, 1);
    a.SetTransform(new b2Vec2(1.5, 2.25), 0.3);
    const jd = new b2RevoluteJointDef();
    jd.Initialize(a, b, new b2Vec2(10, 0));
    jd.collideConnected = false;
    world.CreateJoint(jd);
    const mirror = new GpuWorld(ctx, world);
    mirror.sync();

    const xf = new Float32Array(await readBack(ctx, mirror.bodyXf.buffer, 16 * mirror.bodySlotCount));
    const cell = new Int32Array(await readBack(ctx, mirror.bodyCell.buffer, 8 * mirror.bodySlotCount));
    const flags = new Uint32Array(await readBack(ctx, mirror.bodyFlags.buffer, 4 * mirror.bodySlotCount));
    for (const body of [a, b]) {
      const s = mirror.bodySlot(body);
      expect(cell[2 * s] * 32 + xf[4 * s]).toBeCloseTo(body.m_xf.p.x, 6);
      expect(cell[2 * s + 1] * 32 + xf[4 * s + 1]).toBeCloseTo(body.m_xf.p.y, 6);
      expect(xf[4 * s + 2]).toBe(Math.fround(body.m_xf.q.c));
      expect(xf[4 * s + 3]).toBe(Math.fround(body.m_xf.q.s));
      expect(Math.abs(xf[4 * s])).toBeLessThanOrEqual(16);
      expect(flags[s] >>> 0).toBe(((body.m_flags & 0xffff) | (2 << 16) | BODY_LIVE) >>> 0);
    }
    const shape = new Uint32Array(await readBack(ctx, mirror.fixtureShape.buffer, 16 * mirror.fixtureSlotCount));
    const pool = new Float32Array(await readBack(ctx, mirror.shapePool.buffer, 8 * mirror.shapePool.count));
    const fs = mirror.fixtureSlot(b.GetFixtureList()!);
    expect(shape[4 * fs] & 0xf).toBe(2);
    expect(shape[4 * fs] >>> 8).toBe(4);
    expect(shape[4 * fs + 2]).toBe(mirror.bodySlot(b));
    expect(new Float32Array(shape.buffer)[4 * fs + 3]).toBe(Math.fround(b.GetFixtureList()!.m_shape.m_radius));
    const offset = shape[4 * fs + 1];
    const poly = b.GetFixtureList()!.m_shape as b2PolygonShape;
    for (let i = 0; i < 4; ++i) {
      expect(pool[2 * (offset + i)]).toBe(Math.fround(poly.m_vertices[i].x));
      expect(pool[2 * (offset + 4 + i) + 1]).toBe(Math.fround(poly.m_normals[i].y));
    }
    const range = new Uint32Array(await readBack(ctx, mirror.jointRange.buffer, 8 * mirror.bodySlotCount));
    const list = new Uint32Array(await readBack(ctx, mirror.jointList.buffer, 4 * 2));
    const sa = mirror.bodySlot(a);
    const sb = mirror.bodySlot(b);
    expect(range[2 * sa + 1]).toBe(1);
    expect(list[range[2 * sa]]).toBe(sb);
    expect(list[range[2 * sb]]).toBe(sa);
    expect(mirror.proxyRef.u32[4 * mirror.proxySlot(a.GetFixtureList()!, 0) + 3] & PROXY_JOINTED).toBe(PROXY_JOINTED);
    mirror.destroy();
  });

  it('grows its buffers geometrically and keeps their contents', async () => {
    const world = new b2World(new b2Vec2(0, 0));
    const mirror = new GpuWorld(ctx, world);
    const bodies: b2Body[] = [];
    const capacities = new Set<number>();
    for (let round = 0; round < 5; ++round) {
      for (let i = 0; i < 150; ++i) bodies.push(box(world, bodies.length * 1.5, 0));
      mirror.sync();
      capacities.add(mirror.bodyXf.capacity);
    }
    expect(mirror.bodyXf.capacity).toBe(1024);
    expect([...capacities].every((c) => Math.log2(c) % 1 === 0)).toBe(true);
    const xf = new Float32Array(await readBack(ctx, mirror.bodyXf.buffer, 16 * mirror.bodySlotCount));
    const cell = new Int32Array(await readBack(ctx, mirror.bodyCell.buffer, 8 * mirror.bodySlotCount));
    for (const body of bodies) {
      const s = mirror.bodySlot(body);
      expect(cell[2 * s] * 32 + xf[4 * s]).toBeCloseTo(body.m_xf.p.x, 5);
    }
    mirror.destroy();
  });

  it('keeps positions to 1e-6 m and AABBs to 0.5 ulp at x = 5000 m', async () => {
    const world = new b2World(new b2Vec2(0, 0));
    const bodies: b2Body[] = [];
    for (let i = 0; i < 20; ++i) {
      const b = box(world, 5000.123456789 + i * 0.37, -4999.87654321 - i * 0.11, b2_dynamicBody, 0.25 + 0.05 * i);
      b.SetTransform(b.GetPosition(), 0.1 * i);
      bodies.push(b);
    }
    const mirror = new GpuWorld(ctx, world);
    mirror.sync();
    const broadPhase = new GpuBroadPhase(ctx);
    await broadPhase.update(mirror);
    const aabbs = await broadPhase.readAABBs();
    const aabb = new b2AABB();
    let worstPosition = 0;
    let worstAabb = 0;
    for (const body of bodies) {
      const p = mirror.gpuBodyPosition(mirror.bodySlot(body));
      worstPosition = Math.max(worstPosition, Math.abs(p.x - body.m_xf.p.x), Math.abs(p.y - body.m_xf.p.y));
      const f = body.GetFixtureList()!;
      f.m_shape.ComputeAABB(aabb, body.m_xf, 0);
      const slot = mirror.proxySlot(f, 0);
      const exact = [
        aabb.lowerBound.x - b2_aabbExtension,
        aabb.lowerBound.y - b2_aabbExtension,
        aabb.upperBound.x + b2_aabbExtension,
        aabb.upperBound.y + b2_aabbExtension,
      ];
      for (let k = 0; k < 4; ++k) worstAabb = Math.max(worstAabb, Math.abs(aabbs[4 * slot + k] - exact[k]));
    }
    // positions: cell + float32 offset within half a cell (16 m): 2^-20 m
    expect(worstPosition).toBeLessThan(1e-6);
    // AABB coordinates are float32 world coordinates: half an ulp of 5000 (2^-12) plus the local
    // rounding (about 1e-6)
    expect(worstAabb).toBeLessThan(2 ** -12 + 4e-6);
    // a plain float32 position would have lost up to 2.4e-4 m
    expect(Math.abs(Math.fround(5000.123456789) - 5000.123456789)).toBeGreaterThan(1e-5);
    broadPhase.destroy();
    mirror.destroy();
  });

  it('computes AABBs relative to a chosen world origin, exactly enough far from zero', async () => {
    const world = new b2World(new b2Vec2(0, 0));
    const body = box(world, 5000.123456789, 3000.5);
    const mirror = new GpuWorld(ctx, world, { origin: { x: 5000, y: 3000 } });
    mirror.sync();
    const broadPhase = new GpuBroadPhase(ctx);
    await broadPhase.update(mirror);
    const aabbs = await broadPhase.readAABBs();
    const slot = mirror.proxySlot(body.GetFixtureList()!, 0);
    const originX = mirror.originCell[0] * mirror.cellSize;
    expect(Math.abs(originX + aabbs[4 * slot] - (5000.123456789 - 0.5 - 0.1 - 0.01))).toBeLessThan(2e-6);
    broadPhase.destroy();
    mirror.destroy();
  });

  it('tells when the world has a contact filter the GPU cannot run', () => {
    const world = new b2World(new b2Vec2(0, 0));
    const mirror = new GpuWorld(ctx, world);
    mirror.sync();
    expect(mirror.usesCustomContactFilter).toBe(false);
    class OnlyEven extends b2ContactFilter {
      override ShouldCollide(): boolean {
        return false;
      }
    }
    world.SetContactFilter(new OnlyEven());
    mirror.sync();
    expect(mirror.usesCustomContactFilter).toBe(true);
    world.SetContactFilter(new b2ContactFilter());
    mirror.sync();
    expect(mirror.usesCustomContactFilter).toBe(false);
    mirror.destroy();
  });

  it('compacts the shape pool after many fixtures come and go, AABBs still right', async () => {
    const world = new b2World(new b2Vec2(0, 0));
    const body = box(world, 0, 0);
    const mirror = new GpuWorld(ctx, world);
    const broadPhase = new GpuBroadPhase(ctx);
    for (let round = 0; round < 6; ++round) {
      const fixtures = [];
      for (let i = 0; i < 400; ++i) {
        const chain = new b2ChainShape();
        const n = 3 + ((round * 7 + i) % 9);
        chain.CreateChain(Array.from({ length: n }, (_, k) => new b2Vec2(k, Math.sin(k + i))));
        const fd = new b2FixtureDef();
        fd.shape = chain;
        fixtures.push(body.CreateFixture(fd));
      }
      mirror.sync();
      for (const f of fixtures.slice(0, 390)) body.DestroyFixture(f);
    }
    mirror.sync();
    expect(mirror.shapePool.count).toBeLessThan(2 * 4096 + 10 * 20 + 4096);
    await broadPhase.update(mirror);
    const aabbs = await broadPhase.readAABBs();
    const aabb = new b2AABB();
    for (let f = body.GetFixtureList(); f; f = f.GetNext()) {
      for (let child = 0; child < f.m_proxyCount; ++child) {
        f.m_shape.ComputeAABB(aabb, body.m_xf, child);
        const slot = mirror.proxySlot(f, child);
        expect(aabbs[4 * slot]).toBeCloseTo(aabb.lowerBound.x - 0.1, 5);
        expect(aabbs[4 * slot + 3]).toBeCloseTo(aabb.upperBound.y + 0.1, 5);
      }
    }
    broadPhase.destroy();
    mirror.destroy();
  });
});
