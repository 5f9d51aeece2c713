/*
 * An accuracy target (b2World.SetAccuracyTarget, src/dynamics/b2AccuracyTarget.ts) on the WebGPU
 * backend: the chosen iterations reach the GPU's step, the ladder ends at its last rung without
 * sub-steps, the joint error is measured at the synchronisations (lagging the steps by the
 * read-back), and penetration, whose contacts stay on the GPU, is measured there
 * (WebGPUBackend.GetPenetration) and moves the rung: a target on the study's pyramid is met, the
 * same way on every run.
 */

import { expect, it } from 'vitest';
import * as b2 from '../../src/index';
import type { b2World } from '../../src/dynamics/b2World';
import type { b2Accuracy } from '../../src/dynamics/b2AccuracyTarget';
import { WebGPUBackend } from '../../src-gpu/backend/backend';
import { buildScene } from '../../bench/accuracy/scenes.mjs';
import { describeGpu } from './support';

const DT = 1 / 60;

/** The iterations of every step the backend's stepper takes from now on ("vi/pi"). */
function recordIterations(backend: WebGPUBackend): string[] {
  const stepper = backend.stepper!;
  const seen: string[] = [];
  const step = stepper.step.bind(stepper);
  stepper.step = ((dt: number, vi: number, pi: number, options?: Parameters<typeof step>[3]) => {
    seen.push(`${vi}/${pi}`);
    return step(dt, vi, pi, options);
  }) as typeof stepper.step;
  return seen;
}

describeGpu('an accuracy target on the WebGPU backend', (ctx) => {
  it('steps the GPU at the chosen iterations and measures the joint error of each synchronisation', async () => {
    const world = buildScene(b2, 'chain').world as b2World;
    const backend = await WebGPUBackend.create({ context: ctx });
    await world.SetBackend(backend);
    // The study's rung for 0.05 m is 8/3 in 2 sub-steps; on a backend the ladder ends at 16/6.
    world.SetAccuracyTarget({ jointError: 0.05, penetration: 0.02 });
    const seen = recordIterations(backend);
    for (let i = 0; i < 30; ++i) await world.StepAsync(DT, 8, 3);
    const a = world.GetAccuracy()!;
    expect(seen.length).toBe(30);
    expect(seen[0]).toBe('16/6');
    expect(a.substeps).toBe(1);
    expect(a.measured.jointError).not.toBeNull();
    expect(a.measured.jointError!).toBeLessThan(0.05);
    // The chain's links touch nothing.
    expect(a.measured.penetration).toBe(0);
    expect(a.reason).toMatch(/penetration 0 m within 0\.02 m/);
    // Each step's measures read the synchronisation before it (StepAsync synchronises after its step).
    expect(a.steps).toBe(30);
    await world.SetBackend(null);
  }, 120_000);

  /** The pyramid under a penetration target of 0.02 m for `steps` StepAsync calls: the iterations each GPU step ran, and the report. */
  async function pyramidRun(steps: number): Promise<{ seen: string[]; accuracy: b2Accuracy; bits: number[] }> {
    const world = buildScene(b2, 'pyramid').world as b2World;
    const backend = await WebGPUBackend.create({ context: ctx });
    await world.SetBackend(backend);
    world.SetAccuracyTarget({ penetration: 0.02 });
    const seen = recordIterations(backend);
    const bits: number[] = [];
    for (let i = 0; i < steps; ++i) {
      await world.StepAsync(DT, 8, 3);
      bits.push(new Uint32Array(new Float32Array([world.GetAccuracy()!.measured.penetration!]).buffer)[0]);
    }
    const accuracy = world.GetAccuracy()!;
    await world.SetBackend(null);
    return { seen, accuracy, bits };
  }

  it("meets a penetration target on the study's pyramid from the GPU's measure, the same way on every run", async () => {
    const a = await pyramidRun(100);
    // The study's rung for 0.02 m is 2/1; there the skins' starting overlap does not fall, so the
    // GPU's measure moves the rung up, and the target is met at 4/2.
    expect(a.seen[0]).toBe('2/1');
    expect(a.accuracy.changes).toBeGreaterThan(0);
    expect([a.accuracy.velocityIterations, a.accuracy.positionIterations, a.accuracy.substeps]).toEqual([4, 2, 1]);
    expect(a.seen.at(-1)).toBe('4/2');
    expect(a.accuracy.reason).toMatch(
      /^4\/2 iterations; up from 2\/1 iterations at step \d+: penetration 0\.0\d+ m over the target 0\.02 m; target met: penetration 0\.0\d+ m within 0\.02 m$/,
    );
    expect(a.accuracy.met).toBe(true);
    expect(a.accuracy.measured.penetration!).toBeGreaterThan(0.005);
    expect(a.accuracy.measured.penetration!).toBeLessThan(0.02);
    expect(a.accuracy.worst.penetration!).toBeGreaterThan(0.02);
    const b = await pyramidRun(100);
    expect(b.seen).toEqual(a.seen);
    expect(b.bits).toEqual(a.bits);
    expect(b.accuracy).toEqual(a.accuracy);
  }, 300_000);
});
