/*
 * GpuPipeline records a step as GpuStage lists it: the broad phase's passes, then the narrow
 * phase's, then the solver's, each once and in that order (read from the step's timestamps, which
 * name every pass), and only the stages a step needs: no collide kernel for a pair type the
 * world's fixtures cannot form, no time of impact without bullets or static and kinematic bodies;
 * and nothing at all for a world at rest (skipResting), to the bits that stepping it gives.
 */

import { expect, it } from 'vitest';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody } from '../../src/dynamics/b2Body';
import type { b2Fixture } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { GpuStage, STAGE_PASS } from '../../src-gpu/pipeline';
import { GpuStepper } from '../../src-gpu/stepper';
import { loadGoldenScene } from '../support/scene';
import { describeGpu } from './support';
import { DT, motion, POSITION_ITERATIONS, pyramid, restingWorld, stepUntilAsleep, VELOCITY_ITERATIONS } from './resting';

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
  it.skipIf(!ctx.timestamps)(
    'records the passes of a step in GpuStage order, the solver after collision, time of impact only with continuous physics, the penetration measure only once asked for',
    async () => {
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
        expect(full.penetration).toBe(-1);
        stepper.pipeline.measurePenetration = true;
        const measured = await stepper.step(1 / 60, 8, 3);
        expect(named(measured.gpuTime)).toEqual(passes(GpuStage.BroadPhase, GpuStage.Penetration));
        expect(measured.penetration).toBeGreaterThanOrEqual(0);
        world.SetContinuousPhysics(false);
        const discrete = await stepper.step(1 / 60, 8, 3);
        expect(named(discrete.gpuTime)).toEqual([...passes(GpuStage.BroadPhase, GpuStage.Sleep), STAGE_PASS[GpuStage.Penetration]]);
        expect(discrete.dispatches).toBeLessThan(measured.dispatches);
        expect(collision.dispatches).toBeLessThan(discrete.dispatches);
      } finally {
        stepper.destroy();
      }
    },
  );

  it('records a collide kernel only for the pair types the fixtures can form, and time of impact only with bullets or static and kinematic bodies', async () => {
    const world = new b2World(new b2Vec2(0, 0));
    world.SetContinuousPhysics(true);
    const add = (x: number, shape: b2CircleShape | b2PolygonShape, dynamic = true): b2Fixture => {
      const def = new b2BodyDef();
      if (dynamic) def.type = b2_dynamicBody;
      def.position.Set(x, 0);
      return world.CreateBody(def).CreateFixture(shape, 1);
    };
    const box = new b2PolygonShape();
    box.SetAsBox(0.5, 0.5);
    const circle = new b2CircleShape();
    circle.m_radius = 0.5;
    for (let i = 0; i < 4; ++i) add(2 * i, box);
    const stepper = new GpuStepper(ctx, world);
    try {
      // The second step after a change: the first may colour again after buffers grew (one dispatch more).
      const dispatches = async () => {
        await stepper.step(1 / 60, 8, 3);
        return (await stepper.step(1 / 60, 8, 3)).dispatches;
      };
      // Boxes in free space: the polygons' kernel, no time of impact.
      const boxes = await dispatches();
      add(10, circle);
      const oneCircle = await dispatches();
      expect(oneCircle - boxes, 'polygon-circle').toBe(1);
      const second = add(12, circle);
      const twoCircles = await dispatches();
      expect(twoCircles - oneCircle, 'circles').toBe(1);
      // A sensor set on a fixture the world already has (no structural change): the sensor kernel.
      second.SetSensor(true);
      const sensor = await dispatches();
      expect(sensor - twoCircles, 'sensor').toBe(1);
      // A static body: every dynamic body's contacts with it are time-of-impact candidates.
      add(-20, box, false);
      const ground = await dispatches();
      expect(ground - sensor, 'polygons against static: time of impact').toBe(3);
      world.SetContinuousPhysics(false);
      expect(ground - (await dispatches()), 'continuous physics off').toBe(3);
    } finally {
      stepper.destroy();
    }
  });

  it('records nothing for a world at rest once a step that began asleep is in, to the bits of stepping it; an upload (a box dropped on the pile) steps it again', async () => {
    const run = async (skipResting: boolean) => {
      const { world, boxes } = restingWorld(pyramid(4));
      const stepper = new GpuStepper(ctx, world);
      stepper.pipeline.skipResting = skipResting;
      try {
        await stepUntilAsleep(stepper, boxes);
        const step = () => stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
        const resting = [];
        for (let i = 0; i < 5; ++i) resting.push(await step());
        const restBytes = await stepper.narrowPhase.readAll();
        await stepper.readBodies();
        const rest = motion(boxes);
        const def = new b2BodyDef();
        def.type = b2_dynamicBody;
        def.position.Set(0, 6);
        const box = new b2PolygonShape();
        box.SetAsBox(0.5, 0.5);
        const dropped = world.CreateBody(def);
        dropped.CreateFixture(box, 1);
        const falling = [];
        for (let i = 0; i < 60; ++i) falling.push(await step());
        await stepper.readBodies();
        return {
          resting,
          restBytes,
          rest,
          falling,
          end: motion([...boxes, dropped]),
          endBytes: await stepper.narrowPhase.readAll(),
          skipped: stepper.pipeline.skippedSteps,
        };
      } finally {
        stepper.destroy();
      }
    };
    const skipping = await run(true);
    const stepping = await run(false);
    // The step after the one that put the pile to sleep began asleep; every step after it is skipped.
    expect(skipping.resting.map((r) => [r.skipped, r.awake])).toEqual([[false, 0], ...Array(4).fill([true, 0])]);
    expect(skipping.resting.slice(1).map((r) => r.dispatches)).toEqual([0, 0, 0, 0]);
    expect(stepping.resting.some((r) => r.skipped)).toBe(false);
    expect(skipping.resting[4].contactCount).toBe(stepping.resting[4].contactCount);
    expect(skipping.restBytes).toEqual(stepping.restBytes);
    expect(skipping.rest).toEqual(stepping.rest);
    // The dropped box is recorded at once, lands and wakes the pile: every bit as stepping gives.
    expect(skipping.falling[0].skipped).toBe(false);
    expect(skipping.falling.map((r) => r.awake)).toEqual(stepping.falling.map((r) => r.awake));
    expect(skipping.end).toEqual(stepping.end);
    expect(skipping.endBytes).toEqual(stepping.endBytes);
    expect([skipping.skipped, stepping.skipped]).toEqual([4 + skipping.falling.filter((r) => r.skipped).length, 0]);
  });
});
