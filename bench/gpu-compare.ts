/*
 * The comparison page's panes timed in Node: its own scenes (demos/compare/scenes.ts) and stepping
 * code (demos/compare/pane.ts: JsPane, and GpuPane, which steps through the world API as an
 * application does, world.Step then WebGPUBackend.readTransforms) at the page's slider sizes, the
 * JavaScript engine on the CPU against the WebGPU backend through Dawn, so the page's numbers can
 * be had on a real GPU where no browser runs.
 *
 * Built into one file by `node scripts/build-gpu.mjs` (dist/bench-gpu-compare.mjs, `webgpu` left
 * external). On a lent H100 (`.device` from `bash ../shared/gpu/prepare.sh`): carry `.device` and
 * `dist/bench-gpu-compare.mjs`, run
 *   bash .device/run.sh node --max-old-space-size=16000 dist/bench-gpu-compare.mjs
 *
 *   node dist/bench-gpu-compare.mjs [--scenes pyramids,rain,joint-grid,tumbler] [--sizes 100,...]
 *        [--steps 15] [--js-budget 2] [--quick] [--out DIR]
 *
 * Per scene and size, as the page runs them (sleeping off, seed 1): the JavaScript pane, 20 warm-up
 * steps (or 1 s), then `--steps` steps or `--js-budget` seconds, median step time; the WebGPU pane twice,
 * on a device as a browser gives one (Dawn's validation on) and on one with validation off, each
 * 5 warm-up steps then `--steps` steps, median of Step + readTransforms. Build times (the scene,
 * and the scene plus SetBackend) are reported too. JS/GPU > 1: the GPU pane steps faster.
 * Output: gpu-compare.json and .md in $OUT, or --out, or bench/results, rewritten after every row (a run
 * cut short keeps what it measured); the table on stdout.
 */

import { mkdirSync, writeFileSync } from 'node:fs';
import { cpus } from 'node:os';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { requestGpu } from '../src-gpu/device/device';
import type { GpuContext } from '../src-gpu/device/device';
import { BODY_COUNTS, SCENE_NAMES, TRANSFORM_STRIDE } from '../demos/compare/config';
import type { SceneConfig, SceneName } from '../demos/compare/config';
import { GpuPane, JsPane } from '../demos/compare/pane';
import { crossover, deviceName, fmt, median } from './gpu-support';
import type { Crossover } from './gpu-support';

/** JavaScript warm-up: until V8 has compiled the step (this many steps or this long, at least two steps). */
const JS_WARMUP = 20;
const JS_WARMUP_SECONDS = 1;
const GPU_WARMUP = 5;

interface Timing {
  /** Median step time (ms). */
  ms: number;
  steps: number;
  /** Building the scene (JS), or the scene and attaching the backend (GPU), in ms. */
  buildMs: number;
  contacts: number;
}

interface Row {
  scene: SceneName;
  bodies: number;
  js: Timing | null;
  gpu: Timing | null;
  gpuNoValidation: Timing | null;
  errors: string[];
}

function buffers(bodies: number): { out: Float32Array; awake: Uint8Array } {
  return { out: new Float32Array(TRANSFORM_STRIDE * bodies), awake: new Uint8Array(bodies) };
}

function runJs(config: SceneConfig, steps: number, budgetSeconds: number): Timing {
  const started = performance.now();
  const pane = new JsPane(config);
  const buildMs = performance.now() - started;
  const { out, awake } = buffers(pane.scene.bodies.length);
  const warm = performance.now() + 1000 * JS_WARMUP_SECONDS;
  for (let i = 0; i < JS_WARMUP && (i < 2 || performance.now() < warm); ++i) pane.step(out, awake);
  const times: number[] = [];
  const deadline = performance.now() + 1000 * budgetSeconds;
  while (times.length < steps && (times.length < 2 || performance.now() < deadline)) times.push(pane.step(out, awake).stepMs);
  return { ms: median(times), steps: times.length, buildMs, contacts: pane.stats.contacts };
}

async function runGpu(config: SceneConfig, ctx: GpuContext, steps: number): Promise<Timing> {
  const started = performance.now();
  const pane = await GpuPane.create(config, { context: ctx });
  const buildMs = performance.now() - started;
  try {
    const { out, awake } = buffers(pane.scene.bodies.length);
    for (let i = 0; i < GPU_WARMUP; ++i) await pane.step(out, awake);
    const times: number[] = [];
    for (let i = 0; i < steps; ++i) times.push((await pane.step(out, awake)).stepMs);
    return { ms: median(times), steps: times.length, buildMs, contacts: pane.stats.contacts };
  } finally {
    await pane.destroy();
  }
}

const message = (error: unknown) => (error instanceof Error ? error.message : String(error));
const cell = (t: Timing | null) => (t === null ? '–' : fmt(t.ms));
const ratio = (js: Timing | null, gpu: Timing | null) => (js && gpu ? fmt(js.ms / gpu.ms) : '–');

function markdown(rows: Row[], crossovers: Crossover[], meta: Record<string, unknown>): string {
  const lines = [
    "# The comparison page's panes on a real GPU: JavaScript engine vs WebGPU backend through the world API",
    '',
    `GPU: ${meta.device}. CPU: ${meta.cpu}. Node ${meta.node}. ${meta.date}.`,
    "The page's scenes and stepping code (demos/compare), seed 1, sleeping off, 1/60 s, 8 velocity / 3 position iterations.",
    `JS: b2World.Step, median of up to ${meta.steps} steps (${meta.jsBudget} s budget) after ${JS_WARMUP} (or ${JS_WARMUP_SECONDS} s); WebGPU: world.Step +`,
    `backend.readTransforms (every body's transform, one map), median of ${meta.steps} steps after ${GPU_WARMUP}, with Dawn's`,
    'validation on (as in a browser) and off. Milliseconds per step; JS/GPU above 1: the GPU pane is faster.',
    '',
    '| scene | bodies | JS | WebGPU | WebGPU, validation off | JS/GPU | JS/GPU, validation off | build JS | build + attach GPU |',
    '| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |',
  ];
  for (const r of rows) {
    lines.push(
      `| ${r.scene} | ${r.bodies} | ${cell(r.js)} | ${cell(r.gpu)} | ${cell(r.gpuNoValidation)} | ${ratio(r.js, r.gpu)} | ${ratio(r.js, r.gpuNoValidation)} | ` +
        `${r.js ? fmt(r.js.buildMs) : '–'} | ${r.gpu ? fmt(r.gpu.buildMs) : '–'} |`,
    );
  }
  lines.push('', 'Crossover (the WebGPU pane, validation on, faster than the JavaScript pane):', '');
  for (const c of crossovers) lines.push(`- ${c.scene}: ${c.text}`);
  const failures = rows.filter((r) => r.errors.length > 0);
  if (failures.length > 0) {
    lines.push('', 'Failures:', '');
    for (const r of failures) lines.push(`- ${r.scene} ${r.bodies}: ${r.errors.join('; ')}`);
  }
  return lines.join('\n') + '\n';
}

/** Writes gpu-compare.json and .md with the rows so far (a run cut short keeps what it measured); returns the markdown. */
function write(outDir: string, rows: Row[], scenes: SceneName[], meta: Record<string, unknown>): string {
  const crossovers = scenes.map((scene) =>
    crossover(
      scene,
      rows.filter((r) => r.scene === scene && r.js && r.gpu).map((r) => ({ n: r.bodies, jsMs: r.js!.ms, gpuMs: r.gpu!.ms })),
    ),
  );
  mkdirSync(outDir, { recursive: true });
  const md = markdown(rows, crossovers, meta);
  writeFileSync(path.join(outDir, 'gpu-compare.json'), JSON.stringify({ meta, rows, crossovers }, null, 2) + '\n');
  writeFileSync(path.join(outDir, 'gpu-compare.md'), md);
  return md;
}

async function main(): Promise<number> {
  const { values } = parseArgs({
    args: process.argv.slice(2),
    options: {
      scenes: { type: 'string' },
      sizes: { type: 'string' },
      steps: { type: 'string' },
      'js-budget': { type: 'string' },
      quick: { type: 'boolean' },
      out: { type: 'string' },
      help: { type: 'boolean', short: 'h' },
    },
  });
  if (values.help) {
    process.stdout.write(
      'node dist/bench-gpu-compare.mjs [--scenes pyramids,rain,joint-grid,tumbler] [--sizes 100,...] [--steps 15] [--js-budget 2] [--quick] [--out DIR]\n',
    );
    return 0;
  }
  const quick = values.quick === true;
  const scenes = (values.scenes ?? SCENE_NAMES.join(',')).split(',') as SceneName[];
  for (const scene of scenes) if (!SCENE_NAMES.includes(scene)) throw new Error(`--scenes: unknown scene ${scene} (${SCENE_NAMES.join(', ')})`);
  const sizes = values.sizes !== undefined ? values.sizes.split(',').map(Number) : quick ? [100, 1000] : BODY_COUNTS;
  const steps = Math.max(1, Number(values.steps ?? (quick ? 3 : 15)));
  const jsBudget = Number(values['js-budget'] ?? (quick ? 1 : 2));
  const outDir = values.out ?? process.env.OUT ?? path.resolve('bench/results');

  const validated = await requestGpu();
  const unvalidated = await requestGpu({ skipValidation: true });
  const a = validated.adapterInfo;
  const device = deviceName(a);
  console.error(`adapter: ${device}`);
  const meta = {
    device,
    adapter: a,
    cpu: `${cpus()[0]?.model ?? 'unknown'} (${cpus().length} threads)`,
    node: process.version,
    date: new Date().toISOString(),
    steps,
    jsBudget,
  };
  const rows: Row[] = [];
  const started = performance.now();
  for (const scene of scenes) {
    for (const bodies of sizes) {
      const config: SceneConfig = { scene, bodies, seed: 1, sleep: false };
      const row: Row = { scene, bodies, js: null, gpu: null, gpuNoValidation: null, errors: [] };
      try {
        row.js = runJs(config, steps, jsBudget);
      } catch (error) {
        row.errors.push(`JS: ${message(error)}`);
      }
      try {
        row.gpu = await runGpu(config, validated, steps);
        row.gpuNoValidation = await runGpu(config, unvalidated, steps);
      } catch (error) {
        row.errors.push(`GPU: ${message(error)}`);
      }
      rows.push(row);
      write(outDir, rows, scenes, meta);
      console.error(
        `${scene.padEnd(10)} ${String(bodies).padStart(7)}  js ${cell(row.js)} ms, gpu ${cell(row.gpu)} ms, no validation ${cell(row.gpuNoValidation)} ms` +
          `${row.errors.length > 0 ? `  ${row.errors.join('; ')}` : ''} [${((performance.now() - started) / 1000).toFixed(0)} s]`,
      );
    }
  }
  process.stdout.write(write(outDir, rows, scenes, meta));
  console.error(`wrote ${path.join(outDir, 'gpu-compare.{json,md}')}`);
  validated.destroy();
  unvalidated.destroy();
  return rows.some((r) => r.errors.length > 0) ? 1 : 0;
}

main().then(
  (code) => process.exit(code),
  (error) => {
    console.error(error);
    process.exit(1);
  },
);
