/*
 * GpuPipeline records a step as GpuStage lists it: the broad phase's passes, then the narrow
 * phase's, then the solver's, each once and in that order (read from the step's timestamps, which
 * name every pass), and only the stages a step needs.
 */

import { expect, it } from 'vitest';
import { GpuStage, STAGE_PASS } from '../../src-gpu/pipeline';
import { GpuStepper } from '../../src-gpu/stepper';
import { loadGoldenScene } from '../support/scene';
import { describeGpu } from './support';

/** The broad phase's own passes (GpuStage.BroadPhase). */
const BROAD_PASSES = ['bounds', 'axis', 'sort', 'sweep', 'pairs'];

/** The pass names of stages `first` to `last`, in GpuStage order. */
function passes(first: GpuStage, last: GpuStage): string[] {
  const out: string[] = [];
  for (let stage = first; stage <= last; ++stage) {
    if (stage === GpuStage.BroadPhase) out.push(...BROAD_PASSES);
    else out.push(STAGE_PASS[stage]);
  }
  return out;
}

describeGpu('GPU pipeline', (ctx) => {
  it.skipIf(!ctx.timestamps)('records the passes of a step in GpuStage order, the solver after collision and time of impact only with continuous physics', async () => {
    const scene = loadGoldenScene('pyramid');
    const world = scene.world;
    world.SetContinuousPhysics(true);
    const stepper = new GpuStepper(ctx, world);
    try {
      const named = (gpuTime: Record<string, number> | null) => Object.keys(gpuTime ?? {}).filter((k) => k !== 'total');
      const collision = await stepper.step(0, 8, 3);
      expect(named(collision.gpuTime)).toEqual(passes(GpuStage.BroadPhase, GpuStage.Compact));
      const full = await stepper.step(1 / 60, 8, 3);
      expect(named(full.gpuTime)).toEqual(passes(GpuStage.BroadPhase, GpuStage.TimeOfImpact));
      world.SetContinuousPhysics(false);
      const discrete = await stepper.step(1 / 60, 8, 3);
      expect(named(discrete.gpuTime)).toEqual(passes(GpuStage.BroadPhase, GpuStage.Sleep));
      expect(discrete.dispatches).toBeLessThan(full.dispatches);
      expect(collision.dispatches).toBeLessThan(discrete.dispatches);
    } finally {
      stepper.destroy();
    }
  });
});
