/*
 * The world on the GPU: a b2World built with the normal API, mirrored into the structure-of-arrays
 * buffers described in src-gpu/layout.ts.
 *
 * GpuWorld reads the engine only through its public fields (m_bodyList, m_fixtureList,
 * m_jointList, m_xf, m_sweep...) and imports nothing from src/ but types, so the engine knows
 * nothing of it and a bundle of src-gpu carries no second copy of the engine.
 *
 * sync() walks the world and brings the GPU buffers up to date:
 * - Slots. Each body, fixture, proxy (fixture child) and joint gets a slot, lowest free first, kept
 *   for as long as the object lives; a destroyed object's slot is marked dead and is handed to
 *   the next new object. bodySlot()/bodyAt(), fixtureSlot()/fixtureAt(), proxySlot()/proxyAt()
 *   and jointSlot()/jointAt() are the mapping both ways. A body made inactive keeps its body and
 *   fixture slots and loses its proxy slots, as b2Body::SetActive destroys its proxies.
 * - Incremental uploads. Every record is packed and compared with a CPU shadow copy of the GPU
 *   buffer (MirrorTable, src-gpu/buffers.ts); only records that changed are uploaded, merged into
 *   contiguous ranges. The comparison costs one pass over the packed data; it needs no hooks in the
 *   engine and cannot miss a change (a filter or friction set directly, a force). One exception:
 *   a shape's vertices are packed when its fixture is new and not compared afterwards (reading
 *   every shape each step was half of a sync's time, and Box2D itself does not expect a fixture's
 *   shape to change): after editing a shape in place, call invalidateShape(fixture).
 * - Growth. Tables double their capacity when slots run out; the shape pool (variable-length
 *   shape data) reuses freed ranges of the same size and is compacted when more than half of it is
 *   holes.
 * - Precision. Positions are stored as an integer cell and a float32 offset in it (layout.ts), so a
 *   body at x = 5000 m keeps its position to about 1e-6 m.
 *
 * The mirror goes one way, JavaScript to GPU, until the GPU steps the world (part 3's solver):
 * then `gpuOwnsMotion` is set and the GPU's copy of the body motion (bodyXf, bodyCell, bodySweep,
 * bodyVel) and of the joints' warm-start state (jointState) is the authority: sync() uploads them
 * only for bodies and joints new to the mirror (a reused slot included), and uploads exactly the
 * changed records of those tables. Everything else (mass, forces, damping, flags, fixtures, joint
 * parameters) is still mirrored from the world. Custom contact filters (b2ContactFilter subclasses)
 * cannot run on the GPU: `usesCustomContactFilter` says when the world has one, and the GPU pair
 * set then follows the default filter rules.
 */

import type { b2Body } from '../src/dynamics/b2Body';
import type { b2Fixture } from '../src/dynamics/b2Fixture';
import type { b2World } from '../src/dynamics/b2World';
import type { b2Joint } from '../src/dynamics/joints/b2Joint';
import type { b2RevoluteJoint } from '../src/dynamics/joints/b2RevoluteJoint';
import type { b2DistanceJoint } from '../src/dynamics/joints/b2DistanceJoint';
import type { b2CircleShape } from '../src/collision/shapes/b2CircleShape';
import type { b2EdgeShape } from '../src/collision/shapes/b2EdgeShape';
import type { b2PolygonShape } from '../src/collision/shapes/b2PolygonShape';
import type { b2ChainShape } from '../src/collision/shapes/b2ChainShape';
import type { GpuContext } from './device';
import { MirrorTable } from './buffers';
import type { UploadStats } from './buffers';
import {
  BODY_LIVE,
  DEFAULT_CELL_SIZE,
  JOINT_LIVE,
  PROXY_JOINTED,
  PROXY_LIVE,
  PROXY_SENSOR,
  SHAPE_HAS_VERTEX0,
  SHAPE_HAS_VERTEX3,
  SHAPE_SENSOR,
} from './layout';

const e_circle = 0;
const e_edge = 1;
const e_polygon = 2;
/** b2JointType values of the joints the GPU solves (parameters in jointParams). */
const e_revoluteJoint = 1;
const e_distanceJoint = 3;

/** A fixture slot without proxies. */
const EMPTY_SLOTS: number[] = [];

/** Slots handed out lowest free first; `gen` marks the slots seen by the current sync. */
class SlotAllocator<T> {
  readonly items: (T | null)[] = [];
  readonly slotOf = new Map<T, number>();
  gen = new Uint32Array(64);
  /** Free slots below `highWater`, in descending order (pop() gives the lowest). */
  private free: number[] = [];
  highWater = 0;
  live = 0;

  /** Whether the last acquire() created the slot. */
  created = false;

  /**
   * The item's slot (a new one, lowest free first, when it has none); marks it seen. `hint`, the
   * slot the item had at the same place of the previous walk, skips the map lookup when it holds.
   */
  acquire(item: T, generation: number, hint = -1): number {
    if (hint >= 0 && hint < this.highWater && this.items[hint] === item) {
      this.created = false;
      this.mark(hint, generation);
      return hint;
    }
    let slot = this.slotOf.get(item);
    this.created = slot === undefined;
    if (slot === undefined) {
      slot = this.alloc();
      this.slotOf.set(item, slot);
      this.items[slot] = item;
    }
    this.mark(slot, generation);
    return slot;
  }

  /** A free slot, lowest first (for items tracked by the caller, not by slotOf). */
  alloc(): number {
    const slot = this.free.length > 0 ? this.free.pop()! : this.highWater++;
    this.live++;
    return slot;
  }

  /** Marks `slot` as seen in `generation`. */
  mark(slot: number, generation: number): void {
    if (slot >= this.gen.length) {
      let n = this.gen.length;
      while (n <= slot) n *= 2;
      const gen = new Uint32Array(n);
      gen.set(this.gen);
      this.gen = gen;
    }
    this.gen[slot] = generation;
  }

  /** Releases every slot not seen in `generation`; calls `onRelease(slot, item)` for each. */
  sweep(generation: number, onRelease: (slot: number, item: T) => void): number {
    let released = 0;
    for (let slot = 0; slot < this.highWater; ++slot) {
      const item = this.items[slot];
      if (item !== null && item !== undefined && this.gen[slot] !== generation) {
        this.items[slot] = null;
        this.slotOf.delete(item);
        this.free.push(slot);
        this.live--;
        released++;
        onRelease(slot, item);
      }
    }
    if (released > 0) {
      this.free.sort((a, b) => b - a);
      while (this.free.length > 0 && this.free[0] === this.highWater - 1) {
        this.free.shift();
        this.highWater--;
      }
    }
    return released;
  }
}

/** Ranges of the shape pool, reused by size; compacted by rebuilding. */
class PoolAllocator {
  top = 0;
  live = 0;
  private readonly freeBySize = new Map<number, number[]>();

  alloc(size: number): number {
    this.live += size;
    const list = this.freeBySize.get(size);
    if (list && list.length > 0) return list.pop()!;
    const offset = this.top;
    this.top += size;
    return offset;
  }

  free(offset: number, size: number): void {
    this.live -= size;
    let list = this.freeBySize.get(size);
    if (!list) this.freeBySize.set(size, (list = []));
    list.push(offset);
  }

  reset(): void {
    this.top = 0;
    this.live = 0;
    this.freeBySize.clear();
  }

  get fragmented(): boolean {
    return this.top > 2 * this.live + 4096;
  }
}

export interface GpuWorldOptions {
  /** Cell size in metres, a power of two (default 32). */
  cellSize?: number;
  /** The world origin: AABBs are computed relative to the cell nearest to it (default 0, 0). */
  origin?: { x: number; y: number };
}

export interface SyncStats {
  /** Uploads of this sync, all tables together. */
  upload: UploadStats;
  bodies: { live: number; created: number; released: number };
  fixtures: { live: number; created: number; released: number };
  proxies: { live: number; created: number; released: number };
  joints: { live: number; created: number; released: number };
}

function shapeSize(f: b2Fixture): number {
  const shape = f.m_shape;
  switch (shape.m_type) {
    case e_circle:
      return 1;
    case e_edge:
      return 4;
    case e_polygon:
      return 2 * (shape as b2PolygonShape).m_vertexCount + 1;
    default:
      return (shape as b2ChainShape).m_count + 2;
  }
}

function isCustomContactFilter(filter: object | null): boolean {
  if (filter === null) return false;
  if (Object.prototype.hasOwnProperty.call(filter, 'ShouldCollide')) return true;
  // The deepest prototype defining ShouldCollide is b2ContactFilter.prototype; a subclass that
  // overrides it shows a different function.
  let base: unknown = undefined;
  for (let p = Object.getPrototypeOf(filter); p && p !== Object.prototype; p = Object.getPrototypeOf(p)) {
    if (Object.prototype.hasOwnProperty.call(p, 'ShouldCollide')) base = (p as { ShouldCollide: unknown }).ShouldCollide;
  }
  return (filter as { ShouldCollide?: unknown }).ShouldCollide !== base;
}

export class GpuWorld {
  readonly ctx: GpuContext;
  readonly world: b2World;
  readonly cellSize: number;
  /** The world origin cell: AABBs are relative to originCell * cellSize. */
  readonly originCell: [number, number];

  // Body tables (layout.ts).
  readonly bodyXf: MirrorTable;
  readonly bodyCell: MirrorTable;
  readonly bodySweep: MirrorTable;
  readonly bodyVel: MirrorTable;
  readonly bodyForce: MirrorTable;
  readonly bodyMass: MirrorTable;
  readonly bodyParams: MirrorTable;
  readonly bodyFlags: MirrorTable;
  readonly jointRange: MirrorTable;
  readonly jointList: MirrorTable;
  readonly joints: MirrorTable;
  /** Per joint slot (layout.ts): anchors and the type's parameters (revolute, distance). */
  readonly jointParams: MirrorTable;
  /** Per joint slot: the accumulated impulses and limit state (GPU-owned once the GPU steps). */
  readonly jointState: MirrorTable;
  // Fixture tables.
  readonly fixtureShape: MirrorTable;
  readonly fixtureMaterial: MirrorTable;
  readonly shapePool: MirrorTable;
  // Proxy tables.
  readonly proxyRef: MirrorTable;
  readonly proxyFilter: MirrorTable;
  /**
   * Per proxy slot (layout.ts): the engine's broad-phase proxy id (b2FixtureProxy.proxyId, which
   * orders same-type contacts as b2BroadPhase::QueryCallback does) and the slot's generation
   * (changes whenever the slot is handed to a new proxy, so a contact key names one proxy pair).
   */
  readonly proxyKey: MirrorTable;

  private ownsMotion = false;
  /** The tables the GPU writes once it steps (gpuOwnsMotion). */
  private readonly gpuWrittenTables: MirrorTable[];

  /** The world has a contact filter other than the default; the GPU applies the default rules. */
  usesCustomContactFilter = false;

  private readonly bodySlots = new SlotAllocator<b2Body>();
  private readonly fixtureSlots = new SlotAllocator<b2Fixture>();
  private readonly jointSlots = new SlotAllocator<b2Joint>();
  /** Proxy slots; items[slot] is the owning fixture slot (proxies are found by fixture slot). */
  private readonly proxySlots = new SlotAllocator<number>();
  private readonly proxyFixture: (b2Fixture | null)[] = [];
  private readonly proxyChild: number[] = [];
  /** Generation of each proxy slot (proxyKey.y). */
  private proxyGeneration = new Uint32Array(64);
  /** The proxy slots of each fixture slot, by child index. */
  private readonly fixtureProxies: number[][] = [];
  /** Body slots in body-list order (sync's walk). */
  private walkSlots = new Int32Array(64);
  private walkCount = 0;
  /** The fixture slots in walk order, as hints for the next sync. */
  private fixtureWalk = new Int32Array(64);
  private fixtureWalkCount = 0;
  private readonly pool = new PoolAllocator();
  private fixturePoolOffset: number[] = [];
  private fixturePoolSize: number[] = [];
  /** Per fixture slot: the shape record's type | ghost flags << 4 | count << 8, and the radius. */
  private fixtureShapeWord: number[] = [];
  private fixtureRadius: number[] = [];
  private readonly staleShapes = new Set<b2Fixture>();
  private generation = 0;
  private jointCount: Int32Array = new Int32Array(64);
  private readonly allTables: MirrorTable[];

  constructor(ctx: GpuContext, world: b2World, options: GpuWorldOptions = {}) {
    this.ctx = ctx;
    this.world = world;
    const cellSize = options.cellSize ?? DEFAULT_CELL_SIZE;
    if (!(cellSize > 0) || Math.log2(cellSize) % 1 !== 0) throw new RangeError(`cellSize must be a power of two, got ${cellSize}`);
    this.cellSize = cellSize;
    const origin = options.origin ?? { x: 0, y: 0 };
    this.originCell = [Math.round(origin.x / cellSize), Math.round(origin.y / cellSize)];

    this.bodyXf = new MirrorTable(ctx, 'bodyXf', 4);
    this.bodyCell = new MirrorTable(ctx, 'bodyCell', 2);
    this.bodySweep = new MirrorTable(ctx, 'bodySweep', 8);
    this.bodyVel = new MirrorTable(ctx, 'bodyVel', 4);
    this.bodyForce = new MirrorTable(ctx, 'bodyForce', 4);
    this.bodyMass = new MirrorTable(ctx, 'bodyMass', 4);
    this.bodyParams = new MirrorTable(ctx, 'bodyParams', 4);
    this.bodyFlags = new MirrorTable(ctx, 'bodyFlags', 1);
    this.jointRange = new MirrorTable(ctx, 'jointRange', 2);
    this.jointList = new MirrorTable(ctx, 'jointList', 1);
    this.joints = new MirrorTable(ctx, 'joints', 4);
    this.jointParams = new MirrorTable(ctx, 'jointParams', 12);
    this.jointState = new MirrorTable(ctx, 'jointState', 8);
    this.fixtureShape = new MirrorTable(ctx, 'fixtureShape', 4);
    this.fixtureMaterial = new MirrorTable(ctx, 'fixtureMaterial', 4);
    this.shapePool = new MirrorTable(ctx, 'shapePool', 2, 256);
    this.proxyRef = new MirrorTable(ctx, 'proxyRef', 4);
    this.proxyFilter = new MirrorTable(ctx, 'proxyFilter', 2);
    this.proxyKey = new MirrorTable(ctx, 'proxyKey', 2);
    this.gpuWrittenTables = [this.bodyXf, this.bodyCell, this.bodySweep, this.bodyVel, this.jointState];
    this.allTables = [
      this.bodyXf,
      this.bodyCell,
      this.bodySweep,
      this.bodyVel,
      this.bodyForce,
      this.bodyMass,
      this.bodyParams,
      this.bodyFlags,
      this.jointRange,
      this.jointList,
      this.joints,
      this.jointParams,
      this.jointState,
      this.fixtureShape,
      this.fixtureMaterial,
      this.shapePool,
      this.proxyRef,
      this.proxyFilter,
      this.proxyKey,
    ];
  }

  /**
   * Whether the GPU's body motion (bodyXf, bodyCell, bodySweep, bodyVel) and joint state are the
   * authority: sync() then writes those records only for bodies and joints new to the mirror. Set
   * once the GPU steps the world.
   */
  get gpuOwnsMotion(): boolean {
    return this.ownsMotion;
  }
  set gpuOwnsMotion(value: boolean) {
    if (value === this.ownsMotion) return;
    this.ownsMotion = value;
    for (const table of this.gpuWrittenTables) table.exactUploads = value;
  }

  // ---- The mapping between engine objects and GPU indices ----

  bodySlot(body: b2Body): number {
    return this.bodySlots.slotOf.get(body) ?? -1;
  }
  bodyAt(slot: number): b2Body | null {
    return this.bodySlots.items[slot] ?? null;
  }
  fixtureSlot(fixture: b2Fixture): number {
    return this.fixtureSlots.slotOf.get(fixture) ?? -1;
  }
  fixtureAt(slot: number): b2Fixture | null {
    return this.fixtureSlots.items[slot] ?? null;
  }
  jointSlot(joint: b2Joint): number {
    return this.jointSlots.slotOf.get(joint) ?? -1;
  }
  jointAt(slot: number): b2Joint | null {
    return this.jointSlots.items[slot] ?? null;
  }
  /** The slot of child `childIndex` of `fixture`'s proxies, -1 when it has none (inactive body). */
  proxySlot(fixture: b2Fixture, childIndex: number): number {
    const fixtureSlot = this.fixtureSlot(fixture);
    const slots = fixtureSlot < 0 ? undefined : this.fixtureProxies[fixtureSlot];
    return slots !== undefined && childIndex < slots.length ? slots[childIndex] : -1;
  }
  proxyAt(slot: number): { fixture: b2Fixture; childIndex: number } | null {
    const fixture = this.proxyFixture[slot];
    if (fixture === null || fixture === undefined || this.proxySlots.items[slot] === null) return null;
    return { fixture, childIndex: this.proxyChild[slot] };
  }

  /** Proxy slots [0, proxySlotCount) exist on the GPU (live or dead). */
  get proxySlotCount(): number {
    return this.proxySlots.highWater;
  }
  get liveProxyCount(): number {
    return this.proxySlots.live;
  }
  get bodySlotCount(): number {
    return this.bodySlots.highWater;
  }
  get fixtureSlotCount(): number {
    return this.fixtureSlots.highWater;
  }
  get jointSlotCount(): number {
    return this.jointSlots.highWater;
  }

  /** The generation of a proxy slot: it changes whenever the slot is given to a new proxy. */
  proxyGenerationOf(slot: number): number {
    return slot < this.proxyGeneration.length ? this.proxyGeneration[slot] : 0;
  }

  /** The world position of a body slot as the GPU stores it (cell and float32 offset), in float64. */
  gpuBodyPosition(slot: number): { x: number; y: number } {
    const cx = this.bodyCell.i32[2 * slot];
    const cy = this.bodyCell.i32[2 * slot + 1];
    return { x: cx * this.cellSize + this.bodyXf.f32[4 * slot], y: cy * this.cellSize + this.bodyXf.f32[4 * slot + 1] };
  }

  // ---- Sync ----

  /** Brings the GPU buffers up to date with the world; returns what changed and what it uploaded. */
  sync(): SyncStats {
    this.ctx.assertAlive();
    const gen = ++this.generation;
    const world = this.world;
    const stats: SyncStats = {
      upload: { bytes: 0, writes: 0, elements: 0 },
      bodies: { live: 0, created: 0, released: 0 },
      fixtures: { live: 0, created: 0, released: 0 },
      proxies: { live: 0, created: 0, released: 0 },
      joints: { live: 0, created: 0, released: 0 },
    };
    this.usesCustomContactFilter = isCustomContactFilter(world.m_contactManager.m_contactFilter);

    this.syncBodies(world, gen, stats);

    // 2. Joints, and the per-body lists of joints that turn collision off.
    const edges: number[] = [];
    for (let j = world.m_jointList; j; j = j.m_next) {
      const slot = this.jointSlots.acquire(j, gen);
      if (this.jointSlots.created) stats.joints.created++;
      const a = this.bodySlot(j.m_bodyA);
      const b = this.bodySlot(j.m_bodyB);
      this.joints.commitWords(slot, a, b, j.m_type, (j.m_collideConnected ? 1 : 0) | JOINT_LIVE);
      this.packJoint(slot, j, this.jointSlots.created);
      if (!j.m_collideConnected) {
        edges.push(a * 67108864 + b, b * 67108864 + a);
      }
    }
    stats.joints.released = this.jointSlots.sweep(gen, (slot) => {
      this.joints.commitWords(slot, 0, 0, 0, 0);
    });
    this.packJointGraph(edges);

    this.syncFixtures(world, gen, stats);

    stats.bodies.live = this.bodySlots.live;
    stats.fixtures.live = this.fixtureSlots.live;
    stats.proxies.live = this.proxySlots.live;
    stats.joints.live = this.jointSlots.live;

    const queue = this.ctx.device.queue;
    for (const table of this.allTables) table.flush(queue, stats.upload);
    return stats;
  }

  /** Step 1 of sync: bodies, their slots kept in walk order for syncFixtures and as the next sync's hints. */
  private syncBodies(world: b2World, gen: number, stats: SyncStats): void {
    let walked = 0;
    for (let b = world.m_bodyList; b; b = b.m_next) {
      const slot = this.bodySlots.acquire(b, gen, walked < this.walkCount ? this.walkSlots[walked] : -1);
      if (this.bodySlots.created) stats.bodies.created++;
      this.packBody(slot, b, this.bodySlots.created);
      if (walked === this.walkSlots.length) {
        const grown = new Int32Array(2 * this.walkSlots.length);
        grown.set(this.walkSlots);
        this.walkSlots = grown;
      }
      this.walkSlots[walked++] = slot;
    }
    this.walkCount = walked;
    stats.bodies.released = this.bodySlots.sweep(gen, (slot) => {
      this.bodyFlags.commitWords(slot, 0);
    });
  }

  /** Step 3 of sync: fixtures and their proxies. (Each walk is a method of its own so that V8 optimises it apart.) */
  private syncFixtures(world: b2World, gen: number, stats: SyncStats): void {
    if (this.pool.fragmented) this.compactPool();
    let index = 0;
    let fixtureWalked = 0;
    for (let b = world.m_bodyList; b; b = b.m_next) {
      const bodySlot = this.walkSlots[index++];
      const jointed = this.jointCount[bodySlot] > 0;
      for (let f = b.m_fixtureList; f; f = f.m_next) {
        const hint = fixtureWalked < this.fixtureWalkCount ? this.fixtureWalk[fixtureWalked] : -1;
        const slot = this.fixtureSlots.acquire(f, gen, hint);
        if (fixtureWalked === this.fixtureWalk.length) {
          const grown = new Int32Array(2 * this.fixtureWalk.length);
          grown.set(this.fixtureWalk);
          this.fixtureWalk = grown;
        }
        this.fixtureWalk[fixtureWalked++] = slot;
        if (this.fixtureSlots.created) stats.fixtures.created++;
        this.packFixture(slot, f, bodySlot, this.fixtureSlots.created);
        this.packProxies(f, slot, bodySlot, b.m_type, jointed, gen, stats);
      }
    }
    this.fixtureWalkCount = fixtureWalked;
    stats.fixtures.released = this.fixtureSlots.sweep(gen, (slot, fixture) => {
      this.staleShapes.delete(fixture);
      this.fixtureShape.commitWords(slot, 0, 0, 0, 0);
      if (this.fixturePoolSize[slot] > 0) this.pool.free(this.fixturePoolOffset[slot], this.fixturePoolSize[slot]);
      this.fixturePoolSize[slot] = 0;
      this.fixtureProxies[slot] = EMPTY_SLOTS;
    });
    stats.proxies.released = this.proxySlots.sweep(gen, (slot) => {
      this.proxyFixture[slot] = null;
      this.proxyRef.commitWords(slot, 0, 0, 0, 0);
      this.proxyFilter.commitWords(slot, 0, 0);
      this.proxyKey.commitWords(slot, 0, this.proxyGeneration[slot]);
    });
  }

  private packBody(slot: number, b: b2Body, created: boolean): void {
    if (!this.ownsMotion || created) this.packMotion(slot, b, created && this.ownsMotion);

    this.bodyForce.commitF4(slot, b.m_force.x, b.m_force.y, b.m_torque, 0);
    this.bodyMass.commitF4(slot, b.m_invMass, b.m_invI, b.m_sweep.localCenter.x, b.m_sweep.localCenter.y);
    this.bodyParams.commitF4(slot, b.m_linearDamping, b.m_angularDamping, b.m_gravityScale, 0);

    this.bodyFlags.commitWords(slot, ((b.m_flags & 0xffff) | (b.m_type << 16) | BODY_LIVE) >>> 0);
  }

  /** Packs the motion records (cell, transform, sweep, velocity); `force` uploads them even if unchanged. */
  private packMotion(slot: number, b: b2Body, force: boolean): void {
    const S = this.cellSize;
    const p = b.m_xf.p;
    const cx = Math.round(p.x / S);
    const cy = Math.round(p.y / S);
    const ox = cx * S;
    const oy = cy * S;

    const cell = this.bodyCell.scratchI32;
    cell[0] = cx;
    cell[1] = cy;
    this.bodyCell.commit(slot);

    const xf = this.bodyXf.scratchF32;
    xf[0] = p.x - ox;
    xf[1] = p.y - oy;
    xf[2] = b.m_xf.q.c;
    xf[3] = b.m_xf.q.s;
    this.bodyXf.commit(slot);

    const sw = b.m_sweep;
    const s = this.bodySweep.scratchF32;
    s[0] = sw.c0.x - ox;
    s[1] = sw.c0.y - oy;
    s[2] = sw.a0;
    s[3] = sw.alpha0;
    s[4] = sw.c.x - ox;
    s[5] = sw.c.y - oy;
    s[6] = sw.a;
    s[7] = b.m_sleepTime;
    this.bodySweep.commit(slot);

    const v = this.bodyVel.scratchF32;
    v[0] = b.m_linearVelocity.x;
    v[1] = b.m_linearVelocity.y;
    v[2] = b.m_angularVelocity;
    v[3] = 0;
    this.bodyVel.commit(slot);
    if (force) {
      this.bodyCell.markDirty(slot);
      this.bodyXf.markDirty(slot);
      this.bodySweep.markDirty(slot);
      this.bodyVel.markDirty(slot);
    }
  }

  /** jointParams, and jointState unless the GPU owns it (a new joint's is always uploaded). */
  private packJoint(slot: number, j: b2Joint, created: boolean): void {
    const p = this.jointParams.scratchF32;
    p.fill(0);
    const owned = this.ownsMotion && !created;
    const s = this.jointState.scratchF32;
    s.fill(0);
    if (j.m_type === e_revoluteJoint) {
      const r = j as b2RevoluteJoint;
      p[0] = r.m_localAnchorA.x;
      p[1] = r.m_localAnchorA.y;
      p[2] = r.m_localAnchorB.x;
      p[3] = r.m_localAnchorB.y;
      p[4] = r.m_referenceAngle;
      p[5] = r.m_lowerAngle;
      p[6] = r.m_upperAngle;
      p[7] = r.m_maxMotorTorque;
      p[8] = r.m_motorSpeed;
      p[9] = r.m_enableLimit ? 1 : 0;
      p[10] = r.m_enableMotor ? 1 : 0;
      s[0] = r.m_impulse.x;
      s[1] = r.m_impulse.y;
      s[2] = r.m_impulse.z;
      s[3] = r.m_motorImpulse;
      s[4] = r.m_limitState;
    } else if (j.m_type === e_distanceJoint) {
      const d = j as b2DistanceJoint;
      p[0] = d.m_localAnchorA.x;
      p[1] = d.m_localAnchorA.y;
      p[2] = d.m_localAnchorB.x;
      p[3] = d.m_localAnchorB.y;
      p[4] = d.m_length;
      p[5] = d.m_frequencyHz;
      p[6] = d.m_dampingRatio;
      s[0] = d.m_impulse;
    }
    this.jointParams.commit(slot);
    if (owned) return;
    this.jointState.commit(slot);
    if (created && this.ownsMotion) this.jointState.markDirty(slot);
  }

  private packJointGraph(edges: number[]): void {
    const bodyCount = this.bodySlots.highWater;
    if (this.jointCount.length < bodyCount) this.jointCount = new Int32Array(Math.max(bodyCount, 2 * this.jointCount.length));
    const count = this.jointCount;
    count.fill(0);
    const keys = Float64Array.from(edges).sort();
    for (let i = 0; i < keys.length; ++i) count[Math.floor(keys[i] / 67108864)]++;
    let start = 0;
    for (let slot = 0; slot < bodyCount; ++slot) {
      this.jointRange.commitWords(slot, start, count[slot]);
      start += count[slot];
    }
    for (let i = 0; i < keys.length; ++i) this.jointList.commitWords(i, keys[i] % 67108864);
    if (this.jointList.count < keys.length) this.jointList.setCount(keys.length);
  }

  private compactPool(): void {
    this.pool.reset();
    this.fixturePoolSize = [];
    this.fixturePoolOffset = [];
    this.fixtureShapeWord = [];
    this.fixtureRadius = [];
  }

  private packFixture(slot: number, f: b2Fixture, bodySlot: number, created: boolean): void {
    if (created || this.fixturePoolSize[slot] === undefined || (this.staleShapes.size > 0 && this.staleShapes.delete(f))) {
      this.packShape(slot, f);
    }
    const sensor = f.m_isSensor ? SHAPE_SENSOR << 4 : 0;
    const rec = this.fixtureShape.scratchU32;
    rec[0] = (this.fixtureShapeWord[slot] | sensor) >>> 0;
    rec[1] = this.fixturePoolOffset[slot];
    rec[2] = bodySlot;
    this.fixtureShape.scratchF32[3] = this.fixtureRadius[slot];
    this.fixtureShape.commit(slot);

    this.fixtureMaterial.commitF4(slot, f.m_friction, f.m_restitution, f.m_density, 0);
  }

  /** The shape's data into the pool; its record's type, ghost flags and count into fixtureShapeWord. */
  private packShape(slot: number, f: b2Fixture): void {
    const shape = f.m_shape;
    const size = shapeSize(f);
    if (this.fixturePoolSize[slot] !== size) {
      if (this.fixturePoolSize[slot] > 0) this.pool.free(this.fixturePoolOffset[slot], this.fixturePoolSize[slot]);
      this.fixturePoolOffset[slot] = this.pool.alloc(size);
      this.fixturePoolSize[slot] = size;
    }
    const offset = this.fixturePoolOffset[slot];
    const pool = this.shapePool;
    if (offset + size > pool.capacity) pool.reserve(offset + size);
    let count = 0;
    let flags = 0;
    switch (shape.m_type) {
      case e_circle: {
        const c = shape as b2CircleShape;
        pool.commitF2(offset, c.m_p.x, c.m_p.y);
        count = 1;
        break;
      }
      case e_edge: {
        const e = shape as b2EdgeShape;
        pool.commitF2(offset, e.m_vertex1.x, e.m_vertex1.y);
        pool.commitF2(offset + 1, e.m_vertex2.x, e.m_vertex2.y);
        pool.commitF2(offset + 2, e.m_vertex0.x, e.m_vertex0.y);
        pool.commitF2(offset + 3, e.m_vertex3.x, e.m_vertex3.y);
        count = 2;
        if (e.m_hasVertex0) flags |= SHAPE_HAS_VERTEX0;
        if (e.m_hasVertex3) flags |= SHAPE_HAS_VERTEX3;
        break;
      }
      case e_polygon: {
        const p = shape as b2PolygonShape;
        count = p.m_vertexCount;
        for (let i = 0; i < count; ++i) pool.commitF2(offset + i, p.m_vertices[i].x, p.m_vertices[i].y);
        for (let i = 0; i < count; ++i) pool.commitF2(offset + count + i, p.m_normals[i].x, p.m_normals[i].y);
        pool.commitF2(offset + 2 * count, p.m_centroid.x, p.m_centroid.y);
        break;
      }
      default: {
        const c = shape as b2ChainShape;
        count = c.m_count;
        for (let i = 0; i < count; ++i) pool.commitF2(offset + i, c.m_vertices[i].x, c.m_vertices[i].y);
        pool.commitF2(offset + count, c.m_prevVertex.x, c.m_prevVertex.y);
        pool.commitF2(offset + count + 1, c.m_nextVertex.x, c.m_nextVertex.y);
        if (c.m_hasPrevVertex) flags |= SHAPE_HAS_VERTEX0;
        if (c.m_hasNextVertex) flags |= SHAPE_HAS_VERTEX3;
      }
    }
    this.fixtureShapeWord[slot] = shape.m_type | (flags << 4) | (count << 8);
    this.fixtureRadius[slot] = shape.m_radius;
  }

  /**
   * Uploads `fixture`'s shape again at the next sync. The mirror packs a shape when its fixture is
   * created and does not compare shapes afterwards (reading every vertex of every shape each step
   * was half of a sync's time): call this after editing a fixture's shape in place.
   */
  invalidateShape(fixture: b2Fixture): void {
    this.staleShapes.add(fixture);
  }

  private packProxies(
    f: b2Fixture,
    fixtureSlot: number,
    bodySlot: number,
    bodyType: number,
    jointed: boolean,
    gen: number,
    stats: SyncStats,
  ): void {
    // Proxies belong to (fixture slot, child): a fixture slot is reused only after the sync that
    // released it, so the pair names one live proxy.
    const n = f.m_proxyCount;
    let slots = this.fixtureProxies[fixtureSlot];
    if (slots === undefined || slots === EMPTY_SLOTS) {
      if (n === 0) {
        this.fixtureProxies[fixtureSlot] = EMPTY_SLOTS;
        return;
      }
      slots = [];
      this.fixtureProxies[fixtureSlot] = slots;
    }
    // Children beyond n (a body made inactive) are left unmarked: the sweep releases them.
    if (slots.length > n) slots.length = n;
    if (n === 0) return;
    const filter = f.m_filter;
    const word =
      f.m_shape.m_type | (bodyType << 2) | PROXY_LIVE | (f.m_isSensor ? PROXY_SENSOR : 0) | (jointed ? PROXY_JOINTED : 0);
    const filterWord = ((filter.categoryBits & 0xffff) | ((filter.maskBits & 0xffff) << 16)) >>> 0;
    const group = filter.groupIndex & 0xffff;
    const proxies = this.proxySlots;
    const engineProxies = (f as { m_proxies?: { proxyId: number }[] }).m_proxies;
    for (let child = 0; child < n; ++child) {
      let slot: number;
      let fresh = false;
      if (child < slots.length) {
        slot = slots[child];
      } else {
        slot = proxies.alloc();
        proxies.items[slot] = fixtureSlot;
        slots.push(slot);
        stats.proxies.created++;
        fresh = true;
      }
      proxies.mark(slot, gen);
      this.proxyFixture[slot] = f;
      this.proxyChild[slot] = child;
      this.proxyRef.commitWords(slot, fixtureSlot, child, bodySlot, word);
      this.proxyFilter.commitWords(slot, filterWord, group);
      // The engine's proxy id orders same-type contacts (b2BroadPhase::QueryCallback puts the
      // lower id first, b2Contact::Create makes it fixture A); without one (a synthetic world),
      // the slot orders them. A new proxy in the slot, or a new engine proxy (the body was
      // deactivated and reactivated between syncs), gets a new generation.
      const engineId = engineProxies?.[child]?.proxyId;
      const order = typeof engineId === 'number' && engineId >= 0 ? engineId : slot;
      if (slot >= this.proxyGeneration.length) {
        let size = this.proxyGeneration.length;
        while (size <= slot) size *= 2;
        const grown = new Uint32Array(size);
        grown.set(this.proxyGeneration);
        this.proxyGeneration = grown;
      }
      if (fresh || this.proxyKey.u32[2 * slot] !== order) this.proxyGeneration[slot] = (this.proxyGeneration[slot] + 1) >>> 0;
      this.proxyKey.commitWords(slot, order, this.proxyGeneration[slot]);
    }
  }

  destroy(): void {
    for (const table of this.allTables) table.destroy();
  }
}
