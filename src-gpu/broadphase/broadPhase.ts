/*
 * The GPU broad phase: sweep-and-prune from body transforms to a sorted, deterministic pair list.
 *
 * One update() records one command buffer of five compute passes and reads back 64 bytes:
 *   bounds  proxy AABBs from the bodies (GpuWorld input only)              src-gpu/broadphase/bounds.ts
 *   axis    the sweep axis (variance of the AABB centres) and the strips    src-gpu/broadphase/axis.ts
 *           across the other axis
 *   sort    one entry per (proxy, strip it spans), radix-sorted by          src-gpu/broadphase/keys.ts, radixSort.ts
 *           (strip, quantised lower bound) (24-bit keys, 3 passes)
 *   sweep   sorted AABBs, candidate ranges, work offsets, pairs           src-gpu/broadphase/sweep.ts, scan.ts
 *   pairs   overflow check, pairs radix-sorted by (a, b)                   src-gpu/broadphase/pairs.ts
 * then copies the state words (pair count, overflow, axis, work items) and the pass timestamps to
 * one mappable buffer, read back with a single mapAsync (one GPU round trip per update). If
 * the pairs overflowed the pair buffer, the count the GPU kept counting says exactly how much is
 * needed: the buffer grows (doubling) and the sweep and pair passes run again, so no pair is ever
 * lost. Nothing else is read back; the pairs stay on the GPU for the narrow phase (`pairs`,
 * `pairCount`), and readPairs() copies them out for tests and tools.
 *
 * Pairs follow b2ContactManager::AddPair: proxies of different bodies, at least one body dynamic,
 * no joint with collideConnected == false between the bodies, a contact type for the two shapes
 * (none for edge/chain against edge/chain), and b2ContactFilter::ShouldCollide on the filters.
 * Each pair is (a, b) with a < b, proxy slots of GpuWorld (or indices of a GpuProxySet), and the
 * list is sorted by (a, b): identical on every run on the same device.
 */

import type { GpuContext } from '../device/device';
import { GpuArray } from '../device/buffers';
import { AxisStage } from './axis';
import { AABB_EXTENSION, BoundsStage } from './bounds';
import { KeysStage } from './keys';
import { passRecorder } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import type { PassRecorder } from '../device/kernel';
import { PairsStage } from './pairs';
import { GpuProxySet } from './proxies';
import { digitPasses, RadixSort } from '../primitives/radixSort';
import { SweepStage } from './sweep';
import type { SweepInputs } from './sweep';
import { PassTimer } from '../device/timing';
import { Readback, readBuffer } from '../device/readback';
import { ARGS, INDIRECT_WORDS, KEY_BITS, OVERFLOW_ENTRIES, OVERFLOW_PAIRS, STATE, STATE_WORDS, USAGE } from '../device/layout';
import { GpuWorld } from '../world/world';

/** The label of the read-backs for tests and tools (readBuffer). */
const DEBUG_READ = 'broadphase debug read';

/** The entry sort: the KEY_BITS-bit keys in 8-bit digits. */
const ENTRY_SORT_PASSES = digitPasses(KEY_BITS, 0, 8);

/** Byte offset of the timestamps in the read-back buffer (after the 64-byte state). */
const TIMER_OFFSET = 256;

export interface GpuBroadPhaseOptions {
  /** Pairs the pair buffer holds at first (default 4 per proxy, at least 1024); it grows. */
  initialPairCapacity?: number;
  /** The AABB margin (default b2_aabbExtension, 0.1 m). */
  extension?: number;
  /**
   * Sweep entries the buffers hold at first (default 3 x proxy slots + 64, which the entries
   * cannot exceed in practice; a smaller value exercises the overflow path). It grows.
   */
  initialEntryCapacity?: number;
}

export interface BroadPhaseResult {
  /** Pairs in the sorted list. */
  pairCount: number;
  /** 0: swept along x, 1: along y. */
  axis: number;
  /** Strips across the other axis. */
  strips: number;
  /** Sweep entries (proxies times the strips each spans). */
  entries: number;
  /** Sweep work items (chunks of candidates). */
  workItems: number;
  /** How many times the pair buffer had to grow during this update. */
  regrows: number;
  pairCapacity: number;
  /** Dispatches recorded (the last submission, not counting regrows). */
  dispatches: number;
  /** GPU milliseconds per pass and in total (timestamp queries), null when unavailable. */
  gpuTime: Record<string, number> | null;
}

/**
 * The GPU broad phase (sweep-and-prune), usable alone on a GpuWorld or a GpuProxySet.
 * @internal Advanced: exported for tools, benchmarks and tests; applications use WebGPUBackend
 * through b2World.SetBackend (docs/GPU.md, "The world API on the GPU").
 */
export class GpuBroadPhase {
  readonly ctx: GpuContext;
  readonly extension: number;
  private readonly bounds: BoundsStage;
  private readonly axis: AxisStage;
  private readonly keys: KeysStage;
  private readonly sort: RadixSort;
  private readonly sweep: SweepStage;
  private readonly pairStage: PairsStage;
  private readonly timer: PassTimer;
  private readonly proxyAABBs: GpuArray;
  private readonly items: GpuArray;
  private readonly itemsTmp: GpuArray;
  private entryCapacity = 0;
  private readonly entryCapacityGiven: boolean;
  private readonly pairsA: GpuArray;
  private readonly pairsB: GpuArray;
  readonly state: GPUBuffer;
  readonly indirect: GPUBuffer;
  private readonly readback: Readback;
  private readonly stateWords = new Uint32Array(STATE_WORDS);
  private sortedPairs: GPUBuffer | null = null;
  private lastInputs: SweepInputs | null = null;
  private lastSource: GpuWorld | GpuProxySet | null = null;
  /** Pairs in the last update's sorted list. */
  pairCount = 0;
  /** Times the entry buffers had to grow (over all updates). */
  entryRegrows = 0;
  /** The state words of the last update (layout.ts STATE). */
  lastState: Uint32Array | null = null;
  private busy = false;

  constructor(ctx: GpuContext, options: GpuBroadPhaseOptions = {}) {
    this.ctx = ctx;
    this.extension = options.extension ?? AABB_EXTENSION;
    this.entryCapacityGiven = options.initialEntryCapacity !== undefined;
    this.entryCapacity = options.initialEntryCapacity ?? 0;
    this.bounds = new BoundsStage(ctx);
    this.axis = new AxisStage(ctx);
    this.keys = new KeysStage(ctx);
    this.sort = new RadixSort(ctx);
    this.sweep = new SweepStage(ctx);
    this.pairStage = new PairsStage(ctx);
    this.timer = new PassTimer(ctx, 16);
    this.proxyAABBs = new GpuArray(ctx, 'proxyAABB', 16);
    this.items = new GpuArray(ctx, 'sort items', 8);
    this.itemsTmp = new GpuArray(ctx, 'sort items tmp', 8);
    const capacity = Math.max(1024, options.initialPairCapacity ?? 1024);
    this.pairsA = new GpuArray(ctx, 'pairs', 8, capacity);
    this.pairsB = new GpuArray(ctx, 'pairs tmp', 8, capacity);
    this.state = ctx.createBuffer('broadphase state', 4 * STATE_WORDS, USAGE.STORAGE | USAGE.COPY_DST | USAGE.COPY_SRC);
    this.indirect = ctx.createBuffer('broadphase indirect', 4 * INDIRECT_WORDS, USAGE.STORAGE | USAGE.INDIRECT | USAGE.COPY_DST);
    this.readback = new Readback(ctx, 'broadphase read-back', TIMER_OFFSET + this.timer.bytes);
  }

  /** The pair capacity now. */
  get pairCapacity(): number {
    return this.pairsA.capacity;
  }

  /** The sorted pairs of the last update (vec2<u32> (a, b), `pairCount` of them). */
  get pairs(): GPUBuffer {
    if (!this.sortedPairs) throw new Error('GpuBroadPhase: no update yet');
    return this.sortedPairs;
  }

  /** The inputs of the update being recorded (beginUpdate's), for encodeRegrow. */
  get lastUpdateInputs(): SweepInputs {
    if (!this.lastInputs) throw new Error('GpuBroadPhase: no update yet');
    return this.lastInputs;
  }

  /** The proxy AABBs the last update used (GpuWorld input: computed by the bounds stage). */
  get proxyAABB(): GPUBuffer {
    if (!this.lastInputs) throw new Error('GpuBroadPhase: no update yet');
    return this.lastInputs.proxyAABB;
  }

  /**
   * Finds the pairs of the proxies of a GpuWorld (after its sync()) or of a GpuProxySet. Rejects
   * with GpuDeviceLostError once the device is lost, GpuOutOfMemoryError when a buffer could not
   * be allocated.
   */
  async update(source: GpuWorld | GpuProxySet): Promise<BroadPhaseResult> {
    if (this.busy) throw new Error('GpuBroadPhase.update: the previous update has not finished');
    this.busy = true;
    try {
      return await this.run(source);
    } finally {
      this.busy = false;
    }
  }

  private inputsOf(source: GpuWorld | GpuProxySet): SweepInputs {
    if (source instanceof GpuWorld) {
      this.proxyAABBs.ensure(Math.max(1, source.proxySlotCount));
      return {
        slotCount: source.proxySlotCount,
        liveCount: source.liveProxyCount,
        proxyAABB: this.proxyAABBs.buffer,
        proxyRef: source.proxyRef.buffer,
        proxyFilter: source.proxyFilter.buffer,
        jointRange: source.jointRange.buffer,
        jointList: source.jointList.buffer,
      };
    }
    return source;
  }

  /**
   * Starts an update (used by update() and by GpuNarrowPhase, which appends its passes to the same
   * submission): the inputs, the capacities, and the host-written state words, queued before the
   * passes. Call encodePasses() next.
   */
  beginUpdate(source: GpuWorld | GpuProxySet): SweepInputs {
    const inputs = this.inputsOf(source);
    this.lastInputs = inputs;
    this.lastSource = source;
    if (!this.entryCapacityGiven) this.entryCapacity = Math.max(this.entryCapacity, 3 * inputs.slotCount + 64);
    this.reserve(this.entryCapacity, this.pairsA.capacity);
    const words = this.stateWords;
    words.fill(0);
    words[STATE.PAIR_CAPACITY] = this.pairsA.capacity;
    words[STATE.ENTRY_CAPACITY] = this.entryCapacity;
    words[STATE.SLOT_COUNT] = inputs.slotCount;
    words[STATE.LIVE_COUNT] = inputs.liveCount;
    this.ctx.device.queue.writeBuffer(this.state, 0, words);
    this.sweep.setPairCapacity(this.pairsA.capacity);
    return inputs;
  }

  /** Records the five passes of an update; returns the buffer that will hold the sorted pairs. */
  encodePasses(pass: PassRecorder, inputs: SweepInputs): GPUBuffer {
    const source = this.lastSource;
    const n = inputs.slotCount;
    if (source instanceof GpuWorld) {
      pass('bounds', (rec) => this.bounds.encode(rec, source, inputs.proxyAABB, this.extension));
    }
    pass('axis', (rec) => this.axis.encode(rec, inputs.proxyAABB, n, this.state));
    let sorted: GPUBuffer = this.items.buffer;
    pass('sort', (rec) => {
      this.keys.encode(rec, inputs, this.state, this.items.buffer, this.indirect);
      sorted = this.sort.encode(rec, this.items.buffer, this.itemsTmp.buffer, ENTRY_SORT_PASSES, this.state, STATE.ENTRIES, {
        indirect: this.indirect,
        offset: ARGS.ENTRY_TILES * 4,
        maxCount: this.entryCapacity,
      });
    });
    pass('sweep', (rec) => {
      this.sweep.encodePrepare(rec, this.keys.records.buffer, sorted, this.state, this.indirect);
      this.sweep.encodeEmit(rec, inputs, this.pairsA.buffer, this.state, this.indirect);
    });
    pass('pairs', (rec) => {
      this.sortedPairs = this.pairStage.encode(rec, this.sort, this.pairsA.buffer, this.pairsB.buffer, this.pairsA.capacity, n, this.state, this.indirect);
    });
    return this.sortedPairs!;
  }

  /**
   * After a read-back that shows OVERFLOW_ENTRIES: grows the entry buffers to `total` (at least
   * doubling). The whole update must be recorded again (beginUpdate, encodePasses).
   */
  growEntries(total: number): void {
    this.entryRegrows++;
    this.entryCapacity = Math.max(2 * this.entryCapacity, total);
  }

  /**
   * After a read-back that shows OVERFLOW_PAIRS: grows the pair buffers to hold `found` pairs and
   * queues the state words for a redo of the emit and the pair sort (encodeRegrow).
   */
  growPairs(found: number): void {
    this.reserve(this.entryCapacity, found);
    const cap = this.pairsA.capacity;
    const queue = this.ctx.device.queue;
    queue.writeBuffer(this.state, 4 * STATE.PAIR_COUNT, new Uint32Array([0]));
    queue.writeBuffer(this.state, 4 * STATE.OVERFLOW, new Uint32Array([0]));
    queue.writeBuffer(this.state, 4 * STATE.PAIR_CAPACITY, new Uint32Array([cap]));
    this.sweep.setPairCapacity(cap);
  }

  /** Records the emit and the pair sort again (after growPairs); returns the sorted pairs' buffer. */
  encodeRegrow(rec: Recorder, inputs: SweepInputs): GPUBuffer {
    this.sweep.encodeEmit(rec, inputs, this.pairsA.buffer, this.state, this.indirect);
    this.sortedPairs = this.pairStage.encode(
      rec,
      this.sort,
      this.pairsA.buffer,
      this.pairsB.buffer,
      this.pairsA.capacity,
      inputs.slotCount,
      this.state,
      this.indirect,
    );
    return this.sortedPairs;
  }

  /** Records the state words' copy to `dst` at byte `offset` (64 bytes). */
  encodeStateCopy(encoder: GPUCommandEncoder, dst: GPUBuffer, offset: number): void {
    encoder.copyBufferToBuffer(this.state, 0, dst, offset, 4 * STATE_WORDS);
  }

  /** Ends an update with the state words read back; returns its result. */
  finishUpdate(state: Uint32Array, regrows: number, dispatches: number, gpuTime: Record<string, number> | null): BroadPhaseResult {
    this.pairCount = state[STATE.PAIR_COUNT];
    this.lastState = state.slice();
    return this.resultOf(state, regrows, dispatches, gpuTime);
  }

  /** The result an update's state words (layout.ts STATE) describe, at the pair capacity now. */
  resultOf(state: Uint32Array, regrows: number, dispatches: number, gpuTime: Record<string, number> | null): BroadPhaseResult {
    return {
      pairCount: state[STATE.PAIR_COUNT],
      axis: state[STATE.AXIS],
      strips: state[STATE.STRIPS],
      entries: state[STATE.ENTRIES],
      workItems: state[STATE.WORK_TOTAL],
      regrows,
      pairCapacity: this.pairsA.capacity,
      dispatches,
      gpuTime,
    };
  }

  private async run(source: GpuWorld | GpuProxySet): Promise<BroadPhaseResult> {
    await this.ctx.checkErrors();
    const maxDim = this.ctx.maxWorkgroupsPerDimension;
    const queue = this.ctx.device.queue;
    const readback = this.readback;

    let regrows = 0;
    let dispatches = 0;
    let gpuTime: Record<string, number> | null = null;
    let state: Uint32Array;
    let inputs: SweepInputs;
    for (;;) {
      inputs = this.beginUpdate(source);
      await this.ctx.checkErrors();
      const encoder = this.ctx.device.createCommandEncoder({ label: 'broadphase' });
      this.timer.reset();
      const recorder = passRecorder(encoder, maxDim, this.timer);
      this.encodePasses(recorder.pass, inputs);
      dispatches = recorder.dispatches();
      this.encodeStateCopy(encoder, readback.buffer, 0);
      this.timer.resolveTo(encoder, readback.buffer, TIMER_OFFSET);
      queue.submit([encoder.finish()]);
      const bytes = await readback.read(this.ctx, TIMER_OFFSET + this.timer.bytes);
      state = new Uint32Array(bytes, 0, STATE_WORDS);
      gpuTime = this.timer.parse(bytes, TIMER_OFFSET);
      if ((state[STATE.OVERFLOW] & OVERFLOW_ENTRIES) === 0) break;
      // More sweep entries than room for them (not expected: see keys.ts): grow, redo everything.
      regrows++;
      this.growEntries(state[STATE.ENTRY_TOTAL]);
    }

    while ((state[STATE.OVERFLOW] & OVERFLOW_PAIRS) !== 0) {
      // The GPU counted every pair it found: grow to hold them all, redo the emit and the sort.
      regrows++;
      this.growPairs(state[STATE.PAIR_COUNT]);
      await this.ctx.checkErrors();
      const redo = this.ctx.device.createCommandEncoder({ label: 'broadphase regrow' });
      passRecorder(redo, maxDim, null, ' (regrow)').pass('sweep+pairs', (rec) => this.encodeRegrow(rec, inputs));
      this.encodeStateCopy(redo, readback.buffer, 0);
      queue.submit([redo.finish()]);
      state = new Uint32Array(await readback.read(this.ctx, 4 * STATE_WORDS), 0, STATE_WORDS);
    }
    await this.ctx.checkErrors();
    return this.finishUpdate(state, regrows, dispatches, gpuTime);
  }

  /** Makes room for `entries` sweep entries and `pairs` pairs. */
  private reserve(entries: number, pairs: number): void {
    this.items.ensure(entries);
    this.itemsTmp.ensure(entries);
    this.sweep.reserve(entries);
    this.pairsA.ensure(pairs);
    this.pairsB.ensure(pairs);
    this.sort.reserve(Math.max(entries, this.pairsA.capacity));
  }

  /** The sorted pairs of the last update: 2 words (a, b) per pair. */
  async readPairs(): Promise<Uint32Array> {
    if (this.pairCount === 0) return new Uint32Array(0);
    return new Uint32Array(await readBuffer(this.ctx, this.pairs, 8 * this.pairCount, DEBUG_READ));
  }

  /** The proxy AABBs of the last update: 4 floats per proxy slot. */
  async readAABBs(): Promise<Float32Array> {
    if (!this.lastInputs) throw new Error('GpuBroadPhase: no update yet');
    return new Float32Array(await readBuffer(this.ctx, this.lastInputs.proxyAABB, 16 * this.lastInputs.slotCount, DEBUG_READ));
  }

  destroy(): void {
    for (const a of [this.proxyAABBs, this.items, this.itemsTmp, this.pairsA, this.pairsB]) a.destroy();
    this.state.destroy();
    this.indirect.destroy();
    this.readback.destroy();
    this.timer.destroy();
  }
}
