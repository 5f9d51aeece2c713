/*
 * The GPU narrow phase (and the broad phase before it), 10^3 to 10^6 contacts, by pair-type mix.
 *
 * Built into one file by `node scripts/build-gpu.mjs` (dist/bench-gpu-narrowphase.mjs, `webgpu`
 * left external), so it runs where only Node and .device/node_modules exist:
 *
 *   node dist/bench-gpu-narrowphase.mjs [--contacts 1e3,1e4,1e5,1e6] [--mixes circles,boxes,mixed]
 *        [--steps 10] [--check-max 2e4] [--no-variants] [--quick] [--out DIR]
 *
 * Worlds (gpu-support.ts syntheticWorld: b2World fields, so that 250k bodies cost no
 * engine setup): bodies on a jittered 1 m grid, sized so that each overlaps its neighbours' AABBs
 * (about 4 pairs per body, about half of them touching), n = contacts / 4:
 *   circles  circles of radius 0.48-0.56 m (circle-circle only);
 *   boxes    boxes of half-size 0.42-0.52 m at random angles (polygon-polygon only);
 *   mixed    circles, boxes and hexagons, 5% sensors, and below every 6th row static ground,
 *            chains (1 m segments) or loose edges with ghost vertices: every pair type.
 * Every step a small kernel moves and turns the bodies on the GPU (not counted), then one
 * GpuPipeline.step() runs the broad phase and the narrow phase in one submission.
 * Reported per step (medians): GPU device time per pass (timestamp queries): the broad phase's
 * five passes, the narrow phase's contacts (classify, bin sort), collide per bin (each bin its own
 * pass), persist, compact (the scans and the solver and event lists); the device time of as many
 * empty dispatches as the step records (dispatch overhead); host time of a waiting update split
 * into recording, the submit call and the wait for the read-back; and the wall time per step
 * when steps are not awaited ({ wait: false }, up to four in flight); and the host times again on
 * two more devices, one without timestamp queries and one with Dawn's skip_validation toggle
 * (--no-variants skips them).
 * Check (up to --check-max contacts): the GPU's touching flags against the engine's collide
 * functions (float64) at the GPU's own transforms, every contact.
 * Output: gpu-narrowphase.json and .md in $OUT, or --out, or bench/results.
 */

import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { b2Manifold, b2TestOverlapShapes } from '../src/collision/b2Collision';
import { b2CollideCircles, b2CollidePolygonAndCircle } from '../src/collision/b2CollideCircle';
import { b2CollideEdgeAndCircle, b2CollideEdgeAndPolygon } from '../src/collision/b2CollideEdge';
import { b2CollidePolygons } from '../src/collision/b2CollidePolygon';
import { b2ChainShape } from '../src/collision/shapes/b2ChainShape';
import { b2CircleShape } from '../src/collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../src/collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../src/collision/shapes/b2PolygonShape';
import type { b2Shape } from '../src/collision/shapes/b2Shape';
import { b2Transform, b2Vec2 } from '../src/common/b2Math';
import { GpuBroadPhase } from '../src-gpu/broadphase/broadPhase';
import { requestGpu } from '../src-gpu/device/device';
import type { GpuContext } from '../src-gpu/device/device';
import { BIN, BIN_NAMES, USAGE } from '../src-gpu/device/layout';
import { GpuNarrowPhase } from '../src-gpu/narrowphase/narrowPhase';
import type { NarrowPhaseResult } from '../src-gpu/narrowphase/narrowPhase';
import { GpuPipeline } from '../src-gpu/pipeline';
import { GpuWorld } from '../src-gpu/world/world';
import { box, circle, deviceName, fmt, median, rng, syntheticWorld } from './gpu-support';
import type { SyntheticBody } from './gpu-support';

const DT = 1 / 60;

function hexagon(r: number): b2PolygonShape {
  const s = new b2PolygonShape();
  const v: b2Vec2[] = [];
  for (let i = 0; i < 6; ++i) v.push(new b2Vec2(r * Math.cos((i * Math.PI) / 3), r * Math.sin((i * Math.PI) / 3)));
  s.Set(v, 6);
  return s;
}

/** The bodies of a mix with about `contacts` contacts. */
function makeBodies(mix: string, contacts: number): SyntheticBody[] {
  const r = rng(contacts * 7 + mix.length);
  const n = Math.max(16, Math.round(contacts / 4));
  const side = Math.ceil(Math.sqrt(n));
  const bodies: SyntheticBody[] = [];
  // A few shared shapes (each fixture is packed on its own by the mirror).
  const circles = Array.from({ length: 8 }, (_, k) => circle(0.48 + 0.01 * k));
  const boxes = Array.from({ length: 8 }, (_, k) => box(0.42 + 0.0125 * k, 0.45 + 0.01 * ((k * 3) % 8)));
  const hexes = Array.from({ length: 4 }, (_, k) => hexagon(0.5 + 0.015 * k));
  for (let row = 0; row < side; ++row) {
    const y = row - side / 2;
    if (mix === 'mixed' && row % 6 === 3) {
      // Static ground between this row and the one below (0.5 m from both): a chain (1 m
      // segments) or loose edges with ghost vertices, alternately.
      const x0 = -side / 2 - 0.5;
      const gy = y - 0.5;
      if ((row / 6) % 2 < 1) {
        const chain = new b2ChainShape();
        const vs: b2Vec2[] = [];
        for (let i = 0; i <= side; ++i) vs.push(new b2Vec2(x0 + i, gy + 0.02 * Math.sin(i)));
        chain.CreateChain(vs);
        bodies.push({ x: 0, y: 0, angle: 0, vx: 0, vy: 0, w: 0, dynamic: false, shapes: [chain], sensor: false });
      } else {
        // One static body per edge (a body's fixtures do not collide with each other anyway).
        for (let i = 0; i < side; ++i) {
          const e = new b2EdgeShape();
          e.Set(new b2Vec2(x0 + i, gy), new b2Vec2(x0 + i + 1, gy));
          e.m_vertex0.Set(x0 + i - 1, gy);
          e.m_vertex3.Set(x0 + i + 2, gy);
          e.m_hasVertex0 = i > 0;
          e.m_hasVertex3 = i + 1 < side;
          bodies.push({ x: 0, y: 0, angle: 0, vx: 0, vy: 0, w: 0, dynamic: false, shapes: [e], sensor: false });
        }
      }
    }
    for (let col = 0; col < side && bodies.length < 2 * n; ++col) {
      const x = col - side / 2 + 0.04 * (r() - 0.5);
      let shape: b2Shape;
      if (mix === 'circles') shape = circles[Math.floor(r() * 8)];
      else if (mix === 'boxes') shape = boxes[Math.floor(r() * 8)];
      else {
        const k = r();
        shape = k < 0.4 ? circles[Math.floor(r() * 8)] : k < 0.8 ? boxes[Math.floor(r() * 8)] : hexes[Math.floor(r() * 4)];
      }
      const speed = 0.3 * r();
      const dir = 2 * Math.PI * r();
      bodies.push({
        x,
        y: y + 0.04 * (r() - 0.5),
        angle: mix === 'circles' ? 0 : 2 * Math.PI * r(),
        vx: speed * Math.cos(dir),
        vy: speed * Math.sin(dir),
        w: mix === 'circles' ? 0 : 0.5 * (r() - 0.5),
        dynamic: true,
        shapes: [shape],
        sensor: mix === 'mixed' && r() < 0.05,
      });
    }
  }
  return bodies;
}

// Moves and turns every dynamic body (static ones have zero velocity): p += v dt, q *= rot(w dt),
// velocities reversed every 60 steps so the grid keeps its shape.
const MOVE_WGSL = `
struct Params { count: u32, dt: f32, flip: f32, pad: f32 }
@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read_write> xf: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read_write> vel: array<vec4<f32>>;
@compute @workgroup_size(256)
fn main(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
  let i = gid.x + gid.y * nwg.x * 256u;
  if (i >= params.count) { return; }
  var v = vel[i];
  v = vec4<f32>(v.xyz * params.flip, 0.0);
  var t = xf[i];
  let a = v.z * params.dt;
  let c = cos(a);
  let s = sin(a);
  t = vec4<f32>(t.xy + v.xy * params.dt, c * t.z - s * t.w, s * t.z + c * t.w);
  xf[i] = t;
  vel[i] = v;
}`;

const EMPTY_WGSL = `@compute @workgroup_size(1) fn main() {}`;

interface Row {
  mix: string;
  bodies: number;
  proxies: number;
  pairs: number;
  contacts: number;
  touching: number;
  solver: number;
  bins: number[];
  broadMs: number;
  narrowMs: number;
  compactMs: number;
  stagesMs: Record<string, number>;
  deviceMs: number;
  dispatches: number;
  emptyDispatchMs: number;
  host: { encode: number; submit: number; wait: number; wall: number };
  deferredWallMs: number;
  /** The same steps on other devices (VARIANTS): wall awaited, wall not awaited, device time. */
  variants: Record<string, { wall: number; deferred: number; device: number; record: number; submit: number }>;
  roundTripMs: number;
  mapRoundTripMs: number;
  check: string;
}

const BROAD_PASSES = ['bounds', 'axis', 'sort', 'sweep', 'pairs'];

/** Touching flags of the GPU contacts against the engine's collide functions at the GPU's transforms. */
async function check(ctx: GpuContext, mirror: GpuWorld, narrow: GpuNarrowPhase): Promise<string> {
  const contacts = await narrow.readContacts();
  const size = 16 * mirror.bodySlotCount;
  const staging = ctx.createBuffer('check read', size, USAGE.MAP_READ | USAGE.COPY_DST);
  const enc = ctx.device.createCommandEncoder();
  enc.copyBufferToBuffer(mirror.bodyXf.buffer, 0, staging, 0, size);
  ctx.device.queue.submit([enc.finish()]);
  await staging.mapAsync(1);
  const xfs = new Float32Array(staging.getMappedRange().slice(0));
  staging.unmap();
  staging.destroy();
  const transform = (slot: number) => {
    const cell = [mirror.bodyCell.i32[2 * slot], mirror.bodyCell.i32[2 * slot + 1]];
    const xf = new b2Transform();
    xf.p.Set(cell[0] * mirror.cellSize + xfs[4 * slot], cell[1] * mirror.cellSize + xfs[4 * slot + 1]);
    xf.q.c = xfs[4 * slot + 2];
    xf.q.s = xfs[4 * slot + 3];
    return xf;
  };
  const child = (fixture: { m_shape: b2Shape }, index: number): b2Shape => {
    if (fixture.m_shape.m_type !== 3) return fixture.m_shape;
    const e = new b2EdgeShape();
    (fixture.m_shape as b2ChainShape).GetChildEdge(e, index);
    return e;
  };
  const m = new b2Manifold();
  let differ = 0;
  let touching = 0;
  for (const c of contacts) {
    const pa = mirror.proxyAt(c.proxyA)!;
    const pb = mirror.proxyAt(c.proxyB)!;
    const a = child(pa.fixture, pa.childIndex);
    const b = child(pb.fixture, pb.childIndex);
    const xfA = transform(mirror.bodySlot(pa.fixture.m_body));
    const xfB = transform(mirror.bodySlot(pb.fixture.m_body));
    let t: boolean;
    switch (c.bin) {
      case BIN.SENSOR:
        t = b2TestOverlapShapes(a, 0, b, 0, xfA, xfB);
        break;
      case BIN.CIRCLES:
        b2CollideCircles(m, a as b2CircleShape, xfA, b as b2CircleShape, xfB);
        t = m.pointCount > 0;
        break;
      case BIN.POLYGON_CIRCLE:
        b2CollidePolygonAndCircle(m, a as b2PolygonShape, xfA, b as b2CircleShape, xfB);
        t = m.pointCount > 0;
        break;
      case BIN.POLYGONS:
        b2CollidePolygons(m, a as b2PolygonShape, xfA, b as b2PolygonShape, xfB);
        t = m.pointCount > 0;
        break;
      case BIN.EDGE_CIRCLE:
      case BIN.CHAIN_CIRCLE:
        b2CollideEdgeAndCircle(m, a as b2EdgeShape, xfA, b as b2CircleShape, xfB);
        t = m.pointCount > 0;
        break;
      default:
        b2CollideEdgeAndPolygon(m, a as b2EdgeShape, xfA, b as b2PolygonShape, xfB);
        t = m.pointCount > 0;
    }
    if (t) touching++;
    if (t !== c.touching) differ++;
  }
  return differ === 0 ? `ok (${contacts.length} contacts, ${touching} touching)` : `${differ} of ${contacts.length} differ`;
}

/**
 * One mix at one size. `light`: only the host times (awaited and not awaited), with the collide
 * kernels in one pass: for the device without timestamp queries.
 */
async function runMix(ctx: GpuContext, mix: string, contacts: number, steps: number, checkMax: number, light = false): Promise<Row> {
  const bodies = makeBodies(mix, contacts);
  const world = syntheticWorld(bodies);
  const mirror = new GpuWorld(ctx, world);
  mirror.sync();
  const broad = new GpuBroadPhase(ctx, { initialPairCapacity: 6 * bodies.length + 1024 });
  const narrow = new GpuNarrowPhase(ctx, { initialContactCapacity: 6 * bodies.length + 1024, timeBins: !light });
  const pipeline = new GpuPipeline(ctx, broad, narrow);
  const device = ctx.device;

  const move = device.createComputePipeline({ layout: 'auto', compute: { module: device.createShaderModule({ code: MOVE_WGSL }), entryPoint: 'main' } });
  const params = ctx.createBuffer('move params', 16, USAGE.UNIFORM | USAGE.COPY_DST);
  const moveGroup = device.createBindGroup({
    layout: move.getBindGroupLayout(0),
    entries: [
      { binding: 0, resource: { buffer: params } },
      { binding: 1, resource: { buffer: mirror.bodyXf.buffer } },
      { binding: 2, resource: { buffer: mirror.bodyVel.buffer } },
    ],
  });
  const count = mirror.bodySlotCount;
  const groups = Math.ceil(count / 256);
  let stepIndex = 0;
  const moveStep = () => {
    const words = new ArrayBuffer(16);
    new Uint32Array(words)[0] = count;
    new Float32Array(words).set([DT, stepIndex % 60 === 59 ? -1 : 1], 1);
    device.queue.writeBuffer(params, 0, words);
    stepIndex++;
    const enc = device.createCommandEncoder();
    const pass = enc.beginComputePass();
    pass.setPipeline(move);
    pass.setBindGroup(0, moveGroup);
    pass.dispatchWorkgroups(Math.min(groups, 65535), Math.ceil(groups / 65535));
    pass.end();
    device.queue.submit([enc.finish()]);
  };

  // Waiting steps.
  let last: NarrowPhaseResult | null = null;
  const stages: Record<string, number[]> = {};
  const deviceMs: number[] = [];
  const host = { encode: [] as number[], submit: [] as number[], wait: [] as number[], wall: [] as number[] };
  for (let step = 0; step < steps + 2; ++step) {
    moveStep();
    await device.queue.onSubmittedWorkDone();
    const w0 = performance.now();
    last = await pipeline.step(mirror);
    const wall = performance.now() - w0;
    if (step < 2) continue;
    host.wall.push(wall);
    host.encode.push(last.hostMs.encode);
    host.submit.push(last.hostMs.submit);
    host.wait.push(last.hostMs.wait);
    if (last.gpuTime) {
      deviceMs.push(last.gpuTime.total);
      for (const [k, v] of Object.entries(last.gpuTime)) (stages[k] ??= []).push(v);
    }
  }
  const result = last!;
  const checkText = !light && result.contactCount <= checkMax ? await check(ctx, mirror, narrow) : '–';

  // Steps without waiting: up to four in flight, the wall time per step over the run.
  await pipeline.settle();
  const d0 = performance.now();
  for (let step = 0; step < steps; ++step) {
    moveStep();
    await pipeline.step(mirror, { wait: false });
  }
  await pipeline.settle();
  const deferredWallMs = (performance.now() - d0) / steps;

  // Dispatch overhead: as many empty dispatches as a step records, in one timed pass.
  const empty = device.createComputePipeline({ layout: 'auto', compute: { module: device.createShaderModule({ code: EMPTY_WGSL }), entryPoint: 'main' } });
  const overhead: number[] = [];
  const roundTrip: number[] = [];
  const mapRoundTrip: number[] = [];
  const read = ctx.createBuffer('ts read', 4096, USAGE.MAP_READ | USAGE.COPY_DST);
  if (ctx.timestamps && !light) {
    const qs = device.createQuerySet({ type: 'timestamp', count: 2 });
    const resolve = ctx.createBuffer('ts resolve', 16, USAGE.QUERY_RESOLVE | USAGE.COPY_SRC);
    for (let rep = 0; rep < 7; ++rep) {
      const enc = device.createCommandEncoder();
      const pass = enc.beginComputePass({ timestampWrites: { querySet: qs, beginningOfPassWriteIndex: 0, endOfPassWriteIndex: 1 } });
      pass.setPipeline(empty);
      for (let i = 0; i < result.dispatches; ++i) pass.dispatchWorkgroups(1);
      pass.end();
      enc.resolveQuerySet(qs, 0, 2, resolve, 0);
      enc.copyBufferToBuffer(resolve, 0, read, 0, 16);
      device.queue.submit([enc.finish()]);
      await read.mapAsync(1, 0, 16);
      const t = new BigInt64Array(read.getMappedRange(0, 16).slice(0));
      read.unmap();
      overhead.push(Number(t[1] - t[0]) / 1e6);
    }
    qs.destroy();
    resolve.destroy();
  }
  for (let rep = 0; rep < 9; ++rep) {
    const r0 = performance.now();
    device.queue.submit([device.createCommandEncoder().finish()]);
    await device.queue.onSubmittedWorkDone();
    roundTrip.push(performance.now() - r0);
    const m0 = performance.now();
    const enc = device.createCommandEncoder();
    enc.copyBufferToBuffer(narrow.state, 0, read, 0, 128);
    device.queue.submit([enc.finish()]);
    await read.mapAsync(1, 0, 128);
    read.unmap();
    mapRoundTrip.push(performance.now() - m0);
  }
  read.destroy();

  const stagesMs: Record<string, number> = {};
  for (const [k, v] of Object.entries(stages)) if (k !== 'total') stagesMs[k] = median(v);
  const broadMs = BROAD_PASSES.reduce((s, k) => s + (stagesMs[k] ?? 0), 0);
  const narrowMs = Object.entries(stagesMs)
    .filter(([k]) => !BROAD_PASSES.includes(k))
    .reduce((s, [, v]) => s + v, 0);
  const touching = result.solverCount;
  pipeline.destroy();
  broad.destroy();
  narrow.destroy();
  mirror.destroy();
  params.destroy();
  return {
    mix,
    bodies: bodies.length,
    proxies: mirror.proxySlotCount,
    pairs: result.broad.pairCount,
    contacts: result.contactCount,
    touching,
    solver: result.solverCount,
    bins: result.binCounts,
    broadMs,
    narrowMs,
    compactMs: stagesMs.compact ?? NaN,
    stagesMs,
    deviceMs: median(deviceMs),
    dispatches: result.dispatches,
    emptyDispatchMs: median(overhead),
    host: { encode: median(host.encode), submit: median(host.submit), wait: median(host.wait), wall: median(host.wall) },
    deferredWallMs,
    roundTripMs: median(roundTrip),
    mapRoundTripMs: median(mapRoundTrip),
    check: checkText,
    variants: {},
  };
}

/**
 * Devices created beside the main one, to locate host overhead: without timestamp queries (is the
 * timing part of the wall time?), and with Dawn's `skip_validation` toggle (Dawn validates every
 * dispatchWorkgroupsIndirect with an extra compute dispatch it records, docs/GPU.md "Host
 * overhead"; the kernels here never write a size over the limit, so nothing else changes).
 */
const VARIANTS: { name: string; options: Parameters<typeof requestGpu>[0] }[] = [
  { name: 'no timestamps', options: { timestamps: false } },
  { name: 'skip_validation', options: { dawnOptions: ['disable-dawn-features=timestamp_quantization'], skipValidation: true } },
];

function markdown(rows: Row[], meta: Record<string, unknown>): string {
  const bins = BIN_NAMES.map((n) => n);
  const lines = [
    '# GPU narrow phase (with the broad phase before it)',
    '',
    `Device: ${meta.device}. Node ${meta.node}. ${meta.date}. Milliseconds per step, medians of ${meta.steps} steps.`,
    '',
    '## Device time (timestamp queries)',
    '',
    '| mix | bodies | pairs = contacts | touching (solver) | broad phase | contacts + bins | collide | persist | compact | narrow total | step total | empty dispatches (count) |',
    '| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |',
  ];
  for (const r of rows) {
    const collide = bins.reduce((s, b) => s + (r.stagesMs[`collide ${b}`] ?? 0), 0);
    lines.push(
      `| ${r.mix} | ${r.bodies} | ${r.contacts} | ${r.solver} | ${fmt(r.broadMs)} | ${fmt(r.stagesMs.contacts)} | ${fmt(collide)} | ${fmt(r.stagesMs.persist)} | ${fmt(r.compactMs)} | ${fmt(r.narrowMs)} | ${fmt(r.deviceMs)} | ${fmt(r.emptyDispatchMs)} (${r.dispatches}) |`,
    );
  }
  lines.push('', '## Collide kernels per pair type (device ms; contacts in the bin)', '');
  lines.push(`| mix | contacts | ${bins.join(' | ')} |`);
  lines.push(`| --- | ---: | ${bins.map(() => '---:').join(' | ')} |`);
  for (const r of rows) {
    lines.push(
      `| ${r.mix} | ${r.contacts} | ${bins.map((b, i) => (r.bins[i] ? `${fmt(r.stagesMs[`collide ${b}`])} (${r.bins[i]})` : `${fmt(r.stagesMs[`collide ${b}`])} (0)`)).join(' | ')} |`,
    );
  }
  lines.push('', '## Host time of a step', '');
  lines.push(
    '| mix | contacts | record | submit call | wait for read-back | wall, awaited | device | wall per step, not awaited | empty submit round trip | 128-byte map round trip | check |',
  );
  lines.push('| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |');
  for (const r of rows) {
    lines.push(
      `| ${r.mix} | ${r.contacts} | ${fmt(r.host.encode)} | ${fmt(r.host.submit)} | ${fmt(r.host.wait)} | ${fmt(r.host.wall)} | ${fmt(r.deviceMs)} | ${fmt(r.deferredWallMs)} | ${fmt(r.roundTripMs)} | ${fmt(r.mapRoundTripMs)} | ${r.check} |`,
    );
  }
  const variantNames = [...new Set(rows.flatMap((r) => Object.keys(r.variants)))];
  if (variantNames.length > 0) {
    lines.push('', '## The same steps on other devices (record / submit call / wall awaited / wall not awaited / device)', '');
    lines.push(`| mix | contacts | main device | ${variantNames.join(' | ')} |`);
    lines.push(`| --- | ---: | --- | ${variantNames.map(() => '---').join(' | ')} |`);
    const cell = (v: { record: number; submit: number; wall: number; deferred: number; device: number }) =>
      `${fmt(v.record)} / ${fmt(v.submit)} / ${fmt(v.wall)} / ${fmt(v.deferred)} / ${fmt(v.device)}`;
    for (const r of rows) {
      const main = { record: r.host.encode, submit: r.host.submit, wall: r.host.wall, deferred: r.deferredWallMs, device: r.deviceMs };
      lines.push(`| ${r.mix} | ${r.contacts} | ${cell(main)} | ${variantNames.map((n) => (r.variants[n] ? cell(r.variants[n]) : '–')).join(' | ')} |`);
    }
  }
  lines.push(
    '',
    'broad phase: bounds + axis + sort + sweep + pairs. contacts + bins: classify, match with the previous step,',
    'bin sort and bin sizes. collide: the eight per-bin kernels (each in its own pass; an empty bin runs zero',
    'workgroups). persist: impulses carried by feature id, touching and begin/end flags. compact: the prefix',
    'scans and the solver and event lists. empty dispatches: device time of as many empty dispatches as the',
    'step records (dispatch overhead). record: building the command buffer (JS and Dawn); wait: from the submit',
    'call returning to the read-back resolving; not awaited: steps submitted with { wait: false }, up to four',
    "in flight, total wall time / steps. check: GPU touching flags against the engine (float64) at the GPU's",
    'transforms.',
  );
  return lines.join('\n') + '\n';
}

async function main(): Promise<number> {
  const { values } = parseArgs({
    args: process.argv.slice(2),
    options: {
      contacts: { type: 'string' },
      mixes: { type: 'string' },
      steps: { type: 'string' },
      'check-max': { type: 'string' },
      'no-variants': { type: 'boolean' },
      quick: { type: 'boolean' },
      out: { type: 'string' },
      help: { type: 'boolean', short: 'h' },
    },
  });
  if (values.help) {
    process.stdout.write(
      'node dist/bench-gpu-narrowphase.mjs [--contacts 1e3,1e4,1e5,1e6] [--mixes circles,boxes,mixed] [--steps 10] [--check-max 2e4] [--no-variants] [--quick] [--out DIR]\n',
    );
    return 0;
  }
  const quick = values.quick === true;
  const sizes = (values.contacts ?? (quick ? '1e3,4e3' : '1e3,1e4,1e5,1e6')).split(',').map(Number);
  const mixes = (values.mixes ?? 'circles,boxes,mixed').split(',');
  const steps = Number(values.steps ?? (quick ? 3 : 10));
  const checkMax = Number(values['check-max'] ?? 2e4);
  const outDir = values.out ?? process.env.OUT ?? path.resolve('bench/results');

  let finished = false;
  const ctx = await requestGpu({
    dawnOptions: ['disable-dawn-features=timestamp_quantization'],
    onLost: (info) => {
      if (!finished) console.error('device lost', info);
    },
  });
  const variantCtx: { name: string; ctx: GpuContext }[] = [];
  if (values['no-variants'] !== true) {
    for (const v of VARIANTS) {
      try {
        variantCtx.push({ name: v.name, ctx: await requestGpu(v.options) });
      } catch (err) {
        console.error(`variant ${v.name}: no device (${err instanceof Error ? err.message : String(err)})`);
      }
    }
  }
  const a = ctx.adapterInfo;
  const deviceLine = deviceName(a);
  console.error(`adapter: ${deviceLine}; timestamps: ${ctx.timestamps}`);
  const rows: Row[] = [];
  const started = performance.now();
  for (const size of sizes) {
    for (const mix of mixes) {
      const row = await runMix(ctx, mix, size, steps, checkMax);
      for (const v of variantCtx) {
        const other = await runMix(v.ctx, mix, size, steps, checkMax, true);
        row.variants[v.name] = {
          record: other.host.encode,
          submit: other.host.submit,
          wall: other.host.wall,
          deferred: other.deferredWallMs,
          device: other.deviceMs,
        };
      }
      rows.push(row);
      console.error(
        `${mix.padEnd(8)} ${String(row.contacts).padStart(8)} contacts (${row.solver} touching): broad ${fmt(row.broadMs)} ms, narrow ${fmt(row.narrowMs)} ms ` +
          `(compact ${fmt(row.compactMs)}), device ${fmt(row.deviceMs)} ms; host record ${fmt(row.host.encode)} submit ${fmt(row.host.submit)} wait ${fmt(row.host.wait)} ` +
          `wall ${fmt(row.host.wall)} ms, not awaited ${fmt(row.deferredWallMs)} ms/step; check ${row.check} [${((performance.now() - started) / 1000).toFixed(0)} s]`,
      );
    }
  }
  const meta = { device: deviceLine, adapter: a, node: process.version, date: new Date().toISOString(), steps };
  mkdirSync(outDir, { recursive: true });
  writeFileSync(path.join(outDir, 'gpu-narrowphase.json'), JSON.stringify({ meta, rows }, null, 2) + '\n');
  writeFileSync(path.join(outDir, 'gpu-narrowphase.md'), markdown(rows, meta));
  process.stdout.write(markdown(rows, meta));
  console.error(`wrote ${path.join(outDir, 'gpu-narrowphase.{json,md}')}`);
  finished = true;
  ctx.destroy();
  for (const v of variantCtx) v.ctx.destroy();
  return rows.some((r) => r.check !== '–' && !r.check.startsWith('ok')) ? 1 : 0;
}

main().then(
  (code) => process.exit(code),
  (err) => {
    console.error(err);
    process.exit(2);
  },
);
