/*
 * Accuracy targets (b2World.SetAccuracyTarget / GetAccuracy, src/dynamics/b2AccuracyTarget.ts):
 * the target's checks, the ladder against the accuracy study's results, the controller on the
 * study's scenes (each error measured independently with bench/accuracy/measures.mjs), its
 * determinism, a target no rung meets, Step without a target, and the settings a backend is given.
 */

import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import * as b2 from '../../src/index';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2ArgumentError } from '../../src/common/b2ArgumentError';
import type { b2Body } from '../../src/dynamics/b2Body';
import { b2World } from '../../src/dynamics/b2World';
import type { b2WorldBackend, b2WorldBackendEngine } from '../../src/dynamics/b2WorldBackend';
import { b2AccuracyGrowth, b2AccuracyStudyRung, b2_accuracyLadder, type b2Accuracy, type b2AccuracyTargetDef } from '../../src/dynamics/b2AccuracyTarget';
import { jointErrors, penetration, rmsSpeed } from '../../bench/accuracy/measures.mjs';
import { buildScene, type AccuracySceneId } from '../../bench/accuracy/scenes.mjs';

const DT = 1 / 60;

/** The world of a study scene (sleeping off, as the study runs it). */
function studyWorld(id: AccuracySceneId): b2World {
  return buildScene(b2, id).world as b2World;
}

/** The study's chain with a weight of `ratio` links' mass at its end (the study's has 10). */
function chainWorld(ratio: number): b2World {
  const world = studyWorld('chain');
  let weight: b2Body | null = null;
  for (let b = world.GetBodyList(); b; b = b.GetNext()) if (b.GetFixtureList()?.GetShape().GetType() === b2.b2Shape.e_circle) weight = b;
  const f = weight!.GetFixtureList()!;
  f.SetDensity((f.GetDensity() * ratio) / 10);
  weight!.ResetMassData();
  return world;
}

interface Run {
  /** The settings each frame stepped with, "vi/pi xk". */
  settings: string[];
  /** The largest errors measured by bench/accuracy/measures.mjs: penetration over the last second, joint error over the run, jitter over the last second. */
  penetration: number;
  jointError: number;
  jitter: number;
  /** Velocity iterations per frame (times sub-steps), on average and in the last second. */
  meanIterations: number;
  last: b2Accuracy;
  positions: number[];
}

/** Every body's position and angle, in list order. */
function positionsOf(world: b2World): number[] {
  const out: number[] = [];
  for (let b = world.GetBodyList(); b; b = b.GetNext()) out.push(b.GetPosition().x, b.GetPosition().y, b.GetAngle());
  return out;
}

/** The numbers' bits, so that a comparison tells -0 from 0. */
function bits(xs: number[]): string {
  return Buffer.from(new Float64Array(xs).buffer).toString('hex');
}

function run(world: b2World, target: b2AccuracyTargetDef, seconds: number): Run {
  world.SetAccuracyTarget(target);
  const frames = Math.round(seconds * 60);
  const settings: string[] = [];
  let pen = 0;
  let joint = 0;
  let jitter = 0;
  let iterations = 0;
  for (let f = 1; f <= frames; ++f) {
    // The settings this frame steps with (GetAccuracy after it gives the next frame's).
    const a = world.GetAccuracy()!;
    settings.push(`${a.velocityIterations}/${a.positionIterations} x${a.substeps}`);
    iterations += a.velocityIterations * a.substeps;
    world.Step(DT, 8, 3);
    if (target.jointError !== undefined) joint = Math.max(joint, jointErrors(world).linear);
    if (f > frames - 60) {
      if (target.penetration !== undefined) pen = Math.max(pen, penetration(b2, world).max);
      if (target.jitter !== undefined) jitter = Math.max(jitter, rmsSpeed(world));
    }
  }
  const positions = positionsOf(world);
  return { settings, penetration: pen, jointError: joint, jitter, meanIterations: iterations / frames, last: world.GetAccuracy()!, positions };
}

/** The largest error of `measure` a fixed setting gives (as run() measures it). */
function fixed(world: b2World, vi: number, pi: number, seconds: number, measure: 'penetration' | 'jointError'): number {
  const frames = Math.round(seconds * 60);
  let e = 0;
  for (let f = 1; f <= frames; ++f) {
    world.Step(DT, vi, pi);
    if (measure === 'jointError') e = Math.max(e, jointErrors(world).linear);
    else if (f > frames - 60) e = Math.max(e, penetration(b2, world).max);
  }
  return e;
}

function iterationsOf(a: b2Accuracy): number {
  return a.velocityIterations * a.substeps;
}

describe('the target is checked', () => {
  const bad: [unknown, RegExp][] = [
    [undefined, /b2World\.SetAccuracyTarget: target must be an object \{ penetration\?, jointError\?, jitter\? \} or null, got undefined/],
    [0.01, /target must be an object .* got 0\.01/],
    [[0.01], /target must be an object .* got an array/],
    [{}, /target must give at least one of penetration \(m\), jointError \(m\), jitter \(m\/s\)/],
    [{ penetration: 0 }, /target\.penetration must be a finite number > 0 \(m\), got 0/],
    [{ penetration: -0.01 }, /target\.penetration must be a finite number > 0 \(m\), got -0\.01/],
    [{ jointError: Number.NaN }, /target\.jointError must be a finite number > 0 \(m\), got NaN/],
    [{ jitter: Infinity }, /target\.jitter must be a finite number > 0 \(m\/s\), got Infinity/],
    [{ jitter: '0.001' }, /target\.jitter must be a finite number > 0 \(m\/s\), got the string "0\.001"/],
    [{ penetration: 0.01, joint: 0.01 }, /target\.joint is not a measure of an accuracy target \(penetration, jointError, jitter\)/],
  ];

  it.each(bad)('rejects %j with a message naming the argument and the rule, and keeps the world and its target', (target, message) => {
    const world = studyWorld('stack');
    world.SetAccuracyTarget({ penetration: 0.01 });
    const before = world.GetAccuracy();
    let error: unknown = null;
    try {
      world.SetAccuracyTarget(target as b2AccuracyTargetDef);
    } catch (err) {
      error = err;
    }
    expect(error).toBeInstanceOf(b2ArgumentError);
    expect((error as Error).message).toMatch(message);
    expect(world.GetAccuracy()).toEqual(before);
    world.Step(DT, 8, 3);
    expect(world.GetAccuracy()!.steps).toBe(1);
  });

  it('is copied and frozen: changing the object passed changes nothing', () => {
    const world = studyWorld('stack');
    const target = { penetration: 0.01 };
    world.SetAccuracyTarget(target);
    target.penetration = 1;
    expect(world.GetAccuracy()!.target).toEqual({ penetration: 0.01 });
    expect(Object.isFrozen(world.GetAccuracy()!.target)).toBe(true);
  });

  it('cannot be set during a step', () => {
    const world = studyWorld('stack');
    let error: unknown = null;
    world.SetContactListener(
      Object.assign(new b2.b2ContactListener(), {
        BeginContact: () => {
          try {
            world.SetAccuracyTarget({ penetration: 0.01 });
          } catch (err) {
            error = err;
          }
        },
      }),
    );
    world.Step(DT, 8, 3);
    expect((error as Error).message).toMatch(/b2World\.SetAccuracyTarget: the world is locked/);
    expect(world.GetAccuracy()).toBeNull();
  });
});

describe('the ladder is the accuracy study', () => {
  const study = JSON.parse(readFileSync(new URL('../../bench/results/accuracy/accuracy.json', import.meta.url), 'utf8'));
  const value = (scene: string, method: string, measure: string): number => {
    const s = study.scenes.find((x: { id: string }) => x.id === scene);
    const r = s.results.find((x: { method: string; backend: string }) => x.method === method && x.backend === 'js');
    return measure === 'ms' ? r.msPerSecond : r.measures[measure];
  };
  const methodOf = (r: (typeof b2_accuracyLadder)[number]): string =>
    r.substeps > 1 ? `substeps-${r.substeps}` : `iter-${r.velocityIterations}-${r.positionIterations}`;
  const three = (x: number): number => Number(x.toPrecision(3));

  it("holds the study's JavaScript results to three digits, for each rung and scene", () => {
    for (const r of b2_accuracyLadder) {
      const m = methodOf(r);
      if (r.substeps > 1) expect([r.velocityIterations, r.positionIterations]).toEqual([8, 3]);
      expect(r.study.penetration.stack).toBe(three(value('stack', m, 'penetration max')));
      expect(r.study.penetration.pyramid).toBe(three(value('pyramid', m, 'penetration max')));
      expect(r.study.jointError.chain).toBe(three(value('chain', m, 'joint error')));
      expect(r.study.jointError.mechanisms).toBe(three(value('mechanisms', m, 'joint error')));
      expect(r.study.jitter.stack).toBe(three(value('stack', m, 'jitter')));
      expect(r.study.jitter.pyramid).toBe(three(value('pyramid', m, 'jitter')));
      expect(r.msPerSecond).toBe(three(value('pyramid', m, 'ms')));
    }
  });

  it("is ordered by the pyramid's cost, and 32/12 (left out) costs what 8/3 in 2 sub-steps does and measures more error", () => {
    const costs = b2_accuracyLadder.map((r) => r.msPerSecond);
    expect([...costs].sort((a, b) => a - b)).toEqual(costs);
    expect(value('pyramid', 'iter-32-12', 'ms')).toBeGreaterThan(value('pyramid', 'substeps-2', 'ms'));
    for (const [scene, measure] of [
      ['stack', 'penetration max'],
      ['pyramid', 'penetration max'],
      ['mechanisms', 'joint error'],
      ['stack', 'jitter'],
      ['pyramid', 'jitter'],
    ]) {
      expect(value(scene, 'iter-32-12', measure)).toBeGreaterThan(value(scene, 'substeps-2', measure));
    }
  });

  it('starts each measure at the cheapest rung the study measured below the target', () => {
    const rungOf = (label: string): number => b2_accuracyLadder.findIndex((r) => `${r.velocityIterations}/${r.positionIterations} x${r.substeps}` === label);
    expect(b2AccuracyStudyRung('penetration', 0.01)).toBe(rungOf('4/2 x1'));
    expect(b2AccuracyStudyRung('penetration', 0.006)).toBe(rungOf('8/3 x4'));
    expect(b2AccuracyStudyRung('penetration', 0.001)).toBe(-1);
    expect(b2AccuracyStudyRung('jointError', 0.05)).toBe(rungOf('8/3 x2'));
    expect(b2AccuracyStudyRung('jitter', 0.001)).toBe(rungOf('4/2 x1'));
    // Growth of penetration's excess over the slop from 4/2 to 2/1: the stack's (0.0152 - 0.005) / (0.00973 - 0.005).
    expect(b2AccuracyGrowth(1, 'penetration')).toBeCloseTo((0.0152 - 0.005) / (0.00973 - 0.005), 12);
  });
});

/** The settings a run chose, each with its number of frames, in the order first chosen. */
function chosen(r: Run): string {
  const n = new Map<string, number>();
  for (const s of r.settings) n.set(s, (n.get(s) ?? 0) + 1);
  return [...n].map(([s, k]) => `${s} ${k}`).join(', ');
}

/**
 * A study scene under a target against the fixed conservative 32/12 (32 velocity iterations a
 * frame) and 16/6: the target's measure as run() takes it (bench/accuracy/measures.mjs), printed.
 */
function compare(id: AccuracySceneId, measure: 'penetration' | 'jointError', target: number, seconds: number): Run & { fixed32: number; fixed16: number } {
  const r = run(studyWorld(id), { [measure]: target }, seconds);
  const fixed32 = fixed(studyWorld(id), 32, 12, seconds, measure);
  const fixed16 = fixed(studyWorld(id), 16, 6, seconds, measure);
  const over = measure === 'penetration' ? 'over the last second' : 'over the run';
  console.log(
    `${id}, ${measure} ${target} m: ${r[measure].toExponential(3)} m ${over}, ${r.meanIterations.toFixed(1)} velocity iterations a frame on average ` +
      `(fixed 32/12: 32, ${fixed32.toExponential(3)} m; fixed 16/6: 16, ${fixed16.toExponential(3)} m); ${r.last.changes} changes, chosen: ${chosen(r)}`,
  );
  return { ...r, fixed32, fixed16 };
}

describe("targets met on the study's scenes, at fewer velocity iterations a frame than a fixed 32/12", () => {
  it('stack, penetration 0.01 m: the starting overlap is left to fall; met over the last second at fewer iterations than 16/6', () => {
    const r = compare('stack', 'penetration', 0.01, 10);
    expect(r.penetration).toBeLessThan(0.01);
    expect(r.last.met).toBe(true);
    expect(r.meanIterations).toBeLessThan(32);
    expect(r.meanIterations).toBeLessThan(16);
    // The boxes start with their skins overlapping 0.02 m, an error the solver removes at every
    // rung: the controller climbs only while it falls too slowly, and stops short of 4 sub-steps.
    expect(r.settings.slice(0, 45).every((s) => s === '4/2 x1')).toBe(true);
    expect(r.settings).not.toContain('8/3 x4');
    expect(r.settings.at(-1)).toBe('8/3 x2');
  });

  it('pyramid, penetration 0.006 m: met over the last second, ending at 2/1', () => {
    const r = compare('pyramid', 'penetration', 0.006, 10);
    expect(r.penetration).toBeLessThan(0.006);
    expect(r.last.met).toBe(true);
    expect(r.meanIterations).toBeLessThan(32);
    expect(r.settings.at(-1)).toBe('2/1 x1');
    expect(new Set(r.settings.slice(-60)).size).toBe(1);
  });

  it('chain, joint error 0.02 m: met over the whole run, ending at 16/6', () => {
    const r = compare('chain', 'jointError', 0.02, 5);
    expect(r.jointError).toBeLessThan(0.02);
    expect(r.last.met).toBe(true);
    expect(iterationsOf(r.last)).toBeLessThan(32);
    expect(r.meanIterations).toBeLessThan(32);
  });

  it("mechanisms, joint error 0.05 m: met over the whole run (the pulley's landing included), which the fixed 32/12 is not, and ending below 8/3", () => {
    const r = compare('mechanisms', 'jointError', 0.05, 5);
    expect(r.jointError).toBeLessThan(0.05);
    expect(r.meanIterations).toBeLessThan(32);
    expect(r.fixed32).toBeGreaterThan(0.05);
    expect(iterationsOf(r.last)).toBeLessThan(8);
  });

  it('stack, jitter 0.001 m/s: met over the last second', () => {
    const r = run(studyWorld('stack'), { jitter: 0.001 }, 5);
    console.log(`stack: jitter ${r.jitter.toExponential(3)} m/s (target 0.001) at ${r.settings.at(-1)}`);
    expect(r.jitter).toBeLessThan(0.001);
    expect(r.last.met).toBe(true);
    expect(r.last.measured.jitter).toBeLessThan(0.001);
    expect(r.last.measured.penetration).toBeNull();
  });
});

describe('choices and reasons', () => {
  it('the same scene and target give the same choices and the same final state, bit for bit', () => {
    const a = run(studyWorld('pyramid'), { penetration: 0.006, jitter: 0.01 }, 10);
    const b = run(studyWorld('pyramid'), { penetration: 0.006, jitter: 0.01 }, 10);
    expect(a.last.changes).toBeGreaterThan(2);
    expect(b.settings).toEqual(a.settings);
    expect(b.last).toEqual(a.last);
    expect(bits(b.positions)).toEqual(bits(a.positions));
  });

  it('a target the scene cannot meet climbs to the top rung and says it is not met there', () => {
    const r = run(chainWorld(1000), { jointError: 0.05 }, 4);
    const top = b2_accuracyLadder.at(-1)!;
    expect(r.settings[0]).toBe('8/3 x2');
    expect(r.settings.at(-1)).toBe(`${top.velocityIterations}/${top.positionIterations} x${top.substeps}`);
    expect(r.last.met).toBe(false);
    expect(r.last.reason).toMatch(/target NOT met at the top rung: joint error [0-9.]+ m over the target 0\.05 m/);
    expect(r.last.reason).toMatch(/up from 8\/3 iterations, 4 substeps at step \d+: joint error/);
    expect(r.jointError).toBeGreaterThan(0.05);
  });

  it('a target below what any rung of the study reached starts at the top rung and says why', () => {
    const world = studyWorld('stack');
    world.SetAccuracyTarget({ penetration: 0.001 });
    const a = world.GetAccuracy()!;
    expect([a.velocityIterations, a.positionIterations, a.substeps]).toEqual([8, 3, 8]);
    expect(a.reason).toMatch(/no rung of the study gets penetration below 0\.001 m \(its best: 0\.00501 m\)/);
    expect(a.reason).toMatch(/nothing measured yet/);
    world.Step(DT, 8, 3);
    expect(world.GetAccuracy()!.reason).toMatch(/target NOT met at the top rung: penetration 0\.0\d+ m over the target 0\.001 m/);
  });

  it('reports the settings, the measured errors and a reason after a move down', () => {
    const r = run(studyWorld('pyramid'), { penetration: 0.006 }, 10);
    expect(r.last.target).toEqual({ penetration: 0.006 });
    expect([r.last.velocityIterations, r.last.positionIterations, r.last.substeps]).toEqual([2, 1, 1]);
    expect(r.last.measured.penetration).toBeGreaterThanOrEqual(0.005);
    expect(r.last.measured.penetration).toBeLessThan(0.006);
    expect(r.last.measured.jointError).toBeNull();
    expect(r.last.worst.penetration).toBeGreaterThanOrEqual(r.last.measured.penetration!);
    expect(r.last.steps).toBe(600);
    expect(r.last.reason).toMatch(
      /^2\/1 iterations; down from 4\/2 iterations at step \d+ after 60 steps with room: penetration [0-9.]+ m would stay below half the target 0\.006 m above the 0\.005 m contacts rest at/,
    );
    expect(r.last.reason).toMatch(/target met: penetration 0\.00\d+ m within 0\.006 m$/);
  });

  it('an error over its target that falls is left to its rung, until it falls too slowly to reach the target within the horizon', () => {
    // The stack starts with its boxes' skins overlapping 0.02 m, twice the target, at 4/2.
    const world = studyWorld('stack');
    world.SetAccuracyTarget({ penetration: 0.01 });
    const reasons: string[] = [];
    for (let f = 1; f <= 60; ++f) {
      world.Step(DT, 8, 3);
      reasons.push(world.GetAccuracy()!.reason);
    }
    // First block (15 steps): waiting; second: its largest error below the first's, watched; then falling.
    expect(reasons[19]).toMatch(/^4\/2 iterations; .*target not met yet: penetration 0\.0\d+ m over the target 0\.01 m, watched for a fall$/);
    expect(reasons[39]).toMatch(/^4\/2 iterations; .*target not met yet: penetration 0\.0\d+ m over the target 0\.01 m, falling: left to this rung$/);
    // At the third block's end the fall per block (0.0011 m) would take more than 120 steps to the target: up.
    expect(reasons[44]).toMatch(/^8\/3 iterations; up from 4\/2 iterations at step 45: penetration 0\.0\d+ m over the target 0\.01 m; target not met yet/);
    expect(reasons[59]).toMatch(/^8\/3 iterations; .*, watched for a fall$/);
  });
});

describe('Step without a target', () => {
  it("is the world's own Step: setting a target and removing it changes nothing, bit for bit", () => {
    const plain = studyWorld('pyramid');
    const cleared = studyWorld('pyramid');
    cleared.SetAccuracyTarget({ penetration: 0.006 });
    cleared.SetAccuracyTarget(null);
    expect(cleared.GetAccuracy()).toBeNull();
    for (let i = 0; i < 120; ++i) {
      plain.Step(DT, 8, 3);
      cleared.Step(DT, 8, 3);
    }
    expect(bits(positionsOf(cleared))).toEqual(bits(positionsOf(plain)));
  });

  it("with a target, each frame is the world's own Step at the chosen settings (k steps of dt / k for k sub-steps)", () => {
    const r = run(studyWorld('mechanisms'), { jointError: 0.05 }, 5);
    expect(new Set(r.settings).size).toBeGreaterThan(2);
    expect(r.settings).toContain('8/3 x2');
    const plain = studyWorld('mechanisms');
    for (const s of r.settings) {
      const [, vi, pi, k] = /^(\d+)\/(\d+) x(\d+)$/.exec(s)!.map(Number);
      for (let i = 0; i < k; ++i) plain.Step(DT / k, vi, pi);
    }
    expect(bits(positionsOf(plain))).toEqual(bits(r.positions));
  });
});

/** Steps the world on this engine through the engine functions (as AutoBackend does on JavaScript), recording the settings. */
class EngineBackend implements b2WorldBackend {
  readonly steps: string[] = [];
  private world: b2World | null = null;
  private engine: b2WorldBackendEngine | null = null;
  Attach(world: b2World, engine: b2WorldBackendEngine): void {
    this.world = world;
    this.engine = engine;
  }
  async Detach(): Promise<void> {}
  Step(dt: number, vi: number, pi: number): void {
    this.steps.push(`${vi}/${pi}`);
    this.engine!.step(this.world!, dt, vi, pi);
  }
  async StepAsync(dt: number, vi: number, pi: number): Promise<void> {
    this.Step(dt, vi, pi);
  }
  async Synchronize(): Promise<void> {}
  PullBody(_body: b2Body): void {}
  PullAll(): void {}
}

/** Records the settings; its "synchronisations" (Synchronize) advance the world's epoch and keep the contacts to itself, as WebGPUBackend does. */
class RemoteBackend implements b2WorldBackend {
  readonly steps: string[] = [];
  pulls = 0;
  private world: b2World | null = null;
  Attach(world: b2World): void {
    this.world = world;
  }
  async Detach(): Promise<void> {}
  Step(dt: number, vi: number, pi: number): void {
    this.steps.push(`${dt} ${vi}/${pi}`);
  }
  async StepAsync(dt: number, vi: number, pi: number): Promise<void> {
    this.Step(dt, vi, pi);
    await this.Synchronize();
  }
  async Synchronize(): Promise<void> {
    this.world!.m_stateEpoch++;
  }
  PullBody(_body: b2Body): void {}
  PullAll(): void {
    this.pulls++;
  }
}

/** A RemoteBackend that measures penetration itself (GetPenetration), as WebGPUBackend does on the GPU. */
class MeasuringBackend extends RemoteBackend {
  penetration: number | null = null;
  GetPenetration(): number | null {
    return this.penetration;
  }
}

describe('on a backend', () => {
  it("the chosen iterations reach the backend's Step, without sub-steps (the ladder ends at 16/6)", async () => {
    const world = studyWorld('chain');
    const backend = new RemoteBackend();
    await world.SetBackend(backend);
    world.SetAccuracyTarget({ jointError: 0.05 });
    // The study's rung for 0.05 m is 8/3 in 2 sub-steps; a backend gets the last rung without: 16/6.
    const a = world.GetAccuracy()!;
    expect([a.velocityIterations, a.positionIterations, a.substeps]).toEqual([16, 6, 1]);
    world.Step(DT, 8, 3);
    expect(backend.steps).toEqual([`${DT} 16/6`]);
    await world.StepAsync(DT, 8, 3);
    expect(backend.steps).toEqual([`${DT} 16/6`, `${DT} 16/6`]);
    await world.SetBackend(null);
    expect(world.GetAccuracy()!.substeps).toBe(2);
  });

  it('measures the last synchronisation only, and not penetration where the backend keeps the contacts', async () => {
    const world = studyWorld('stack');
    const backend = new RemoteBackend();
    await world.SetBackend(backend);
    world.SetAccuracyTarget({ penetration: 0.01, jitter: 1 });
    world.Step(DT, 8, 3);
    world.Step(DT, 8, 3);
    // Nothing synchronised yet: the state is the one before the target, measured once.
    expect(backend.pulls).toBe(1);
    await world.Synchronize();
    world.Step(DT, 8, 3);
    expect(backend.pulls).toBe(2);
    const a = world.GetAccuracy()!;
    expect(a.measured.penetration).toBeNull();
    expect(a.measured.jitter).toBe(0);
    expect(a.reason).toMatch(/penetration not measured here \(the backend keeps the contacts\), target 0\.01 m/);
    // Unmeasured, penetration never lets the rung fall below the study's (4/2) however calm the rest.
    for (let i = 0; i < 400; ++i) await world.StepAsync(DT, 8, 3);
    expect(world.GetAccuracy()!.velocityIterations).toBeGreaterThanOrEqual(4);
  });

  it('takes penetration from a backend that keeps the contacts and measures them (GetPenetration)', async () => {
    const world = studyWorld('stack');
    const backend = new MeasuringBackend();
    await world.SetBackend(backend);
    world.SetAccuracyTarget({ penetration: 0.01 });
    backend.penetration = 0.004;
    await world.StepAsync(DT, 8, 3);
    await world.StepAsync(DT, 8, 3);
    let a = world.GetAccuracy()!;
    expect(a.measured.penetration).toBe(0.004);
    expect(a.reason).toMatch(/target met: penetration 0\.004 m within 0\.01 m$/);
    // A synchronised step that measured nothing (it did not solve) leaves the measure out.
    backend.penetration = null;
    await world.StepAsync(DT, 8, 3);
    a = world.GetAccuracy()!;
    expect(a.measured.penetration).toBeNull();
    expect(a.reason).toMatch(/penetration not measured in the last synchronisation \(no step it shows solved\), target 0\.01 m/);
    // A level error over the target climbs from the study's rung (4/2), as on this engine.
    backend.penetration = 0.02;
    for (let i = 0; i < 40; ++i) await world.StepAsync(DT, 8, 3);
    a = world.GetAccuracy()!;
    expect(a.worst.penetration).toBe(0.02);
    expect(a.velocityIterations).toBeGreaterThan(4);
    expect(a.reason).toMatch(/up from 4\/2 iterations at step \d+: penetration 0\.02 m over the target 0\.01 m/);
  });

  it('measures everything, contacts included, when the backend lets this engine step the world', async () => {
    const world = studyWorld('pyramid');
    const backend = new EngineBackend();
    await world.SetBackend(backend);
    // On a backend the ladder stops at 16/6 (the study's rung, 8/3 in 4 sub-steps, is out of reach).
    const r = run(world, { penetration: 0.006 }, 3);
    expect(r.settings[0]).toBe('16/6 x1');
    expect(r.last.measured.penetration).toBeGreaterThan(0.004);
    expect(backend.steps.length).toBe(180);
  });
});

it('b2World and the package entry export the API', () => {
  expect(typeof b2.b2World.prototype.SetAccuracyTarget).toBe('function');
  expect(typeof b2.b2World.prototype.GetAccuracy).toBe('function');
  expect(b2.b2_accuracyLadder).toBe(b2_accuracyLadder);
  expect(new b2World(new b2Vec2(0, -10)).GetAccuracy()).toBeNull();
});
