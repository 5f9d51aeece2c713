/*
 * The GPU narrow phase: from the broad phase's pairs to Box2D contacts, persistent across steps.
 *
 * Its stages, recorded by GpuPipeline (pipeline.ts) after the broad phase's:
 *   contacts  oriented contacts (b2Contact::Create's A/B rule), keys, match with the previous
 *             step's contacts (binary search on the sorted keys), the contacts of sleeping or
 *             static bodies kept (b2ContactManager::Collide skips them), bins by pair type (one
 *             stable 4-bit radix pass: count, scan, scatter), the bins' indirect sizes   contacts.ts
 *   collide   one kernel per bin: circles, polygon-circle, polygons, edge-circle, edge-polygon,
 *             chain-circle, chain-polygon, sensors (b2TestOverlap); an empty bin's indirect
 *             size is zero workgroups, so nothing runs for it; kept contacts are in no bin
 *                                                                        collideCircle.ts,
 *                                                                        collidePolygon.ts,
 *                                                                        collideEdge.ts, overlap.ts
 *   persist   touching state, impulses carried by b2ContactID key, began/ended; kept contacts
 *             take the previous step's manifold as it was                          persist.ts
 *   compact   prefix scans: the solver's list of touching non-sensor contacts, and the
 *             begin/end events (contacts gone with their pair included)  compact.ts
 * In:  the pairs and the state words of the broad phase (bindStep), the mirror's tables (the
 *      awake flags as the step starts among them).
 * Out: contact set `cur` (keys, manifolds), contactRef, the solver list, the events, the counts
 *      in `state` (layout.ts NP); the solver reads them (outputs()).
 * Contacts are the pairs, in pair order (sorted by proxy slots): contact i of a step is pair i.
 * Two contact sets (keys and manifolds) alternate: each step writes one and reads the other as
 * the previous step's (endUpdate() swaps them once a step succeeded). If the pairs or the
 * contacts did not fit, the counts the GPU kept say how much room is needed (growContacts).
 * Same inputs, same outputs, bit for bit, on one device: positions come from scans and stable
 * sorts, never from atomics.
 */

import type { GpuContext } from '../device/device';
import { GpuArray } from '../device/buffers';
import { Uniform } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import type { BroadPhaseResult } from '../broadphase/broadPhase';
import { ContactsStage } from './contacts';
import type { ContactsInputs } from './contacts';
import { binInUse } from './collide';
import type { CollideInputs, CollideStage } from './collide';
import { CollideCircleStage } from './collideCircle';
import { CollidePolygonStage } from './collidePolygon';
import { CollideEdgeStage } from './collideEdge';
import { OverlapStage } from './overlap';
import { PersistStage } from './persist';
import { CompactStage } from './compact';
import { readBuffer } from '../device/readback';
import { decodeContacts, decodeEvents } from './records';
import type { GpuContactEvent, GpuContactRecord } from './records';
import { packWorldContacts } from './seed';
import type { PersistInputs } from './persist';
import type { CompactInputs } from './compact';
import type { SolverInputs } from '../solver/solver';
import { BIN_COUNT, MANIFOLD_WORDS, NP, NP_INDIRECT_WORDS, NP_STATE_WORDS, USAGE } from '../device/layout';
import type { GpuWorld, WorldCensus } from '../world/world';

/** The label of the read-backs for tests and tools (readBuffer). */
const DEBUG_READ = 'narrowphase debug read';

export interface GpuNarrowPhaseOptions {
  /** Contacts the buffers hold at first (default 1024); they grow (doubling) to what is needed. */
  initialContactCapacity?: number;
  /** Time each bin's kernel in a pass of its own ('collide <bin>' in gpuTime; for benchmarks). */
  timeBins?: boolean;
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
  /**
   * Colours the step's solver used (SV.COLOURS_USED: below COLOUR_CAP, up to the last non-empty
   * one); -1 when the step did not solve or overflowed.
   */
  coloursUsed: number;
  /**
   * The deepest penetration (m) of the touching non-sensor contacts' manifold points at the
   * transforms after the step (SV.PENETRATION: the accuracy target's measure, computed on the GPU
   * by the solver's penetration stage, GpuPipeline.measurePenetration); 0 when nothing touches,
   * -1 when the step did not measure it, did not solve or overflowed.
   */
  penetration: number;
  /**
   * Items (joints and contacts) per colour of the step's solver, colours 0 .. COLOUR_CAP - 1, then
   * the overflow set (from SV.COLOUR_START; GpuSolver.passColours follows them); null when the
   * step did not solve or overflowed.
   */
  colourItems: number[] | null;
  /**
   * Non-static bodies awake after the step (SV.AWAKE); -1 when the step did not solve or
   * overflowed. 0: the world is at rest (GpuPipeline.skipResting).
   */
  awake: number;
  /** Begin/end events. */
  eventCount: number;
  /** Contacts per bin (layout.ts BIN order): the contacts collided this step. */
  binCounts: number[];
  /** Contacts kept from the previous step without collision (bodies asleep or static: NP.KEPT). */
  keptCount: number;
  contactCapacity: number;
  /** Times the contact buffers grew during this step. */
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
  /** The world was at rest and nothing changed: nothing was recorded (GpuPipeline.skipResting). */
  skipped: boolean;
  /** { wait: false }: resolves with this step's own result once its read-back is in. */
  settled?: Promise<NarrowPhaseResult>;
}

/**
 * The GPU narrow phase: contact buffers and the stages GpuPipeline records.
 * @internal Advanced: exported for tools, benchmarks and tests; applications use WebGPUBackend
 * through b2World.SetBackend (docs/GPU.md, "The world API on the GPU").
 */
export class GpuNarrowPhase {
  readonly ctx: GpuContext;
  /** Each bin's kernel records in a pass of its own ('collide <bin>' in gpuTime). */
  readonly timeBins: boolean;
  /** The bins in order, for passes of one bin each. */
  readonly bins: readonly number[];
  private readonly contacts: ContactsStage;
  /** The collide stage of each bin. */
  private readonly binStage: CollideStage[] = [];
  private readonly persist: PersistStage;
  private readonly compact: CompactStage;
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
  private capacity: number;
  /** The contact set the next step writes (the other holds the previous step's contacts). */
  private cur = 0;
  /** The set the last step wrote. */
  private lastSet = 1;
  /** Contact-buffer growths over all steps. */
  contactRegrows = 0;
  // The step being recorded (bindStep): filled in place so that recording allocates nothing.
  private readonly contactsIo: ContactsInputs;
  private readonly collideIo: CollideInputs;
  private readonly setIo: PersistInputs & CompactInputs;
  private readonly solverIo: SolverInputs;
  private census: WorldCensus | null = null;

  constructor(ctx: GpuContext, options: GpuNarrowPhaseOptions = {}) {
    this.ctx = ctx;
    this.capacity = Math.max(16, options.initialContactCapacity ?? 1024);
    this.timeBins = options.timeBins === true;
    this.contacts = new ContactsStage(ctx);
    const bins: number[] = [];
    for (const stage of [new CollideCircleStage(ctx), new CollidePolygonStage(ctx), new CollideEdgeStage(ctx), new OverlapStage(ctx)]) {
      for (const bin of stage.kernels.keys()) {
        this.binStage[bin] = stage;
        bins.push(bin);
      }
    }
    this.bins = bins.sort((x, y) => x - y);
    this.persist = new PersistStage(ctx);
    this.compact = new CompactStage(ctx);
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
    this.reserve(cap);
    const placeholder = this.state;
    this.contactsIo = {
      broadState: placeholder,
      pairs: placeholder,
      proxyRef: placeholder,
      proxyKey: placeholder,
      npState: this.state,
      npIndirect: this.indirect,
      curKey: placeholder,
      prevKey: placeholder,
      contactRef: placeholder,
      items: placeholder,
      itemsTmp: placeholder,
      bodyFlags: placeholder,
      bodyAwake: placeholder,
    };
    this.collideIo = {
      params: this.collideParams.buffer,
      npState: this.state,
      npIndirect: this.indirect,
      binned: placeholder,
      contactRef: placeholder,
      fixtureShape: placeholder,
      shapePool: placeholder,
      bodyXf: placeholder,
      bodyCell: placeholder,
      manifolds: placeholder,
    };
    this.setIo = {
      npState: this.state,
      npIndirect: this.indirect,
      contactRef: placeholder,
      manifolds: placeholder,
      prevManifolds: placeholder,
      solverFlags: placeholder,
      eventFlags: placeholder,
      curKey: placeholder,
      prevKey: placeholder,
      solverList: placeholder,
      events: placeholder,
    };
    this.solverIo = {
      broadState: placeholder,
      npState: this.state,
      solverList: placeholder,
      contactRefs: placeholder,
      manifolds: placeholder,
      contactCapacity: 0,
      lastSolverCount: -1,
      lastColourItems: null,
    };
  }

  // ---- Outputs (the last step's) ----

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

  /** Grows the contact buffers (doubling) to hold `needed` contacts; both sets keep their contents. */
  growContacts(needed: number): void {
    if (needed <= this.capacity) return;
    let capacity = this.capacity;
    while (capacity < needed) capacity *= 2;
    this.reserve(capacity);
    this.contactRegrows++;
  }

  /** Queues the host-written state words of a step or its rerun: the capacity, no overflow. */
  beginUpdate(mirror: GpuWorld): void {
    this.reserve(this.capacity);
    this.ctx.device.queue.writeBuffer(this.state, 4 * NP.CAPACITY, new Uint32Array([this.capacity, 0]));
    this.collideParams.f32[0] = mirror.cellSize;
    this.collideParams.upload();
  }

  /**
   * Names the buffers the stages recorded next read and write: the broad phase's sorted `pairs`
   * and its state words (`broadState`: pair count, overflow), the mirror's tables, and contact set
   * `cur` (the other set as the previous step's). After beginUpdate(), before encodeContacts().
   */
  bindStep(mirror: GpuWorld, pairs: GPUBuffer, broadState: GPUBuffer): void {
    this.census = mirror.census;
    const curKey = this.keys[this.cur].buffer;
    const prevKey = this.keys[1 - this.cur].buffer;
    const manifolds = this.manifoldSets[this.cur].buffer;
    const c = this.contactsIo;
    c.broadState = broadState;
    c.pairs = pairs;
    c.proxyRef = mirror.proxyRef.buffer;
    c.proxyKey = mirror.proxyKey.buffer;
    c.curKey = curKey;
    c.prevKey = prevKey;
    c.contactRef = this.contactRef.buffer;
    c.items = this.items.buffer;
    c.itemsTmp = this.itemsTmp.buffer;
    c.bodyFlags = mirror.bodyFlags.buffer;
    c.bodyAwake = mirror.bodyAwake.buffer;
    const k = this.collideIo;
    k.binned = this.items.buffer;
    k.contactRef = this.contactRef.buffer;
    k.fixtureShape = mirror.fixtureShape.buffer;
    k.shapePool = mirror.shapePool.buffer;
    k.bodyXf = mirror.bodyXf.buffer;
    k.bodyCell = mirror.bodyCell.buffer;
    k.manifolds = manifolds;
    const s = this.setIo;
    s.contactRef = this.contactRef.buffer;
    s.manifolds = manifolds;
    s.prevManifolds = this.manifoldSets[1 - this.cur].buffer;
    s.solverFlags = this.solverFlags.buffer;
    s.eventFlags = this.eventFlags.buffer;
    s.curKey = curKey;
    s.prevKey = prevKey;
    s.solverList = this.solverListArray.buffer;
    s.events = this.eventArray.buffer;
  }

  /** GpuStage.Contacts: contacts from the pairs, matched and binned by pair type. */
  readonly encodeContacts = (rec: Recorder): void => {
    this.collideIo.binned = this.contacts.encode(rec, this.contactsIo, this.cur);
  };

  /** Whether the world of the step being recorded can fill `bin` (binInUse). */
  binInUse(bin: number): boolean {
    return this.census === null || binInUse(bin, this.census);
  }

  /** GpuStage.Collide: the kernel of every bin the world can fill. */
  readonly encodeCollide = (rec: Recorder): void => {
    for (const bin of this.bins) if (this.binInUse(bin)) this.binStage[bin].encodeBin(rec, bin, this.collideIo);
  };

  /** GpuStage.Collide, one bin (timeBins). */
  encodeCollideBin(rec: Recorder, bin: number): void {
    this.binStage[bin].encodeBin(rec, bin, this.collideIo);
  }

  /** GpuStage.Persist. */
  readonly encodePersist = (rec: Recorder): void => this.persist.encode(rec, this.setIo);

  /** GpuStage.Compact. */
  readonly encodeCompact = (rec: Recorder): void => this.compact.encode(rec, this.setIo);

  /** What the solver reads of the step being recorded (the set bindStep named). */
  outputs(broadState: GPUBuffer): SolverInputs {
    const o = this.solverIo;
    o.broadState = broadState;
    o.solverList = this.solverListArray.buffer;
    o.contactRefs = this.contactRef.buffer;
    o.manifolds = this.manifoldSets[this.cur].buffer;
    o.contactCapacity = this.capacity;
    return o;
  }

  /** Records the state words' copy to `dst` at byte `offset`. */
  encodeStateCopy(encoder: GPUCommandEncoder, dst: GPUBuffer, offset: number): void {
    encoder.copyBufferToBuffer(this.state, 0, dst, offset, 4 * NP_STATE_WORDS);
  }

  /** Ends a step that succeeded (or was submitted, { wait: false }): its set becomes the previous step's. */
  endUpdate(): void {
    this.lastSet = this.cur;
    this.cur = 1 - this.cur;
  }

  /** Forgets the previous step's contacts: the next step starts cold (no warm start, all begin). */
  reset(): void {
    this.ctx.device.queue.writeBuffer(this.state, 4 * NP.COUNT_0, new Uint32Array([0, 0]));
  }

  /**
   * Takes the JavaScript world's contacts as the previous step's (keys, manifolds, impulses,
   * touching state), so that the next step warm-starts from the engine's state: for handing a
   * running world to the GPU (and for tests). `mirror` must be synced. Contacts of proxies the
   * mirror does not have are skipped. Returns how many contacts were taken.
   */
  seedFromWorld(mirror: GpuWorld): number {
    const { count: n, keys, manifolds } = packWorldContacts(mirror);
    this.growContacts(n);
    const set = 1 - this.cur;
    const queue = this.ctx.device.queue;
    queue.writeBuffer(this.keys[set].buffer, 0, keys);
    queue.writeBuffer(this.manifoldSets[set].buffer, 0, manifolds);
    queue.writeBuffer(this.state, 4 * (NP.COUNT_0 + set), new Uint32Array([n]));
    return n;
  }

  // ---- Read-back for tests and tools (not part of a step) ----

  /** The narrow phase's state words now (layout.ts NP). */
  async readState(): Promise<Uint32Array> {
    return new Uint32Array(await readBuffer(this.ctx, this.state, 4 * NP_STATE_WORDS, DEBUG_READ));
  }

  /** The last step's contacts, decoded. */
  async readContacts(): Promise<GpuContactRecord[]> {
    const np = await this.readState();
    const n = np[NP.CONTACTS];
    if (n === 0) return [];
    const keys = new Uint32Array(await readBuffer(this.ctx, this.contactKeys, 16 * n, DEBUG_READ));
    const refs = new Uint32Array(await readBuffer(this.ctx, this.contactRef.buffer, 32 * n, DEBUG_READ));
    const manifolds = await readBuffer(this.ctx, this.manifolds, 4 * MANIFOLD_WORDS * n, DEBUG_READ);
    return decodeContacts(keys, refs, manifolds, n);
  }

  /** The last step's solver list (contact indices). */
  async readSolverList(): Promise<Uint32Array> {
    const n = (await this.readState())[NP.SOLVER];
    return n === 0 ? new Uint32Array(0) : new Uint32Array(await readBuffer(this.ctx, this.solverList, 4 * n, DEBUG_READ));
  }

  /** The last step's begin/end events. */
  async readEvents(): Promise<GpuContactEvent[]> {
    const n = (await this.readState())[NP.EVENTS];
    if (n === 0) return [];
    const w = new Uint32Array(await readBuffer(this.ctx, this.events, 16 * n, DEBUG_READ));
    return decodeEvents(w, n);
  }

  /**
   * Every output of the last step as bytes (counts, keys, contactRef, manifolds, solver list,
   * events; not the capacities): for determinism checks.
   */
  async readAll(): Promise<Uint8Array> {
    const np = await this.readState();
    const n = np[NP.CONTACTS];
    const counts = [NP.CONTACTS, NP.PREV, NP.PAIRS, NP.SOLVER, NP.EVENTS, NP.EVENT_SLOTS, NP.KEPT].map((w) => np[w]);
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
    this.collideParams.destroy();
  }
}
