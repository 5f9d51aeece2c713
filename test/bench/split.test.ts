// The iteration split (bench/split.mjs): the line fit, the option checks, the engines' settable
// iteration counts and a quick run. No timing assertions: speed is what the benchmark measures.
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { buildBundles } from '../support/bundles';
import { SPLIT_ENGINES, SPLIT_ENGINE_IDS, fitLine, formatSplit, resolveSplitOptions, runSplit } from '../../bench/split.mjs';
import { makeScene } from '../../bench/scenes.mjs';

// One bundle of the working tree for the WebPhysics adapter, as `runSplit` would build it.
let bundles: { dir: string; remove(): void };
let oursBundle = '';

beforeAll(() => {
  bundles = buildBundles();
  oursBundle = path.join(bundles.dir, 'webphysics.mjs');
});

afterAll(() => {
  bundles.remove();
});

describe('fitLine', () => {
  it('recovers the intercept and slope of points on a line, with no residual', () => {
    const fit = fitLine([
      [1, 2.5],
      [3, 3.5],
      [5, 4.5],
      [8, 6],
    ]);
    expect(fit.intercept).toBeCloseTo(2, 12);
    expect(fit.slope).toBeCloseTo(0.5, 12);
    expect(fit.maxResidual).toBeCloseTo(0, 12);
  });

  it('reports the largest distance of a point from the least-squares line', () => {
    const fit = fitLine([
      [0, 0],
      [1, 1],
      [2, 0],
    ]);
    expect(fit.slope).toBeCloseTo(0, 12);
    expect(fit.intercept).toBeCloseTo(1 / 3, 12);
    expect(fit.maxResidual).toBeCloseTo(2 / 3, 12);
  });

  it('refuses points that do not span two x values', () => {
    expect(() => fitLine([[3, 1]])).toThrow(/two or more distinct x/);
    expect(() =>
      fitLine([
        [3, 1],
        [3, 2],
      ]),
    ).toThrow(/two or more distinct x/);
  });
});

describe('split options', () => {
  it('defaults to bench2d, WebPhysics against box2d-wasm, velocity iterations 1, 3, 5 and 8', () => {
    const o = resolveSplitOptions({});
    expect(o.scene).toBe('bench2d');
    expect(o.engines).toEqual(['webphysics', 'box2d-wasm']);
    expect(o.vary).toBe('velocity');
    expect(o.iterations).toEqual([1, 3, 5, 8]);
    expect(o.rounds).toBe(3);
  });

  it('takes comma lists as the command line gives them', () => {
    const o = resolveSplitOptions({ engines: 'planck,box2dweb', iterations: '2,6', rounds: '2', vary: 'position' });
    expect(o.engines).toEqual(['planck', 'box2dweb']);
    expect(o.iterations).toEqual([2, 6]);
    expect(o.rounds).toBe(2);
    expect(o.vary).toBe('position');
  });

  it('names the option and the rule a bad value breaks', () => {
    expect(() => resolveSplitOptions({ scene: 'nope' })).toThrow(/unknown scene "nope"/);
    expect(() => resolveSplitOptions({ engines: 'matter' })).toThrow(/engine "matter" has no Box2D 2.x iteration counts/);
    expect(() => resolveSplitOptions({ engines: [] })).toThrow(/engines must name at least one engine/);
    expect(() => resolveSplitOptions({ iterations: '3,3' })).toThrow(/at least two different counts/);
    expect(() => resolveSplitOptions({ iterations: '0,3' })).toThrow(/iterations must be a positive integer, not "0"/);
    expect(() => resolveSplitOptions({ rounds: 1.5 })).toThrow(/rounds must be a positive integer, not "1.5"/);
    expect(() => resolveSplitOptions({ vary: 'both' as never })).toThrow(/vary must be velocity or position, not "both"/);
  });
});

describe('settable iteration counts', () => {
  it('takes part for exactly the Box2D 2.x engines', () => {
    expect(SPLIT_ENGINE_IDS).toEqual(['webphysics', 'box2d-wasm', 'box2dweb', 'box2d-core', 'planck']);
  });

  it.each(SPLIT_ENGINE_IDS)('%s: setIterations changes the simulation from the next step on', async (id) => {
    const engine = SPLIT_ENGINES.find((e) => e.id === id)!;
    const api = await engine.load({ oursBundle });
    const scene = makeScene('bench2d', { quick: true })!;
    const top = scene.track[0];
    const run = (velocityIterations: number, positionIterations: number) => {
      const w = engine.create(api, scene, { sleep: false });
      w.setIterations(velocityIterations, positionIterations);
      for (let i = 0; i < 40; i++) w.step();
      const p = w.position(top);
      w.destroy();
      return p;
    };
    const asDefined = run(scene.velocityIterations, scene.positionIterations);
    expect(run(scene.velocityIterations, scene.positionIterations)).toEqual(asDefined);
    expect(run(1, 1)).not.toEqual(asDefined);
  });
});

describe('runSplit in quick mode', () => {
  it('times every count for every engine and fits a line through the points', async () => {
    const result = await runSplit({ quick: true, engines: ['webphysics', 'planck'], iterations: [1, 4], ours: oursBundle, log: null });
    expect(result.scene).toBe('bench2d');
    expect(result.vary).toBe('velocity');
    expect(result.protocol).toMatchObject({ rounds: 1, iterations: [1, 4] });
    expect(result.engines.map((e) => e.id)).toEqual(['webphysics', 'planck']);
    for (const e of result.engines) {
      expect(e.points.map(([v]) => v)).toEqual([1, 4]);
      for (const [, ms] of e.points) expect(ms).toBeGreaterThan(0);
      // Two points: the line passes through both.
      expect(e.fixedMs + 4 * e.perIterationMs).toBeCloseTo(e.points[1][1], 9);
      expect(e.maxResidualMs).toBeCloseTo(0, 9);
    }
    const table = formatSplit(result);
    expect(table).toMatch(/^bench2d, sleeping off, velocity iterations varied, 3 position iterations/);
    expect(table).toContain('WebPhysics');
    expect(table).toContain('planck');
  }, 120_000);
});
