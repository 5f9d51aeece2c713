/*
 * The large-world page's frame timed in Node: its scenes (demos/compare/scenes.ts: pyramids, rain,
 * sand) stepped by the WebGPU backend through the world API and drawn by GpuRenderer into an
 * offscreen 1920 x 1080 texture, as large.html steps and draws them into its canvas, 10^4 to 10^6
 * bodies. A frame is world.Step, renderer.drawTo, then waiting for the queue (onSubmittedWorkDone):
 * the wall time of one step and one draw with nothing overlapped. The step alone (Step, then the
 * queue) and the draw alone (drawTo, then the queue) are timed the same way, to say which part
 * stands in the way of 60 frames a second.
 *
 * Built into one file by `node scripts/build-gpu.mjs` (dist/bench-gpu-render.mjs, `webgpu` left
 * external). On a lent H100 (`.device` from `bash ../shared/gpu/prepare.sh`): carry `.device` and
 * `dist/bench-gpu-render.mjs`, run
 *   bash .device/run.sh node --max-old-space-size=60000 dist/bench-gpu-render.mjs
 *
 *   node dist/bench-gpu-render.mjs [--scenes pyramids,rain,sand] [--sizes 1e4,1e5,1e6] [--frames 20]
 *        [--quick] [--out DIR]
 *
 * Per scene and size (sleeping off, seed 1, Dawn's validation off): GPU_WARMUP frames, then
 * `--frames` frames, steps and draws; medians. Output: gpu-render.json and .md in $OUT, or --out,
 * or bench/results, rewritten after every row (a run cut short keeps what it measured).
 */

import { mkdirSync, writeFileSync } from 'node:fs';
import { cpus } from 'node:os';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { WebGPUBackend } from '../src-gpu/backend/backend';
import { requestGpu } from '../src-gpu/device/device';
import type { GpuContext } from '../src-gpu/device/device';
import { TEXTURE_USAGE } from '../src-gpu/device/layout';
import { GpuRenderer } from '../src-gpu/render/render';
import { DT, POSITION_ITERATIONS, VELOCITY_ITERATIONS } from '../demos/compare/config';
import type { SceneName } from '../demos/compare/config';
import { buildScene } from '../demos/compare/scenes';
import { deviceName, fmt, median } from './gpu-support';

const SCENES: SceneName[] = ['pyramids', 'rain', 'sand'];
const MAX_BODIES = 1_000_000;
const GPU_WARMUP = 5;
const WIDTH = 1920;
const HEIGHT = 1080;

interface Row {
  scene: SceneName;
  bodies: number;
  buildMs: number;
  attachMs: number;
  /** Medians in milliseconds: a step and a draw, a step alone, a draw alone. */
  frameMs: number;
  stepMs: number;
  drawMs: number;
  /** Proxy slots the renderer examined (its cull pass, on the GPU, picks those drawn; none is read back). */
  drawn: number;
  error: string | null;
}

function message(error: unknown): string {
  return error instanceof Error ? error.message : String(error);
}

async function runRow(ctx: GpuContext, scene: SceneName, bodies: number, frames: number): Promise<Row> {
  const row: Row = { scene, bodies, buildMs: NaN, attachMs: NaN, frameMs: NaN, stepMs: NaN, drawMs: NaN, drawn: 0, error: null };
  const t0 = performance.now();
  const built = buildScene({ scene, bodies, seed: 1, sleep: false }, MAX_BODIES);
  row.buildMs = performance.now() - t0;
  const backend = await WebGPUBackend.create({ context: ctx });
  const t1 = performance.now();
  await built.world.SetBackend(backend);
  row.attachMs = performance.now() - t1;
  const renderer = new GpuRenderer(backend, null);
  const { view } = built;
  Object.assign(renderer.camera, { x: view.x, y: view.y, scale: Math.min(WIDTH / (2 * view.halfWidth), HEIGHT / (2 * view.halfHeight)) });
  const texture = ctx.device.createTexture({ size: [WIDTH, HEIGHT], format: renderer.format, usage: TEXTURE_USAGE.RENDER_ATTACHMENT });
  const queue = ctx.device.queue;
  const step = () => built.world.Step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
  const timed = async (n: number, body: () => Promise<void>): Promise<number> => {
    const times: number[] = [];
    for (let i = 0; i < n; ++i) {
      const s = performance.now();
      await body();
      await queue.onSubmittedWorkDone();
      times.push(performance.now() - s);
    }
    return median(times);
  };
  try {
    await timed(GPU_WARMUP, async () => {
      step();
      await renderer.drawTo(texture);
    });
    row.frameMs = await timed(frames, async () => {
      step();
      await renderer.drawTo(texture);
    });
    row.stepMs = await timed(frames, async () => {
      step();
      await backend.submitted();
    });
    row.drawMs = await timed(frames, () => renderer.drawTo(texture));
    row.drawn = renderer.lastFrame?.proxies ?? 0;
  } finally {
    texture.destroy();
    renderer.destroy();
    await backend.destroy();
  }
  return row;
}

function markdown(rows: Row[], meta: Record<string, unknown>): string {
  const lines = [
    `# GPU frame: step and draw (${meta.device})`,
    '',
    `${meta.date}; Node ${meta.node}; ${meta.cpu}; ${WIDTH} x ${HEIGHT} rgba8unorm target; medians of ${meta.frames} frames after ${GPU_WARMUP}.`,
    '',
    '| scene | bodies | frame (step + draw) ms | fps | step ms | draw ms | build s | attach s |',
    '| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |',
  ];
  for (const r of rows) {
    if (r.error !== null) {
      lines.push(`| ${r.scene} | ${r.bodies} | failed: ${r.error} | | | | | |`);
      continue;
    }
    lines.push(
      `| ${r.scene} | ${r.bodies} | ${fmt(r.frameMs)} | ${(1000 / r.frameMs).toFixed(0)} | ${fmt(r.stepMs)} | ${fmt(r.drawMs)} | ${(r.buildMs / 1000).toFixed(1)} | ${(r.attachMs / 1000).toFixed(1)} |`,
    );
  }
  return lines.join('\n') + '\n';
}

function write(outDir: string, rows: Row[], meta: Record<string, unknown>): string {
  mkdirSync(outDir, { recursive: true });
  const md = markdown(rows, meta);
  writeFileSync(path.join(outDir, 'gpu-render.json'), JSON.stringify({ meta, rows }, null, 2) + '\n');
  writeFileSync(path.join(outDir, 'gpu-render.md'), md);
  return md;
}

async function main(): Promise<number> {
  const { values } = parseArgs({
    args: process.argv.slice(2),
    options: {
      scenes: { type: 'string' },
      sizes: { type: 'string' },
      frames: { type: 'string' },
      quick: { type: 'boolean' },
      out: { type: 'string' },
      help: { type: 'boolean', short: 'h' },
    },
  });
  if (values.help) {
    process.stdout.write('node dist/bench-gpu-render.mjs [--scenes pyramids,rain,sand] [--sizes 1e4,1e5,1e6] [--frames 20] [--quick] [--out DIR]\n');
    return 0;
  }
  const quick = values.quick === true;
  const scenes = (values.scenes ?? SCENES.join(',')).split(',') as SceneName[];
  for (const scene of scenes) if (!SCENES.includes(scene)) throw new Error(`--scenes: unknown scene ${scene} (${SCENES.join(', ')})`);
  const sizes = (values.sizes ?? (quick ? '1e3' : '1e4,1e5,1e6')).split(',').map(Number);
  for (const n of sizes)
    if (!Number.isInteger(n) || n < 100 || n > MAX_BODIES) throw new Error(`--sizes: each must be an integer from 100 to ${MAX_BODIES}; got ${n}`);
  const frames = Math.max(1, Number(values.frames ?? (quick ? 3 : 20)));
  const outDir = values.out ?? process.env.OUT ?? path.resolve('bench/results');

  const ctx = await requestGpu({ skipValidation: true });
  const a = ctx.adapterInfo;
  const device = deviceName(a);
  console.error(`adapter: ${device}`);
  const meta = {
    device,
    adapter: a,
    cpu: `${cpus()[0]?.model ?? 'unknown'} (${cpus().length} threads)`,
    node: process.version,
    date: new Date().toISOString(),
    frames,
  };
  const rows: Row[] = [];
  const started = performance.now();
  for (const bodies of sizes) {
    for (const scene of scenes) {
      let row: Row;
      try {
        row = await runRow(ctx, scene, bodies, frames);
      } catch (error) {
        row = { scene, bodies, buildMs: NaN, attachMs: NaN, frameMs: NaN, stepMs: NaN, drawMs: NaN, drawn: 0, error: message(error) };
      }
      rows.push(row);
      write(outDir, rows, meta);
      console.error(
        `${scene.padEnd(9)} ${String(bodies).padStart(8)}  ` +
          (row.error ?? `frame ${fmt(row.frameMs)} ms (step ${fmt(row.stepMs)}, draw ${fmt(row.drawMs)}), drawn ${row.drawn}`) +
          ` [${((performance.now() - started) / 1000).toFixed(0)} s]`,
      );
    }
  }
  process.stdout.write(write(outDir, rows, meta));
  ctx.destroy();
  return rows.some((r) => r.error !== null) ? 1 : 0;
}

main().then(
  (code) => process.exit(code),
  (error) => {
    console.error(error);
    process.exit(1);
  },
);
