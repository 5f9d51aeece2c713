#!/usr/bin/env node
// Splits each Box2D 2.x engine's step time into the part that grows with the velocity (or
// position) iterations and the rest (collision, island building, solver set-up, broad-phase):
//   node bench/split.mjs [--scene bench2d] [--engines webphysics,box2d-wasm] [--vary velocity]
//                        [--iterations 1,3,5,8] [--rounds 3] [--preroll N] [--steps N]
//                        [--ours FILE] [--quick] [--json]
// The scene runs, sleeping off, with its steps taking the iteration counts in turn (the other
// count as the scene defines it); per engine a least-squares line through the best-round median
// step time at each count gives the cost of one iteration (slope) and of everything else in the
// step (intercept). Ratios of those two between engines show where one engine loses to another,
// which the full benchmark's one number cannot. Position iterations stop early once the contacts
// are within tolerance, so their line is a looser fit (the fit error column says how loose). Only
// engines with Box2D 2.x's iteration counts take part; v3's and Rapier's substeps are another
// trade.
//
// For programs: `runSplit(options)` resolves to the results object, `fitLine(points)` is the fit.
import { pathToFileURL } from 'node:url';
import os from 'node:os';
import v8 from 'node:v8';
import { ENGINES, OURS, SCENE_IDS, buildOurs, cpuCaches, positiveInt, quantile } from './harness.mjs';
import { fullGC } from './memory.mjs';
import { describeCaches } from './report.mjs';
import { makeScene, sceneStepper } from './scenes.mjs';
import { runCommand } from './command.mjs';

/** The engine adapters that take Box2D 2.x's velocity and position iteration counts. */
export const SPLIT_ENGINES = ENGINES.filter((e) => /^Box2D 2\./.test(e.family));
export const SPLIT_ENGINE_IDS = SPLIT_ENGINES.map((e) => e.id);

export const SPLIT_USAGE = `usage: node bench/split.mjs [options]

  --scene ID        scene (default bench2d): ${SCENE_IDS.join(', ')}
  --engines a,b     engines (default webphysics,box2d-wasm): ${SPLIT_ENGINE_IDS.join(', ')}
  --vary KIND       velocity or position: the iterations whose count varies (default velocity)
  --iterations a,b  iteration counts, at least two (default 1,3,5,8)
  --rounds N        rounds, each on fresh worlds (default 3)
  --preroll N       untimed steps per world (default: the scene's)
  --steps N         timed steps per world (default: the scene's, times the number of counts)
  --ours FILE       use this webphysics.mjs bundle instead of building the working tree
  --quick           tiny protocol for smoke tests
  --json            print the results JSON to stdout (the table goes to stderr)
  -h, --help        this text`;

/**
 * The least-squares line through points [[x, y], ...] (at least two distinct x): { intercept,
 * slope, maxResidual }, maxResidual the largest |y - line(x)|, a check that the cost is linear.
 */
export function fitLine(points) {
  const xs = new Set(points.map(([x]) => x));
  if (xs.size < 2) throw new Error('fitLine needs points at two or more distinct x');
  const n = points.length;
  const mx = points.reduce((s, [x]) => s + x, 0) / n;
  const my = points.reduce((s, [, y]) => s + y, 0) / n;
  let sxy = 0;
  let sxx = 0;
  for (const [x, y] of points) {
    sxy += (x - mx) * (y - my);
    sxx += (x - mx) * (x - mx);
  }
  const slope = sxy / sxx;
  const intercept = my - slope * mx;
  const maxResidual = Math.max(...points.map(([x, y]) => Math.abs(y - (intercept + slope * x))));
  return { intercept, slope, maxResidual };
}

/** Fills in defaults and checks the options; see runSplit. */
export function resolveSplitOptions(opts = {}) {
  const scene = opts.scene ?? 'bench2d';
  if (!SCENE_IDS.includes(scene)) throw new Error(`unknown scene "${scene}" (known: ${SCENE_IDS.join(', ')})`);
  const engines = opts.engines ?? [OURS, 'box2d-wasm'];
  const engineIds = Array.isArray(engines)
    ? engines
    : String(engines)
        .split(',')
        .map((s) => s.trim())
        .filter(Boolean);
  for (const id of engineIds) {
    if (!SPLIT_ENGINE_IDS.includes(id)) {
      throw new Error(`engine "${id}" has no Box2D 2.x iteration counts (engines: ${SPLIT_ENGINE_IDS.join(', ')})`);
    }
  }
  if (engineIds.length === 0) throw new Error('engines must name at least one engine');
  const iterations = opts.iterations ?? [1, 3, 5, 8];
  const counts = (Array.isArray(iterations) ? iterations : String(iterations).split(',')).map((v) => positiveInt('iterations', v));
  if (new Set(counts).size < 2) throw new Error('iterations must list at least two different counts');
  const vary = opts.vary ?? 'velocity';
  if (vary !== 'velocity' && vary !== 'position') throw new Error(`vary must be velocity or position, not "${vary}"`);
  return {
    scene,
    vary,
    engines: engineIds,
    iterations: counts,
    rounds: positiveInt('rounds', opts.rounds, opts.quick ? 1 : 3),
    preroll: opts.preroll === undefined ? null : positiveInt('preroll', opts.preroll),
    steps: opts.steps === undefined ? null : positiveInt('steps', opts.steps),
    quick: Boolean(opts.quick),
    ours: opts.ours ?? null,
    log: opts.log === undefined ? (s) => process.stderr.write(s + '\n') : (opts.log ?? (() => {})),
  };
}

/**
 * One world whose steps take the iteration counts in turn (step i runs counts[i % n]), so every
 * count is timed on the same trajectory: a world run at one count alone settles differently, and
 * its collision work would move with the count. Returns the median ms per step of each count over
 * the `steps` timed steps after `preroll`.
 */
function timeWorld(engine, api, scene, vary, counts, preroll, steps) {
  fullGC();
  const w = engine.create(api, scene, { sleep: false });
  const { step } = sceneStepper(w, scene);
  const n = counts.length;
  const use = (count) => (vary === 'velocity' ? w.setIterations(count, scene.positionIterations) : w.setIterations(scene.velocityIterations, count));
  for (let i = 0; i < preroll; i++) {
    use(counts[i % n]);
    step();
  }
  const times = counts.map(() => []);
  for (let i = 0; i < steps; i++) {
    const k = (preroll + i) % n;
    use(counts[k]);
    const t = performance.now();
    step();
    times[k].push(performance.now() - t);
  }
  w.destroy();
  return times.map((t) =>
    quantile(
      t.sort((a, b) => a - b),
      0.5,
    ),
  );
}

/**
 * Runs the split and resolves to { scene, vary, velocityIterations, positionIterations, machine,
 * protocol, engines: [{ id, name, points: [[iterations, ms]], fixedMs, perIterationMs,
 * maxResidualMs }] }. Options: scene, engines, vary ('velocity' or 'position'), iterations,
 * rounds, preroll, steps (default: the scene's steps for each count), quick, ours (a prebuilt
 * webphysics.mjs), log.
 */
export async function runSplit(options = {}) {
  const o = resolveSplitOptions(options);
  // As in runBench: engines take turns in one process, so V8 must not flush the idle ones' bytecode.
  v8.setFlagsFromString('--no-flush-bytecode');
  const base = makeScene(o.scene, { quick: o.quick });
  const protocol = o.quick ? base.quick : base.protocol;
  const preroll = o.preroll ?? protocol.preroll;
  const steps = o.steps ?? protocol.steps * o.iterations.length;

  let oursBundle = o.ours;
  if (o.engines.includes(OURS) && !oursBundle) oursBundle = buildOurs(o.log).bundle;
  const loaded = [];
  for (const id of o.engines) {
    const engine = SPLIT_ENGINES.find((e) => e.id === id);
    loaded.push({ engine, api: await engine.load({ oursBundle }) });
  }

  // best[engine][count]: the lowest round median, as the benchmark's best-round figure.
  const best = loaded.map(() => o.iterations.map(() => Infinity));
  for (let r = 0; r < o.rounds; r++) {
    // The engine order rotates per round, as in runBench, so drift spreads over all of them.
    for (let j = 0; j < loaded.length; j++) {
      const e = (j + r) % loaded.length;
      const scene = makeScene(o.scene, { quick: o.quick });
      const medians = timeWorld(loaded[e].engine, loaded[e].api, scene, o.vary, o.iterations, preroll, steps);
      best[e] = best[e].map((ms, k) => Math.min(ms, medians[k]));
    }
    o.log(`round ${r + 1} of ${o.rounds} done`);
  }

  return {
    scene: o.scene,
    vary: o.vary,
    velocityIterations: base.velocityIterations,
    positionIterations: base.positionIterations,
    machine: { cpuModel: os.cpus()[0]?.model ?? 'unknown', caches: cpuCaches(), node: process.version },
    protocol: { rounds: o.rounds, preroll, steps, iterations: o.iterations },
    engines: loaded.map(({ engine }, e) => {
      const points = o.iterations.map((v, k) => [v, best[e][k]]);
      const fit = fitLine(points);
      return {
        id: engine.id,
        name: engine.name,
        points,
        fixedMs: fit.intercept,
        perIterationMs: fit.slope,
        maxResidualMs: fit.maxResidual,
      };
    }),
  };
}

/** The results as a table; ratios are to the first engine. */
export function formatSplit(result) {
  const [first] = result.engines;
  const ratio = (a, b) => (b > 0 ? `${(a / b).toFixed(2)}x` : '-');
  const head = result.protocol.iterations.map((v) => `${v} it`.padStart(8)).join('');
  const fixed = result.vary === 'velocity' ? `${result.positionIterations} position iterations` : `${result.velocityIterations} velocity iterations`;
  const lines = [
    `${result.scene}, sleeping off, ${result.vary} iterations varied, ${fixed}; best-round median ms per step ` +
      `(${result.protocol.rounds} rounds, ${result.protocol.steps} steps after ${result.protocol.preroll}); ` +
      `${result.machine.cpuModel}${result.machine.caches.length ? `, ${describeCaches(result.machine.caches)}` : ''}, Node ${result.machine.node}`,
    `${'engine'.padEnd(22)}${head}  per iteration     rest of step   fit error`,
  ];
  for (const e of result.engines) {
    const cells = e.points.map(([, ms]) => ms.toFixed(3).padStart(8)).join('');
    lines.push(
      `${e.name.padEnd(22)}${cells}  ${e.perIterationMs.toFixed(4).padStart(7)} ${ratio(e.perIterationMs, first.perIterationMs).padStart(6)}` +
        `  ${e.fixedMs.toFixed(3).padStart(7)} ${ratio(e.fixedMs, first.fixedMs).padStart(6)}  ${e.maxResidualMs.toFixed(3).padStart(9)}`,
    );
  }
  return lines.join('\n');
}

/** Runs the command line `argv` (without node and script); resolves to the exit code. */
export function main(argv = process.argv.slice(2)) {
  return runCommand(argv, {
    options: {
      scene: { type: 'string' },
      engines: { type: 'string' },
      vary: { type: 'string' },
      iterations: { type: 'string' },
      rounds: { type: 'string' },
      preroll: { type: 'string' },
      steps: { type: 'string' },
      ours: { type: 'string' },
      quick: { type: 'boolean' },
    },
    usage: SPLIT_USAGE,
    check: resolveSplitOptions,
    run: runSplit,
    format: formatSplit,
  });
}

if (import.meta.url === pathToFileURL(process.argv[1] ?? '').href) {
  process.exitCode = await main();
}
