/*
 * GpuStepper (src-gpu/stepper.ts): stepping on the GPU as b2World::Step does, with the GPU as the
 * authority for body motion. Collision overflow reruns the solver with complete lists; 2.2.1's
 * position early exit stops the position passes on the GPU; new bodies and forces set in
 * JavaScript reach the GPU while existing bodies' motion is not overwritten; static bodies never
 * move, kinematic bodies move at their velocity, and with dt = 0 nothing moves.
 */

import { expect, it } from 'vitest';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody, b2_kinematicBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import { b2World } from '../../src/dynamics/b2World';
import { GpuStepper } from '../../src-gpu/stepper';
import { describeGpu } from './support';

const DT = 1 / 60;

function world(): { world: b2World; ground: b2Body } {
  const w = new b2World(new b2Vec2(0, -10));
  const ground = w.CreateBody(new b2BodyDef());
  const shape = new b2PolygonShape();
  shape.SetAsBox(20, 1, new b2Vec2(0, -1), 0);
  ground.CreateFixture(shape, 0);
  return { world: w, ground };
}

function box(w: b2World, x: number, y: number, type = b2_dynamicBody): b2Body {
  const def = new b2BodyDef();
  def.type = type;
  def.position.Set(x, y);
  const body = w.CreateBody(def);
  const shape = new b2PolygonShape();
  shape.SetAsBox(0.5, 0.5);
  body.CreateFixture(shape, 1);
  return body;
}

function pyramidWorld(): b2World {
  const { world: w } = world();
  for (let row = 0; row < 8; ++row) for (let i = 0; i < 8 - row; ++i) box(w, -4 + i + 0.5 * row + 0.5, 0.5 + row);
  return w;
}

function motion(w: b2World): number[] {
  const out: number[] = [];
  for (let b = w.m_bodyList; b; b = b.m_next) out.push(b.m_xf.p.x, b.m_xf.p.y, b.m_sweep.a, b.m_linearVelocity.x, b.m_linearVelocity.y, b.m_angularVelocity);
  return out;
}

describeGpu('GPU stepper', (ctx) => {
  it('reruns the solver with the collision passes after an overflow: the same bodies, bit for bit, as with room to spare', async () => {
    const roomy = pyramidWorld();
    const tight = pyramidWorld();
    const a = new GpuStepper(ctx, roomy);
    const b = new GpuStepper(ctx, tight, { broadPhase: { initialPairCapacity: 16 }, narrowPhase: { initialContactCapacity: 16 } });
    for (let i = 0; i < 10; ++i) {
      await a.step(DT, 8, 3);
      await b.step(DT, 8, 3);
    }
    expect(b.narrowPhase.contactRegrows).toBeGreaterThan(0);
    await a.readBodies();
    await b.readBodies();
    expect(motion(tight)).toEqual(motion(roomy));
    a.destroy();
    b.destroy();
  });

  it('steps without waiting (up to four steps in flight) to the same bits as waiting for each step', async () => {
    const waited = pyramidWorld();
    const queued = pyramidWorld();
    const a = new GpuStepper(ctx, waited);
    const b = new GpuStepper(ctx, queued);
    for (let i = 0; i < 12; ++i) {
      await a.step(DT, 8, 3);
      await b.step(DT, 8, 3, { wait: false });
    }
    await b.pipeline.settle();
    await a.readBodies();
    await b.readBodies();
    expect(motion(queued)).toEqual(motion(waited));
    a.destroy();
    b.destroy();
  });

  it('stops the position iterations once every separation is >= -3 b2_linearSlop, and runs them all while deeper', async () => {
    const { world: w } = world();
    const sunk = box(w, 0, 0.4);
    const stepper = new GpuStepper(ctx, w);
    await stepper.step(DT, 8, 3);
    // 10 cm into the ground: an iteration corrects at most b2_baumgarte x the separation.
    let state = await stepper.solver.readState();
    expect(state.positionIterations).toBe(3);
    expect(state.positionSolved).toBe(false);
    for (let i = 0; i < 60; ++i) await stepper.step(DT, 8, 3);
    state = await stepper.solver.readState();
    expect(state.positionIterations).toBe(1);
    expect(state.positionSolved).toBe(true);
    await stepper.readBodies();
    // Pushed out to separation -b2_linearSlop: 0.5 + two polygon skins (0.02) - 0.005.
    expect(sunk.m_xf.p.y).toBeCloseTo(0.515, 3);
    stepper.destroy();
  });

  it('keeps the GPU as the authority for motion, takes new bodies and forces from the world, clears forces after the step', async () => {
    const { world: w, ground } = world();
    const first = box(w, -3, 0.5);
    const stepper = new GpuStepper(ctx, w);
    for (let i = 0; i < 5; ++i) await stepper.step(DT, 8, 3);
    // The world's copy is stale until read back; a later sync must not push it to the GPU.
    first.m_xf.p.y = 50;
    const late = box(w, 3, 5);
    late.ApplyForceToCenter(new b2Vec2(600, 0));
    expect(late.m_force.x).toBe(600);
    await stepper.step(DT, 8, 3);
    expect(late.m_force.x).toBe(0);
    await stepper.readBodies();
    expect(first.m_xf.p.y).toBeGreaterThan(0.49);
    expect(first.m_xf.p.y).toBeLessThan(0.52);
    // The late box fell one step from rest and was pushed along x: v = h (g, F / m).
    expect(late.m_linearVelocity.y).toBeCloseTo(-10 * DT, 5);
    expect(late.m_linearVelocity.x).toBeCloseTo((600 / late.m_mass) * DT, 4);
    expect(ground.m_xf.p.x).toBe(0);
    expect(ground.m_xf.p.y).toBe(0);
    stepper.destroy();
  });

  it('moves kinematic bodies at their velocity, never static ones, and nothing with dt = 0', async () => {
    const { world: w, ground } = world();
    const k = box(w, 0, 5, b2_kinematicBody);
    k.SetLinearVelocity(new b2Vec2(1, 0));
    k.SetAngularVelocity(0.5);
    const d = box(w, 5, 3);
    const stepper = new GpuStepper(ctx, w);
    await stepper.step(0, 8, 3);
    await stepper.readBodies();
    expect([k.m_xf.p.x, d.m_xf.p.y, d.m_linearVelocity.y]).toEqual([0, 3, 0]);
    for (let i = 0; i < 30; ++i) await stepper.step(DT, 8, 3);
    await stepper.readBodies();
    expect(k.m_xf.p.x).toBeCloseTo(0.5, 5);
    expect(k.m_xf.p.y).toBeCloseTo(5, 6);
    expect(k.m_sweep.a).toBeCloseTo(0.25, 5);
    expect(k.m_linearVelocity.x).toBeCloseTo(1, 6);
    expect(ground.m_xf.p.y).toBe(0);
    expect(ground.m_sweep.a).toBe(0);
    stepper.destroy();
  });
});
