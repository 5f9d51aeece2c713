/*
 * The GPU narrow phase: from the broad phase's pairs to Box2D contacts, persistent across steps.
 *
 * update(mirror, broadPhase) records the broad phase and the narrow phase into one command buffer
 * and reads back 192 bytes of counts (plus timestamps) with one map:
 *   contacts  oriented contacts (b2Contact::Create's A/B rule), keys, match with the previous
 *             step's contacts (binary search on the sorted keys), bins by pair type (one stable
 *             4-bit radix pass: count, scan, scatter), the bins' indirect sizes   contacts.ts
 *   collide   one kernel per bin: circles, polygon-circle, polygons, edge-circle, edge-polygon,
 *             chain-circle, chain-polygon, sensors (b2TestOverlap); an empty bin's indirect
 *             size is zero workgroups, so nothing runs for it            collideCircle.ts,
 *                                                                        collidePolygon.ts,
 *                                                                        collideEdge.ts, overlap.ts
 *   persist   touching state, impulses carried by b2ContactID key, began/ended     persist.ts
 *   compact   prefix scans: the solver's list of touching non-sensor contacts, and the
 *             begin/end events (contacts gone with their pair included)  compact.ts
 * Contacts are the pairs, in pair order (sorted by proxy slots): contact i of a step is pair i.
 * Two contact sets (keys and manifolds) alternate: each step writes one and reads the other as
 * the previous step's. Everything stays on the GPU; the read-back is what the host needs to size
 * buffers: if the pairs or the contacts did not fit, the buffers grow to the count the GPU kept
 * and the passes that overflowed run again (the previous set is untouched until a step succeeds).
 * Same inputs, same outputs, bit for bit, on one device: positions come from scans and stable
 * sorts, never from atomics.
 * Passes of later stages (the solver) join the same command buffer through the update's
 * `after` option, which receives this recording's output buffers.
 *
 * With { wait: false } an update returns once submitted: its read-back completes in the
 * background and is looked at before the next update records anything (a ring of read-back
 * buffers keeps up to four steps in flight). An overflow found that way grows the buffers for the
 * following steps; the step that overflowed keeps the first `capacity` contacts in key order (or
 * none, for a pair overflow) and says so in its result (`overflowed`). Headroom (capacities of at
 * least 1.5 x the last counts seen) makes that rare.
 */

import type { b2Contact } from '../src/dynamics/contacts/b2Contact';
import { b2ContactFlags } from '../src/common/b2Constants';
import type { GpuContext } from './device';
import { GpuArray } from './buffers';
import { passRecorder, Uniform } from './kernel';
import type { PassRecorder } from './kernel';
import type { BroadPhaseResult, GpuBroadPhase } from './broadPhase';
import { ContactsStage } from './contacts';
import type { ContactsInputs } from './contacts';
import type { CollideInputs, CollideStage } from './collide';
import { CollideCircleStage } from './collideCircle';
import { CollidePolygonStage } from './collidePolygon';
import { CollideEdgeStage } from './collideEdge';
import { OverlapStage } from './overlap';
import { PersistStage } from './persist';
import { CompactStage } from './compact';
import { PassTimer } from './timing';
import { Readback, ReadbackRing, readBuffer } from './readback';
import {
  BIN_COUNT,
  BIN_NAMES,
  MANIFOLD_WORDS,
  MF,
  NO_CONTACT,
  NP,
  NP_INDIRECT_WORDS,
  NP_STATE_WORDS,
  OVERFLOW_CONTACTS,
  OVERFLOW_ENTRIES,
  OVERFLOW_PAIRS,
  STATE,
  STATE_WORDS,
  USAGE,
} from './layout';
import type { GpuWorld } from './world';

/** The label of the read-backs for tests and tools (readBuffer). */
const DEBUG_READ = 'narrowphase debug read';

export interface GpuNarrowPhaseOptions {
  /** Contacts the buffers hold at first (default 1024); they grow (doubling) to what is needed. */
  initialContactCapacity?: number;
  /** Time each bin's kernel in a pass of its own ('collide <bin>' in gpuTime; for benchmarks). */
  timeBins?: boolean;
}

export interface NarrowPhaseUpdateOptions {
  /**
   * true (default): wait for this step's read-back and redo what overflowed before returning.
   * false: return once submitted (see the file header).
   */
  wait?: boolean;
  /**
   * Records more passes after the narrow phase's, into the same command buffer (the solver, part
   * 3). Called once per recording: again when an overflow makes the host rerun the narrow phase,
   * so the passes must do nothing when the state buffers show an overflow (the rerun's state
   * has none).
   */
  after?: (pass: PassRecorder, outputs: NarrowPhaseOutputs) => void;
}

/** The buffers a step's later passes read (the set this recording writes). */
export interface NarrowPhaseOutputs {
  /** The broad phase's state (STATE: its overflow word). */
  broadState: GPUBuffer;
  /** The narrow phase's state (NP: counts, overflow). */
  npState: GPUBuffer;
  solverList: GPUBuffer;
  contactRefs: GPUBuffer;
  /** This step's manifolds. */
  manifolds: GPUBuffer;
  /** Contacts the buffers hold (a bound on every per-contact list). */
  contactCapacity: number;
}

export interface NarrowPhaseResult {
  /** The broad phase's part of the step. */
  broad: BroadPhaseResult;
  /** Contacts this step (the pairs, or the first `contactCapacity` of them after an overflow). */
  contactCount: number;
  /** Contacts of the previous step. */
  previousCount: number;
  /** Touching non-sensor contacts (the solver list's length). */
  solverCount: number;
  /** Begin/end events. */
  eventCount: number;
  /** Contacts per bin (layout.ts BIN order). */
  binCounts: number[];
  contactCapacity: number;
  /** Times the contact buffers grew during this update. */
  contactRegrows: number;
  /** Dispatches recorded by the step's first submission (broad and narrow phase). */
  dispatches: number;
  /** GPU milliseconds per pass (timestamp queries), null when unavailable. */
  gpuTime: Record<string, number> | null;
  /**
   * Host milliseconds: recording, the submit call, and the wait for the read-back (with
   * { wait: false }: the wait for a free read-back buffer, i.e. for the oldest step in flight).
   */
  hostMs: { encode: number; submit: number; wait: number };
  /** The step ran out of room and its lists are truncated (only with { wait: false }). */
  overflowed: boolean;
  /** { wait: false }: the counts above are those of the latest step whose read-back is in. */
  pending: boolean;
  /** { wait: false }: resolves with this step's own result once its read-back is in. */
  settled?: Promise<NarrowPhaseResult>;
}

/** A contact as readContacts() returns it (a debugging and test view of the GPU records). */
export interface GpuContactRecord {
  index: number;
  /** The pair: proxy slots, a < b. */
  a: number;
  b: number;
  /** Proxy slots of fixture A and fixture B (b2Contact's order). */
  proxyA: number;
  proxyB: number;
  fixtureA: number;
  childA: number;
  fixtureB: number;
  childB: number;
  bin: number;
  sensor: boolean;
  touching: boolean;
  began: boolean;
  ended: boolean;
  /** Matched a contact of the previous step. */
  warm: boolean;
  /** The previous step's index, or -1. */
  previous: number;
  /** b2Manifold::Type (0 when there are no points). */
  type: number;
  pointCount: number;
  localNormal: { x: number; y: number };
  localPoint: { x: number; y: number };
  points: { localPoint: { x: number; y: number }; id: number; normalImpulse: number; tangentImpulse: number }[];
}

export interface GpuContactEvent {
  /** EVENT_BEGIN (1) or EVENT_END (2). */
  kind: number;
  proxyA: number;
  proxyB: number;
  /** This step's contact index, or the previous step's for a contact gone with its pair. */
  index: number;
  /** The contact is gone (its pair left the broad phase's list) rather than no longer touching. */
  vanished: boolean;
}

/** Byte layout of the read-back: broad-phase state, narrow-phase state, timestamps. */
const NP_STATE_OFFSET = 64;
const TIMER_OFFSET = 256;

const { e_touchingFlag } = b2ContactFlags;

interface InFlight {
  settled: Promise<NarrowPhaseResult>;
  result: NarrowPhaseResult | null;
  /** The broad phase's state words of the step. */
  state: Uint32Array | null;
}

export class GpuNarrowPhase {
  readonly ctx: GpuContext;
  private readonly contacts: ContactsStage;
  private readonly collideStages: CollideStage[];
  private readonly persist: PersistStage;
  private readonly compact: CompactStage;
  private readonly timer: PassTimer;
  private readonly timeBins: boolean;
  private readonly collideParams: Uniform;
  private readonly keys: [GpuArray, GpuArray];
  private readonly manifoldSets: [GpuArray, GpuArray];
  private readonly contactRef: GpuArray;
  private readonly items: GpuArray;
  private readonly itemsTmp: GpuArray;
  private readonly solverFlags: GpuArray;
  private readonly eventFlags: GpuArray;
  private readonly solverListArray: GpuArray;
  private readonly eventArray: GpuArray;
  /** Counts between stages (layout.ts NP), never read back inside a step but for the 128 bytes. */
  readonly state: GPUBuffer;
  /** Indirect dispatch sizes (layout.ts NP_ARGS). */
  readonly indirect: GPUBuffer;
  private readonly readback: Readback;
  private readonly ring: ReadbackRing;
  private readonly inFlight: InFlight[] = [];
  private capacity: number;
  private givenPairs: GpuArray | null = null;
  private givenState: GPUBuffer | null = null;
  /** The contact set the next update writes (the other holds the previous step's contacts). */
  private cur = 0;
  /** The set the last update wrote. */
  private lastSet = 1;
  private busy = false;
  /** The result of the last update whose counts are known. */
  lastResult: NarrowPhaseResult | null = null;
  /** Steps that overflowed with { wait: false } (their lists were truncated). */
  truncatedSteps = 0;
  /** Contact-buffer growths over all updates. */
  contactRegrows = 0;

  constructor(ctx: GpuContext, options: GpuNarrowPhaseOptions = {}) {
    this.ctx = ctx;
    this.capacity = Math.max(16, options.initialContactCapacity ?? 1024);
    this.timeBins = options.timeBins === true;
    this.contacts = new ContactsStage(ctx);
    this.collideStages = [new CollideCircleStage(ctx), new CollidePolygonStage(ctx), new CollideEdgeStage(ctx), new OverlapStage(ctx)];
    this.persist = new PersistStage(ctx);
    this.compact = new CompactStage(ctx);
    this.timer = new PassTimer(ctx, 32);
    this.collideParams = new Uniform(ctx, 'collide params', 4);
    const cap = this.capacity;
    this.keys = [new GpuArray(ctx, 'contact keys 0', 16, cap), new GpuArray(ctx, 'contact keys 1', 16, cap)];
    this.manifoldSets = [new GpuArray(ctx, 'manifolds 0', 4 * MANIFOLD_WORDS, cap), new GpuArray(ctx, 'manifolds 1', 4 * MANIFOLD_WORDS, cap)];
    this.contactRef = new GpuArray(ctx, 'contactRef', 32, cap);
    this.items = new GpuArray(ctx, 'bin items', 8, cap);
    this.itemsTmp = new GpuArray(ctx, 'bin items tmp', 8, cap);
    this.solverFlags = new GpuArray(ctx, 'solver flags', 4, cap);
    this.eventFlags = new GpuArray(ctx, 'event flags', 4, 2 * cap);
    this.solverListArray = new GpuArray(ctx, 'solver list', 4, cap);
    this.eventArray = new GpuArray(ctx, 'contact events', 16, 2 * cap);
    this.state = ctx.createBuffer('narrowphase state', 4 * NP_STATE_WORDS, USAGE.STORAGE | USAGE.COPY_DST | USAGE.COPY_SRC);
    this.indirect = ctx.createBuffer('narrowphase indirect', 4 * NP_INDIRECT_WORDS, USAGE.STORAGE | USAGE.INDIRECT | USAGE.COPY_DST);
    this.readback = new Readback(ctx, 'narrowphase read-back', TIMER_OFFSET + this.timer.bytes);
    this.ring = new ReadbackRing(ctx, 'narrowphase deferred read-back', TIMER_OFFSET + this.timer.bytes, 4);
    this.reserve(cap);
  }

  // ---- Outputs (the last update's; the solver binds these) ----

  /** Contacts the buffers hold now. */
  get contactCapacity(): number {
    return this.capacity;
  }
  /** This step's manifold records (layout.ts), MANIFOLD_WORDS u32 per contact. */
  get manifolds(): GPUBuffer {
    return this.manifoldSets[this.lastSet].buffer;
  }
  /** The previous step's manifold records. */
  get previousManifolds(): GPUBuffer {
    return this.manifoldSets[1 - this.lastSet].buffer;
  }
  /** This step's contact keys (vec4<u32>: a, b, generation a, generation b), sorted. */
  get contactKeys(): GPUBuffer {
    return this.keys[this.lastSet].buffer;
  }
  /** This step's oriented fixtures per contact (2 x vec4<u32>, layout.ts). */
  get contactRefs(): GPUBuffer {
    return this.contactRef.buffer;
  }
  /** Indices of the touching non-sensor contacts (npState[NP.SOLVER] of them). */
  get solverList(): GPUBuffer {
    return this.solverListArray.buffer;
  }
  /** Begin/end events (vec4<u32>, npState[NP.EVENTS] of them). */
  get events(): GPUBuffer {
    return this.eventArray.buffer;
  }

  /** Makes room for `capacity` contacts; both contact sets keep their contents. */
  private reserve(capacity: number): void {
    for (const a of [...this.keys, ...this.manifoldSets]) a.ensure(capacity, a.capacity);
    for (const a of [this.contactRef, this.items, this.itemsTmp, this.solverFlags, this.solverListArray]) a.ensure(capacity);
    this.eventFlags.ensure(2 * capacity);
    this.eventArray.ensure(2 * capacity);
    this.contacts.reserve(capacity);
    this.compact.reserve(capacity);
    this.capacity = Math.max(this.capacity, capacity);
  }

  private growContacts(needed: number): void {
    if (needed <= this.capacity) return;
    let capacity = this.capacity;
    while (capacity < needed) capacity *= 2;
    this.reserve(capacity);
    this.contactRegrows++;
  }

  /** Queues the host-written state words of a (re)run: the capacity, no overflow. */
  private beginStep(mirror: GpuWorld): void {
    this.reserve(this.capacity);
    this.ctx.device.queue.writeBuffer(this.state, 4 * NP.CAPACITY, new Uint32Array([this.capacity, 0]));
    this.collideParams.f32[0] = mirror.cellSize;
    this.collideParams.upload();
  }

  /** Records the narrow phase's passes for contact set `set`. */
  private encodePasses(pass: PassRecorder, mirror: GpuWorld, pairs: GPUBuffer, broadState: GPUBuffer, set: number): void {
    const curKey = this.keys[set].buffer;
    const prevKey = this.keys[1 - set].buffer;
    const manifolds = this.manifoldSets[set].buffer;
    const prevManifolds = this.manifoldSets[1 - set].buffer;
    const contactsIo: ContactsInputs = {
      broadState,
      pairs,
      proxyRef: mirror.proxyRef.buffer,
      proxyKey: mirror.proxyKey.buffer,
      npState: this.state,
      npIndirect: this.indirect,
      curKey,
      prevKey,
      contactRef: this.contactRef.buffer,
      items: this.items.buffer,
      itemsTmp: this.itemsTmp.buffer,
    };
    let binned: GPUBuffer = this.items.buffer;
    pass('contacts', (rec) => {
      binned = this.contacts.encode(rec, contactsIo, set);
    });
    const collideIo: CollideInputs = {
      params: this.collideParams.buffer,
      npState: this.state,
      npIndirect: this.indirect,
      binned,
      contactRef: this.contactRef.buffer,
      fixtureShape: mirror.fixtureShape.buffer,
      shapePool: mirror.shapePool.buffer,
      bodyXf: mirror.bodyXf.buffer,
      bodyCell: mirror.bodyCell.buffer,
      manifolds,
    };
    const bins: [CollideStage, number][] = [];
    for (const stage of this.collideStages) for (const bin of stage.kernels.keys()) bins.push([stage, bin]);
    bins.sort((x, y) => x[1] - y[1]);
    if (this.timeBins) {
      for (const [stage, bin] of bins) pass(`collide ${BIN_NAMES[bin]}`, (rec) => stage.encodeBin(rec, bin, collideIo));
    } else {
      pass('collide', (rec) => {
        for (const [stage, bin] of bins) stage.encodeBin(rec, bin, collideIo);
      });
    }
    const io = {
      npState: this.state,
      npIndirect: this.indirect,
      contactRef: this.contactRef.buffer,
      manifolds,
      prevManifolds,
      solverFlags: this.solverFlags.buffer,
      eventFlags: this.eventFlags.buffer,
      curKey,
      prevKey,
      solverList: this.solverListArray.buffer,
      events: this.eventArray.buffer,
    };
    pass('persist', (rec) => this.persist.encode(rec, io));
    pass('compact', (rec) => this.compact.encode(rec, io));
  }

  /**
   * One step of collision detection: the broad phase's update of `mirror` (after its sync()) and
   * the narrow phase on its pairs, in one submission. Rejects with GpuDeviceLostError once the
   * device is lost, GpuOutOfMemoryError when a buffer could not be allocated.
   */
  async update(mirror: GpuWorld, broadPhase: GpuBroadPhase, options: NarrowPhaseUpdateOptions = {}): Promise<NarrowPhaseResult> {
    if (this.busy) throw new Error('GpuNarrowPhase.update: the previous update has not finished');
    this.busy = true;
    try {
      return options.wait === false ? await this.runDeferred(mirror, broadPhase, options.after) : await this.runWaiting(mirror, broadPhase, options.after);
    } finally {
      this.busy = false;
    }
  }

  /** Records the whole step (broad + narrow phase) and the copies for its read-back into `rb`. */
  private recordStep(mirror: GpuWorld, bp: GpuBroadPhase, rb: GPUBuffer, after: NarrowPhaseUpdateOptions['after']): { encoder: GPUCommandEncoder; dispatches: () => number } {
    const inputs = bp.beginUpdate(mirror);
    this.beginStep(mirror);
    const encoder = this.ctx.device.createCommandEncoder({ label: 'collision step' });
    this.timer.reset();
    const { pass, dispatches } = passRecorder(encoder, this.ctx.maxWorkgroupsPerDimension, this.timer);
    const pairs = bp.encodePasses(pass, inputs);
    this.encodePasses(pass, mirror, pairs, bp.state, this.cur);
    after?.(pass, this.outputs(bp.state, this.cur));
    bp.encodeStateCopy(encoder, rb, 0);
    encoder.copyBufferToBuffer(this.state, 0, rb, NP_STATE_OFFSET, 4 * NP_STATE_WORDS);
    this.timer.resolveTo(encoder, rb, TIMER_OFFSET);
    return { encoder, dispatches };
  }

  private result(
    broad: BroadPhaseResult,
    np: Uint32Array,
    regrows: number,
    dispatches: number,
    gpuTime: Record<string, number> | null,
    hostMs: NarrowPhaseResult['hostMs'],
    pending: boolean,
  ): NarrowPhaseResult {
    const binCounts: number[] = [];
    for (let b = 0; b < BIN_COUNT; ++b) binCounts.push(np[NP.BINS + b + 1] - np[NP.BINS + b]);
    return {
      broad,
      contactCount: np[NP.CONTACTS],
      previousCount: np[NP.PREV],
      solverCount: np[NP.SOLVER],
      eventCount: np[NP.EVENTS],
      binCounts,
      contactCapacity: this.capacity,
      contactRegrows: regrows,
      dispatches,
      gpuTime,
      hostMs,
      overflowed: (np[NP.OVERFLOW] & OVERFLOW_CONTACTS) !== 0 || (broad.pairCount > 0 && np[NP.PAIRS] === 0),
      pending,
    };
  }

  /** The outputs of contact set `set` for passes recorded after the narrow phase. */
  private outputs(broadState: GPUBuffer, set: number): NarrowPhaseOutputs {
    return {
      broadState,
      npState: this.state,
      solverList: this.solverListArray.buffer,
      contactRefs: this.contactRef.buffer,
      manifolds: this.manifoldSets[set].buffer,
      contactCapacity: this.capacity,
    };
  }

  private async runWaiting(mirror: GpuWorld, bp: GpuBroadPhase, after: NarrowPhaseUpdateOptions['after']): Promise<NarrowPhaseResult> {
    await this.ctx.checkErrors();
    const queue = this.ctx.device.queue;
    const rb = this.readback;
    const maxDim = this.ctx.maxWorkgroupsPerDimension;
    let bpRegrows = 0;
    let npRegrows = 0;
    let dispatches = 0;
    let gpuTime: Record<string, number> | null = null;
    let state: Uint32Array;
    let np: Uint32Array;
    const hostMs = { encode: 0, submit: 0, wait: 0 };
    let inputs;
    for (;;) {
      const t0 = performance.now();
      const step = this.recordStep(mirror, bp, rb.buffer, after);
      inputs = bp.lastUpdateInputs;
      await this.ctx.checkErrors();
      const t1 = performance.now();
      queue.submit([step.encoder.finish()]);
      const t2 = performance.now();
      const bytes = await rb.read(this.ctx, TIMER_OFFSET + this.timer.bytes);
      const t3 = performance.now();
      hostMs.encode += t1 - t0;
      hostMs.submit += t2 - t1;
      hostMs.wait += t3 - t2;
      dispatches = step.dispatches();
      state = new Uint32Array(bytes, 0, STATE_WORDS);
      np = new Uint32Array(bytes, NP_STATE_OFFSET, NP_STATE_WORDS);
      gpuTime = this.timer.parse(bytes, TIMER_OFFSET);
      if ((state[STATE.OVERFLOW] & OVERFLOW_ENTRIES) === 0) break;
      bpRegrows++;
      bp.growEntries(state[STATE.ENTRY_TOTAL]);
    }
    const before = this.contactRegrows;
    while ((state[STATE.OVERFLOW] & OVERFLOW_PAIRS) !== 0 || (np[NP.OVERFLOW] & OVERFLOW_CONTACTS) !== 0) {
      const pairOverflow = (state[STATE.OVERFLOW] & OVERFLOW_PAIRS) !== 0;
      if (pairOverflow) {
        bpRegrows++;
        bp.growPairs(state[STATE.PAIR_COUNT]);
        this.growContacts(state[STATE.PAIR_COUNT]);
      } else {
        this.growContacts(np[NP.PAIRS]);
      }
      this.beginStep(mirror);
      await this.ctx.checkErrors();
      const encoder = this.ctx.device.createCommandEncoder({ label: 'collision step (regrow)' });
      let pairs = bp.pairs;
      const { pass } = passRecorder(encoder, maxDim, null, ' (regrow)');
      if (pairOverflow) pass('pairs', (rec) => (pairs = bp.encodeRegrow(rec, inputs)));
      this.encodePasses(pass, mirror, pairs, bp.state, this.cur);
      after?.(pass, this.outputs(bp.state, this.cur));
      bp.encodeStateCopy(encoder, rb.buffer, 0);
      encoder.copyBufferToBuffer(this.state, 0, rb.buffer, NP_STATE_OFFSET, 4 * NP_STATE_WORDS);
      queue.submit([encoder.finish()]);
      const bytes = await rb.read(this.ctx, NP_STATE_OFFSET + 4 * NP_STATE_WORDS);
      state = new Uint32Array(bytes, 0, STATE_WORDS);
      np = new Uint32Array(bytes, NP_STATE_OFFSET, NP_STATE_WORDS);
    }
    await this.ctx.checkErrors();
    const broad = bp.finishUpdate(state, bpRegrows, dispatches, gpuTime);
    this.lastSet = this.cur;
    this.cur = 1 - this.cur;
    const result = this.result(broad, np, this.contactRegrows - before + npRegrows, dispatches, gpuTime, hostMs, false);
    this.lastResult = result;
    return result;
  }

  /**
   * The narrow phase alone on a given pair list (proxy slots of `mirror`, a < b, sorted by (a, b),
   * two words per pair), as if the broad phase had found exactly these pairs: for tests of the
   * collide kernels on chosen shape pairs, and for tools. The contact sets persist as in update().
   */
  async updateWithPairs(mirror: GpuWorld, pairs: Uint32Array): Promise<NarrowPhaseResult> {
    if (this.busy) throw new Error('GpuNarrowPhase.updateWithPairs: the previous update has not finished');
    this.busy = true;
    try {
      await this.ctx.checkErrors();
      const n = pairs.length / 2;
      for (let i = 1; i < n; ++i) {
        const a0 = pairs[2 * i - 2];
        const b0 = pairs[2 * i - 1];
        if (pairs[2 * i] < a0 || (pairs[2 * i] === a0 && pairs[2 * i + 1] <= b0)) throw new RangeError('updateWithPairs: pairs must be sorted by (a, b) without duplicates');
      }
      this.givenPairs ??= new GpuArray(this.ctx, 'given pairs', 8, 64);
      this.givenState ??= this.ctx.createBuffer('given pair state', 4 * STATE_WORDS, USAGE.STORAGE | USAGE.COPY_DST);
      this.givenPairs.ensure(Math.max(1, n));
      const queue = this.ctx.device.queue;
      if (n > 0) queue.writeBuffer(this.givenPairs.buffer, 0, pairs.buffer, pairs.byteOffset, 8 * n);
      const words = new Uint32Array(STATE_WORDS);
      words[STATE.PAIR_COUNT] = n;
      words[STATE.PAIR_SORT_COUNT] = n;
      queue.writeBuffer(this.givenState, 0, words);
      this.growContacts(n);
      const maxDim = this.ctx.maxWorkgroupsPerDimension;
      const rb = this.readback;
      let np: Uint32Array;
      let dispatches = 0;
      let gpuTime: Record<string, number> | null = null;
      this.beginStep(mirror);
      const encoder = this.ctx.device.createCommandEncoder({ label: 'narrow phase on given pairs' });
      this.timer.reset();
      const recorder = passRecorder(encoder, maxDim, this.timer);
      this.encodePasses(recorder.pass, mirror, this.givenPairs.buffer, this.givenState, this.cur);
      dispatches = recorder.dispatches();
      encoder.copyBufferToBuffer(this.state, 0, rb.buffer, NP_STATE_OFFSET, 4 * NP_STATE_WORDS);
      this.timer.resolveTo(encoder, rb.buffer, TIMER_OFFSET);
      await this.ctx.checkErrors();
      queue.submit([encoder.finish()]);
      const bytes = await rb.read(this.ctx, TIMER_OFFSET + this.timer.bytes);
      np = new Uint32Array(bytes, NP_STATE_OFFSET, NP_STATE_WORDS);
      gpuTime = this.timer.parse(bytes, TIMER_OFFSET);
      await this.ctx.checkErrors();
      this.lastSet = this.cur;
      this.cur = 1 - this.cur;
      const broad: BroadPhaseResult = { pairCount: n, axis: 0, strips: 0, entries: 0, workItems: 0, regrows: 0, pairCapacity: n, dispatches: 0, gpuTime: null };
      const result = this.result(broad, np, 0, dispatches, gpuTime, { encode: 0, submit: 0, wait: 0 }, false);
      this.lastResult = result;
      return result;
    } finally {
      this.busy = false;
    }
  }

  /** Looks at the read-backs that are in, oldest first: counts, and growth after an overflow. */
  private absorbSettled(bp: GpuBroadPhase): void {
    while (this.inFlight.length > 0 && this.inFlight[0].result !== null) {
      const entry = this.inFlight.shift()!;
      const r = entry.result!;
      const state = entry.state!;
      this.lastResult = r;
      const pairsFound = state[STATE.PAIR_COUNT];
      if ((state[STATE.OVERFLOW] & OVERFLOW_ENTRIES) !== 0) bp.growEntries(state[STATE.ENTRY_TOTAL]);
      // Headroom: keep 1.5 x the last counts.
      const want = Math.ceil(1.5 * pairsFound);
      if (want > bp.pairCapacity) bp.growPairs(want);
      if (want > this.capacity) this.growContacts(want);
      if (r.overflowed) this.truncatedSteps++;
    }
  }

  private async runDeferred(mirror: GpuWorld, bp: GpuBroadPhase, after: NarrowPhaseUpdateOptions['after']): Promise<NarrowPhaseResult> {
    await this.ctx.checkErrors();
    this.absorbSettled(bp);
    const tr = performance.now();
    const rb = await this.ring.next();
    this.absorbSettled(bp);
    const t0 = performance.now();
    const step = this.recordStep(mirror, bp, rb.buffer, after);
    await this.ctx.checkErrors();
    const t1 = performance.now();
    this.ctx.device.queue.submit([step.encoder.finish()]);
    const t2 = performance.now();
    const dispatches = step.dispatches();
    const names = this.timer;
    const entry: InFlight = { settled: null as unknown as Promise<NarrowPhaseResult>, result: null, state: null };
    const capacity = this.capacity;
    entry.settled = rb.read(this.ctx, TIMER_OFFSET + names.bytes).then((bytes) => {
      const state = new Uint32Array(bytes, 0, STATE_WORDS).slice();
      const np = new Uint32Array(bytes, NP_STATE_OFFSET, NP_STATE_WORDS);
      const broad: BroadPhaseResult = {
        pairCount: state[STATE.PAIR_COUNT],
        axis: state[STATE.AXIS],
        strips: state[STATE.STRIPS],
        entries: state[STATE.ENTRIES],
        workItems: state[STATE.WORK_TOTAL],
        regrows: 0,
        pairCapacity: bp.pairCapacity,
        dispatches,
        gpuTime: null,
      };
      const r = this.result(broad, np, 0, dispatches, null, { encode: t1 - t0, submit: t2 - t1, wait: performance.now() - t2 }, false);
      r.contactCapacity = capacity;
      r.overflowed = r.overflowed || (state[STATE.OVERFLOW] & (OVERFLOW_PAIRS | OVERFLOW_ENTRIES)) !== 0;
      entry.state = state;
      entry.result = r;
      return r;
    });
    this.inFlight.push(entry);
    this.lastSet = this.cur;
    this.cur = 1 - this.cur;
    const last = this.lastResult;
    const base: NarrowPhaseResult = last
      ? { ...last, hostMs: { encode: t1 - t0, submit: t2 - t1, wait: t0 - tr }, dispatches }
      : this.result(
          { pairCount: 0, axis: 0, strips: 0, entries: 0, workItems: 0, regrows: 0, pairCapacity: bp.pairCapacity, dispatches, gpuTime: null },
          new Uint32Array(NP_STATE_WORDS),
          0,
          dispatches,
          null,
          { encode: t1 - t0, submit: t2 - t1, wait: t0 - tr },
          true,
        );
    return { ...base, pending: true, settled: entry.settled };
  }

  /** Waits for every update in flight ({ wait: false }) and takes in their counts. */
  async settle(broadPhase: GpuBroadPhase): Promise<NarrowPhaseResult | null> {
    await Promise.all(this.inFlight.map((e) => e.settled.catch(() => undefined)));
    this.absorbSettled(broadPhase);
    return this.lastResult;
  }

  /** Forgets the previous step's contacts: the next update starts cold (no warm start, all begin). */
  reset(): void {
    this.ctx.device.queue.writeBuffer(this.state, 4 * NP.COUNT_0, new Uint32Array([0, 0]));
  }

  /**
   * Takes the JavaScript world's contacts as the previous step's (keys, manifolds, impulses,
   * touching state), so that the next update warm-starts from the engine's state: for handing a
   * running world to the GPU (and for tests). `mirror` must be synced. Contacts of proxies the
   * mirror does not have are skipped. Returns how many contacts were taken.
   */
  seedFromWorld(mirror: GpuWorld): number {
    const records: { a: number; b: number; words: Uint32Array }[] = [];
    const f32 = new Float32Array(1);
    const u32 = new Uint32Array(f32.buffer);
    const bits = (x: number) => {
      f32[0] = x;
      return u32[0];
    };
    for (let c: b2Contact | null = mirror.world.m_contactManager.m_contactList; c; c = c.m_next) {
      const pa = mirror.proxySlot(c.m_fixtureA, c.m_indexA);
      const pb = mirror.proxySlot(c.m_fixtureB, c.m_indexB);
      if (pa < 0 || pb < 0) continue;
      const a = Math.min(pa, pb);
      const b = Math.max(pa, pb);
      const m = c.m_manifold;
      const touching = (c.m_flags & e_touchingFlag) !== 0;
      const sensor = c.m_fixtureA.m_isSensor || c.m_fixtureB.m_isSensor;
      const w = new Uint32Array(4 + MANIFOLD_WORDS);
      w[0] = a;
      w[1] = b;
      w[2] = mirror.proxyGenerationOf(a);
      w[3] = mirror.proxyGenerationOf(b);
      const count = m.pointCount;
      let header = count > 0 ? (m.type | (count << 2)) >>> 0 : 0;
      if (touching) header |= MF.TOUCHING;
      if (sensor) header |= MF.SENSOR;
      if (pa > pb) header |= MF.SWAPPED;
      const h = 4;
      w[h] = header;
      w[h + 1] = count > 0 ? m.points[0].id.key : 0;
      w[h + 2] = count > 1 ? m.points[1].id.key : 0;
      w[h + 3] = NO_CONTACT;
      if (count > 0) {
        w[h + 4] = bits(m.localNormal.x);
        w[h + 5] = bits(m.localNormal.y);
        w[h + 6] = bits(m.localPoint.x);
        w[h + 7] = bits(m.localPoint.y);
      }
      for (let k = 0; k < count; ++k) {
        const p = m.points[k];
        w[h + 8 + 2 * k] = bits(p.localPoint.x);
        w[h + 9 + 2 * k] = bits(p.localPoint.y);
        w[h + 12 + 2 * k] = bits(p.normalImpulse);
        w[h + 13 + 2 * k] = bits(p.tangentImpulse);
      }
      records.push({ a, b, words: w });
    }
    records.sort((x, y) => x.a - y.a || x.b - y.b);
    const n = records.length;
    this.growContacts(n);
    const set = 1 - this.cur;
    const keyWords = new Uint32Array(4 * Math.max(1, n));
    const manifoldWords = new Uint32Array(MANIFOLD_WORDS * Math.max(1, n));
    records.forEach((r, i) => {
      keyWords.set(r.words.subarray(0, 4), 4 * i);
      manifoldWords.set(r.words.subarray(4), MANIFOLD_WORDS * i);
    });
    const queue = this.ctx.device.queue;
    queue.writeBuffer(this.keys[set].buffer, 0, keyWords);
    queue.writeBuffer(this.manifoldSets[set].buffer, 0, manifoldWords);
    queue.writeBuffer(this.state, 4 * (NP.COUNT_0 + set), new Uint32Array([n]));
    return n;
  }

  // ---- Read-back for tests and tools (not part of a step) ----


  /** The narrow phase's state words now (layout.ts NP). */
  async readState(): Promise<Uint32Array> {
    return new Uint32Array(await readBuffer(this.ctx, this.state, 4 * NP_STATE_WORDS, DEBUG_READ));
  }

  /** The last update's contacts, decoded. */
  async readContacts(): Promise<GpuContactRecord[]> {
    const np = await this.readState();
    const n = np[NP.CONTACTS];
    if (n === 0) return [];
    const keys = new Uint32Array(await readBuffer(this.ctx, this.contactKeys, 16 * n, DEBUG_READ));
    const refs = new Uint32Array(await readBuffer(this.ctx, this.contactRef.buffer, 32 * n, DEBUG_READ));
    const mw = await readBuffer(this.ctx, this.manifolds, 4 * MANIFOLD_WORDS * n, DEBUG_READ);
    const mu = new Uint32Array(mw);
    const mf = new Float32Array(mw);
    const out: GpuContactRecord[] = [];
    for (let i = 0; i < n; ++i) {
      const m = MANIFOLD_WORDS * i;
      const h = mu[m];
      const count = (h >> 2) & 3;
      const swapped = (h & MF.SWAPPED) !== 0;
      const a = keys[4 * i];
      const b = keys[4 * i + 1];
      const points: GpuContactRecord['points'] = [];
      for (let k = 0; k < count; ++k) {
        points.push({
          localPoint: { x: mf[m + 8 + 2 * k], y: mf[m + 9 + 2 * k] },
          id: mu[m + 1 + k],
          normalImpulse: mf[m + 12 + 2 * k],
          tangentImpulse: mf[m + 13 + 2 * k],
        });
      }
      out.push({
        index: i,
        a,
        b,
        proxyA: swapped ? b : a,
        proxyB: swapped ? a : b,
        fixtureA: refs[8 * i],
        childA: refs[8 * i + 1],
        fixtureB: refs[8 * i + 4],
        childB: refs[8 * i + 5],
        bin: (refs[8 * i + 3] >> 4) & 0xf,
        sensor: (h & MF.SENSOR) !== 0,
        touching: (h & MF.TOUCHING) !== 0,
        began: (h & MF.BEGAN) !== 0,
        ended: (h & MF.ENDED) !== 0,
        warm: (h & MF.WARM) !== 0,
        previous: mu[m + 3] === NO_CONTACT ? -1 : mu[m + 3],
        type: h & 3,
        pointCount: count,
        localNormal: { x: mf[m + 4], y: mf[m + 5] },
        localPoint: { x: mf[m + 6], y: mf[m + 7] },
        points,
      });
    }
    return out;
  }

  /** The last update's solver list (contact indices). */
  async readSolverList(): Promise<Uint32Array> {
    const n = (await this.readState())[NP.SOLVER];
    return n === 0 ? new Uint32Array(0) : new Uint32Array(await readBuffer(this.ctx, this.solverList, 4 * n, DEBUG_READ));
  }

  /** The last update's begin/end events. */
  async readEvents(): Promise<GpuContactEvent[]> {
    const n = (await this.readState())[NP.EVENTS];
    if (n === 0) return [];
    const w = new Uint32Array(await readBuffer(this.ctx, this.events, 16 * n, DEBUG_READ));
    const out: GpuContactEvent[] = [];
    for (let i = 0; i < n; ++i) {
      const index = w[4 * i + 3];
      out.push({
        kind: w[4 * i + 2],
        proxyA: w[4 * i],
        proxyB: w[4 * i + 1],
        index: index & 0x7fffffff,
        vanished: (index & 0x80000000) !== 0,
      });
    }
    return out;
  }

  /**
   * Every output of the last update as bytes (counts, keys, contactRef, manifolds, solver list,
   * events; not the capacities): for determinism checks.
   */
  async readAll(): Promise<Uint8Array> {
    const np = await this.readState();
    const n = np[NP.CONTACTS];
    const counts = [NP.CONTACTS, NP.PREV, NP.PAIRS, NP.SOLVER, NP.EVENTS, NP.EVENT_SLOTS].map((w) => np[w]);
    for (let b = 0; b <= BIN_COUNT; ++b) counts.push(np[NP.BINS + b]);
    const parts = [
      new Uint8Array(Uint32Array.from(counts).buffer),
      new Uint8Array(await readBuffer(this.ctx, this.contactKeys, 16 * n, DEBUG_READ)),
      new Uint8Array(await readBuffer(this.ctx, this.contactRef.buffer, 32 * n, DEBUG_READ)),
      new Uint8Array(await readBuffer(this.ctx, this.manifolds, 4 * MANIFOLD_WORDS * n, DEBUG_READ)),
      new Uint8Array(await readBuffer(this.ctx, this.solverList, 4 * np[NP.SOLVER], DEBUG_READ)),
      new Uint8Array(await readBuffer(this.ctx, this.events, 16 * np[NP.EVENTS], DEBUG_READ)),
    ];
    const out = new Uint8Array(parts.reduce((s, p) => s + p.length, 0));
    let at = 0;
    for (const p of parts) {
      out.set(p, at);
      at += p.length;
    }
    return out;
  }

  destroy(): void {
    for (const a of [
      ...this.keys,
      ...this.manifoldSets,
      this.contactRef,
      this.items,
      this.itemsTmp,
      this.solverFlags,
      this.eventFlags,
      this.solverListArray,
      this.eventArray,
    ])
      a.destroy();
    this.state.destroy();
    this.indirect.destroy();
    this.readback.destroy();
    this.ring.destroy();
    this.timer.destroy();
    this.collideParams.destroy();
    this.givenPairs?.destroy();
    this.givenState?.destroy();
  }
}
