/*
 * The world on the GPU: a b2World built with the normal API, mirrored into the structure-of-arrays
 * buffers described in src-gpu/device/layout.ts.
 *
 * GpuWorld reads the engine only through its public fields (m_bodyList, m_fixtureList,
 * m_jointList, m_xf, m_sweep...) and imports from src/ only types and the leaf module of flags
 * and type numbers (src/common/b2Constants.ts), so the engine knows nothing of it and a bundle of
 * src-gpu carries no second copy of the engine.
 *
 * sync() walks the world and brings the GPU buffers up to date:
 * - Slots. Each body, fixture, proxy (fixture child) and joint gets a slot, lowest free first, kept
 *   for as long as the object lives; a destroyed object's slot is marked dead and is handed to
 *   the next new object. bodySlot()/bodyAt(), fixtureSlot()/fixtureAt(), proxySlot()/proxyAt()
 *   and jointSlot()/jointAt() are the mapping both ways. A body made inactive keeps its body and
 *   fixture slots and loses its proxy slots, as b2Body::SetActive destroys its proxies.
 * - Incremental uploads. Every record is packed and compared with a CPU shadow copy of the GPU
 *   buffer (MirrorTable, src-gpu/device/buffers.ts); only records that changed are uploaded, merged into
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
 * The mirror goes one way, JavaScript to GPU, until the GPU steps the world (GpuStepper):
 * then `gpuOwnsMotion` is set and the GPU's copy of the body motion (bodyXf, bodyCell, bodySweep,
 * bodyVel) and of the joints' warm-start state (jointState) is the authority: sync() uploads them
 * only for bodies and joints new to the mirror (a reused slot included), and uploads exactly the
 * changed records of those tables. Everything else (mass, forces, damping, flags, fixtures, joint
 * parameters) is still mirrored from the world.
 * The awake flag (bodyAwake) is GPU-owned in the same way, with one more rule: the GPU wakes and
 * puts bodies to sleep (islands.ts) and GpuStepper's pulls (pullBody, pullAll: a body fetching the
 * last read-back) write e_awakeFlag and m_sleepTime back, and the flag into bodyAwake's shadow;
 * sync() looks at the awake flag of the bodies that fetched the last read-back only, and uploads
 * it when the world's e_awakeFlag differs from the value last uploaded or read back (SetAwake(false),
 * or a wake after a read-back that showed the body asleep), for a body new to the mirror, for every
 * body when b2World::m_allowSleep was turned off (SetAllowSleeping(false) wakes them all), and for
 * every body the API woke (b2ChangeListener.BodyWoken: a force, an impulse, a mouse joint's target),
 * even when its flag already said awake, since the GPU may have put it to sleep after the read-back.
 * sleepTime (word 7 of bodySweep) is never uploaded after that: the GPU keeps 2.2.1's rule that a
 * sleeping body has zero velocity and sleep time, so a body put to sleep or woken from JavaScript
 * gets them there. IsAwake() shows the flag of the last read-back, not the GPU's since.
 * Custom contact filters (b2ContactFilter subclasses) cannot run on the GPU:
 * `usesCustomContactFilter` says when the world has one, and the GPU pair set then follows the
 * default filter rules.
 */

import type { b2Body } from '../../src/dynamics/b2Body';
import type { b2Fixture } from '../../src/dynamics/b2Fixture';
import type { b2World } from '../../src/dynamics/b2World';
import type { b2Joint } from '../../src/dynamics/joints/b2Joint';
import type { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import type { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import type { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import type { b2ChainShape } from '../../src/collision/shapes/b2ChainShape';
import { b2BodyFlags, b2BodyType, b2ShapeType } from '../../src/common/b2Constants';
import type { GpuContext } from '../device/device';
import { MirrorTable } from '../device/buffers';
import type { UploadStats } from '../device/buffers';
import { ChangeLog, ObjectSlots, PoolAllocator, SlotAllocator, withRoom } from './slots';
import { packJoint, unpackJointState } from './joints';
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
} from '../device/layout';

const { e_circle, e_edge, e_polygon } = b2ShapeType;
const { e_awakeFlag } = b2BodyFlags;

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

/**
 * What the world holds, for the step to leave out stages it cannot need: fixtures by
 * b2Shape::Type and sensors (the collide kernel of each pair type), bullets and static or
 * kinematic bodies with fixtures (the time of impact). Counted by every full walk of sync();
 * between walks a changed fixture or body can only add to it, so it never undercounts.
 */
export interface WorldCensus {
  /** Fixtures per b2Shape::Type (circle, edge, polygon, chain). */
  readonly shapes: Int32Array;
  sensors: number;
  bullets: number;
  /** Static and kinematic bodies with fixtures. */
  nonDynamic: number;
}

/**
 * The world mirrored on the GPU (structure-of-arrays tables, uploaded incrementally).
 * @internal Advanced: exported for tools, benchmarks and tests; applications use WebGPUBackend
 * through b2World.SetBackend (docs/GPU.md, "The world API on the GPU").
 */
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
  /** Per body slot: 1 awake, 0 asleep; GPU-owned once the GPU steps (see the header). */
  readonly bodyAwake: MirrorTable;
  readonly jointRange: MirrorTable;
  readonly jointList: MirrorTable;
  readonly joints: MirrorTable;
  /** Per joint slot (layout.ts): anchors and the type's parameters, every type. */
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
  /** The world's change listener while this mirror is its latest one. */
  private readonly changes = new ChangeLog();
  /** b2World::m_allowSleep at the last sync, and whether this sync saw it turned off. */
  private allowSleep = true;
  private wakeAll = false;
  /** The tables the GPU writes once it steps (gpuOwnsMotion). */
  private readonly gpuWrittenTables: MirrorTable[];

  /** The world has a contact filter other than the default; the GPU applies the default rules. */
  usesCustomContactFilter = false;

  private readonly bodySlots = new ObjectSlots<b2Body>();
  private readonly fixtureSlots = new ObjectSlots<b2Fixture>();
  private readonly jointSlots = new ObjectSlots<b2Joint>();
  /** Proxy slots; items[slot] is the owning fixture slot (proxies are found by fixture slot). */
  private readonly proxySlots = new SlotAllocator<number>();
  private readonly proxyFixture: (b2Fixture | null)[] = [];
  private proxyChild = new Int32Array(64);
  /** Generation of each proxy slot (proxyKey.y). */
  private proxyGeneration = new Uint32Array(64);
  /**
   * The proxy slots of each fixture slot: child 0's (-1 for none), and the other children's for
   * the fixtures that have more (chains). A typed array rather than an array a fixture: a world of
   * a million single-child fixtures then makes no million small objects to collect.
   */
  private fixtureProxy0 = new Int32Array(64).fill(-1);
  private readonly fixtureProxyRest = new Map<number, number[]>();
  /** Body slots in body-list order (sync's walk). */
  private walkSlots = new Int32Array(64);
  private walkCount = 0;
  /** The fixture slots in walk order, as hints for the next sync. */
  private fixtureWalk = new Int32Array(64);
  /** Slots whose uploaded force or torque may be non-zero (every such slot is listed): clearForces() zeroes them. */
  private forcedSlots = new Int32Array(64);
  private forcedCount = 0;
  private fixtureWalkCount = 0;
  private readonly pool = new PoolAllocator();
  /**
   * Per fixture slot: the shape's place in the pool (size 0: not packed since the slot was taken
   * or the pool compacted), the shape record's type | ghost flags << 4 | count << 8, and the radius.
   */
  private fixturePoolOffset = new Int32Array(64);
  private fixturePoolSize = new Int32Array(64);
  private fixtureShapeWord = new Int32Array(64);
  private fixtureRadius = new Float64Array(64);
  private readonly staleShapes = new Set<b2Fixture>();
  private generation = 0;
  private jointCount: Int32Array = new Int32Array(64);
  private readonly allTables: MirrorTable[];
  readonly census: WorldCensus = { shapes: new Int32Array(4), sensors: 0, bullets: 0, nonDynamic: 0 };

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
    this.bodyAwake = new MirrorTable(ctx, 'bodyAwake', 1);
    this.jointRange = new MirrorTable(ctx, 'jointRange', 2);
    this.jointList = new MirrorTable(ctx, 'jointList', 1);
    this.joints = new MirrorTable(ctx, 'joints', 4);
    this.jointParams = new MirrorTable(ctx, 'jointParams', 20);
    this.jointState = new MirrorTable(ctx, 'jointState', 8);
    this.fixtureShape = new MirrorTable(ctx, 'fixtureShape', 4);
    this.fixtureMaterial = new MirrorTable(ctx, 'fixtureMaterial', 4);
    this.shapePool = new MirrorTable(ctx, 'shapePool', 2, 256);
    this.proxyRef = new MirrorTable(ctx, 'proxyRef', 4);
    this.proxyFilter = new MirrorTable(ctx, 'proxyFilter', 2);
    this.proxyKey = new MirrorTable(ctx, 'proxyKey', 2);
    this.gpuWrittenTables = [this.bodyXf, this.bodyCell, this.bodySweep, this.bodyVel, this.bodyAwake, this.jointState];
    this.allTables = [
      this.bodyXf,
      this.bodyCell,
      this.bodySweep,
      this.bodyVel,
      this.bodyForce,
      this.bodyMass,
      this.bodyParams,
      this.bodyFlags,
      this.bodyAwake,
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
    world.SetChangeListener(this.changes);
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
    return this.bodySlots.slotOf(body);
  }
  bodyAt(slot: number): b2Body | null {
    return this.bodySlots.items[slot] ?? null;
  }
  fixtureSlot(fixture: b2Fixture): number {
    return this.fixtureSlots.slotOf(fixture);
  }
  fixtureAt(slot: number): b2Fixture | null {
    return this.fixtureSlots.items[slot] ?? null;
  }
  jointSlot(joint: b2Joint): number {
    return this.jointSlots.slotOf(joint);
  }
  jointAt(slot: number): b2Joint | null {
    return this.jointSlots.items[slot] ?? null;
  }
  /** The slot of child `childIndex` of `fixture`'s proxies, -1 when it has none (inactive body). */
  proxySlot(fixture: b2Fixture, childIndex: number): number {
    const fixtureSlot = this.fixtureSlot(fixture);
    if (fixtureSlot < 0 || fixtureSlot >= this.fixtureProxy0.length || this.fixtureProxy0[fixtureSlot] < 0) return -1;
    if (childIndex === 0) return this.fixtureProxy0[fixtureSlot];
    return this.fixtureProxyRest.get(fixtureSlot)?.[childIndex - 1] ?? -1;
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

    // b2World::SetAllowSleeping(false) wakes every body, including those the GPU put to sleep
    // since the last read-back (the world's flags still say awake there).
    this.wakeAll = this.allowSleep && !world.m_allowSleep;
    this.allowSleep = world.m_allowSleep;

    // Everything is walked while the engine moves the bodies, after a body, fixture or joint came
    // or went, when sleeping was turned off, or when another listener replaced the change log;
    // otherwise only what the change log names (and every joint: they report nothing).
    const log = this.changes;
    const full = !this.ownsMotion || log.structure || this.wakeAll || world.m_changeListener !== log;
    if (full) {
      this.reserveFor(world);
      this.syncBodies(world, gen, stats);
    } else {
      log.bodies.forEach(this.packChangedBody);
    }

    // 2. Joints, and the per-body lists of joints that turn collision off (only a structural
    // change alters those).
    const edges: number[] = [];
    this.jointSlots.beginWalk();
    for (let j = world.m_jointList; j; j = j.m_next) {
      const slot = this.jointSlots.acquire(j, gen);
      if (this.jointSlots.created) stats.joints.created++;
      const a = this.bodySlot(j.m_bodyA);
      const b = this.bodySlot(j.m_bodyB);
      this.joints.commitWords(slot, a, b, j.m_type, (j.m_collideConnected ? 1 : 0) | JOINT_LIVE);
      this.commitJoint(slot, j, this.jointSlots.created);
      if (full && !j.m_collideConnected) {
        edges.push(a * 67108864 + b, b * 67108864 + a);
      }
    }
    if (full) {
      stats.joints.released = this.jointSlots.sweep(gen, (slot) => {
        this.joints.commitWords(slot, 0, 0, 0, 0);
      });
      this.packJointGraph(edges);
    }

    if (full) {
      this.syncFixtures(world, gen, stats);
    } else {
      for (const f of log.fixtures) this.packChangedFixture(f, gen, stats);
    }
    // Motion set through the API overrides the GPU's for that body.
    if (this.ownsMotion) {
      log.bodies.forEach(this.packSetMotion);
      log.woken.forEach(this.packWoken);
    }
    log.reset();

    stats.bodies.live = this.bodySlots.live;
    stats.fixtures.live = this.fixtureSlots.live;
    stats.proxies.live = this.proxySlots.live;
    stats.joints.live = this.jointSlots.live;

    const queue = this.ctx.device.queue;
    for (const table of this.allTables) table.flush(queue, stats.upload);
    return stats;
  }

  /**
   * Grows the tables once to what the world holds, instead of doubling them over and over while a
   * large world is first walked (each doubling a new buffer and shadow, and work for the collector).
   */
  private reserveFor(world: b2World): void {
    const bodies = world.m_bodyCount;
    if (bodies <= this.bodyXf.capacity) return;
    let fixtures = 0;
    let proxies = 0;
    let shapes = this.pool.top;
    for (let b = world.m_bodyList; b; b = b.m_next) {
      fixtures += b.m_fixtureCount;
      for (let f = b.m_fixtureList; f; f = f.m_next) {
        proxies += f.m_proxyCount;
        shapes += shapeSize(f);
      }
    }
    const perBody = [
      this.bodyXf,
      this.bodyCell,
      this.bodySweep,
      this.bodyVel,
      this.bodyForce,
      this.bodyMass,
      this.bodyParams,
      this.bodyFlags,
      this.bodyAwake,
      this.jointRange,
    ];
    const perFixture = [this.fixtureShape, this.fixtureMaterial];
    const perProxy = [this.proxyRef, this.proxyFilter, this.proxyKey];
    MirrorTable.reserveAll(
      [this.shapePool, ...perBody, ...perFixture, ...perProxy],
      [shapes, ...perBody.map(() => bodies), ...perFixture.map(() => fixtures), ...perProxy.map(() => proxies)],
    );
    if (fixtures > 0) this.fixtureRoom(fixtures - 1);
    if (proxies > 0) {
      this.proxyChild = withRoom(this.proxyChild, proxies - 1);
      this.proxyGeneration = withRoom(this.proxyGeneration, proxies - 1);
    }
    this.fixtureProxy0 = withRoom(this.fixtureProxy0, fixtures, -1);
    this.walkSlots = withRoom(this.walkSlots, bodies);
    this.fixtureWalk = withRoom(this.fixtureWalk, fixtures);
  }

  /** Calls `visit` for every body the API changed since the last sync (the change log: applied forces included). */
  forEachChangedBody(visit: (body: b2Body) => void): void {
    for (const body of this.changes.bodies.keys()) visit(body);
  }

  /** A body in the change log, when sync() does not walk them all. */
  private readonly packChangedBody = (_motion: boolean, b: b2Body): void => {
    const slot = this.bodySlot(b);
    if (slot >= 0) this.packBody(slot, b, false);
    this.countBody(b);
  };

  private countBody(b: b2Body): void {
    const census = this.census;
    if (b.m_type !== b2BodyType.b2_dynamicBody) {
      if (b.m_fixtureList) census.nonDynamic++;
    } else if ((b.m_flags & b2BodyFlags.e_bulletFlag) !== 0) {
      census.bullets++;
    }
  }

  private countFixture(f: b2Fixture): void {
    this.census.shapes[f.m_shape.m_type]++;
    if (f.m_isSensor) this.census.sensors++;
  }

  /**
   * A body the API woke: its awake word is uploaded even when it already says awake, since the GPU
   * may have put the body to sleep after the read-back the word came from.
   */
  private readonly packWoken = (b: b2Body): void => {
    const slot = this.bodySlot(b);
    if (slot >= 0 && (b.m_flags & e_awakeFlag) !== 0) {
      this.bodyAwake.commitWords(slot, 1);
      this.bodyAwake.markDirty(slot);
    }
  };

  /** A body whose motion the API set: its motion records are uploaded over the GPU's. */
  private readonly packSetMotion = (motion: boolean, b: b2Body): void => {
    const slot = this.bodySlot(b);
    if (motion && slot >= 0) this.packMotion(slot, b, true);
  };

  /** A fixture in the change log, when sync() does not walk them all. */
  private packChangedFixture(f: b2Fixture, gen: number, stats: SyncStats): void {
    const slot = this.fixtureSlot(f);
    const bodySlot = this.bodySlot(f.m_body);
    if (slot < 0 || bodySlot < 0) return;
    this.countFixture(f);
    this.packFixture(slot, f, bodySlot, false);
    this.packProxies(f, slot, bodySlot, f.m_body.m_type, this.jointCount[bodySlot] > 0, gen, stats);
  }

  /**
   * b2World::ClearForces for a world the GPU steps (GpuStepper calls it after each step, as
   * b2World::Step does): zeroes the forces of the bodies whose uploaded force is not zero (every
   * other body's force is zero already, unless written to m_force directly) and leaves the zeros
   * for the next upload. Those bodies are listed as their force is packed: a million bodies
   * without forces cost nothing here.
   */
  clearForces(): void {
    for (let i = 0; i < this.forcedCount; ++i) {
      const slot = this.forcedSlots[i];
      const b = this.bodyAt(slot);
      if (b !== null) {
        b.m_force.SetZero();
        b.m_torque = 0.0;
      }
      this.bodyForce.commitF4(slot, 0, 0, 0, 0);
    }
    this.forcedCount = 0;
  }

  /** Step 1 of sync: bodies, their slots kept in walk order for syncFixtures and as the next sync's hints. */
  private syncBodies(world: b2World, gen: number, stats: SyncStats): void {
    let walked = 0;
    this.bodySlots.beginWalk();
    for (let b = world.m_bodyList; b; b = b.m_next) {
      const slot = this.bodySlots.acquire(b, gen, walked < this.walkCount ? this.walkSlots[walked] : -1);
      if (this.bodySlots.created) stats.bodies.created++;
      this.packBody(slot, b, this.bodySlots.created);
      this.walkSlots = withRoom(this.walkSlots, walked);
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
    const census = this.census;
    census.shapes.fill(0);
    census.sensors = census.bullets = census.nonDynamic = 0;
    this.fixtureSlots.beginWalk();
    for (let b = world.m_bodyList; b; b = b.m_next) {
      const bodySlot = this.walkSlots[index++];
      const jointed = this.jointCount[bodySlot] > 0;
      this.countBody(b);
      for (let f = b.m_fixtureList; f; f = f.m_next) {
        this.countFixture(f);
        const hint = fixtureWalked < this.fixtureWalkCount ? this.fixtureWalk[fixtureWalked] : -1;
        const slot = this.fixtureSlots.acquire(f, gen, hint);
        this.fixtureWalk = withRoom(this.fixtureWalk, fixtureWalked);
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
      this.fixtureProxy0[slot] = -1;
      this.fixtureProxyRest.delete(slot);
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

    const f = this.bodyForce.f32;
    const unforced = slot >= this.bodyForce.count || (f[4 * slot] === 0 && f[4 * slot + 1] === 0 && f[4 * slot + 2] === 0);
    this.bodyForce.commitF4(slot, b.m_force.x, b.m_force.y, b.m_torque, 0);
    if (unforced && (b.m_force.x !== 0 || b.m_force.y !== 0 || b.m_torque !== 0)) {
      this.forcedSlots = withRoom(this.forcedSlots, this.forcedCount);
      this.forcedSlots[this.forcedCount++] = slot;
    }
    this.bodyMass.commitF4(slot, b.m_invMass, b.m_invI, b.m_sweep.localCenter.x, b.m_sweep.localCenter.y);
    this.bodyParams.commitF4(slot, b.m_linearDamping, b.m_angularDamping, b.m_gravityScale, 0);

    this.bodyFlags.commitWords(slot, ((b.m_flags & 0xffff) | (b.m_type << 16) | BODY_LIVE) >>> 0);
    // The awake flag (header): commit uploads it when it differs from the last value uploaded or
    // read back; a new body's, and every body's once sleeping is turned off, always. A body that has
    // not fetched the last read-back's state (b2Body.PullState) shows an older flag, which is not
    // the application's: the GPU's stands.
    if (!this.ownsMotion || created || this.wakeAll || b.m_stateEpoch === this.world.m_stateEpoch) {
      this.bodyAwake.commitWords(slot, (b.m_flags & e_awakeFlag) !== 0 ? 1 : 0);
    }
    if (this.ownsMotion && (created || this.wakeAll)) this.bodyAwake.markDirty(slot);
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
  private commitJoint(slot: number, j: b2Joint, created: boolean): void {
    const owned = this.ownsMotion && !created;
    packJoint(j, this.jointParams, this.jointState, this.cellSize, this);
    this.jointParams.commit(slot);
    if (owned) return;
    this.jointState.commit(slot);
    if (created && this.ownsMotion) this.jointState.markDirty(slot);
  }

  /**
   * The GPU's joint state (jointState words, 8 per joint slot, as read back) into the joints'
   * impulses and limit states, the inverse of packJoint's state words (joints.ts): so that the engine's next
   * step warm-starts the joints from the GPU's impulses. The shadow takes the same words.
   */
  unpackJointStates(state: Float32Array): void {
    const n = Math.min(this.jointSlotCount, state.length >> 3);
    this.jointState.f32.set(state.subarray(0, 8 * n));
    for (let slot = 0; slot < n; ++slot) {
      const j = this.jointAt(slot);
      if (j === null) continue;
      unpackJointState(j, state, 8 * slot);
    }
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
    this.fixturePoolSize.fill(0);
  }

  private packFixture(slot: number, f: b2Fixture, bodySlot: number, created: boolean): void {
    this.fixtureRoom(slot);
    if (created || this.fixturePoolSize[slot] === 0 || (this.staleShapes.size > 0 && this.staleShapes.delete(f))) {
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

  /** Room in the per-fixture arrays for fixture slot `slot` (reserveFor makes it for a whole world at once). */
  private fixtureRoom(slot: number): void {
    if (slot < this.fixturePoolSize.length) return;
    this.fixturePoolOffset = withRoom(this.fixturePoolOffset, slot);
    this.fixturePoolSize = withRoom(this.fixturePoolSize, slot);
    this.fixtureShapeWord = withRoom(this.fixtureShapeWord, slot);
    this.fixtureRadius = withRoom(this.fixtureRadius, slot);
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

  private packProxies(f: b2Fixture, fixtureSlot: number, bodySlot: number, bodyType: number, jointed: boolean, gen: number, stats: SyncStats): void {
    // Proxies belong to (fixture slot, child): a fixture slot is reused only after the sync that
    // released it, so the pair names one live proxy.
    const n = f.m_proxyCount;
    this.fixtureProxy0 = withRoom(this.fixtureProxy0, fixtureSlot, -1);
    // Children beyond n (a body made inactive) are left unmarked: the sweep releases them.
    if (n === 0) {
      this.fixtureProxy0[fixtureSlot] = -1;
      this.fixtureProxyRest.delete(fixtureSlot);
      return;
    }
    let rest = this.fixtureProxyRest.get(fixtureSlot);
    if (rest !== undefined && rest.length > n - 1) rest.length = n - 1;
    const filter = f.m_filter;
    const word = f.m_shape.m_type | (bodyType << 2) | PROXY_LIVE | (f.m_isSensor ? PROXY_SENSOR : 0) | (jointed ? PROXY_JOINTED : 0);
    const filterWord = ((filter.categoryBits & 0xffff) | ((filter.maskBits & 0xffff) << 16)) >>> 0;
    const group = filter.groupIndex & 0xffff;
    const proxies = this.proxySlots;
    const engineProxies = (f as { m_proxies?: { proxyId: number }[] }).m_proxies;
    for (let child = 0; child < n; ++child) {
      let slot = child === 0 ? this.fixtureProxy0[fixtureSlot] : (rest?.[child - 1] ?? -1);
      let fresh = false;
      if (slot < 0) {
        slot = proxies.alloc();
        proxies.items[slot] = fixtureSlot;
        if (child === 0) {
          this.fixtureProxy0[fixtureSlot] = slot;
        } else {
          if (rest === undefined) this.fixtureProxyRest.set(fixtureSlot, (rest = []));
          rest.push(slot);
        }
        stats.proxies.created++;
        fresh = true;
      }
      proxies.mark(slot, gen);
      this.proxyFixture[slot] = f;
      this.proxyChild = withRoom(this.proxyChild, slot);
      this.proxyChild[slot] = child;
      this.proxyRef.commitWords(slot, fixtureSlot, child, bodySlot, word);
      this.proxyFilter.commitWords(slot, filterWord, group);
      // The engine's proxy id orders same-type contacts (b2BroadPhase::QueryCallback puts the
      // lower id first, b2Contact::Create makes it fixture A); without one (a synthetic world),
      // the slot orders them. A new proxy in the slot, or a new engine proxy (the body was
      // deactivated and reactivated between syncs), gets a new generation.
      const engineId = engineProxies?.[child]?.proxyId;
      const order = typeof engineId === 'number' && engineId >= 0 ? engineId : slot;
      this.proxyGeneration = withRoom(this.proxyGeneration, slot);
      if (fresh || this.proxyKey.u32[2 * slot] !== order) this.proxyGeneration[slot] = (this.proxyGeneration[slot] + 1) >>> 0;
      this.proxyKey.commitWords(slot, order, this.proxyGeneration[slot]);
    }
  }

  destroy(): void {
    if (this.world.m_changeListener === this.changes) this.world.SetChangeListener(null);
    for (const table of this.allTables) table.destroy();
    this.bodySlots.dispose();
    this.fixtureSlots.dispose();
    this.jointSlots.dispose();
  }
}
