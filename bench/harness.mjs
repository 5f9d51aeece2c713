// The benchmark harness: builds each scene in each engine, times its steps, measures memory, checks
// that the scene simulates, and reports (terminal tables, JSON, SVG charts).
//
// Protocol, per scene and sleep setting: `rounds` rounds; in each, every engine in turn (the order
// rotates from round to round, so slow drift on a shared machine spreads over all engines) gets a
// forced full GC, builds a fresh world, steps it `preroll` times untimed (JIT warm-up, settling,
// the tumbler's fill), then `steps` steps timed one by one with tinybench. Per-step times of all
// rounds are pooled for the median and p95. The last round then runs `allocSteps` more steps to
// count allocated bytes (see memory.mjs), and reads the counts and sanity check. World heap and
// heap growth come from a process of the engine's own (heap.mjs).
import { execFileSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readdirSync, readFileSync, writeFileSync, rmSync } from 'node:fs';
import os from 'node:os';
import v8 from 'node:v8';
import path from 'node:path';
import { Bench, hrtimeNow } from 'tinybench';
import { SCENE_IDS, makeScene, sceneStepper, totalBodies } from './scenes.mjs';
import { fullGC, measureAllocation } from './memory.mjs';
import { measureHeapInChild } from './heap.mjs';
import { formatSceneTables, chartSvg, markdownSummary, compactSummary, describeCaches } from './report.mjs';
import { repoRoot } from './engines/common.mjs';
import webphysics from './engines/webphysics.mjs';
import box2dWasm from './engines/box2d-wasm.mjs';
import box2d3Wasm from './engines/box2d3-wasm.mjs';
import rapier from './engines/rapier.mjs';
import phaserBox2d from './engines/phaser-box2d.mjs';
import box2dweb from './engines/box2dweb.mjs';
import box2dCore from './engines/box2d-core.mjs';
import planck from './engines/planck.mjs';
import matter from './engines/matter.mjs';

/** Every engine adapter, in table order: ours first, then native stand-ins, then JavaScript. */
export const ENGINES = [webphysics, box2dWasm, box2d3Wasm, rapier, phaserBox2d, box2dweb, box2dCore, planck, matter];
export const ENGINE_IDS = ENGINES.map((e) => e.id);
export { SCENE_IDS };
export const OURS = 'webphysics';
/**
 * `--baseline FILE`: another WebPhysics bundle (for example one built from git HEAD) run as one more
 * engine, `webphysics-baseline`, with the same adapter, so a change is measured side by side with
 * the code before it, in the same process and rounds.
 */
export const BASELINE = 'webphysics-baseline';
const baselineAdapter = {
  ...webphysics,
  id: BASELINE,
  name: 'WebPhysics baseline',
  load: ({ baselineBundle }) => webphysics.load({ oursBundle: baselineBundle }),
};

/** The adapter of an engine id, the baseline's included. */
export function engineById(id) {
  const e = id === BASELINE ? baselineAdapter : ENGINES.find((x) => x.id === id);
  if (!e) throw new Error(`unknown engine "${id}"`);
  return e;
}
export const RESULTS_SCHEMA = 'webphysics-bench/1';

const list = (v, all, what) => {
  if (v === undefined || v === null || v === 'all') return [...all];
  const ids = Array.isArray(v)
    ? v
    : String(v)
        .split(',')
        .map((s) => s.trim())
        .filter(Boolean);
  for (const id of ids) if (!all.includes(id)) throw new Error(`unknown ${what} "${id}" (known: ${all.join(', ')})`);
  return ids;
};

/** Fills in defaults and checks the options; see runBench. */
export function resolveOptions(opts = {}) {
  const sleep = opts.sleep ?? 'both';
  if (!['on', 'off', 'both'].includes(sleep)) throw new Error(`sleep must be on, off or both, not "${sleep}"`);
  const quick = Boolean(opts.quick);
  const engines = list(opts.engines, ENGINE_IDS, 'engine');
  if (opts.baseline && !engines.includes(BASELINE)) engines.splice(engines.includes(OURS) ? engines.indexOf(OURS) + 1 : 0, 0, BASELINE);
  return {
    scenes: list(opts.scenes, SCENE_IDS, 'scene'),
    engines,
    sleep,
    quick,
    steps: opts.steps ?? null,
    rounds: opts.rounds ?? null,
    preroll: opts.preroll ?? null,
    allocSteps: opts.allocSteps ?? null,
    allocPreroll: opts.allocPreroll ?? 0,
    ours: opts.ours ?? null,
    baseline: opts.baseline ?? null,
    // Quick runs print only, unless told where to write.
    write: opts.write ?? (quick ? Boolean(opts.outDir) : true),
    outDir: opts.outDir ?? path.join(repoRoot, 'bench', 'results'),
    charts: opts.charts ?? true,
    log: opts.log === undefined ? (s) => process.stderr.write(s + '\n') : (opts.log ?? (() => {})),
    print: opts.print === undefined ? (s) => process.stdout.write(s + '\n') : (opts.print ?? (() => {})),
  };
}

/** Builds the ES module bundle of the working tree into a temporary folder; returns its path. */
export function buildOurs(log) {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'webphysics-bench-'));
  const t = performance.now();
  execFileSync(process.execPath, [path.join(repoRoot, 'scripts', 'build.mjs'), dir], { cwd: repoRoot, stdio: 'inherit' });
  log(`built ${path.join(dir, 'webphysics.mjs')} in ${((performance.now() - t) / 1000).toFixed(1)} s`);
  return { bundle: path.join(dir, 'webphysics.mjs'), dir };
}

function machine() {
  const cpus = os.cpus();
  return {
    cpus: cpus.length,
    cpuModel: cpus[0]?.model ?? 'unknown',
    memoryGiB: Math.round(os.totalmem() / 2 ** 30),
    caches: cpuCaches(),
    node: process.version,
    v8: process.versions.v8,
    platform: `${os.platform()} ${os.release()} ${os.arch()}`,
  };
}

/**
 * The first CPU's data caches, as Linux lists them in sysfs: [{ level, kib, sharedBy }], sharedBy
 * the number of CPUs sharing that cache; [] where sysfs has no such list. Recorded because the
 * ratio of a JavaScript engine to a WebAssembly one moves with them more than with anything else:
 * bench2d's data fits a 2 MiB cache for box2d-wasm and not for WebPhysics (bench/README.md).
 */
export function cpuCaches(dir = '/sys/devices/system/cpu/cpu0/cache') {
  let entries;
  try {
    entries = readdirSync(dir).filter((e) => /^index\d+$/.test(e));
  } catch {
    return [];
  }
  const read = (e, f) => readFileSync(path.join(dir, e, f), 'utf8').trim();
  const out = [];
  for (const e of entries) {
    try {
      if (read(e, 'type') === 'Instruction') continue;
      const size = /^(\d+)K$/.exec(read(e, 'size'));
      if (!size) continue;
      out.push({ level: Number(read(e, 'level')), kib: Number(size[1]), sharedBy: cpuCount(read(e, 'shared_cpu_list')) });
    } catch {
      // An entry without the files above (some kernels and containers): left out.
    }
  }
  return out.sort((a, b) => a.level - b.level);
}

/** The number of CPUs in a sysfs CPU list such as "0-3,8". */
function cpuCount(list) {
  let n = 0;
  for (const part of list.split(',')) {
    const [lo, hi = lo] = part.split('-').map(Number);
    n += hi - lo + 1;
  }
  return n;
}

/** Option `name`'s value v as a positive integer (fallback when absent); throws naming it otherwise. */
export function positiveInt(name, v, fallback) {
  if (v === undefined || v === null) return fallback;
  const n = Number(v);
  if (!Number.isInteger(n) || n < 1) throw new Error(`${name} must be a positive integer, not "${v}"`);
  return n;
}

/** The q-quantile of ascending values `sorted`, interpolated between neighbours; null for none. */
export function quantile(sorted, q) {
  if (sorted.length === 0) return null;
  const pos = (sorted.length - 1) * q;
  const lo = Math.floor(pos);
  return lo + 1 < sorted.length ? sorted[lo] + (pos - lo) * (sorted[lo + 1] - sorted[lo]) : sorted[lo];
}

function summarize(samples) {
  const s = [...samples].sort((a, b) => a - b);
  const total = s.reduce((a, b) => a + b, 0);
  const mean = total / s.length;
  return {
    medianMs: quantile(s, 0.5),
    p95Ms: quantile(s, 0.95),
    meanMs: mean,
    minMs: s[0],
    maxMs: s[s.length - 1],
    stepsPerSecond: 1000 / mean,
    samples: s.length,
  };
}

/** One round of one engine on one scene; returns per-step times and, on the last round, the rest. */
function runRound(engine, api, scene, sleep, protocol, last) {
  fullGC();
  const w = engine.create(api, scene, { sleep });
  const stepper = sceneStepper(w, scene);
  const doStep = stepper.step;
  const readTrack = () => scene.track.map((i) => w.position(i));
  const before = readTrack();

  for (let i = 0; i < protocol.preroll; i++) doStep();

  // tinybench calls the task function once when it is added (to see whether it is async), so the
  // step only runs once armed by beforeAll.
  fullGC();
  let armed = false;
  const bench = new Bench({ iterations: protocol.steps, time: 0, warmup: false, now: hrtimeNow, throws: true });
  bench.add(
    'step',
    () => {
      if (armed) doStep();
    },
    {
      beforeAll() {
        armed = true;
      },
      afterAll() {
        armed = false;
      },
    },
  );
  bench.runSync();
  const result = bench.tasks[0].result;
  if (result.error) throw result.error;
  const samples = [...result.latency.samples];
  if (samples.length !== protocol.steps) throw new Error(`tinybench ran ${samples.length} steps, not ${protocol.steps}`);

  let extra = null;
  if (last) {
    for (let i = 0; i < protocol.allocPreroll; i++) doStep();
    fullGC();
    const alloc = measureAllocation(() => {
      for (let i = 0; i < protocol.allocSteps; i++) doStep();
    });
    const after = readTrack();
    extra = {
      memory: {
        worldBytes: null,
        heapGrowthBytes: null,
        allocBytesPerStep: alloc.bytes / protocol.allocSteps,
        allocSteps: protocol.allocSteps,
        gcPer1000Steps: (alloc.gcCount * 1000) / protocol.allocSteps,
        gcMsPerStep: alloc.gcMs / protocol.allocSteps,
        wasmBytes: w.wasmBytes ? w.wasmBytes() : null,
      },
      counts: { bodies: w.bodyCount(), contacts: w.contactCount(), steps: stepper.steps },
      check: scene.check(before, after),
      sample: after[0],
    };
  }
  w.destroy();
  return { samples, extra };
}

/**
 * Runs the benchmark and returns the results object (also written as JSON unless write is false).
 * Options: scenes, engines (arrays or comma lists, default all), sleep ('on' | 'off' | 'both'),
 * quick (tiny protocol for tests and CI smoke), steps / rounds / preroll / allocSteps (override
 * every scene's protocol), ours (path of a prebuilt webphysics.mjs instead of building one),
 * write, outDir (default bench/results), charts, log / print (functions, or null for silence).
 */
export async function runBench(options = {}) {
  const o = resolveOptions(options);
  // Engines take turns in one process, and every forced GC ages the bytecode of the engines not
  // running; V8 would then flush it and recompile it in the next round. An app with one engine
  // never sees that (its step code runs every frame), so flushing is turned off for the run.
  v8.setFlagsFromString('--no-flush-bytecode');
  const started = new Date();
  const m = machine();
  const caches = m.caches.length ? `, ${describeCaches(m.caches)}` : '';
  o.log(`webphysics bench: ${m.cpus} x ${m.cpuModel}${caches}, Node ${m.node}, ${started.toISOString()}`);

  let built = null;
  let oursBundle = o.ours;
  if (o.engines.includes(OURS) && !oursBundle) {
    built = buildOurs(o.log);
    oursBundle = built.bundle;
  }

  const engines = [];
  for (const id of o.engines) {
    const e = engineById(id);
    try {
      const t = performance.now();
      const api = await e.load({ oursBundle, baselineBundle: o.baseline });
      engines.push({ e, api, error: null });
      o.log(`loaded ${e.name} ${e.version ?? ''} in ${(performance.now() - t).toFixed(0)} ms`);
    } catch (err) {
      engines.push({
        e,
        api: null,
        error: String(err?.stack ?? err)
          .split('\n')
          .slice(0, 3)
          .join(' | '),
      });
      o.log(`could not load ${e.name}: ${err?.message ?? err}`);
    }
  }

  const sleeps = o.sleep === 'both' ? [false, true] : [o.sleep === 'on'];
  o.print(
    'median and p95: ms per step over all timed steps; steps/s: 1000 / mean; x ours: median / WebPhysics median ' +
      '(below 1 is faster than WebPhysics); alloc/step: JS heap bytes allocated per step in steady state; ' +
      'heap growth: JS heap kept by the run; world heap: JS heap held by the world (+ wasm linear memory)',
  );
  const out = {
    schema: RESULTS_SCHEMA,
    date: started.toISOString(),
    machine: m,
    options: {
      scenes: o.scenes,
      engines: o.engines,
      sleep: o.sleep,
      quick: o.quick,
      steps: o.steps,
      rounds: o.rounds,
      preroll: o.preroll,
      allocSteps: o.allocSteps,
      allocPreroll: o.allocPreroll,
      ours: oursBundle ? (built ? 'built from the working tree (scripts/build.mjs)' : oursBundle) : null,
      baseline: o.baseline,
    },
    engines: engines.map(({ e, error, api }) => ({
      id: e.id,
      name: e.name,
      package: e.pkg ?? 'webphysics',
      version: e.version,
      family: e.family,
      notes: e.notes,
      simd: api?.simd,
      loadError: error,
    })),
    scenes: [],
  };

  for (const sceneId of o.scenes) {
    const scene = makeScene(sceneId, { quick: o.quick });
    if (!scene) {
      o.log(`skipping ${sceneId}: its data file is missing (set WEBPHYSICS_GOLDEN)`);
      out.scenes.push({ id: sceneId, skipped: 'scene data missing' });
      continue;
    }
    const base = o.quick ? scene.quick : scene.protocol;
    const protocol = {
      preroll: o.preroll ?? base.preroll,
      steps: o.steps ?? base.steps,
      rounds: o.rounds ?? base.rounds,
    };
    protocol.allocSteps = o.allocSteps ?? (o.quick ? null : base.allocSteps) ?? Math.min(protocol.steps, 32);
    protocol.allocPreroll = o.allocPreroll;
    const sceneOut = {
      id: scene.id,
      title: scene.title,
      description: scene.description + (o.quick ? ' (quick mode: built small)' : ''),
      bodies: totalBodies(scene),
      joints: scene.joints.length,
      settings: { dt: scene.dt, velocityIterations: scene.velocityIterations, positionIterations: scene.positionIterations },
      protocol,
      results: [],
    };
    for (const sleep of sleeps) {
      const rows = engines.map(({ e, api, error }) => ({
        engine: e.id,
        name: e.name,
        sleep,
        status: error ? 'error' : 'ok',
        reason: error ? `load failed: ${error}` : e.supports(scene),
        samples: [],
        roundMedians: [],
        extra: null,
      }));
      for (const r of rows) if (r.reason && r.status === 'ok') r.status = 'skipped';
      const t0 = performance.now();
      for (let round = 0; round < protocol.rounds; round++) {
        const last = round === protocol.rounds - 1;
        const order = rows.map((_, i) => (i + round) % rows.length);
        for (const i of order) {
          const row = rows[i];
          if (row.status !== 'ok') continue;
          const { e, api } = engines[i];
          try {
            const { samples, extra } = runRound(e, api, scene, sleep, protocol, last);
            row.samples.push(...samples);
            row.roundMedians.push(
              quantile(
                [...samples].sort((a, b) => a - b),
                0.5,
              ),
            );
            if (extra) row.extra = extra;
          } catch (err) {
            row.status = 'error';
            row.reason = String(err?.message ?? err);
            o.log(`${e.name} failed on ${scene.id}: ${err?.stack ?? err}`);
          }
        }
      }
      for (const r of rows) {
        if (r.status !== 'ok' || !r.extra) continue;
        try {
          Object.assign(
            r.extra.memory,
            measureHeapInChild({
              engine: r.engine,
              oursBundle,
              baselineBundle: o.baseline,
              scene: scene.id,
              quick: o.quick,
              sleep,
              steps: protocol.preroll + protocol.steps + protocol.allocPreroll + protocol.allocSteps,
            }),
          );
        } catch (err) {
          o.log(String(err?.message ?? err));
        }
      }
      const ours = rows.find((r) => r.engine === OURS && r.status === 'ok');
      const oursTiming = ours ? summarize(ours.samples) : null;
      for (const r of rows) {
        const timing = r.status === 'ok' ? summarize(r.samples) : null;
        sceneOut.results.push({
          engine: r.engine,
          sleep: r.sleep,
          status: r.status,
          reason: r.reason ?? null,
          timing: timing && { ...timing, roundMedians: r.roundMedians, bestRoundMedianMs: Math.min(...r.roundMedians) },
          ratioToOurs: timing && oursTiming ? timing.medianMs / oursTiming.medianMs : null,
          memory: r.extra?.memory ?? null,
          counts: r.extra?.counts ?? null,
          check: r.extra?.check ?? null,
        });
      }
      o.log(`${scene.id} sleep ${sleep ? 'on' : 'off'}: ${((performance.now() - t0) / 1000).toFixed(1)} s`);
      o.print(formatSceneTables(sceneOut, out.engines, sleep));
    }
    out.scenes.push(sceneOut);
  }
  out.durationSeconds = (Date.now() - started.getTime()) / 1000;

  if (o.write) {
    mkdirSync(o.outDir, { recursive: true });
    const stamp = started
      .toISOString()
      .replace(/[:]/g, '-')
      .replace(/\.\d+Z$/, 'Z');
    const name = `${stamp}${o.quick ? '-quick' : ''}.json`;
    const json = JSON.stringify(out, null, 1);
    writeFileSync(path.join(o.outDir, name), json);
    writeFileSync(path.join(o.outDir, 'latest.json'), json);
    const compact = [false, true]
      .filter((sleep) => sleeps.includes(sleep))
      .map((sleep) => `Sleeping ${sleep ? 'on' : 'off'}: best-round median ms per step (x ours)\n\n${compactSummary(out, sleep)}`);
    const md = `# Benchmark results (${name})\n\n${compact.join('\n\n')}\n\n${markdownSummary(out, '.')}\n`;
    writeFileSync(path.join(o.outDir, 'latest.md'), md);
    out.files = [path.join(o.outDir, name), path.join(o.outDir, 'latest.json'), path.join(o.outDir, 'latest.md')];
    if (o.charts) {
      for (const s of out.scenes) {
        if (s.skipped) continue;
        const file = path.join(o.outDir, `${s.id}.svg`);
        writeFileSync(file, chartSvg(s, out));
        out.files.push(file);
      }
    }
    o.log(`wrote ${out.files.map((f) => path.relative(process.cwd(), f)).join(', ')}`);
  }
  if (built) rmSync(built.dir, { recursive: true, force: true });
  return out;
}
