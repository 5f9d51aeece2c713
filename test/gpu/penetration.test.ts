/*
 * The GPU's penetration measure (shaders/solver/penetration.wgsl, WebGPUBackend.GetPenetration):
 * after each step it equals, to float32 rounding, the accuracy target's own measure
 * (penetrationOf, src/dynamics/b2AccuracyTarget.ts) on the host: the engine's contacts created and
 * collided (b2Contact.Create, Update) at the transforms the step started from, their points'
 * depths taken at the transforms it ended at, both read back from the GPU. 0 when nothing touches.
 */

import { expect, it } from 'vitest';
import * as b2 from '../../src/index';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { penetrationOf } from '../../src/dynamics/b2AccuracyTarget';
import { b2BodyDef, b2_dynamicBody, b2_staticBody } from '../../src/dynamics/b2Body';
import type { b2Fixture } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { b2Contact } from '../../src/dynamics/contacts/b2Contact';
import { WebGPUBackend } from '../../src-gpu/backend/backend';
import { buildScene } from '../../bench/accuracy/scenes.mjs';
import { describeGpu } from './support';

const DT = 1 / 60;
/** float32 positions within a cell, evaluated in float32 on the GPU and in float64 on the host. */
const TOLERANCE = 1e-5;

/**
 * The engine's contacts of every pair of non-sensor fixture children on two bodies (not both
 * static), A the lower proxy id as the engine's pair search orders them, collided now at the
 * bodies' transforms (the manifold and the touching flag), as a contact list.
 */
function contactsNow(world: b2World): b2Contact | null {
  world.PullState();
  const children: { fixture: b2Fixture; index: number }[] = [];
  for (let b = world.m_bodyList; b; b = b.m_next) {
    for (let f = b.m_fixtureList; f; f = f.m_next) {
      if (f.IsSensor()) continue;
      for (let i = 0; i < f.m_proxyCount; ++i) children.push({ fixture: f, index: i });
    }
  }
  children.sort((p, q) => p.fixture.m_proxies[p.index].proxyId - q.fixture.m_proxies[q.index].proxyId);
  let list: b2Contact | null = null;
  for (let i = 0; i < children.length; ++i) {
    for (let j = i + 1; j < children.length; ++j) {
      const a = children[i];
      const b = children[j];
      const bodyA = a.fixture.m_body;
      const bodyB = b.fixture.m_body;
      if (bodyA === bodyB || (bodyA.m_type === b2_staticBody && bodyB.m_type === b2_staticBody)) continue;
      const c = b2Contact.Create(a.fixture, a.index, b.fixture, b.index);
      if (c === null) continue;
      c.Update(null);
      c.m_next = list;
      list = c;
    }
  }
  return list;
}

/** Steps `world` on `backend` `steps` times, comparing the GPU's penetration with the host's after each; returns the GPU's. */
async function compareSteps(world: b2World, backend: WebGPUBackend, steps: number): Promise<number[]> {
  await world.SetBackend(backend);
  // The first call turns the measure on for the steps recorded after it.
  expect(backend.GetPenetration()).toBeNull();
  const measured: number[] = [];
  for (let i = 0; i < steps; ++i) {
    const contacts = contactsNow(world);
    await world.StepAsync(DT, 8, 3);
    world.PullState();
    const host = penetrationOf(contacts);
    const gpu = backend.GetPenetration();
    expect(gpu, `step ${i}`).not.toBeNull();
    expect(Math.abs(gpu! - host), `step ${i}: GPU ${gpu} m, host ${host} m`).toBeLessThan(TOLERANCE);
    measured.push(gpu!);
  }
  await world.SetBackend(null);
  return measured;
}

describeGpu('the GPU penetration measure', (ctx) => {
  it("equals the engine's measure on the host after each step of the accuracy study's pyramid", async () => {
    const world = buildScene(b2, 'pyramid').world as b2World;
    const backend = await WebGPUBackend.create({ context: ctx });
    expect(backend.GetPenetration()).toBeNull();
    const measured = await compareSteps(world, backend, 12);
    // The boxes are placed touching, so their skins overlap by 2 b2_polygonRadius at first.
    expect(measured[0]).toBeGreaterThan(0.015);
    expect(measured.at(-1)!).toBeGreaterThan(0.004);
  }, 120_000);

  it('equals it for circles and boxes on both sides of a cell boundary (x = 16 m with 32 m cells)', async () => {
    const world = new b2World(new b2Vec2(0, -10));
    world.SetAllowSleeping(false);
    const ground = world.CreateBody(new b2BodyDef());
    const floor = new b2PolygonShape();
    floor.SetAsBox(8, 0.5, new b2Vec2(16, -0.5), 0);
    ground.CreateFixture(floor, 0);
    const add = (x: number, y: number, shape: b2CircleShape | b2PolygonShape) => {
      const def = new b2BodyDef();
      def.type = b2_dynamicBody;
      def.position.Set(x, y);
      world.CreateBody(def).CreateFixture(shape, 1);
    };
    const ball = new b2CircleShape();
    ball.m_radius = 0.5;
    const box = new b2PolygonShape();
    box.SetAsBox(0.5, 0.5);
    // Circles on the ground, a circle on a circle and on a box, each pair straddling x = 16.
    add(15.55, 0.48, ball);
    add(16.45, 0.48, ball);
    add(15.55, 1.46, ball);
    add(17.5, 0.5, box);
    add(17.6, 1.48, ball);
    const backend = await WebGPUBackend.create({ context: ctx });
    const measured = await compareSteps(world, backend, 8);
    expect(Math.max(...measured)).toBeGreaterThan(0.01);
  }, 120_000);

  it('is 0 when nothing touches', async () => {
    const world = new b2World(new b2Vec2(0, 0));
    const box = new b2PolygonShape();
    box.SetAsBox(0.5, 0.5);
    for (let i = 0; i < 4; ++i) {
      const def = new b2BodyDef();
      def.type = b2_dynamicBody;
      def.position.Set(3 * i, 0);
      world.CreateBody(def).CreateFixture(box, 1);
    }
    const backend = await WebGPUBackend.create({ context: ctx });
    expect(await compareSteps(world, backend, 2)).toEqual([0, 0]);
  }, 60_000);
});
