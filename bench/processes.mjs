#!/usr/bin/env node
// Step times of engines side by side, each run in a Node process of its own:
//   node bench/processes.mjs [--scene bench2d] [--engines webphysics,box2d-wasm] [--runs 10]
//                            [--steps 600] [--windows 64-192,192-600] [--ours FILE]
//                            [--baseline FILE] [--box2d DIR] [--quick] [--json]
// A run of an engine is a fresh process that builds the scene three times, steps each world
// `steps` times (sleeping off) and reports, for each window of steps, the median step time over
// the second and third worlds (the first warms the JIT up). Runs of the engines alternate, and
// each engine's figure per window is the median of its runs. Against the benchmark's one process
// (bench/harness.mjs) this costs a process start per run and gains steadiness: no engine's garbage
// or compiled code is in another's heap, and no engine keeps another world alive while one is
// timed. Changes of a few percent, which move less than the benchmark's run-to-run spread, are
// measured this way (docs/PORTING.md). With --box2d, Box2D 2.2.1's own C++ runs too, as the engines
// box2d-native and box2d-native-f64 (bench/native.mjs), in the same alternation.
//
// For programs: `runProcesses(options)` resolves to the results object.
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { BASELINE, ENGINE_IDS, OURS, SCENE_IDS, buildOurs, engineById, positiveInt, quantile } from './harness.mjs';
import { makeScene, sceneStepper } from './scenes.mjs';
import { runCommand, runJsonChild, runJsonProgram } from './command.mjs';
import { NATIVE_ENGINES, box2dIncludeDir, buildNative, nativeSceneText } from './native.mjs';

export const PROCESSES_USAGE = `usage: node bench/processes.mjs [options]

  --scene ID        scene (default bench2d): ${SCENE_IDS.join(', ')}
  --engines a,b     engines (default webphysics,box2d-wasm): ${ENGINE_IDS.join(', ')}, ${BASELINE},
                    ${Object.keys(NATIVE_ENGINES).join(', ')}
  --runs N          processes per engine, alternating (default 10)
  --steps N         steps per world, three worlds a process (default 600)
  --windows a-b,... step windows [a, b) to report (default 64-192,192-600)
  --ours FILE       use this webphysics.mjs bundle instead of building the working tree
  --baseline FILE   the bundle ${BASELINE} runs (needed when it is among the engines)
  --box2d DIR       a Box2D 2.2.1 checkout, built with g++ ($CXX) for the native engines
  --quick           the scene built small, 2 runs of 40 steps, windows 4-20,20-40
  --json            print the results JSON to stdout (the table goes to stderr)
  -h, --help        this text`;

const WORLDS = 3;

/** "64-192,192-600" as [[64, 192], [192, 600]], each window within [0, steps). */
export function parseWindows(text, steps) {
  return String(text)
    .split(',')
    .map((w) => {
      const m = /^\s*(\d+)-(\d+)\s*$/.exec(w);
      if (!m) throw new Error(`window "${w}" is not FROM-TO`);
      const [a, b] = [Number(m[1]), Number(m[2])];
      if (!(a < b && b <= steps)) throw new Error(`window ${a}-${b} must satisfy FROM < TO <= steps (${steps})`);
      return [a, b];
    });
}

/** Fills in defaults and checks the options; see runProcesses. */
export function resolveProcessesOptions(opts = {}) {
  const quick = Boolean(opts.quick);
  const scene = opts.scene ?? 'bench2d';
  if (!SCENE_IDS.includes(scene)) throw new Error(`unknown scene "${scene}" (known: ${SCENE_IDS.join(', ')})`);
  const list = opts.engines ?? [OURS, 'box2d-wasm'];
  const engines = Array.isArray(list)
    ? list
    : String(list)
        .split(',')
        .map((s) => s.trim())
        .filter(Boolean);
  if (engines.length === 0) throw new Error('engines must name at least one engine');
  for (const id of engines) if (!NATIVE_ENGINES[id]) engineById(id);
  if (engines.includes(BASELINE) && !opts.baseline) throw new Error(`${BASELINE} needs --baseline FILE`);
  const native = engines.filter((id) => NATIVE_ENGINES[id]);
  if (native.length > 0 && !opts.box2d) throw new Error(`${native.join(', ')} needs --box2d DIR`);
  if (opts.box2d) box2dIncludeDir(opts.box2d);
  const steps = positiveInt('steps', opts.steps, quick ? 40 : 600);
  return {
    scene,
    engines,
    runs: positiveInt('runs', opts.runs, quick ? 2 : 10),
    steps,
    windows: parseWindows(opts.windows ?? (quick ? '4-20,20-40' : '64-192,192-600'), steps),
    quick,
    ours: opts.ours ?? null,
    baseline: opts.baseline ?? null,
    box2d: opts.box2d ?? null,
    log: opts.log === undefined ? (s) => process.stderr.write(s + '\n') : (opts.log ?? (() => {})),
  };
}

/**
 * Runs every engine `runs` times, each in a process of its own, and resolves to { scene, steps,
 * windows, runs, engines: [{ id, name, windowMs: [median of the runs per window], runsMs: [[ms per
 * window] per run] }] }. Options: scene, engines, runs, steps, windows, quick, ours, baseline, box2d,
 * log.
 */
export async function runProcesses(options = {}) {
  const o = resolveProcessesOptions(options);
  let oursBundle = o.ours;
  let built = null;
  if (o.engines.includes(OURS) && !oursBundle) {
    built = buildOurs(o.log);
    oursBundle = built.bundle;
  }
  let nativeDir = null;
  try {
    let runNative = null;
    if (o.engines.some((id) => NATIVE_ENGINES[id])) {
      const exe = await buildNative(o.box2d, o.log);
      nativeDir = mkdtempSync(path.join(os.tmpdir(), 'webphysics-native-scene-'));
      const sceneFile = path.join(nativeDir, `${o.scene}.txt`);
      writeFileSync(sceneFile, nativeSceneText(makeScene(o.scene, { quick: o.quick }), o.steps));
      const windows = o.windows.map(([a, b]) => `${a}-${b}`);
      runNative = (id) => runJsonProgram(exe[NATIVE_ENGINES[id].build], [sceneFile, String(o.steps), ...windows], id);
    }
    const runs = o.engines.map(() => []);
    for (let r = 0; r < o.runs; r++) {
      for (let i = 0; i < o.engines.length; i++) {
        const id = o.engines[i];
        if (NATIVE_ENGINES[id]) {
          runs[i].push(runNative(id));
          continue;
        }
        const args = JSON.stringify({ engine: id, oursBundle, baselineBundle: o.baseline, scene: o.scene, quick: o.quick, steps: o.steps, windows: o.windows });
        runs[i].push(runJsonChild([fileURLToPath(import.meta.url), '--child', args], id));
      }
      o.log(`run ${r + 1} of ${o.runs} done`);
    }
    return {
      scene: o.scene,
      steps: o.steps,
      windows: o.windows,
      runs: o.runs,
      engines: o.engines.map((id, i) => ({
        id,
        name: NATIVE_ENGINES[id]?.name ?? engineById(id).name,
        windowMs: o.windows.map((_, k) =>
          quantile(
            runs[i].map((run) => run[k]).sort((a, b) => a - b),
            0.5,
          ),
        ),
        runsMs: runs[i],
      })),
    };
  } finally {
    if (built) rmSync(built.dir, { recursive: true, force: true });
    if (nativeDir) rmSync(nativeDir, { recursive: true, force: true });
  }
}

/** The results as a table: each window's median ms per step, and its ratio to the first engine's. */
export function formatProcesses(result) {
  const head = result.windows.map(([a, b]) => `steps ${a}-${b}`);
  const first = result.engines[0];
  const rows = result.engines.map((e) => [
    e.name.padEnd(22),
    ...e.windowMs.map((ms, k) => `${ms.toFixed(3)} ${(ms / first.windowMs[k]).toFixed(2)}x`.padStart(16)),
  ]);
  return [
    `${result.scene}, sleeping off: median of ${result.runs} processes per engine of the median ms per step over worlds 2-3 of ${WORLDS} (${result.steps} steps each); x the first engine`,
    ['engine'.padEnd(22), ...head.map((h) => h.padStart(16))].join(''),
    ...rows.map((r) => r.join('')),
  ].join('\n');
}

/** One run, in the child: the window medians of worlds 2-3. */
async function child(args) {
  const o = JSON.parse(args);
  const engine = engineById(o.engine);
  const api = await engine.load({ oursBundle: o.oursBundle, baselineBundle: o.baselineBundle });
  const kept = [];
  for (let k = 0; k < WORLDS; k++) {
    const scene = makeScene(o.scene, { quick: o.quick });
    const w = engine.create(api, scene, { sleep: false });
    const { step } = sceneStepper(w, scene);
    const t = [];
    for (let i = 0; i < o.steps; i++) {
      const a = performance.now();
      step();
      t.push(performance.now() - a);
    }
    w.destroy();
    if (k > 0) kept.push(t);
  }
  const medians = o.windows.map(([a, b]) =>
    quantile(
      kept.flatMap((t) => t.slice(a, b)).sort((x, y) => x - y),
      0.5,
    ),
  );
  process.stdout.write(`${JSON.stringify(medians)}\n`);
}

/** The command line `argv` (without node and the script); resolves to the exit code. */
export function main(argv = process.argv.slice(2)) {
  return runCommand(argv, {
    options: {
      scene: { type: 'string' },
      engines: { type: 'string' },
      runs: { type: 'string' },
      steps: { type: 'string' },
      windows: { type: 'string' },
      ours: { type: 'string' },
      baseline: { type: 'string' },
      box2d: { type: 'string' },
      quick: { type: 'boolean' },
    },
    usage: PROCESSES_USAGE,
    check: resolveProcessesOptions,
    run: runProcesses,
    format: formatProcesses,
  });
}

if (process.argv[1] && import.meta.url === pathToFileURL(process.argv[1]).href) {
  if (process.argv[2] === '--child') {
    child(process.argv[3]).catch((err) => {
      process.stderr.write(`${err?.stack ?? err}\n`);
      process.exit(1);
    });
  } else {
    process.exitCode = await main();
  }
}
