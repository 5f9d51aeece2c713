/*
 * The GPU backend's full step (GpuStepper: broad phase + narrow phase + solver) against the
 * JavaScript engine stepping the same world, 10^3 to 10^6 bodies.
 *
 * Built into one file by `node scripts/build-gpu.mjs` (dist/bench-gpu-step.mjs, `webgpu` left
 * external), so it runs where only Node and .device/node_modules exist:
 *
 *   node dist/bench-gpu-step.mjs [--sizes 1e3,1e4,1e5,1e6] [--scenes pyramids,rain,balls] [--steps 10]
 *        [--js-max 1e5] [--js-budget 3] [--fused on|off] [--skip-resting on|off] [--continuous on|off] [--auto] [--validation] [--quick] [--out DIR]
 *
 * On a lent H100 (kind nvidia-h100-x1; `.device` from `bash ../shared/gpu/prepare.sh`): carry
 * `.device` and `dist/bench-gpu-step.mjs`, run
 *   bash .device/run.sh node --expose-gc --max-old-space-size=60000 dist/bench-gpu-step.mjs
 *
 * Scenes, built with the engine's API (n dynamic bodies plus static ground, density 1,
 * friction 0.6, gravity -10):
 *   pyramids  pyramids of 20 rows (210 boxes of 0.5 m half-size) side by side, 22 m apart, built at
 *             rest on the ground; the last one is cut short so that there are exactly n boxes;
 *   rain      circles (radius 0.25-0.5 m) and boxes (half-size 0.25-0.45 m, random angles) on a
 *             1.5 m grid jittered by up to 0.1 m (no overlaps), four times wider than high, from
 *             1 m above the ground, falling with random initial velocities (down to -4 m/s, +-1 m/s
 *             sideways);
 *   balls     rain's layout with circles only, on an edge for ground: a scene without polygons or
 *             joints (--scenes balls; not in the default set);
 *   settled   pyramids with sleeping on, each on a ground body of its own (22 m wide), stepped
 *             SETTLE_STEPS times before anything is timed (on each backend), so that the timed
 *             steps are those of a world at rest, its islands asleep: what a world costs when
 *             nothing moves (--scenes settled; not in the default set). The GPU table gives the
 *             bodies still awake after the timed steps.
 * --skip-resting on|off: whether a world at rest skips its steps (GpuPipeline.skipResting; default
 *   on; off measures what the GPU's stages cost a sleeping world).
 * --continuous on|off: continuous physics in both engines (default off; on adds the GPU's time of
 *   impact stage: what b2World's default costs).
 * --fused on|off: the solver's fused passes for every size, or for none (GpuSolverOptions.fused);
 * default: by the solver's items (FUSED_SOLVER_ITEMS). --auto: AutoBackend's calibration measured on this
 * adapter (its crossover and the fitted costs), before the rows: in a fresh process, after the
 * device warm-up, as an application's first AutoBackend measures it.
 * Both engines: 1/60 s, 8 velocity / 3 position iterations, sleeping and continuous physics off
 * (resting pyramids would fall asleep and cost nothing: this measures the full step's work), but
 * for the settled scene's sleeping and --continuous on.
 * GPU: a device with Dawn's validation off (requestGpu skipValidation; --validation keeps it on, as
 * browsers run it) and timestamp queries when
 * the adapter has them. Each world gets a GpuStepper; after GPU_WARMUP awaited steps (on the H100
 * the first five steps of 10^6 pyramids take 36 ms of device time, then 14.7: a warm-up of 3
 * put those slow steps into the medians), `--steps` awaited
 * steps give the wall time of step() (mirror sync, recording, submit, wait for the 324-byte
 * read-back), its host split, the device time (timestamp span of the step's passes, and per part:
 * broad phase, narrow phase, solver) and the dispatches recorded; then, after STREAM_WARMUP steps
 * not awaited (the stream's first read-backs grow the buffers to 1.5x the counts: that reallocation
 * is not a steady-state cost), `--steps` more steps not awaited ({ wait: false }, up to four in
 * flight) give the wall time per step of a stream of steps, and the host time each step spent
 * recording and waiting for a free read-back buffer (the GPU being the bottleneck).
 * World API: the same world built again and attached to a WebGPUBackend (SetBackend timed), then
 * GPU_WARMUP synchronised steps, then `--steps` steps of world.Step + await world.Synchronize() (the
 * Step call and the synchronisation timed apart), the same with a synchronisation every 4 steps,
 * with the bulk read of every transform after the synchronisation (backend.readTransforms), and
 * with the bulk read alone: what an application pays through the documented path.
 * Before the first row, DEVICE_WARMUP_S seconds of untimed steps (an idle GPU runs its first
 * steps at low clocks). Each world is built after a full collection and timed after another (with --expose-gc; meta's
 * heapSettled), so no phase pays for collecting the last one's world.
 * JS: the same world built again, WARMUP steps, then world.Step timed per step, `--steps` steps or
 * until `--js-budget` seconds have passed, for sizes up to `--js-max`. Times are medians.
 * JS/GPU is the throughput ratio (JS ms / GPU ms: above 1 the GPU steps faster). The crossover per
 * scene is the smallest measured size where the awaited GPU step beats the engine, and the size
 * where the ratio crosses 1 interpolated in log-log between the measured sizes around it.
 * A size that fails on the GPU (a buffer over the device's limits, out of memory) is reported with
 * its message and the run goes on; the exit code is then 1.
 * Output: gpu-step.json, .md and .svg in $OUT, or --out, or bench/results; the table on stdout.
 */

import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { constants, PerformanceObserver } from 'node:perf_hooks';
import { parseArgs } from 'node:util';
import type { b2Shape } from '../src/collision/shapes/b2Shape';
import { b2Vec2 } from '../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody } from '../src/dynamics/b2Body';
import { b2FixtureDef } from '../src/dynamics/b2Fixture';
import { b2World } from '../src/dynamics/b2World';
import { requestGpu } from '../src-gpu/device/device';
import type { GpuContext } from '../src-gpu/device/device';
import { WebGPUBackend } from '../src-gpu/backend/backend';
import { GpuStepper } from '../src-gpu/stepper';
import { AutoBackend } from '../src-gpu/backend/auto';
import type { AutoCalibration } from '../src-gpu/backend/calibration';
import type { GpuSolverOptions } from '../src-gpu/solver/solver';
import { b2EdgeShape } from '../src/collision/shapes/b2EdgeShape';
import { box, circle, crossover, deviceName, fmt, logLogChart, median, rng, settleHeap, sizeText } from './gpu-support';
import type { Crossover } from './gpu-support';

/**
 * Node's garbage collections ('gc' performance entries) that started between start() and stop():
 * how many, of which major (mark-compact), and their total ms. Node delivers the entries a while
 * after the collection, so stop() waits for them.
 */
class GcTally {
  count = 0;
  major = 0;
  ms = 0;
  private from = 0;
  private until = Infinity;
  private readonly observer = new PerformanceObserver((list) => this.add(list.getEntries()));

  private add(entries: readonly PerformanceEntry[]): void {
    for (const e of entries) {
      if (e.startTime < this.from || e.startTime > this.until) continue;
      this.count++;
      if (((e as PerformanceEntry & { detail?: { kind?: number } }).detail?.kind ?? 0) === constants.NODE_PERFORMANCE_GC_MAJOR) this.major++;
      this.ms += e.duration;
    }
  }

  start(): void {
    this.from = performance.now();
    this.observer.observe({ entryTypes: ['gc'] });
  }

  async stop(): Promise<{ count: number; major: number; ms: number }> {
    this.until = performance.now();
    await new Promise((resolve) => setTimeout(resolve, GC_ENTRY_WAIT_MS));
    this.add(this.observer.takeRecords());
    this.observer.disconnect();
    return { count: this.count, major: this.major, ms: this.ms };
  }
}

/** How long stop() waits for the entries of the collections it counts. */
const GC_ENTRY_WAIT_MS = 300;

const DT = 1 / 60;
const VELOCITY_ITERATIONS = 8;
const POSITION_ITERATIONS = 3;
/** Steps before timing: the first creates every contact, the next ones grow the GPU buffers. */
const WARMUP = 3;
const GPU_WARMUP = 10;
/** Seconds of untimed steps before the first row: an idle GPU runs its first steps at low clocks. */
const DEVICE_WARMUP_S = 2;
/** Steps not awaited before the stream is timed: four fill the read-back ring, three more settle. */
const STREAM_WARMUP = 7;
const SCENES = ['pyramids', 'rain'];
const ALL_SCENES = [...SCENES, 'balls', 'settled'];
/** Untimed steps of the settled scene: its pyramids fall asleep after about 240 steps on either engine. */
const SETTLE_STEPS = 300;
const PYRAMID_ROWS = 20;
const PYRAMID_PITCH = PYRAMID_ROWS + 2;
const RAIN_SPACING = 1.5;
const BROAD_PASSES = new Set(['bounds', 'axis', 'sort', 'sweep', 'pairs']);

/** b2World.SetContinuousPhysics for every scene (--continuous). */
let continuous = false;

/** A world for both engines without a ground: gravity, sleeping off, continuous physics as --continuous. */
function worldWithoutGround(): b2World {
  const world = new b2World(new b2Vec2(0, -10));
  world.SetAllowSleeping(false);
  world.SetContinuousPhysics(continuous);
  return world;
}

/** A static ground body at x = `x` of half-width `halfWidth` with its top at y = 0: a box, or an edge. */
function addGround(world: b2World, halfWidth: number, x = 0, edgeGround = false): void {
  const def = new b2BodyDef();
  def.position.Set(x, 0);
  const ground = world.CreateBody(def);
  const fd = new b2FixtureDef();
  if (edgeGround) {
    const edge = new b2EdgeShape();
    edge.Set(new b2Vec2(-halfWidth, 0), new b2Vec2(halfWidth, 0));
    fd.shape = edge;
  } else {
    fd.shape = box(halfWidth, 1, new b2Vec2(0, -1));
  }
  fd.friction = 0.6;
  ground.CreateFixture(fd);
}

/** worldWithoutGround() and one ground of half-width `halfWidth` under the origin. */
function emptyWorld(halfWidth: number, edgeGround = false): b2World {
  const world = worldWithoutGround();
  addGround(world, halfWidth, 0, edgeGround);
  return world;
}

/**
 * n boxes in pyramids of PYRAMID_ROWS rows, bottom row first (bench/scenes.mjs's layout), on one
 * ground box, or with `groundEach` on a ground body of their own under each: float32 contacts with
 * a polygon kilometres from its body's origin carry a rounding of its coordinates that the position
 * iterations never converge under, so pyramids far out on one ground never sleep on the GPU.
 */
function pyramids(n: number, groundEach = false): b2World {
  const perPyramid = (PYRAMID_ROWS * (PYRAMID_ROWS + 1)) / 2;
  const count = Math.ceil(n / perPyramid);
  const world = groundEach ? worldWithoutGround() : emptyWorld((count * PYRAMID_PITCH) / 2 + 5);
  const bd = new b2BodyDef();
  bd.type = b2_dynamicBody;
  const fd = new b2FixtureDef();
  fd.shape = box(0.5, 0.5);
  fd.density = 1;
  fd.friction = 0.6;
  const h = 0.5;
  let made = 0;
  for (let k = 0; k < count; ++k) {
    const centre = (k - (count - 1) / 2) * PYRAMID_PITCH;
    if (groundEach) addGround(world, PYRAMID_PITCH / 2, centre);
    for (let i = 0; i < PYRAMID_ROWS; ++i) {
      for (let j = i; j < PYRAMID_ROWS && made < n; ++j, ++made) {
        bd.position.Set(centre + (i + 1) * h + 2 * (j - i) * h - h * PYRAMID_ROWS, (2 * i + 1) * h);
        world.CreateBody(bd).CreateFixture(fd);
      }
    }
  }
  return world;
}

/** n circles and boxes (only circles, on an edge: `balls`) on a jittered grid, falling. */
function rain(n: number, balls = false): b2World {
  const r = rng(n * 13 + 5);
  const rows = Math.max(1, Math.round(Math.sqrt(n / 4)));
  const cols = Math.ceil(n / rows);
  const world = emptyWorld((cols * RAIN_SPACING) / 2 + 5, balls);
  const circles = [circle(0.25), circle(0.375), circle(0.5)];
  const shapes: b2Shape[] = balls ? circles : [...circles, box(0.25, 0.25), box(0.45, 0.3), box(0.35, 0.45)];
  const bd = new b2BodyDef();
  bd.type = b2_dynamicBody;
  const fd = new b2FixtureDef();
  fd.density = 1;
  fd.friction = 0.6;
  let made = 0;
  for (let row = 0; row < rows; ++row) {
    for (let col = 0; col < cols && made < n; ++col, ++made) {
      bd.position.Set((col - (cols - 1) / 2) * RAIN_SPACING + 0.2 * (r() - 0.5), 1 + row * RAIN_SPACING + 0.2 * (r() - 0.5));
      bd.angle = 2 * Math.PI * r();
      bd.linearVelocity.Set(2 * r() - 1, -4 * r());
      fd.shape = shapes[Math.floor(r() * shapes.length)];
      world.CreateBody(bd).CreateFixture(fd);
    }
  }
  return world;
}

function buildWorld(scene: string, n: number): b2World {
  if (scene === 'pyramids') return pyramids(n);
  if (scene === 'rain') return rain(n);
  if (scene === 'balls') return rain(n, true);
  if (scene === 'settled') {
    const world = pyramids(n, true);
    world.SetAllowSleeping(true);
    return world;
  }
  throw new Error(`unknown scene ${scene} (${ALL_SCENES.join(', ')})`);
}

/**
 * The scene built after a full collection (its build time into `row`), and collected again. Each
 * phase builds its own world, so that main()'s frame never holds one: a suspended async function
 * keeps its locals, and the last phase's million bodies doubled what every collection of the
 * next one marked.
 */
function freshWorld(scene: string, n: number, row?: Row): b2World {
  settleHeap();
  const b0 = performance.now();
  const world = buildWorld(scene, n);
  if (row !== undefined) row.buildMs = performance.now() - b0;
  settleHeap();
  return world;
}

/** The dynamic bodies whose flag in `awake` (by body slot) is set. */
function awakeDynamic(stepper: GpuStepper, awake: Uint8Array): number {
  let count = 0;
  for (let slot = 0; slot < awake.length; ++slot) if (awake[slot] !== 0 && stepper.mirror.bodyAt(slot)?.GetType() === b2_dynamicBody) count++;
  return count;
}

/** Untimed steps before a scene is timed: `steps`, or SETTLE_STEPS for the settled scene. */
function warmup(scene: string, steps: number): number {
  return scene === 'settled' ? Math.max(steps, SETTLE_STEPS) : steps;
}

/** --fused: the solver's fused passes forced on or off; by body count when undefined. */
const solverOptions: GpuSolverOptions = {};
/** GpuPipeline.skipResting for every stepper (--skip-resting). */
let skipResting = true;

/** AutoBackend's crossover on this adapter, measured as an application's first settle() does. */
async function runCalibration(ctx: GpuContext): Promise<{ crossover: AutoCalibration | null; choice: string; ms: number }> {
  const world = pyramids(100);
  const auto = await AutoBackend.create({ context: ctx });
  const t0 = performance.now();
  await world.SetBackend(auto);
  await auto.settle();
  const ms = performance.now() - t0;
  const result = { crossover: auto.crossover, choice: auto.choice.reason, ms };
  await world.SetBackend(null);
  return result;
}

function message(err: unknown): string {
  return err instanceof Error ? `${err.name}: ${err.message}` : String(err);
}

interface GpuRow {
  /** new GpuStepper(): mirror the world, upload it. */
  setupMs: number;
  wallMs: number;
  /** Wall time per step over `steps` steps not awaited (up to four in flight). */
  deferredMs: number;
  /** Per step not awaited: host time recording and submitting, and waiting for a free read-back buffer. */
  deferredHostMs: { record: number; wait: number };
  deviceMs: number;
  /** Device time per part of the step: broad phase, narrow phase, solver. */
  partsMs: { broad: number; narrow: number; solve: number };
  /** Device time per timed pass (median over the awaited steps), by pass name. */
  passesMs: Record<string, number>;
  /** Host split of an awaited step: mirror sync and other work before recording, recording, the submit call, the wait. */
  hostMs: { sync: number; record: number; submit: number; wait: number };
  dispatches: number;
  contacts: number;
  touching: number;
  /** Dynamic bodies awake after the timed steps. */
  awake: number;
  /** Awaited timed steps skipped at rest (GpuPipeline.skipResting): device time 0. */
  skipped: number;
  /** Steps not awaited whose buffers overflowed (their lists truncated). */
  truncatedSteps: number;
}

async function runGpu(ctx: GpuContext, scene: string, n: number, steps: number, row: Row): Promise<GpuRow> {
  const world = freshWorld(scene, n, row);
  const t0 = performance.now();
  const stepper = new GpuStepper(ctx, world, { solver: solverOptions });
  stepper.pipeline.skipResting = skipResting;
  try {
    const setupMs = performance.now() - t0;
    for (let i = 0; i < warmup(scene, GPU_WARMUP); ++i) await stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    const wall: number[] = [];
    const device: number[] = [];
    const parts = { broad: [] as number[], narrow: [] as number[], solve: [] as number[] };
    const passes: Record<string, number[]> = {};
    const host = { sync: [] as number[], record: [] as number[], submit: [] as number[], wait: [] as number[] };
    let last = null;
    let skipped = 0;
    for (let i = 0; i < steps; ++i) {
      const w0 = performance.now();
      last = await stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
      const w = performance.now() - w0;
      wall.push(w);
      const h = last.hostMs;
      host.sync.push(w - h.encode - h.submit - h.wait);
      host.record.push(h.encode);
      host.submit.push(h.submit);
      host.wait.push(h.wait);
      if (last.skipped) {
        skipped++;
        device.push(0);
        parts.broad.push(0);
        parts.narrow.push(0);
        parts.solve.push(0);
      } else if (last.gpuTime) {
        device.push(last.gpuTime.total);
        const sum = { broad: 0, narrow: 0, solve: 0 };
        for (const [name, ms] of Object.entries(last.gpuTime)) {
          if (name === 'total') continue;
          (passes[name] ??= []).push(ms);
          sum[name.startsWith('solve') ? 'solve' : BROAD_PASSES.has(name) ? 'broad' : 'narrow'] += ms;
        }
        parts.broad.push(sum.broad);
        parts.narrow.push(sum.narrow);
        parts.solve.push(sum.solve);
      }
    }
    for (let i = 0; i < STREAM_WARMUP; ++i) await stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS, { wait: false });
    await stepper.pipeline.settle();
    const deferredHost = { record: 0, wait: 0 };
    const d0 = performance.now();
    for (let i = 0; i < steps; ++i) {
      const r = await stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS, { wait: false });
      deferredHost.record += r.hostMs.encode + r.hostMs.submit;
      deferredHost.wait += r.hostMs.wait;
    }
    await stepper.pipeline.settle();
    const deferredMs = (performance.now() - d0) / steps;
    const slots = stepper.mirror.bodySlotCount;
    const awakeFlags = new Uint8Array(slots);
    await stepper.readTransforms(new Float32Array(4 * slots), awakeFlags);
    return {
      awake: awakeDynamic(stepper, awakeFlags),
      skipped,
      setupMs,
      wallMs: median(wall),
      deferredMs,
      deferredHostMs: { record: deferredHost.record / steps, wait: deferredHost.wait / steps },
      deviceMs: median(device),
      partsMs: { broad: median(parts.broad), narrow: median(parts.narrow), solve: median(parts.solve) },
      passesMs: Object.fromEntries(Object.entries(passes).map(([name, ms]) => [name, median(ms)])),
      hostMs: { sync: median(host.sync), record: median(host.record), submit: median(host.submit), wait: median(host.wait) },
      dispatches: last?.dispatches ?? 0,
      contacts: last?.contactCount ?? 0,
      touching: last?.solverCount ?? 0,
      truncatedSteps: stepper.pipeline.truncatedSteps,
    };
  } finally {
    // After a failure, steps may still be in flight: let their read-backs end before destroying.
    await stepper.pipeline.settle().catch(() => undefined);
    stepper.destroy();
  }
}

/**
 * The world API an application uses (WebGPUBackend), on a world built afresh: attaching it, and
 * per step (medians) Step + Synchronize every step with its split, Step + Synchronize every 4 steps,
 * Step + Synchronize + the bulk read of every transform, and Step + the bulk read alone.
 */
interface WorldApiRow {
  /** world.SetBackend(backend) (the pipelines are compiled already), and the garbage collections in it. */
  attachMs: number;
  attachGc: { count: number; major: number; ms: number };
  /** Step then await Synchronize, each step: wall, the Step call, and the Synchronize. */
  syncEach: { wallMs: number; stepMs: number; syncMs: number };
  /** Four Steps, then await Synchronize: wall per step. */
  syncEvery4Ms: number;
  /** Step, await Synchronize, await readTransforms of every body: median and slowest step. */
  syncAndBulkMs: number;
  syncAndBulkMaxMs: number;
  /** Garbage collections during those steps (with the bulk-only steps between them): per step. */
  syncAndBulkGc: { count: number; major: number; ms: number };
  /** Step, await readTransforms of every body (no Synchronize). */
  bulkMs: number;
  /** Of the bulk read, the host's share: from the map resolving to the Float32Array filled. */
  bulkCopyMs: number;
  /**
   * After a synchronisation, world.PullState(): every body fetched and the proxies moved, as a
   * query does (and as every synchronisation did before bodies fetched their state when read).
   */
  pullAllMs: number;
}

async function runWorldApi(ctx: GpuContext, scene: string, n: number, steps: number): Promise<WorldApiRow> {
  const world = freshWorld(scene, n);
  const backend = await WebGPUBackend.create({ context: ctx, stepper: { solver: solverOptions } });
  const attachTally = new GcTally();
  attachTally.start();
  const a0 = performance.now();
  await world.SetBackend(backend);
  const attachMs = performance.now() - a0;
  const attachGc = await attachTally.stop();
  backend.stepper!.pipeline.skipResting = skipResting;
  try {
    const out = new Float32Array(4 * backend.stepper!.mirror.bodySlotCount);
    const step = () => world.Step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    for (let i = 0; i < warmup(scene, GPU_WARMUP); ++i) {
      step();
      await world.Synchronize();
    }
    const wall: number[] = [];
    const stepCall: number[] = [];
    const sync: number[] = [];
    for (let i = 0; i < steps; ++i) {
      const t0 = performance.now();
      step();
      const t1 = performance.now();
      await world.Synchronize();
      const t2 = performance.now();
      wall.push(t2 - t0);
      stepCall.push(t1 - t0);
      sync.push(t2 - t1);
    }
    const every4: number[] = [];
    for (let i = 0; i < Math.max(1, Math.round(steps / 4)); ++i) {
      const t0 = performance.now();
      for (let k = 0; k < 4; ++k) step();
      await world.Synchronize();
      every4.push((performance.now() - t0) / 4);
    }
    const syncAndBulk: number[] = [];
    const bulk: number[] = [];
    const bulkCopy: number[] = [];
    const gc = new GcTally();
    gc.start();
    for (let i = 0; i < steps; ++i) {
      const t0 = performance.now();
      step();
      await world.Synchronize();
      await backend.readTransforms(out);
      syncAndBulk.push(performance.now() - t0);
      const t1 = performance.now();
      step();
      await backend.readTransforms(out);
      bulk.push(performance.now() - t1);
      bulkCopy.push(backend.readStats!.unpackMs);
    }
    const gcSeen = await gc.stop();
    const pullAll: number[] = [];
    for (let i = 0; i < Math.max(1, Math.round(steps / 2)); ++i) {
      step();
      await world.Synchronize();
      const t0 = performance.now();
      world.PullState();
      pullAll.push(performance.now() - t0);
    }
    return {
      attachMs,
      attachGc,
      pullAllMs: median(pullAll),
      syncEach: { wallMs: median(wall), stepMs: median(stepCall), syncMs: median(sync) },
      syncEvery4Ms: median(every4),
      syncAndBulkMs: median(syncAndBulk),
      syncAndBulkMaxMs: Math.max(...syncAndBulk),
      syncAndBulkGc: { count: gcSeen.count / steps, major: gcSeen.major / steps, ms: gcSeen.ms / steps },
      bulkMs: median(bulk),
      bulkCopyMs: median(bulkCopy),
    };
  } finally {
    await backend.destroy();
  }
}

interface JsRow {
  ms: number;
  steps: number;
  contacts: number;
}

function runJs(scene: string, n: number, steps: number, budgetSeconds: number): JsRow {
  const world = freshWorld(scene, n);
  for (let i = 0; i < warmup(scene, WARMUP); ++i) world.Step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
  const times: number[] = [];
  const start = performance.now();
  while (times.length < steps && (times.length === 0 || performance.now() - start < budgetSeconds * 1000)) {
    const s0 = performance.now();
    world.Step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    times.push(performance.now() - s0);
  }
  return { ms: median(times), steps: times.length, contacts: world.GetContactCount() };
}

interface Row {
  scene: string;
  /** Dynamic bodies (plus one static ground). */
  bodies: number;
  buildMs: number;
  gpu: GpuRow | null;
  gpuError: string | null;
  api: WorldApiRow | null;
  apiError: string | null;
  js: JsRow | null;
  jsError: string | null;
}

function markdown(rows: Row[], crossovers: Crossover[], meta: Record<string, unknown>): string {
  const lines = [
    '# Full step on the GPU (broad phase + narrow phase + solver) vs the JavaScript engine',
    '',
    `Device: ${meta.device}; timestamps: ${meta.timestamps}; Dawn validation ${meta.skipValidation ? 'off' : 'on'}. Node ${meta.node}. ${meta.date}. ${meta.heapSettled ? 'Full garbage collection before each world is built and before it is timed.' : "Run without --expose-gc: a phase may pay for collecting the previous one's world."}`,
    `1/60 s, ${VELOCITY_ITERATIONS} velocity / ${POSITION_ITERATIONS} position iterations, sleeping ${meta.continuous ? 'off, continuous physics on (--continuous on),' : 'and continuous physics off'}`,
    `in both (resting pyramids would fall asleep and cost nothing: this measures the full step's work; the settled scene sleeps and has ${SETTLE_STEPS} warm-up steps). ${GPU_WARMUP} warm-up steps on the GPU, ${WARMUP} in JS, then medians of ${meta.steps} steps`,
    `(JS: at most ${meta.steps} steps or ${meta.jsBudget} s). Milliseconds per step. Solver passes: ${meta.fused === undefined ? 'fused up to FUSED_SOLVER_ITEMS contacts and joints' : meta.fused ? 'fused at every size (--fused on)' : 'per colour at every size (--fused off)'}.`,
    '',
    '| scene | bodies | awake | contacts (touching) | dispatches | GPU wall | GPU not awaited | GPU device | device: broad / narrow / solve | JS | JS/GPU wall | JS/GPU not awaited |',
    '| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |',
  ];
  for (const r of rows) {
    const g = r.gpu;
    const gpuCells = g
      ? `${g.awake}${g.skipped > 0 ? ` (${g.skipped} skipped)` : ''} | ${g.contacts} (${g.touching}) | ${g.dispatches} | ${fmt(g.wallMs)} | ${fmt(g.deferredMs)} | ${fmt(g.deviceMs)} | ${fmt(g.partsMs.broad)} / ${fmt(g.partsMs.narrow)} / ${fmt(g.partsMs.solve)}`
      : `failed: ${r.gpuError ?? '–'} | | | | | | `;
    const js = r.js ? `${fmt(r.js.ms)}${r.js.steps < (meta.steps as number) ? ` (${r.js.steps} steps)` : ''}` : r.jsError ? `failed: ${r.jsError}` : '–';
    const ratio = (gpuMs: number | undefined) => (r.js && gpuMs ? fmt(r.js.ms / gpuMs) : '–');
    lines.push(`| ${r.scene} | ${r.bodies} | ${gpuCells} | ${js} | ${ratio(g?.wallMs)} | ${ratio(g?.deferredMs)} |`);
  }
  lines.push('', 'Crossover (awaited GPU step faster than the engine):', '');
  for (const c of crossovers) lines.push(`- ${c.scene}: ${c.text}`);
  lines.push(
    '',
    '## The world API (WebGPUBackend), per step (ms)',
    '',
    '| scene | bodies | build the world (µs a body) | SetBackend | of which GC (major) | Step + Synchronize | of which Step | of which Synchronize | Synchronize every 4 steps | Step + Synchronize + bulk read | slowest of those | GCs a step, major (ms) | Step + bulk read | of which the host copy | Step + Synchronize / GpuStepper awaited | fetch every body and proxy |',
    '| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |',
  );
  for (const r of rows) {
    const a = r.api;
    if (a === null) {
      lines.push(`| ${r.scene} | ${r.bodies} | ${fmt((1000 * r.buildMs) / r.bodies)} | failed: ${r.apiError ?? '–'} | | | | | | | | | | | | |`);
      continue;
    }
    const ratio = r.gpu ? fmt(a.syncEach.wallMs / r.gpu.wallMs) : '–';
    lines.push(
      `| ${r.scene} | ${r.bodies} | ${fmt((1000 * r.buildMs) / r.bodies)} | ${fmt(a.attachMs)} | ${fmt(a.attachGc.ms)} (${a.attachGc.major}) | ${fmt(a.syncEach.wallMs)} | ${fmt(a.syncEach.stepMs)} | ${fmt(a.syncEach.syncMs)} | ` +
        `${fmt(a.syncEvery4Ms)} | ${fmt(a.syncAndBulkMs)} | ${fmt(a.syncAndBulkMaxMs)} | ${a.syncAndBulkGc.count.toFixed(1)}, ${a.syncAndBulkGc.major.toFixed(1)} (${fmt(a.syncAndBulkGc.ms)}) | ${fmt(a.bulkMs)} | ${fmt(a.bulkCopyMs)} | ${ratio} | ${fmt(a.pullAllMs)} |`,
    );
  }
  lines.push(
    '',
    '## Host time of an awaited GPU step (ms)',
    '',
    '| scene | bodies | setup (new GpuStepper) | mirror sync and other | record | submit call | wait | not awaited: record + submit | not awaited: wait for room | not-awaited steps truncated |',
    '| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |',
  );
  for (const r of rows) {
    const g = r.gpu;
    if (g)
      lines.push(
        `| ${r.scene} | ${r.bodies} | ${fmt(g.setupMs)} | ${fmt(g.hostMs.sync)} | ${fmt(g.hostMs.record)} | ${fmt(g.hostMs.submit)} | ${fmt(g.hostMs.wait)} | ${fmt(g.deferredHostMs.record)} | ${fmt(g.deferredHostMs.wait)} | ${g.truncatedSteps} |`,
      );
  }
  const solverPasses = [...new Set(rows.flatMap((r) => Object.keys(r.gpu?.passesMs ?? {}).filter((name) => name.startsWith('solve'))))];
  if (solverPasses.length > 0) {
    lines.push(
      '',
      '## Solver device time per pass (ms)',
      '',
      `| scene | bodies | ${solverPasses.join(' | ')} |`,
      `| --- | ---: |${' ---: |'.repeat(solverPasses.length)}`,
    );
    for (const r of rows) {
      const g = r.gpu;
      if (g) lines.push(`| ${r.scene} | ${r.bodies} | ${solverPasses.map((name) => fmt(g.passesMs[name])).join(' | ')} |`);
    }
  }
  lines.push(
    '',
    `bodies: dynamic bodies, plus one static ground (the settled scene: one under each pyramid); awake: of them, those awake after the timed steps (all, unless sleeping is on: the settled scene), and the awaited timed steps skipped as a world at rest (device time 0; skipping ${skipResting ? 'on' : 'off: --skip-resting off'}). contacts: the GPU's contacts (broad-phase pairs) and, in`,
    'parentheses, the touching ones the solver takes. GPU wall: GpuStepper.step() from call to resolved promise',
    '(mirror sync, recording, submit, wait for the read-back). GPU not awaited: steps submitted with { wait: false }',
    "(up to four in flight), total wall time / steps. GPU device: timestamp span of the step's passes; broad /",
    'narrow / solve: sums of their passes. JS: b2World.Step. JS/GPU: throughput ratio (above 1: the GPU is faster).',
    'Host table: setup is new GpuStepper() (the first row\'s includes compiling the pipelines); "mirror sync and',
    'other" is the wall time of step() outside the narrow phase\'s recording, submit and wait, mostly GpuWorld.sync().',
    'Not awaited: per step, host time recording and submitting, and waiting for a free read-back buffer (four in',
    'flight: the wait is the GPU finishing the oldest step; near the not-awaited time per step, the GPU is the limit).',
    'World API: the same scene built again (build: b2World objects, µs a body) and attached with SetBackend (pipelines',
    'already compiled; the time of the garbage collections in it, and how many were major); then world.Step and await world.Synchronize() (the bodies fetch their state when read: none is',
    'read here), every step and every 4 steps, and with the bulk read of every transform (backend.readTransforms into',
    'a Float32Array: packed on the GPU, then one copy on the host, whose time is shown; the slowest of those steps, and',
    'the garbage collections a step while they and the bulk-only steps between them ran, the major (mark-compact) ones, and their ms);',
    'last, world.PullState() after a synchronisation: every body fetched and the broad-phase proxies moved, as a query',
    'does, and as every synchronisation did before bodies fetched their state when read.',
  );
  const calibration = meta.calibration as Awaited<ReturnType<typeof runCalibration>> | null;
  if (calibration) {
    lines.push(
      '',
      '## AutoBackend on this adapter',
      '',
      calibration.crossover
        ? `Crossover: ${calibration.crossover.crossoverBodies} bodies (${calibration.crossover.source}); measured at the first settle() in ${fmt(calibration.ms)} ms. A 100-body world: ${calibration.choice}.`
        : `Not measured: ${calibration.choice}.`,
    );
  }
  return lines.join('\n') + '\n';
}

function svgChart(rows: Row[]): string {
  return logLogChart(rows, {
    title: 'Full step (broad + narrow phase + solver): GPU vs the JavaScript engine',
    xLabel: 'bodies',
    x: (r) => r.bodies,
    xText: sizeText,
    group: (r) => r.scene,
    colours: { pyramids: '#1f77b4', rain: '#d62728' },
    series: [
      { label: 'GPU wall', value: (r) => r.gpu?.wallMs, dash: '' },
      { label: 'GPU not awaited', value: (r) => r.gpu?.deferredMs, dash: '6 3' },
      { label: 'GPU device', value: (r) => r.gpu?.deviceMs, dash: '1 3' },
      { label: 'JS engine', value: (r) => r.js?.ms, dash: '10 3 2 3' },
    ],
  });
}

async function main(): Promise<number> {
  const { values } = parseArgs({
    args: process.argv.slice(2),
    options: {
      sizes: { type: 'string' },
      scenes: { type: 'string' },
      steps: { type: 'string' },
      'js-max': { type: 'string' },
      'js-budget': { type: 'string' },
      validation: { type: 'boolean' },
      quick: { type: 'boolean' },
      fused: { type: 'string' },
      'skip-resting': { type: 'string' },
      continuous: { type: 'string' },
      auto: { type: 'boolean' },
      out: { type: 'string' },
      help: { type: 'boolean', short: 'h' },
    },
  });
  if (values.help) {
    process.stdout.write(
      'node dist/bench-gpu-step.mjs [--sizes 1e3,1e4,1e5,1e6] [--scenes pyramids,rain,balls,settled] [--steps 10] [--js-max 1e5] [--js-budget 3] [--fused on|off] [--skip-resting on|off] [--continuous on|off] [--auto] [--validation] [--quick] [--out DIR]\n',
    );
    return 0;
  }
  const quick = values.quick === true;
  const sizes = (values.sizes ?? (quick ? '1e3,1e4' : '1e3,1e4,1e5,1e6')).split(',').map(Number);
  const scenes = (values.scenes ?? SCENES.join(',')).split(',');
  const steps = Math.max(1, Number(values.steps ?? (quick ? 3 : 10)));
  const jsMax = Number(values['js-max'] ?? 1e5);
  const jsBudget = Number(values['js-budget'] ?? (quick ? 1 : 3));
  const outDir = values.out ?? process.env.OUT ?? path.resolve('bench/results');
  for (const scene of scenes) if (!ALL_SCENES.includes(scene)) throw new Error(`unknown scene ${scene} (${ALL_SCENES.join(', ')})`);
  if (values.fused !== undefined) {
    if (values.fused !== 'on' && values.fused !== 'off') throw new Error(`--fused must be on or off, got ${values.fused}`);
    solverOptions.fused = values.fused === 'on';
  }
  if (values['skip-resting'] !== undefined) {
    if (values['skip-resting'] !== 'on' && values['skip-resting'] !== 'off') throw new Error(`--skip-resting must be on or off, got ${values['skip-resting']}`);
    skipResting = values['skip-resting'] === 'on';
  }
  if (values.continuous !== undefined) {
    if (values.continuous !== 'on' && values.continuous !== 'off') throw new Error(`--continuous must be on or off, got ${values.continuous}`);
    continuous = values.continuous === 'on';
  }

  let finished = false;
  const ctx = await requestGpu({
    dawnOptions: ['disable-dawn-features=timestamp_quantization'],
    skipValidation: values.validation !== true,
    onLost: (info) => {
      if (!finished) console.error('device lost', info);
    },
  });
  const a = ctx.adapterInfo;
  const deviceLine = deviceName(a);
  console.error(`adapter: ${deviceLine}; timestamps: ${ctx.timestamps}`);
  const rows: Row[] = [];
  {
    const stepper = new GpuStepper(ctx, pyramids(10_000), { solver: solverOptions });
    const t0 = performance.now();
    while (performance.now() - t0 < DEVICE_WARMUP_S * 1000) await stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    stepper.destroy();
  }
  let calibration: Awaited<ReturnType<typeof runCalibration>> | null = null;
  // First, in a fresh process, as an application's first AutoBackend measures it.
  if (values.auto === true) {
    settleHeap();
    calibration = await runCalibration(ctx);
    console.error(
      `AutoBackend: ${calibration.crossover ? `${calibration.crossover.crossoverBodies} bodies (${calibration.crossover.source})` : 'not measured'}; ${calibration.choice}; ${fmt(calibration.ms)} ms`,
    );
  }
  const started = performance.now();
  for (const n of sizes) {
    for (const scene of scenes) {
      const row: Row = { scene, bodies: n, buildMs: 0, gpu: null, gpuError: null, api: null, apiError: null, js: null, jsError: null };
      try {
        row.gpu = await runGpu(ctx, scene, n, steps, row);
      } catch (err) {
        row.gpuError = message(err);
      }
      try {
        row.api = await runWorldApi(ctx, scene, n, steps);
      } catch (err) {
        row.apiError = message(err);
      }
      if (n <= jsMax) {
        try {
          row.js = runJs(scene, n, steps, jsBudget);
        } catch (err) {
          row.jsError = message(err);
        }
      }
      rows.push(row);
      const g = row.gpu;
      console.error(
        `${scene.padEnd(8)} ${String(n).padStart(8)}  ` +
          (g
            ? `contacts ${g.contacts} (${g.touching} touching), ${g.dispatches} dispatches; gpu wall ${fmt(g.wallMs)} ms, not awaited ${fmt(g.deferredMs)} ms, device ${fmt(g.deviceMs)} ms`
            : `gpu failed: ${row.gpuError}`) +
          `; world API ${row.api ? `attach ${fmt(row.api.attachMs)} ms, step + sync ${fmt(row.api.syncEach.wallMs)} ms, + bulk ${fmt(row.api.syncAndBulkMs)} ms` : (row.apiError ?? '–')}` +
          `; js ${row.js ? `${fmt(row.js.ms)} ms` : (row.jsError ?? '–')} [build ${fmt(row.buildMs)} ms; ${((performance.now() - started) / 1000).toFixed(0)} s]`,
      );
    }
  }
  const crossovers = scenes.map((s) =>
    crossover(
      s,
      rows.filter((r) => r.scene === s && r.gpu && r.js).map((r) => ({ n: r.bodies, jsMs: r.js!.ms, gpuMs: r.gpu!.wallMs })),
    ),
  );
  const meta = {
    fused: solverOptions.fused,
    continuous,
    calibration,
    device: deviceLine,
    adapter: a,
    timestamps: ctx.timestamps,
    skipValidation: values.validation !== true,
    node: process.version,
    date: new Date().toISOString(),
    dt: DT,
    velocityIterations: VELOCITY_ITERATIONS,
    positionIterations: POSITION_ITERATIONS,
    warmup: WARMUP,
    gpuWarmup: GPU_WARMUP,
    steps,
    jsBudget,
    jsMax,
    heapSettled: settleHeap(),
    sleeping: false,
    continuousPhysics: false,
    limits: { maxStorageBufferBindingSize: ctx.limits.maxStorageBufferBindingSize, maxBufferSize: ctx.limits.maxBufferSize },
  };
  mkdirSync(outDir, { recursive: true });
  const md = markdown(rows, crossovers, meta);
  writeFileSync(path.join(outDir, 'gpu-step.json'), JSON.stringify({ meta, rows, crossovers }, null, 2) + '\n');
  writeFileSync(path.join(outDir, 'gpu-step.md'), md);
  writeFileSync(path.join(outDir, 'gpu-step.svg'), svgChart(rows) + '\n');
  process.stdout.write(md);
  console.error(`wrote ${path.join(outDir, 'gpu-step.{json,md,svg}')}`);
  finished = true;
  ctx.destroy();
  return rows.some((r) => r.gpuError !== null || r.apiError !== null || r.jsError !== null) ? 1 : 0;
}

main().then(
  (code) => process.exit(code),
  (err) => {
    console.error(err);
    process.exit(1);
  },
);
