/*
 * AutoBackend (src-gpu/backend/auto.ts, docs/GPU.md "Choosing the backend automatically"): the
 * choice and its reason (crossover, software adapter, no adapter, PreSolve), the engine's own
 * trajectory while it steps, switching both ways with hysteresis as bodies come and go, the
 * fall-back after a lost device, the calibration's measurement and cache, and bad options.
 */

import { describe, expect, it } from 'vitest';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import { b2World } from '../../src/dynamics/b2World';
import { b2WorldBackendEngineFunctions } from '../../src/dynamics/b2WorldBackend';
import { b2ContactListener } from '../../src/dynamics/b2WorldCallbacks';
import { AUTO_DOWN, AUTO_UP, AutoBackend } from '../../src-gpu/backend/auto';
import type { AutoChoice } from '../../src-gpu/backend/auto';
import { calibrationFor } from '../../src-gpu/backend/calibration';
import { requestGpu } from '../../src-gpu/device/device';
import { describeGpu } from './support';

const DT = 1 / 60;

/** A GPU object without an adapter, as a browser with WebGPU blocklisted gives. */
const noAdapter = { requestAdapter: async () => null } as unknown as GPU;

/** Ground and `n - 1` boxes in a grid above it, apart from each other: `n` bodies. */
function boxWorld(n: number): { world: b2World; boxes: b2Body[] } {
  const world = new b2World(new b2Vec2(0, -10));
  const ground = new b2PolygonShape();
  ground.SetAsBox(100, 1, new b2Vec2(0, -1), 0);
  world.CreateBody(new b2BodyDef()).CreateFixture(ground, 0);
  const shape = new b2PolygonShape();
  shape.SetAsBox(0.4, 0.4);
  const def = new b2BodyDef();
  def.type = b2_dynamicBody;
  const boxes: b2Body[] = [];
  for (let i = 0; i < n - 1; ++i) {
    def.position.Set(-60 + 1.5 * (i % 80), 0.5 + 1.5 * Math.floor(i / 80));
    const body = world.CreateBody(def);
    body.CreateFixture(shape, 1);
    boxes.push(body);
  }
  return { world, boxes };
}

function positions(bodies: b2Body[]): number[] {
  return bodies.flatMap((b) => [b.GetPosition().x, b.GetPosition().y, b.GetAngle()]);
}

class PreSolveListener extends b2ContactListener {
  calls = 0;
  override PreSolve(): void {
    this.calls++;
  }
}

describe('AutoBackend without WebGPU', () => {
  it('with no WebGPU adapter picks JavaScript for good and says so; create() does not fail', async () => {
    const auto = await AutoBackend.create({ gpu: noAdapter, calibration: { crossoverBodies: 10, source: 'stub' } });
    const { world } = boxWorld(100);
    await world.SetBackend(auto);
    await world.StepAsync(DT, 8, 3);
    expect(auto.ctx).toBeNull();
    expect(auto.choice.backend).toBe('js');
    expect(auto.choice.reason).toMatch(/^js: no WebGPU adapter/);
    expect((world.GetBackend() as AutoBackend).choice).toEqual(auto.choice);
  });

  it('steps on the engine bit for bit as a world without a backend: 60 steps give exactly the same positions', async () => {
    const plain = boxWorld(30);
    const auto = boxWorld(30);
    await auto.world.SetBackend(await AutoBackend.create({ gpu: noAdapter }));
    for (let i = 0; i < 60; ++i) {
      plain.world.Step(DT, 8, 3);
      if (i % 2 === 0) auto.world.Step(DT, 8, 3);
      else await auto.world.StepAsync(DT, 8, 3);
      if (i % 5 === 0) await auto.world.Synchronize();
    }
    expect(positions(auto.boxes)).toEqual(positions(plain.boxes));
    expect(auto.world.GetContactCount()).toBe(plain.world.GetContactCount());
    await auto.world.SetBackend(null);
    plain.world.Step(DT, 8, 3);
    auto.world.Step(DT, 8, 3);
    expect(positions(auto.boxes)).toEqual(positions(plain.boxes));
  });

  it('rejects bad options naming the option and the rule', async () => {
    await expect(AutoBackend.create({ calibration: { crossoverBodies: 0, source: 'x' } })).rejects.toThrow(
      /options\.calibration\.crossoverBodies must be a number > 0/,
    );
    await expect(AutoBackend.create({ calibration: { crossoverBodies: NaN, source: 'x' } })).rejects.toThrow(/crossoverBodies must be a number > 0.*NaN/);
    await expect(AutoBackend.create({ calibration: { crossoverBodies: 10, source: '' } })).rejects.toThrow(
      /options\.calibration\.source must be a non-empty string/,
    );
    await expect(AutoBackend.create({ calibration: null as never })).rejects.toThrow(/options\.calibration must be an object/);
    await expect(AutoBackend.create({ onChange: 3 as never })).rejects.toThrow(/options\.onChange must be a function/);
    await expect(AutoBackend.create({ context: {} as never })).rejects.toThrow(/options\.context must be a GpuContext/);
    await expect(AutoBackend.create(null as never)).rejects.toThrow(/options must be an object/);
  });
});

describeGpu('AutoBackend on WebGPU (SwiftShader)', (ctx) => {
  it('a 100-body world picks JavaScript and explains: below a stubbed crossover of 1,000 bodies', async () => {
    const auto = await AutoBackend.create({ context: ctx, calibration: { crossoverBodies: 1000, source: 'test stub' } });
    const { world } = boxWorld(100);
    await world.SetBackend(auto);
    await world.StepAsync(DT, 8, 3);
    expect(auto.active).toBeNull();
    expect(auto.choice).toEqual({ backend: 'js', reason: 'js: 100 bodies, below the crossover on this adapter (1,000 bodies; test stub)' });
  });

  it('a 100-body world picks JavaScript on the software adapter without a calibration, saying the adapter is software', async () => {
    expect(ctx.adapterInfo.software).toBe(true);
    const auto = await AutoBackend.create({ context: ctx });
    const { world } = boxWorld(100);
    await world.SetBackend(auto);
    await world.StepAsync(DT, 8, 3);
    expect(auto.choice.backend).toBe('js');
    expect(auto.choice.reason).toMatch(/^js: the adapter is software \(.+\): never picked for speed$/);
  });

  it('any world on a software adapter picks JavaScript with the software reason, even 20,000 bodies, and never calibrates', async () => {
    const auto = await AutoBackend.create({ context: ctx });
    const { world } = boxWorld(20000);
    await world.SetBackend(auto);
    world.Step(DT, 8, 3);
    await world.Synchronize();
    await auto.settle();
    expect(auto.active).toBeNull();
    expect(auto.crossover).toBeNull();
    expect(auto.choice.reason).toMatch(/^js: the adapter is software/);
    expect(world.GetContactCount()).toBeGreaterThan(0);
  });

  it(`goes to WebGPU above the crossover x ${AUTO_UP}, back to JavaScript below x ${AUTO_DOWN} at the next Synchronize, never flipping in between; bodies carry over`, async () => {
    const changes: AutoChoice[] = [];
    const auto = await AutoBackend.create({ context: ctx, calibration: { crossoverBodies: 500, source: 'test stub' }, onChange: (c) => changes.push(c) });
    const { world, boxes } = boxWorld(1000);
    await world.SetBackend(auto);
    expect(auto.choice.backend).toBe('webgpu');
    expect(auto.choice.reason).toBe('webgpu: 1,000 bodies, above the crossover on this adapter (500 bodies; test stub)');
    expect(auto.active).not.toBeNull();
    for (let i = 0; i < 3; ++i) world.Step(DT, 8, 3);
    await world.Synchronize();
    // The GPU owns the contacts while it steps the world.
    expect(world.GetContactCount()).toBe(0);
    expect(auto.active!.readbacks).toBe(1);

    // 1000 -> 450: within the band (400..625), stays on the GPU.
    const kept = boxes.slice(0, 449);
    for (const b of boxes.slice(449)) world.DestroyBody(b);
    expect(world.GetBodyCount()).toBe(450);
    world.Step(DT, 8, 3);
    await world.Synchronize();
    expect(auto.choice.backend).toBe('webgpu');
    expect(auto.choice.reason).toMatch(/^webgpu: 450 bodies, not below 0\.8 x the crossover/);
    expect(changes).toEqual([]);

    // 450 -> 399: the next Step notes it, the next Synchronize switches.
    for (const b of kept.splice(398)) world.DestroyBody(b);
    expect(world.GetBodyCount()).toBe(399);
    world.Step(DT, 8, 3);
    expect(auto.choice.backend).toBe('webgpu');
    expect(auto.choice.reason).toMatch(/switching at the next Synchronize$/);
    await world.Synchronize();
    const handedBack = positions(kept);
    expect(auto.choice.backend).toBe('js');
    expect(auto.active).toBeNull();
    expect(changes.map((c) => c.backend)).toEqual(['js']);
    expect(changes[0].reason).toBe('js: 399 bodies, below the crossover on this adapter (500 bodies; test stub)');
    // The engine continues from the GPU's state: contacts rebuilt, no body lost, a step moves little.
    expect(world.GetBodyCount()).toBe(399);
    world.Step(DT, 8, 3);
    const moved = positions(kept).map((v, i) => Math.abs(v - handedBack[i]));
    expect(Math.max(...moved)).toBeLessThan(0.1);
    expect(world.GetContactCount()).toBeGreaterThan(0);

    // 399 -> 600: within the band, stays on JavaScript.
    const shape = new b2PolygonShape();
    shape.SetAsBox(0.4, 0.4);
    const def = new b2BodyDef();
    def.type = b2_dynamicBody;
    const grow = (n: number): void => {
      while (world.GetBodyCount() < n) {
        const i = world.GetBodyCount();
        def.position.Set(-60 + 1.5 * (i % 80), 20 + 1.5 * Math.floor(i / 80));
        const body = world.CreateBody(def);
        body.CreateFixture(shape, 1);
        kept.push(body);
      }
    };
    grow(600);
    world.Step(DT, 8, 3);
    await world.Synchronize();
    expect(auto.choice.backend).toBe('js');
    expect(auto.choice.reason).toMatch(/^js: 600 bodies, not above 1\.25 x the crossover/);

    // 600 -> 700: back to the GPU at the next Synchronize, positions carried exactly.
    grow(700);
    world.Step(DT, 8, 3);
    expect(auto.active).toBeNull();
    const before = positions(kept);
    await world.Synchronize();
    expect(auto.choice.backend).toBe('webgpu');
    expect(positions(kept)).toEqual(before);
    await world.StepAsync(DT, 8, 3);
    expect(changes.map((c) => c.backend)).toEqual(['js', 'webgpu']);
    expect(world.GetBodyCount()).toBe(700);
    for (const b of kept) {
      expect(Number.isFinite(b.GetPosition().y)).toBe(true);
      expect(b.GetPosition().y).toBeGreaterThan(0);
    }
    await world.SetBackend(null);
    expect(world.GetBackend()).toBeNull();
    expect(world.GetBodyCount()).toBe(700);
  });

  it('a PreSolve listener forces JavaScript, with that reason; one set while on the GPU moves the world at the next Synchronize, its step taken there', async () => {
    const calibration = { crossoverBodies: 10, source: 'test stub' };
    const first = boxWorld(50);
    const listener = new PreSolveListener();
    first.world.SetContactListener(listener);
    const auto = await AutoBackend.create({ context: ctx, calibration });
    await first.world.SetBackend(auto);
    expect(auto.choice).toEqual({ backend: 'js', reason: 'js: the contact listener has PreSolve, which the GPU cannot run' });

    const second = boxWorld(50);
    const changes: AutoChoice[] = [];
    const later = await AutoBackend.create({ context: ctx, calibration, onChange: (c) => changes.push(c) });
    await second.world.SetBackend(later);
    expect(later.choice.backend).toBe('webgpu');
    for (let i = 0; i < 30; ++i) await second.world.StepAsync(DT, 8, 3);
    second.world.SetContactListener(listener);
    second.world.Step(DT, 8, 3);
    expect(listener.calls).toBe(0);
    await second.world.Synchronize();
    expect(later.choice.backend).toBe('js');
    expect(changes).toEqual([{ backend: 'js', reason: 'js: the contact listener has PreSolve, which the GPU cannot run' }]);
    // The kept step ran on the engine, the boxes resting on the ground.
    expect(listener.calls).toBeGreaterThan(0);
  });

  it('a lost device while the GPU steps the world: the next Synchronize carries on with JavaScript from the last synchronisation for every body, read or not, says why, calls onChange, loses no body', async () => {
    const lossCtx = await requestGpu();
    const changes: AutoChoice[] = [];
    const auto = await AutoBackend.create({ context: lossCtx, calibration: { crossoverBodies: 20, source: 'test stub' }, onChange: (c) => changes.push(c) });
    const { world, boxes } = boxWorld(60);
    // Falling from 10 m up: half a second later every box is more than a metre below where it was attached.
    for (const b of boxes) b.SetTransform(new b2Vec2(b.GetPosition().x, b.GetPosition().y + 10), 0);
    await world.SetBackend(auto);
    expect(auto.choice.backend).toBe('webgpu');
    for (let i = 0; i < 30; ++i) await world.StepAsync(DT, 8, 3);
    // The last synchronisation's state, taken in bulk: no body has fetched it.
    const inner = auto.active!;
    const slots = new Float64Array(4 * inner.stepper!.mirror.bodySlotCount);
    await inner.readTransforms(slots);
    const synced = boxes.flatMap((b) => [slots[4 * inner.bodySlot(b)], slots[4 * inner.bodySlot(b) + 1]]);
    expect(boxes.every((b) => b.m_stateEpoch !== world.m_stateEpoch)).toBe(true);

    lossCtx.device.destroy();
    await lossCtx.lost;
    world.Step(DT, 8, 3);
    await world.Synchronize();
    expect(auto.choice.backend).toBe('js');
    expect(auto.choice.reason).toMatch(/^js: the WebGPU device was lost \(destroyed.*\); carried on from the last synchronisation$/);
    expect(changes.map((c) => c.backend)).toEqual(['js']);
    expect(world.GetBodyCount()).toBe(60);
    // The step taken after the loss ran on the engine, from the last synchronised state.
    const after = boxes.flatMap((b) => [b.GetPosition().x, b.GetPosition().y]);
    const moved = after.map((v, i) => Math.abs(v - synced[i]));
    expect(Math.max(...moved)).toBeLessThan(0.1);
    expect(after).not.toEqual(synced);
    for (let i = 0; i < 5; ++i) await world.StepAsync(DT, 8, 3);
    expect(auto.choice.backend).toBe('js');
    await world.SetBackend(null);
    expect(world.GetBodyCount()).toBe(60);
  });

  it('the calibration measures a crossover on the device (a number > 0, Infinity when the GPU never catches up) and is cached per adapter', async () => {
    const first = calibrationFor(ctx, b2WorldBackendEngineFunctions);
    expect(calibrationFor(ctx, b2WorldBackendEngineFunctions)).toBe(first);
    const measured = await first;
    expect(measured.crossoverBodies).toBeGreaterThan(0);
    expect(measured.source).toMatch(/^measured: JavaScript .* ms \+ .* µs a body, WebGPU .* \(211 and 2101 bodies\)$/);
    // A second AutoBackend on this adapter, told to measure (a hardware adapter would be), takes the cached one.
    expect(await calibrationFor(ctx, b2WorldBackendEngineFunctions)).toBe(measured);
  }, 60_000);
});
