/*
 * The GPU broad phase against the JavaScript dynamic tree, 10^3 to 10^6 proxies.
 *
 * Built into one file by `node scripts/build-gpu.mjs` (dist/bench-gpu-broadphase.mjs, with the
 * `webgpu` package left external), so it runs where only Node and .device/node_modules exist:
 *
 *   node dist/bench-gpu-broadphase.mjs [--sizes 1e3,1e4,1e5,1e6] [--scenarios uniform,clustered,huge]
 *        [--steps 20] [--js-budget 4] [--js-max 1e6] [--no-check] [--quick] [--out DIR]
 *
 * Each scenario is a world of n bodies with one fixture each (boxes and circles, 0.1-0.5 m),
 * moving at up to 4 m/s at 60 Hz:
 *   uniform    centres uniform in a square of side 1.6 sqrt(n) m (about one pair per proxy);
 *   clustered  half of them uniform, half in dense discs (8 x the density);
 *   huge       uniform, plus one static box covering the whole square (n more pairs).
 * GPU: the world is mirrored once (GpuWorld), then every step a small kernel moves the bodies on
 * the GPU (not counted) and GpuBroadPhase.update() finds the pairs from the body transforms:
 * bounds, axis, sort, sweep, pairs. Reported per step: the device time of those passes
 * (timestamp queries; medians), per pass, and the wall time of update() (encode, submit, wait, read
 * back the 64-byte state). Dispatch overhead is measured apart: the same number of dispatches of an
 * empty kernel (device time), and an empty submit + onSubmittedWorkDone round trip (wall).
 * JS: the engine's b2BroadPhase (b2DynamicTree) with the same bodies and motion: every step each
 * body's swept AABB goes to MoveProxy, then UpdatePairs (median ms per step; steps until
 * --js-budget seconds; the first UpdatePairs after creating the proxies, which queries all of them,
 * is skipped). The tree re-queries only proxies that left their fat AABB, so it reports new pairs
 * only; the GPU recomputes every pair from scratch.
 * Check: the GPU pair count equals a CPU sweep over the GPU's own AABBs (--no-check skips it).
 * Output: gpu-broadphase.json, .md and .svg in $OUT, or --out, or bench/results.
 */

import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { b2AABB } from '../src/collision/b2Collision';
import { b2BroadPhase } from '../src/collision/b2BroadPhase';
import { b2CircleShape } from '../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../src/collision/shapes/b2PolygonShape';
import type { b2Shape } from '../src/collision/shapes/b2Shape';
import { b2Transform, b2Vec2 } from '../src/common/b2Math';
import { GpuBroadPhase } from '../src-gpu/broadphase/broadPhase';
import type { BroadPhaseResult } from '../src-gpu/broadphase/broadPhase';
import { requestGpu } from '../src-gpu/device/device';
import type { GpuContext } from '../src-gpu/device/device';
import { USAGE } from '../src-gpu/device/layout';
import { GpuWorld } from '../src-gpu/world/world';
import { deviceName, fmt, logLogChart, median, rng, syntheticWorld } from './gpu-support';
import type { SyntheticBody } from './gpu-support';

const DT = 1 / 60;

interface Scenario {
  name: string;
  n: number;
  side: number;
  x: Float64Array;
  y: Float64Array;
  vx: Float64Array;
  vy: Float64Array;
  shape: b2Shape[];
  dynamic: Uint8Array;
}

function makeScenario(name: string, n: number): Scenario {
  const r = rng(n * 31 + name.length);
  const side = 1.6 * Math.sqrt(n);
  const count = name === 'huge' ? n + 1 : n;
  const s: Scenario = {
    name,
    n: count,
    side,
    x: new Float64Array(count),
    y: new Float64Array(count),
    vx: new Float64Array(count),
    vy: new Float64Array(count),
    shape: [],
    dynamic: new Uint8Array(count),
  };
  // A few shared shapes (fixtures clone them; the GPU mirror packs each fixture).
  const shapes: b2Shape[] = [];
  for (let k = 0; k < 8; ++k) {
    const h = 0.1 + 0.4 * (k / 7);
    if (k % 4 === 3) {
      const c = new b2CircleShape();
      c.m_radius = h;
      shapes.push(c);
    } else {
      const p = new b2PolygonShape();
      p.SetAsBox(h, h * (0.6 + (0.4 * ((k * 5) % 7)) / 6));
      shapes.push(p);
    }
  }
  const clusters = Math.max(1, Math.round(n / 20000));
  const perCluster = n / 2 / clusters;
  const density = n / (side * side);
  const clusterRadius = Math.sqrt(perCluster / (8 * density) / Math.PI);
  const centres = Array.from({ length: clusters }, () => [(r() - 0.5) * (side - 2 * clusterRadius), (r() - 0.5) * (side - 2 * clusterRadius)]);
  for (let i = 0; i < n; ++i) {
    if (name === 'clustered' && i % 2 === 1) {
      const [cx, cy] = centres[(i >> 1) % clusters];
      const a = 2 * Math.PI * r();
      const d = clusterRadius * Math.sqrt(r());
      s.x[i] = cx + d * Math.cos(a);
      s.y[i] = cy + d * Math.sin(a);
    } else {
      s.x[i] = (r() - 0.5) * side;
      s.y[i] = (r() - 0.5) * side;
    }
    const speed = 4 * r();
    const dir = 2 * Math.PI * r();
    s.vx[i] = speed * Math.cos(dir);
    s.vy[i] = speed * Math.sin(dir);
    s.shape.push(shapes[Math.floor(r() * shapes.length)]);
    s.dynamic[i] = 1;
  }
  if (name === 'huge') {
    const ground = new b2PolygonShape();
    ground.SetAsBox(side / 2, side / 2);
    s.shape.push(ground);
    s.dynamic[n] = 0;
  }
  return s;
}

/** Moves body i one step (float64), bouncing off the square's walls. */
function moveBody(s: Scenario, i: number): void {
  if (!s.dynamic[i]) return;
  const h = s.side / 2;
  let x = s.x[i] + s.vx[i] * DT;
  let y = s.y[i] + s.vy[i] * DT;
  if (x < -h || x > h) {
    s.vx[i] = -s.vx[i];
    x = s.x[i];
  }
  if (y < -h || y > h) {
    s.vy[i] = -s.vy[i];
    y = s.y[i];
  }
  s.x[i] = x;
  s.y[i] = y;
}

/** The scenario's bodies for syntheticWorld: one shape each. */
function scenarioBodies(s: Scenario): SyntheticBody[] {
  const bodies: SyntheticBody[] = [];
  for (let i = 0; i < s.n; ++i) {
    bodies.push({ x: s.x[i], y: s.y[i], angle: 0, vx: s.vx[i], vy: s.vy[i], w: 0, dynamic: s.dynamic[i] !== 0, shapes: [s.shape[i]], sensor: false });
  }
  return bodies;
}

const MOVE_WGSL = `
struct Params { count: u32, dt: f32, half: f32, cellSize: f32 }
@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read_write> xf: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read_write> vel: array<vec4<f32>>;
@group(0) @binding(3) var<storage, read> cell: array<vec2<i32>>;
@compute @workgroup_size(256)
fn main(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
  let i = gid.x + gid.y * nwg.x * 256u;
  if (i >= params.count) { return; }
  var v = vel[i];
  var t = xf[i];
  let next = t.xy + v.xy * params.dt;
  let world = vec2<f32>(cell[i]) * params.cellSize + next;
  if (abs(world.x) > params.half) { v.x = -v.x; } else { t.x = next.x; }
  if (abs(world.y) > params.half) { v.y = -v.y; } else { t.y = next.y; }
  xf[i] = t;
  vel[i] = v;
}`;

const EMPTY_WGSL = `@compute @workgroup_size(1) fn main() {}`;

/** Pairs of live AABBs (float32, read back from the GPU) that overlap, by a CPU sweep along x. */
function cpuPairCount(aabbs: Float32Array, dynamic: (slot: number) => boolean): number {
  const n = aabbs.length / 4;
  const order: number[] = [];
  for (let i = 0; i < n; ++i) if (aabbs[4 * i] <= aabbs[4 * i + 2]) order.push(i);
  order.sort((a, b) => aabbs[4 * a] - aabbs[4 * b]);
  let count = 0;
  for (let i = 0; i < order.length; ++i) {
    const a = order[i];
    const ux = aabbs[4 * a + 2];
    for (let j = i + 1; j < order.length; ++j) {
      const b = order[j];
      if (aabbs[4 * b] > ux) break;
      if (aabbs[4 * b + 1] <= aabbs[4 * a + 3] && aabbs[4 * a + 1] <= aabbs[4 * b + 3] && (dynamic(a) || dynamic(b))) count++;
    }
  }
  return count;
}

interface GpuRow {
  deviceMs: number;
  stagesMs: Record<string, number>;
  wallMs: number;
  overheadMs: number;
  roundTripMs: number;
  dispatches: number;
  pairs: number;
  strips: number;
  entries: number;
  syncMs: number;
  checked: boolean | null;
}

async function runGpu(ctx: GpuContext, s: Scenario, steps: number, check: boolean): Promise<GpuRow> {
  const world = syntheticWorld(scenarioBodies(s));
  const mirror = new GpuWorld(ctx, world);
  const t0 = performance.now();
  mirror.sync();
  const syncMs = performance.now() - t0;
  const broadPhase = new GpuBroadPhase(ctx, { initialPairCapacity: 4 * s.n });
  const device = ctx.device;

  const move = device.createComputePipeline({
    layout: 'auto',
    compute: { module: device.createShaderModule({ code: MOVE_WGSL }), entryPoint: 'main' },
  });
  const params = ctx.createBuffer('move params', 16, USAGE.UNIFORM | USAGE.COPY_DST);
  const words = new ArrayBuffer(16);
  new Uint32Array(words)[0] = s.n;
  new Float32Array(words).set([DT, s.side / 2, mirror.cellSize], 1);
  device.queue.writeBuffer(params, 0, words);
  const moveGroup = device.createBindGroup({
    layout: move.getBindGroupLayout(0),
    entries: [
      { binding: 0, resource: { buffer: params } },
      { binding: 1, resource: { buffer: mirror.bodyXf.buffer } },
      { binding: 2, resource: { buffer: mirror.bodyVel.buffer } },
      { binding: 3, resource: { buffer: mirror.bodyCell.buffer } },
    ],
  });
  const groups = Math.ceil(s.n / 256);
  const moveStep = () => {
    const enc = device.createCommandEncoder();
    const pass = enc.beginComputePass();
    pass.setPipeline(move);
    pass.setBindGroup(0, moveGroup);
    pass.dispatchWorkgroups(Math.min(groups, 65535), Math.ceil(groups / 65535));
    pass.end();
    device.queue.submit([enc.finish()]);
  };

  let last: BroadPhaseResult | null = null;
  const device_: number[] = [];
  const wall: number[] = [];
  const stages: Record<string, number[]> = {};
  for (let step = 0; step < steps + 2; ++step) {
    moveStep();
    await device.queue.onSubmittedWorkDone();
    const w0 = performance.now();
    last = await broadPhase.update(mirror);
    const w = performance.now() - w0;
    if (step < 2) continue; // warm-up
    wall.push(w);
    if (last.gpuTime) {
      device_.push(last.gpuTime.total);
      for (const [k, v] of Object.entries(last.gpuTime)) (stages[k] ??= []).push(v);
    }
  }

  // Dispatch overhead: as many empty dispatches as the update recorded, in one timed pass.
  const empty = device.createComputePipeline({
    layout: 'auto',
    compute: { module: device.createShaderModule({ code: EMPTY_WGSL }), entryPoint: 'main' },
  });
  const overhead: number[] = [];
  const roundTrip: number[] = [];
  if (ctx.timestamps) {
    const qs = device.createQuerySet({ type: 'timestamp', count: 2 });
    const resolve = ctx.createBuffer('ts resolve', 16, USAGE.QUERY_RESOLVE | USAGE.COPY_SRC);
    const read = ctx.createBuffer('ts read', 16, USAGE.MAP_READ | USAGE.COPY_DST);
    for (let rep = 0; rep < 7; ++rep) {
      const enc = device.createCommandEncoder();
      const pass = enc.beginComputePass({ timestampWrites: { querySet: qs, beginningOfPassWriteIndex: 0, endOfPassWriteIndex: 1 } });
      pass.setPipeline(empty);
      for (let i = 0; i < last!.dispatches; ++i) pass.dispatchWorkgroups(1);
      pass.end();
      enc.resolveQuerySet(qs, 0, 2, resolve, 0);
      enc.copyBufferToBuffer(resolve, 0, read, 0, 16);
      device.queue.submit([enc.finish()]);
      await read.mapAsync(1);
      const t = new BigInt64Array(read.getMappedRange().slice(0));
      read.unmap();
      overhead.push(Number(t[1] - t[0]) / 1e6);
    }
  }
  for (let rep = 0; rep < 9; ++rep) {
    const r0 = performance.now();
    device.queue.submit([device.createCommandEncoder().finish()]);
    await device.queue.onSubmittedWorkDone();
    roundTrip.push(performance.now() - r0);
  }

  let checked: boolean | null = null;
  if (check) {
    const aabbs = await broadPhase.readAABBs();
    const dyn = (slot: number) => ((mirror.bodyFlags.u32[mirror.bodySlot(mirror.proxyAt(slot)!.fixture.m_body)] >>> 16) & 3) === 2;
    checked = cpuPairCount(aabbs, dyn) === last!.pairCount;
  }
  const stagesMs: Record<string, number> = {};
  for (const [k, v] of Object.entries(stages)) if (k !== 'total') stagesMs[k] = median(v);
  broadPhase.destroy();
  mirror.destroy();
  return {
    deviceMs: median(device_),
    stagesMs,
    wallMs: median(wall),
    overheadMs: median(overhead),
    roundTripMs: median(roundTrip),
    dispatches: last!.dispatches,
    pairs: last!.pairCount,
    strips: last!.strips,
    entries: last!.entries,
    syncMs,
    checked,
  };
}

interface JsRow {
  ms: number;
  steps: number;
  createMs: number;
  newPairs: number;
  movedFraction: number;
}

function runJs(s: Scenario, budgetSeconds: number): JsRow {
  const bp = new b2BroadPhase();
  const xf = new b2Transform();
  const aabb1 = new b2AABB();
  const aabb2 = new b2AABB();
  const aabb = new b2AABB();
  const displacement = new b2Vec2();
  const ids = new Int32Array(s.n);
  const t0 = performance.now();
  for (let i = 0; i < s.n; ++i) {
    xf.p.Set(s.x[i], s.y[i]);
    s.shape[i].ComputeAABB(aabb, xf, 0);
    ids[i] = bp.CreateProxy(aabb, i);
  }
  let pairs = 0;
  const counter = { AddPair: () => void pairs++ };
  // Steady state only: the first UpdatePairs would query every new proxy once (not a step's work).
  bp.m_moveCount = 0;
  const createMs = performance.now() - t0;
  const times: number[] = [];
  let moved = 0;
  const start = performance.now();
  while (times.length < 2 || (performance.now() - start < budgetSeconds * 1000 && times.length < 50)) {
    pairs = 0;
    const s0 = performance.now();
    for (let i = 0; i < s.n; ++i) {
      if (!s.dynamic[i]) continue;
      // b2Fixture::Synchronize: the AABB swept from the old transform to the new one.
      const x1 = s.x[i];
      const y1 = s.y[i];
      xf.p.Set(x1, y1);
      s.shape[i].ComputeAABB(aabb1, xf, 0);
      moveBody(s, i);
      xf.p.Set(s.x[i], s.y[i]);
      s.shape[i].ComputeAABB(aabb2, xf, 0);
      aabb.Combine2(aabb1, aabb2);
      displacement.Set(s.x[i] - x1, s.y[i] - y1);
      bp.MoveProxy(ids[i], aabb, displacement);
    }
    moved = bp.m_moveCount;
    bp.UpdatePairs(counter);
    times.push(performance.now() - s0);
  }
  return { ms: median(times), steps: times.length, createMs, newPairs: pairs, movedFraction: moved / s.n };
}

function svgChart(rows: Row[]): string {
  return logLogChart(rows, {
    title: 'Broad phase per step: GPU sweep-and-prune vs the JavaScript dynamic tree',
    xLabel: 'proxies',
    x: (r) => r.proxies,
    xText: (v) => v.toExponential(0).replace('e+', 'e'),
    group: (r) => r.scenario,
    colours: { uniform: '#1f77b4', clustered: '#d62728', huge: '#2ca02c' },
    series: [
      { label: 'GPU device', value: (r) => r.gpu?.deviceMs, dash: '' },
      { label: 'GPU wall', value: (r) => r.gpu?.wallMs, dash: '6 3' },
      { label: 'GPU wall, no validation', value: (r) => r.unvalidated?.wallMs, dash: '1 2' },
      { label: 'JS tree', value: (r) => r.js?.ms, dash: '2 3' },
    ],
  });
}

interface Row {
  scenario: string;
  proxies: number;
  gpu: GpuRow | null;
  /** The same update on a second device with Dawn's validation off (GpuContextOptions.skipValidation). */
  unvalidated: GpuRow | null;
  js: JsRow | null;
}

function markdown(rows: Row[], meta: Record<string, unknown>): string {
  const lines = [
    `# GPU broad phase vs the JavaScript dynamic tree`,
    '',
    `Device: ${meta.device}. Node ${meta.node}. ${meta.date}. Milliseconds per step, medians.`,
    '',
    '| scenario | proxies | pairs | GPU device ms | bounds | axis | sort | sweep | pairs | empty dispatches ms | GPU wall ms | GPU wall, no validation | JS tree ms | JS moved | JS/GPU wall, no validation | check |',
    '| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |',
  ];
  for (const r of rows) {
    const g = r.gpu;
    const st = g?.stagesMs ?? {};
    lines.push(
      `| ${r.scenario} | ${r.proxies} | ${g?.pairs ?? '–'} | ${fmt(g?.deviceMs)} | ${fmt(st.bounds)} | ${fmt(st.axis)} | ${fmt(st.sort)} | ${fmt(st.sweep)} | ${fmt(st.pairs)} | ${fmt(g?.overheadMs)} (${g?.dispatches ?? '–'}) | ${fmt(g?.wallMs)} | ${fmt(r.unvalidated?.wallMs)} | ${fmt(r.js?.ms)} | ${r.js ? `${(100 * r.js.movedFraction).toFixed(0)}%` : '–'} | ${r.js && r.unvalidated ? fmt(r.js.ms / r.unvalidated.wallMs) : '–'} | ${g?.checked === null || g === null ? '–' : g.checked ? 'ok' : 'MISMATCH'} |`,
    );
  }
  lines.push(
    '',
    'GPU device ms: timestamp-query time of the broad-phase passes (bounds, axis, sort, sweep, pairs);',
    'empty dispatches: the same number of dispatches of an empty kernel (the part of the device time that',
    'is dispatch overhead); GPU wall: GpuBroadPhase.update() from call to resolved promise (encode, submit,',
    `wait, 64-byte read-back; an empty submit round trip is ${fmt(rows.find((r) => r.gpu)?.gpu?.roundTripMs)} ms). JS tree: b2BroadPhase MoveProxy for`,
    'every body + UpdatePairs; "moved" is the share of proxies that left their fat AABB and were re-queried.',
    "GPU wall, no validation: the same on a second device created with skipValidation (Dawn's skip_validation",
    "toggle): Dawn's validation of each recorded command is most of the host time on the H100.",
    'check: the GPU pair count equals a CPU sweep over the same AABBs.',
  );
  return lines.join('\n') + '\n';
}

async function main(): Promise<number> {
  const { values } = parseArgs({
    args: process.argv.slice(2),
    options: {
      sizes: { type: 'string' },
      scenarios: { type: 'string' },
      steps: { type: 'string' },
      'js-budget': { type: 'string' },
      'js-max': { type: 'string' },
      'no-check': { type: 'boolean' },
      'no-js': { type: 'boolean' },
      quick: { type: 'boolean' },
      out: { type: 'string' },
      help: { type: 'boolean', short: 'h' },
    },
  });
  if (values.help) {
    process.stdout.write(
      'node dist/bench-gpu-broadphase.mjs [--sizes 1e3,1e4,1e5,1e6] [--scenarios uniform,clustered,huge] [--steps 20] [--js-budget 4] [--js-max 1e6] [--no-check] [--no-js] [--quick] [--out DIR]\n',
    );
    return 0;
  }
  const quick = values.quick === true;
  const sizes = (values.sizes ?? (quick ? '1e3,1e4' : '1e3,1e4,1e5,1e6')).split(',').map(Number);
  const scenarios = (values.scenarios ?? 'uniform,clustered,huge').split(',');
  const steps = Number(values.steps ?? (quick ? 3 : 20));
  const jsBudget = Number(values['js-budget'] ?? (quick ? 0.5 : 4));
  const jsMax = Number(values['js-max'] ?? 1e6);
  const outDir = values.out ?? process.env.OUT ?? path.resolve('bench/results');

  let finished = false;
  const ctx = await requestGpu({
    dawnOptions: ['disable-dawn-features=timestamp_quantization'],
    onLost: (info) => {
      if (!finished) console.error('device lost', info);
    },
  });
  const unvalidatedCtx = await requestGpu({ dawnOptions: ['disable-dawn-features=timestamp_quantization'], skipValidation: true });
  const a = ctx.adapterInfo;
  const deviceLine = deviceName(a);
  console.error(`adapter: ${deviceLine}; timestamps: ${ctx.timestamps}`);
  const rows: Row[] = [];
  for (const size of sizes) {
    for (const name of scenarios) {
      const scenario = makeScenario(name, size);
      const gpu = await runGpu(ctx, scenario, steps, values['no-check'] !== true);
      const unvalidated = await runGpu(unvalidatedCtx, makeScenario(name, size), steps, false);
      const js = values['no-js'] || size > jsMax ? null : runJs(makeScenario(name, size), jsBudget);
      const row: Row = { scenario: name, proxies: scenario.n, gpu, unvalidated, js };
      rows.push(row);
      console.error(
        `${name.padEnd(9)} ${String(scenario.n).padStart(8)}  pairs ${String(gpu.pairs).padStart(8)}  gpu ${fmt(gpu.deviceMs)} ms (${Object.entries(
          gpu.stagesMs,
        )
          .map(([k, v]) => `${k} ${fmt(v)}`)
          .join(
            ', ',
          )}; empty ${fmt(gpu.overheadMs)})  wall ${fmt(gpu.wallMs)} ms (no validation ${fmt(unvalidated.wallMs)})  js ${fmt(js?.ms)} ms  check ${gpu.checked}`,
      );
    }
  }
  const meta = {
    device: deviceLine,
    adapter: a,
    node: process.version,
    date: new Date().toISOString(),
    steps,
    limits: { maxStorageBufferBindingSize: ctx.limits.maxStorageBufferBindingSize },
  };
  mkdirSync(outDir, { recursive: true });
  writeFileSync(path.join(outDir, 'gpu-broadphase.json'), JSON.stringify({ meta, rows }, null, 2) + '\n');
  writeFileSync(path.join(outDir, 'gpu-broadphase.md'), markdown(rows, meta));
  writeFileSync(path.join(outDir, 'gpu-broadphase.svg'), svgChart(rows) + '\n');
  process.stdout.write(markdown(rows, meta));
  console.error(`wrote ${path.join(outDir, 'gpu-broadphase.{json,md,svg}')}`);
  finished = true;
  ctx.destroy();
  unvalidatedCtx.destroy();
  return rows.some((r) => r.gpu?.checked === false) ? 1 : 0;
}

main().then(
  (code) => process.exit(code),
  (err) => {
    console.error(err);
    process.exit(2);
  },
);
