/*
 * An accuracy target (b2World.SetAccuracyTarget, src/dynamics/b2AccuracyTarget.ts) on the WebGPU
 * backend: the chosen iterations reach the GPU's step, the ladder ends at its last rung without
 * sub-steps, the joint error is measured at the synchronisations (lagging the steps by the
 * read-back), and penetration, whose contacts stay on the GPU, is not measured.
 */

import { expect, it } from 'vitest';
import * as b2 from '../../src/index';
import type { b2World } from '../../src/dynamics/b2World';
import { WebGPUBackend } from '../../src-gpu/backend/backend';
import { buildScene } from '../../bench/accuracy/scenes.mjs';
import { describeGpu } from './support';

const DT = 1 / 60;

describeGpu('an accuracy target on the WebGPU backend', (ctx) => {
  it('steps the GPU at the chosen iterations and measures the joint error of each synchronisation', async () => {
    const world = buildScene(b2, 'chain').world as b2World;
    const backend = await WebGPUBackend.create({ context: ctx });
    await world.SetBackend(backend);
    // The study's rung for 0.05 m is 8/3 in 2 sub-steps; on a backend the ladder ends at 16/6.
    world.SetAccuracyTarget({ jointError: 0.05, penetration: 0.02 });
    const stepper = backend.stepper!;
    const seen: string[] = [];
    const step = stepper.step.bind(stepper);
    stepper.step = ((dt: number, vi: number, pi: number, options?: Parameters<typeof step>[3]) => {
      seen.push(`${vi}/${pi}`);
      return step(dt, vi, pi, options);
    }) as typeof stepper.step;
    for (let i = 0; i < 30; ++i) await world.StepAsync(DT, 8, 3);
    const a = world.GetAccuracy()!;
    expect(seen.length).toBe(30);
    expect(seen[0]).toBe('16/6');
    expect(a.substeps).toBe(1);
    expect(a.measured.jointError).not.toBeNull();
    expect(a.measured.jointError!).toBeLessThan(0.05);
    expect(a.measured.penetration).toBeNull();
    expect(a.reason).toMatch(/penetration not measured here \(the backend keeps the contacts\)/);
    // Each step's measures read the synchronisation before it (StepAsync synchronises after its step).
    expect(a.steps).toBe(30);
    await world.SetBackend(null);
  }, 120_000);
});
