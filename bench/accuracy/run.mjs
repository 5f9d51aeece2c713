#!/usr/bin/env node
// The accuracy study: every scene of scenes.mjs stepped by every method of methods.mjs, each a
// point (milliseconds per simulated second, error) per measure, and the stability limits of
// limits.mjs; docs/ACCURACY.md says what each number means.
//   node bench/accuracy/run.mjs [--scenes a,b] [--methods a,b] [--gpu-methods a,b] [--peers a,b]
//                               [--quick] [--no-limits] [--gpu] [--out DIR] [--ours FILE]
// writes accuracy.json, accuracy.md and one SVG chart per scene and measure (log axes, the
// Pareto front highlighted) into bench/results/accuracy, or --out. `--quick` runs a small subset
// in seconds (CI's tests run it). `--gpu` adds the WebGPU backend's runs of some methods and their
// stability limits (on a software adapter such as SwiftShader their errors are reported and their
// times are not; merge.mjs joins parts run apart); the peer engines of `npm run bench` run every scene at their
// own settings, measured where positions suffice (default: all of them; --quick: none; --peers ''
// for none). For programs: runAccuracy(b2, options) resolves to the results.

import { mkdirSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { bisectLimit } from './limits.mjs';
import { DEFAULT_METHOD, METHODS, REFERENCE, applyMethod, methodById, stepFrame } from './methods.mjs';
import { jointErrors, trajectoryError } from './measures.mjs';
import { createBox2D221World } from '../engines/box2d221.mjs';
import {
  ACCURACY_SCENES,
  ACCURACY_SCENE_IDS,
  buildScene,
  chainData,
  plateData,
  pyramidData,
  referencePositions,
  scenePositions,
  stackData,
} from './scenes.mjs';
import { accuracyMarkdown, paretoFront, paretoSvg } from './report.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const repoRoot = path.resolve(here, '../..');

export const ACCURACY_SCHEMA = 'webphysics-accuracy/1';

/** The scenes and methods of `--quick`. */
const QUICK_SCENES = ['pendulum', 'bounce', 'slide', 'chain'];
const QUICK_METHODS = ['iter-2-1', 'iter-8-3', 'substeps-2'];
/** The methods the WebGPU backend runs with --gpu (on SwiftShader a frame takes tens of milliseconds). */
const GPU_METHODS = ['iter-4-2', 'iter-8-3', 'iter-16-6', 'dt-30', 'substeps-2'];

/**
 * Runs scene `id` under `m` once, on the JavaScript engine or, given `gpu` (gpuBackend()), on the
 * WebGPU backend (each frame's steps, then world.Synchronize()): the measures, the milliseconds
 * of stepping per simulated second, the final positions.
 */
async function runSceneOnce(b2, id, m, gpu = null) {
  const scene = ACCURACY_SCENES[id];
  const { world, data, view, probe } = buildScene(b2, id);
  applyMethod(world, m);
  const backend = gpu === null ? null : await gpu.create();
  if (backend !== null) await world.SetBackend(backend);
  try {
    const frames = Math.round(scene.seconds * m.frameHz);
    let stepping = 0;
    for (let f = 1; f <= frames; ++f) {
      const t0 = performance.now();
      stepFrame(world, m);
      if (backend !== null) await world.Synchronize();
      stepping += performance.now() - t0;
      probe.sample(f / m.frameHz);
    }
    return { measures: probe.result(), msPerSecond: stepping / scene.seconds, final: scenePositions(data, view) };
  } finally {
    await backend?.destroy();
  }
}

/**
 * Runs scene `id` once on peer engine `engine` (an adapter of bench/engines, its module `api`)
 * at its own settings (1/60 s steps; 8/3 iterations where it has them, Box2D v3 and Rapier their
 * substeps or solver iterations); the measures that need only positions.
 */
function runPeerOnce(engine, api, id) {
  const scene = ACCURACY_SCENES[id];
  const data = scene.data();
  const instance = engine.create(api, data, { sleep: false });
  try {
    const probe = scene.probe({ position: instance.position, world: null, b2: null });
    const frames = Math.round(scene.seconds * 60);
    let stepping = 0;
    for (let f = 1; f <= frames; ++f) {
      const t0 = performance.now();
      instance.step();
      stepping += performance.now() - t0;
      probe.sample(f / 60);
    }
    return { measures: probe.result(), msPerSecond: stepping / scene.seconds, final: scenePositions(data, instance) };
  } finally {
    instance.destroy();
  }
}

/**
 * The WebGPU backend of webphysics-gpu.node.mjs beside the engine bundle, on one device: `create()`
 * makes a backend for a world, `timed` says whether its times mean anything (not on a software
 * adapter such as SwiftShader, which the study still uses for the GPU's accuracy).
 */
export async function gpuBackend(gpuBundle) {
  const gpu = await import(pathToFileURL(path.resolve(gpuBundle)).href);
  const context = await gpu.requestGpu({ skipValidation: true });
  return {
    adapter: context.adapterInfo,
    timed: !context.adapterInfo.software,
    create: () => gpu.WebGPUBackend.create({ context }),
  };
}

/**
 * Runs `once` `rounds` times and keeps the fastest time (the first run of a method pays for
 * compiling its code paths); the measures are the same in every run (the engines are
 * deterministic), which is checked.
 */
async function runScene(rounds, label, once) {
  let best = await once();
  for (let i = 1; i < rounds; ++i) {
    const r = await once();
    if (JSON.stringify(r.measures) !== JSON.stringify(best.measures)) throw new Error(`${label}: two runs measured differently`);
    if (r.msPerSecond < best.msPerSecond) best = r;
  }
  return best;
}

/**
 * Whether a stack or pyramid still stands: its top box within half a box of where it started
 * (settling under load moves it by up to about 0.3 m in a pyramid of base 20; a collapse, more).
 */
function stands(top, start) {
  return Math.hypot(top[0] - start[0], top[1] - start[1]) < 0.5;
}

/**
 * Runs a world for `seconds` of `m`'s frames, on the WebGPU backend given `gpu` (synchronised
 * after every frame); calls `check` after each frame and stops when it says false.
 */
async function runWhile(world, m, seconds, check, gpu = null) {
  applyMethod(world, m);
  const backend = gpu === null ? null : await gpu.create();
  if (backend !== null) await world.SetBackend(backend);
  try {
    const frames = Math.round(seconds * m.frameHz);
    for (let f = 1; f <= frames; ++f) {
      stepFrame(world, m);
      if (backend !== null) await world.Synchronize();
      if (!check()) return false;
    }
    return true;
  } finally {
    await backend?.destroy();
  }
}

/** Standing 10 s: the top box (the last body) of a stack or pyramid built from `data` within half a box of where it started. */
function standsFor(b2, data, m, gpu, seconds = 10) {
  const built = createBox2D221World(b2, data, { sleep: false });
  const top = data.bodies.length - 1;
  const start = built.position(top);
  return runWhile(built.world, m, seconds, () => stands(built.position(top), start), gpu);
}

/**
 * The stability limits (docs/ACCURACY.md, "Stability limits"), each the limit of a stated test
 * found by bisection, for method `m` (the time-step and iteration limits vary that one setting of
 * it), on the JavaScript engine or, given `gpu` (gpuBackend()), on the WebGPU backend.
 */
export async function stabilityLimits(b2, m, { quick = false, gpu = null } = {}) {
  const out = [];
  const owner = gpu === null ? m.id : `webgpu ${m.id}`;
  const limit = async (id, test, unit, lo, hi, options, passes) => {
    const r = await bisectLimit(passes, lo, hi, options);
    out.push({ id, test, unit, method: owner, range: [lo, hi], smallest: options.smallest === true, ...r });
  };
  await limit(
    'stack height',
    'the tallest column of unit boxes whose top box stays within 0.5 m of its start for 10 s',
    'boxes',
    2,
    quick ? 16 : 80,
    { integer: true },
    (h) => standsFor(b2, stackData(h), m, gpu),
  );
  const base = quick ? 12 : 20;
  await limit(
    'iterations',
    `the fewest iterations (velocity and position, n of each) that keep a pyramid of base ${base} standing 10 s (top box within 0.5 m)`,
    'iterations',
    1,
    32,
    { integer: true, smallest: true },
    (n) => standsFor(b2, pyramidData(base), { ...m, velocityIterations: n, positionIterations: n }, gpu),
  );
  await limit(
    'frame time',
    "the longest frame (taken in the method's substeps) with which a pyramid of base 10 stands 10 s (top box within 0.5 m)",
    's',
    1 / 240,
    1 / 4,
    { tolerance: 1e-3 },
    (dt) => standsFor(b2, pyramidData(10), { ...m, frameHz: 1 / dt }, gpu),
  );
  await limit(
    'mass ratio',
    'log10 of the largest weight-to-link mass ratio at the end of a 10-link chain whose joints stay within 0.1 m for 5 s',
    'log10 ratio',
    0,
    4,
    { tolerance: 0.02 },
    (log10Ratio) => {
      const { world } = createBox2D221World(b2, chainData(10, 10 ** log10Ratio), { sleep: false });
      return runWhile(world, m, 5, () => jointErrors(world).linear < 0.1, gpu);
    },
  );
  // Whether a ball crossing the plate is stopped depends on where its steps fall (one landing in
  // the plate's near half is pushed back, one past the middle out the far side): the test takes
  // eight starts spread over one step's travel and passes only if the plate stops all of them,
  // which makes it monotone in the speed.
  const stopped = async (speed, continuous, phase) => {
    const built = createBox2D221World(b2, plateData(speed, (phase * speed) / (m.frameHz * m.substeps)), { sleep: false });
    built.world.SetContinuousPhysics(continuous);
    let x = 0;
    await runWhile(built.world, m, 1, () => ((x = built.position(1)[0]), true), gpu);
    return x < 5;
  };
  for (const continuous of [false, true]) {
    await limit(
      continuous ? 'tunnelling speed (continuous)' : 'tunnelling speed',
      `the fastest ball (radius 0.1 m) that a static plate 0.05 m thick stops from any of 8 starts over one step, continuous physics ${continuous ? 'on' : 'off'} (at most b2_maxTranslation per step)`,
      'm/s',
      1,
      2 * m.frameHz * m.substeps,
      { tolerance: 0.5 },
      async (speed) => {
        for (let k = 0; k < 8; ++k) if (!(await stopped(speed, continuous, k / 8))) return false;
        return true;
      },
    );
  }
  return out;
}

/**
 * The stability limits a peer engine's adapter can be tested on (positions only, its own
 * settings): stack height, frame time (the scene's step) and tunnelling speed with its own
 * continuous collision, by the same tests as stabilityLimits.
 */
export async function peerLimits(engine, api) {
  const out = [];
  const limit = async (id, test, unit, lo, hi, options, passes) => {
    const r = await bisectLimit(passes, lo, hi, options);
    out.push({ id, test, unit, method: engine.id, range: [lo, hi], smallest: false, ...r });
  };
  /** Steps a world built from `data` for `seconds`; false as soon as `check(instance)` is. */
  const runPeer = (data, seconds, check) => {
    const instance = engine.create(api, data, { sleep: false });
    try {
      const steps = Math.round(seconds / data.dt);
      for (let k = 0; k < steps; ++k) {
        instance.step();
        if (!check(instance)) return false;
      }
      return true;
    } finally {
      instance.destroy();
    }
  };
  const standsPeer = (data) => {
    const top = data.bodies.length - 1;
    const start = [data.bodies[top].x, data.bodies[top].y];
    return runPeer(data, 10, (instance) => {
      const p = instance.position(top);
      return p !== null && stands(p, start);
    });
  };
  await limit(
    'stack height',
    'the tallest column of unit boxes whose top box stays within 0.5 m of its start for 10 s',
    'boxes',
    2,
    80,
    { integer: true },
    (h) => standsPeer(stackData(h)),
  );
  await limit(
    'frame time',
    'the longest step with which a pyramid of base 10 stands 10 s (top box within 0.5 m)',
    's',
    1 / 240,
    1 / 4,
    { tolerance: 1e-3 },
    (dt) => standsPeer({ ...pyramidData(10), dt }),
  );
  await limit(
    'tunnelling speed',
    "the fastest ball (radius 0.1 m) that a static plate 0.05 m thick stops from any of 8 starts over one step, with the engine's own continuous collision",
    'm/s',
    1,
    120,
    { tolerance: 0.5 },
    (speed) => {
      for (let k = 0; k < 8; ++k) {
        const data = plateData(speed, (k / 8) * (speed / 60));
        let x = 0;
        runPeer(data, 1, (instance) => {
          x = instance.position(1)?.[0] ?? Infinity;
          return true;
        });
        if (!(x < 5)) return false;
      }
      return true;
    },
  );
  return out;
}

/**
 * The study with engine module `b2` (the exports of webphysics): each scene under each method,
 * the trajectory scenes against REFERENCE, the Pareto front per scene and measure, and each
 * method's stability limits.
 */
export async function runAccuracy(b2, options = {}) {
  const quick = options.quick === true;
  const sceneIds = options.scenes ?? (quick ? QUICK_SCENES : ACCURACY_SCENE_IDS);
  const methods = (options.methods ?? (quick ? QUICK_METHODS : METHODS.map((m) => m.id))).map(methodById);
  const log = options.log ?? (() => {});
  const rounds = options.rounds ?? 2;
  const gpu = options.gpu ?? null;
  const peers = options.peers ?? [];
  const gpuMethods = gpu === null ? [] : (options.gpuMethods ?? GPU_METHODS).map(methodById);
  const scenes = [];
  for (const id of sceneIds) {
    const scene = ACCURACY_SCENES[id];
    if (!scene) throw new RangeError(`unknown scene '${id}': ${ACCURACY_SCENE_IDS.join(', ')}`);
    const reference = scene.trajectory ? referencePositions(b2, id) : null;
    // Untimed: the scene's code paths compiled before the first method is timed.
    await runSceneOnce(b2, id, DEFAULT_METHOD);
    const results = [];
    const record = (backend, method, r) => {
      const measures = { ...r.measures };
      if (reference) measures['trajectory error'] = trajectoryError(reference, r.final).max;
      const msPerSecond = backend === 'webgpu' && !gpu.timed ? null : r.msPerSecond;
      const key = backend === 'js' ? method : backend === 'webgpu' ? `webgpu ${method}` : backend;
      results.push({ key, method, backend, msPerSecond, measures });
      log(`${id} / ${key}: ${msPerSecond === null ? 'untimed' : `${msPerSecond.toFixed(2)} ms per simulated second`}, ${JSON.stringify(measures)}`);
    };
    for (const m of methods) record('js', m.id, await runScene(rounds, `${id} ${m.id}`, () => runSceneOnce(b2, id, m)));
    // The GPU's runs: one each (untimed on a software adapter; deterministic either way).
    for (const m of gpuMethods) record('webgpu', m.id, await runScene(gpu.timed ? rounds : 1, `${id} webgpu ${m.id}`, () => runSceneOnce(b2, id, m, gpu)));
    // The peers, at their own settings, where the scene's measures need only positions.
    for (const { engine, api } of scene.worldOnly ? [] : peers) {
      const unsupported = engine.supports(scene.data());
      if (unsupported !== null) {
        log(`${id} / ${engine.id}: not run (${unsupported})`);
        continue;
      }
      record(engine.id, 'default', await runScene(rounds, `${id} ${engine.id}`, () => runPeerOnce(engine, api, id)));
    }
    const measureNames = Object.keys(results[0]?.measures ?? {});
    const fronts = Object.fromEntries(measureNames.map((name) => [name, paretoFront(results, name).map((r) => r.key)]));
    scenes.push({ id, title: scene.title, seconds: scene.seconds, measures: measureNames, results, fronts });
  }
  // Every method's limits; --quick: the default method's only.
  const limits = [];
  if (options.limits !== false) {
    for (const m of quick ? [DEFAULT_METHOD] : methods) limits.push(...(await stabilityLimits(b2, m, { quick })));
    for (const { engine, api } of peers) limits.push(...(await peerLimits(engine, api)));
    // The GPU's (a test is seconds of simulated time, frame by frame synchronised); --quick: the default method's only.
    if (gpu !== null && options.gpuLimits !== false) {
      for (const m of quick ? [DEFAULT_METHOD] : gpuMethods) limits.push(...(await stabilityLimits(b2, m, { quick, gpu })));
    }
  }
  for (const l of limits) log(`limit ${l.id}: ${l.limit} ${l.unit}${l.outside ? ` (${l.outside} the range)` : ''} after ${l.tests} tests`);
  const cpus = os.cpus();
  return {
    schema: ACCURACY_SCHEMA,
    date: new Date().toISOString(),
    quick,
    machine: { cpus: cpus.length, cpuModel: cpus[0]?.model ?? 'unknown', node: process.version, gpu: gpu?.adapter ?? null },
    methods: [...new Set([...methods, ...gpuMethods]), ...(sceneIds.some((id) => ACCURACY_SCENES[id].trajectory) ? [REFERENCE] : [])],
    peers: peers.map(({ engine }) => ({ id: engine.id, name: engine.name, version: engine.version ?? null, family: engine.family, notes: engine.notes ?? [] })),
    scenes,
    limits,
  };
}

/** Writes accuracy.json, accuracy.md and the charts into `dir`; returns the files written. */
export function writeAccuracy(results, dir) {
  mkdirSync(dir, { recursive: true });
  const files = [path.join(dir, 'accuracy.json'), path.join(dir, 'accuracy.md')];
  writeFileSync(files[0], JSON.stringify(results, null, 2) + '\n');
  writeFileSync(files[1], accuracyMarkdown(results));
  for (const scene of results.scenes) {
    for (const measure of scene.measures) {
      const file = path.join(dir, `accuracy-${scene.id}-${measure.replaceAll(' ', '-')}.svg`);
      writeFileSync(file, paretoSvg(scene, measure, results));
      files.push(file);
    }
  }
  return files;
}

/**
 * The peer engines' adapters (bench/engines) with their modules loaded: `ids`, or null for every
 * engine but WebPhysics; one that fails to load is left out, with a line on stderr.
 */
export async function loadPeers(ids, oursBundle) {
  if (ids !== null && ids.length === 0) return [];
  const { ENGINES } = await import('../harness.mjs');
  const known = ENGINES.filter((e) => e.id !== 'webphysics');
  for (const id of ids ?? []) if (!known.some((e) => e.id === id)) throw new RangeError(`unknown peer '${id}': ${known.map((e) => e.id).join(', ')}`);
  const out = [];
  for (const engine of known.filter((e) => ids === null || ids.includes(e.id))) {
    try {
      out.push({ engine, api: await engine.load({ oursBundle }) });
    } catch (e) {
      process.stderr.write(`${engine.id}: not loaded (${e instanceof Error ? e.message : e})\n`);
    }
  }
  return out;
}

const USAGE = `usage: node bench/accuracy/run.mjs [--scenes a,b] [--methods a,b] [--gpu-methods a,b] [--peers a,b] [--quick] [--no-limits] [--gpu] [--out DIR] [--ours FILE]
  scenes:  ${ACCURACY_SCENE_IDS.join(', ')} ('' for none: the limits only)
  methods: ${METHODS.map((m) => m.id).join(', ')} ('' for none: the GPU's only)
  gpu methods (default): ${GPU_METHODS.join(', ')}`;

async function main() {
  const { values } = parseArgs({
    options: {
      scenes: { type: 'string' },
      methods: { type: 'string' },
      'gpu-methods': { type: 'string' },
      quick: { type: 'boolean', default: false },
      'no-limits': { type: 'boolean', default: false },
      gpu: { type: 'boolean', default: false },
      peers: { type: 'string' },
      out: { type: 'string' },
      ours: { type: 'string' },
      help: { type: 'boolean', default: false },
    },
  });
  if (values.help) {
    process.stdout.write(USAGE + '\n');
    return;
  }
  let bundle = values.ours;
  if (!bundle) {
    const { buildOurs } = await import('../harness.mjs');
    bundle = buildOurs((s) => process.stderr.write(s + '\n')).bundle;
  }
  const b2 = await import(pathToFileURL(path.resolve(bundle)).href);
  const gpu = values.gpu ? await gpuBackend(path.join(path.dirname(bundle), 'webphysics-gpu.node.mjs')) : null;
  if (gpu) process.stderr.write(`WebGPU: ${gpu.adapter.description || gpu.adapter.device}${gpu.timed ? '' : ' (software: its runs are not timed)'}\n`);
  const peers = await loadPeers(values.peers === undefined ? (values.quick ? [] : null) : values.peers === '' ? [] : values.peers.split(','), bundle);
  const results = await runAccuracy(b2, {
    gpu,
    peers,
    quick: values.quick,
    scenes: values.scenes === '' ? [] : values.scenes?.split(','),
    methods: values.methods === '' ? [] : values.methods?.split(','),
    gpuMethods: values['gpu-methods']?.split(','),
    limits: !values['no-limits'],
    log: (s) => process.stderr.write(s + '\n'),
  });
  const dir = values.out ?? path.join(repoRoot, 'bench', 'results', 'accuracy');
  for (const f of writeAccuracy(results, dir)) process.stderr.write(`wrote ${path.relative(process.cwd(), f)}\n`);
  process.stdout.write(accuracyMarkdown(results));
}

if (import.meta.url === pathToFileURL(process.argv[1] ?? '').href) {
  main().catch((e) => {
    process.stderr.write(`${e instanceof Error ? e.message : e}\n${USAGE}\n`);
    process.exit(1);
  });
}
