/*
 * Stepping a b2World on the GPU: the broad phase, the narrow phase and the solver of a step in
 * one command buffer and one submission (two when collision overflows and the host reruns it,
 * the solver with it), recorded by GpuPipeline (pipeline.ts) in b2World::Step's order (Collide,
 * Solve, then SolveTOI when the world's continuous physics is on: timeOfImpact.ts, one parallel
 * pass without 2.2.1's TOI sub-steps).
 *
 * In:  a b2World built with the normal API; step(dt, velocityIterations, positionIterations).
 * Out: the bodies' motion on the GPU (GpuWorld's bodyXf, bodyCell, bodySweep, bodyVel), contacts
 *      and impulses in the narrow phase's buffers; readState() reads the motion, the awake flag and
 *      the sleep time back with one map and keeps them mapped on the host (taken from the map a
 *      chunk of bodies at a time as they are read: MappedState), writing the joints' impulses and
 *      limit states into the b2Joint objects; pullBody() and pullAll() write the bodies' into their
 *      b2Body objects (readBodies(): both at once).
 * Authority: once the constructor has uploaded the world, the GPU's copy of the body motion is
 * the one that counts (GpuWorld.gpuOwnsMotion; so the first step need not walk the whole world
 * again): the world's bodies keep their old positions and velocities until they are pulled.
 * Motion set through the API (SetTransform, SetLinearVelocity, impulses) replaces the
 * GPU's for that body at the next step (GpuWorld's change log, b2ChangeListener), computed from the
 * state the body had in JavaScript: read back first. Everything else still flows from the world at
 * each step: bodies and fixtures created or destroyed, masses, forces (cleared after each step when
 * the world auto-clears them, as b2World::Step does), damping, gravity, materials.
 * Handing over a running world: the constructor takes the world's contacts and their impulses as
 * the previous step's (GpuNarrowPhase.seedFromWorld) and its 1 / dt of the last step, so the first
 * GPU step warm-starts as the engine's next step would.
 * Joints: all ten types of 2.2.1 are solved (solveJoints.ts), coloured with the contacts.
 * Sleeping: islands and sleep timers on the GPU (islands.ts); the awake flag is GPU-owned like the
 * motion, and SetAwake from JavaScript reaches the GPU by GpuWorld's rule (its header). A world at
 * rest (every body asleep, nothing uploaded since) records no step at all (GpuPipeline.skipResting).
 * Unlike 2.2.1 (docs/GPU.md, "The solver"): no TOI island solve or sub-steps (a body is stopped at
 * its time of impact and the next step solves the contact). Contact listeners: WebGPUBackend
 * (backend.ts) reads events and contacts in readState()'s map and delivers them after the step.
 */

import type { b2Body } from '../src/dynamics/b2Body';
import type { b2World } from '../src/dynamics/b2World';
import { b2BodyFlags, b2WorldFlags } from '../src/common/b2Constants';
import type { GpuContext } from './device/device';
import { GpuBroadPhase } from './broadphase/broadPhase';
import type { GpuBroadPhaseOptions } from './broadphase/broadPhase';
import { GpuNarrowPhase } from './narrowphase/narrowPhase';
import type { GpuNarrowPhaseOptions, NarrowPhaseResult } from './narrowphase/narrowPhase';
import { GpuPipeline } from './pipeline';
import { GpuSolver } from './solver/solver';
import type { GpuSolverOptions, SolverStep } from './solver/solver';
import { GpuWorld } from './world/world';
import { GpuTransformRead } from './query/transforms';
import type { GpuWorldOptions } from './world/world';
import { MappedState, STATE_CHUNK, StagingBuffer } from './device/readback';
import type { MappedField } from './device/readback';

export interface GpuStepperOptions {
  world?: GpuWorldOptions;
  broadPhase?: GpuBroadPhaseOptions;
  narrowPhase?: GpuNarrowPhaseOptions;
  solver?: GpuSolverOptions;
  /**
   * Copy each read-back's body state to the host whole, instead of taking it from the map a chunk
   * at a time as bodies are read: the state then outlives the map, which a lost device takes
   * with it, at the price of copying 76 bytes a body at every read (AutoBackend sets it).
   */
  keepReadBack?: boolean;
}

/** A range of a GPU buffer read back in readState()'s map (offset and size multiples of 4). */
export interface GpuReadRange {
  buffer: GPUBuffer;
  offset: number;
  size: number;
  /** Set by readState(): the range's bytes in the mapped state, readable until the next readState(). */
  data: Uint8Array | null;
}

export interface GpuStepOptions {
  /** false: return once submitted (GpuPipeline's { wait: false }); default true. */
  wait?: boolean;
}

const { e_clearForces } = b2WorldFlags;
const { e_awakeFlag } = b2BodyFlags;
/** Bytes per body slot in readState()'s staging buffer: xf 16, cell 8, sweep 32, velocity 16, awake 4. */
const BODY_READ_BYTES = 76;
/** Bytes per joint slot read back with the bodies: jointState, impulses and limit state. */
const JOINT_STATE_BYTES = 32;
/** The per-body fields of readState()'s staging buffer, in its order. */
const STATE_FIELDS: readonly MappedField[] = [
  { words: 4, view: (buffer, byteOffset, length) => new Float32Array(buffer, byteOffset, length) },
  { words: 2, view: (buffer, byteOffset, length) => new Int32Array(buffer, byteOffset, length) },
  { words: 8, view: (buffer, byteOffset, length) => new Float32Array(buffer, byteOffset, length) },
  { words: 4, view: (buffer, byteOffset, length) => new Float32Array(buffer, byteOffset, length) },
  { words: 1, view: (buffer, byteOffset, length) => new Uint32Array(buffer, byteOffset, length) },
];
const XF = 0;
const CELL = 1;
const SWEEP = 2;
const VEL = 3;
const AWAKE = 4;
const STATE_CHUNK_MASK = STATE_CHUNK - 1;

function align8(bytes: number): number {
  return Math.ceil(bytes / 8) * 8;
}
/** Bytes per body slot in readTransforms()'s staging buffer for a Float64Array: xf 16, cell 8, awake 4. */
const TRANSFORM_READ_BYTES = 28;

/** What the last read-back cost the host. */
export interface GpuReadStats {
  /** Bytes mapped. */
  bytes: number;
  /** Milliseconds from the map resolving to the data written out (the host's share of the read). */
  unpackMs: number;
  /**
   * Milliseconds the last time every body was brought to a read-back's state (WebGPUBackend's
   * PullAll: the bodies written and the engine's proxies moved, before a query or the debug draw).
   */
  pullMs: number;
}

/**
 * Steps a b2World on the GPU without the world API: WebGPUBackend is built on it.
 * @internal Advanced: exported for tools, benchmarks and tests; applications use WebGPUBackend
 * through b2World.SetBackend (docs/GPU.md, "The world API on the GPU").
 */
export class GpuStepper {
  readonly ctx: GpuContext;
  readonly world: b2World;
  readonly mirror: GpuWorld;
  readonly broadPhase: GpuBroadPhase;
  readonly narrowPhase: GpuNarrowPhase;
  readonly solver: GpuSolver;
  /** Records and submits the steps; its settle() waits for the steps in flight ({ wait: false }). */
  readonly pipeline: GpuPipeline;
  /** Steps taken on the GPU. */
  steps = 0;
  /** What the last readState() or readTransforms() cost (unpacking: joints and extras; bodies are pulled later). */
  readonly readStats: GpuReadStats = { bytes: 0, unpackMs: 0, pullMs: 0 };
  private invDt0: number;
  /** Two staging buffers for readState: the one holding the last state stays mapped while the other is read into. */
  private readonly bodyStaging: [StagingBuffer, StagingBuffer];
  /** Which of them holds the last read state (mapped), -1 for none. */
  private stagingNow = -1;
  /** The last read state's bodies, fetched from the map a chunk at a time (fields: STATE_FIELDS). */
  private readonly state = new MappedState(STATE_FIELDS);
  /** Whether the last read state is the GPU's current one (no step since): readTransforms() reads it instead of mapping again. */
  private stateFresh = false;
  private readonly transformStaging: StagingBuffer;
  private readonly transformRead: GpuTransformRead;
  private readonly keepReadBack: boolean;
  private readonly solverStep: SolverStep = { dt: 0, dtRatio: 0, velocityIterations: 0, positionIterations: 0, warmStarting: true, gravity: { x: 0, y: 0 } };

  constructor(ctx: GpuContext, world: b2World, options: GpuStepperOptions = {}) {
    this.ctx = ctx;
    this.world = world;
    this.keepReadBack = options.keepReadBack === true;
    this.mirror = new GpuWorld(ctx, world, options.world);
    this.broadPhase = new GpuBroadPhase(ctx, options.broadPhase);
    this.narrowPhase = new GpuNarrowPhase(ctx, options.narrowPhase);
    this.solver = new GpuSolver(ctx, options.solver);
    this.pipeline = new GpuPipeline(ctx, this.broadPhase, this.narrowPhase, this.solver);
    this.bodyStaging = [
      new StagingBuffer(ctx, 'stepper body read-back 0', 64 * BODY_READ_BYTES),
      new StagingBuffer(ctx, 'stepper body read-back 1', 64 * BODY_READ_BYTES),
    ];
    this.transformStaging = new StagingBuffer(ctx, 'stepper transform read-back', 64 * TRANSFORM_READ_BYTES);
    this.transformRead = new GpuTransformRead(ctx);
    this.mirror.sync();
    this.mirror.gpuOwnsMotion = true;
    this.narrowPhase.seedFromWorld(this.mirror);
    this.invDt0 = world.m_inv_dt0;
  }

  /**
   * One b2World::Step on the GPU. dt = 0 runs collision only (as the engine does). Resolves with the
   * collision step's counts; with { wait: false } once submitted (pipeline.settle() waits).
   */
  async step(dt: number, velocityIterations: number, positionIterations: number, options: GpuStepOptions = {}): Promise<NarrowPhaseResult> {
    const world = this.world;
    this.stateFresh = false;
    // A world at rest skips its steps until something is uploaded (GpuPipeline.skipResting).
    if (this.mirror.sync().upload.writes > 0) this.pipeline.inputsChanged();
    // The forces are on the GPU now; b2World::Step clears them after the step.
    if ((world.m_flags & e_clearForces) !== 0) this.mirror.clearForces();
    const solve = dt > 0;
    if (solve) {
      const s = this.solverStep;
      s.dt = dt;
      s.dtRatio = this.invDt0 * dt;
      s.velocityIterations = velocityIterations;
      s.positionIterations = positionIterations;
      s.warmStarting = world.m_warmStarting;
      s.gravity = world.m_gravity;
      this.solver.configure(s, this.mirror);
    }
    const result = await this.pipeline.step(this.mirror, { wait: options.wait, solve });
    if (solve) {
      this.invDt0 = 1 / dt;
      world.m_inv_dt0 = this.invDt0;
    }
    this.steps++;
    return result;
  }

  /**
   * Reads the bodies' state back with one map, after every step submitted so far, and keeps it on
   * the host (the staging buffer stays mapped until the next read): pullBody() and pullAll() write
   * it into b2Body objects as they are needed. The joints' impulses and limit states are written
   * into the b2Joint objects at once; `extras` (events, contacts: WebGPUBackend) come in the same
   * map, as views readable until the next read. Returns the number of body slots read.
   */
  async readState(extras: GpuReadRange[] = []): Promise<number> {
    const ctx = this.ctx;
    ctx.assertAlive();
    const mirror = this.mirror;
    const n = mirror.bodySlotCount;
    const joints = mirror.jointSlotCount;
    // Ranges taken from a map start at multiples of 8.
    const jointsAt = align8(BODY_READ_BYTES * n);
    let bytes = jointsAt + JOINT_STATE_BYTES * joints;
    for (const r of extras) bytes = align8(bytes) + r.size;
    if (bytes === 0) return 0;
    // The other staging buffer than the one holding the state now, which stays readable until this one is mapped.
    const next = this.stagingNow === 0 ? 1 : 0;
    const target = this.bodyStaging[next];
    const staging = target.get(bytes);
    const encoder = ctx.device.createCommandEncoder({ label: 'stepper body read-back' });
    encoder.copyBufferToBuffer(mirror.bodyXf.buffer, 0, staging, 0, 16 * n);
    encoder.copyBufferToBuffer(mirror.bodyCell.buffer, 0, staging, 16 * n, 8 * n);
    encoder.copyBufferToBuffer(mirror.bodySweep.buffer, 0, staging, 24 * n, 32 * n);
    encoder.copyBufferToBuffer(mirror.bodyVel.buffer, 0, staging, 56 * n, 16 * n);
    encoder.copyBufferToBuffer(mirror.bodyAwake.buffer, 0, staging, 72 * n, 4 * n);
    if (joints > 0) encoder.copyBufferToBuffer(mirror.jointState.buffer, 0, staging, jointsAt, JOINT_STATE_BYTES * joints);
    let at = jointsAt + JOINT_STATE_BYTES * joints;
    for (const r of extras) {
      at = align8(at);
      if (r.size > 0) encoder.copyBufferToBuffer(r.buffer, r.offset, staging, at, r.size);
      at += r.size;
    }
    ctx.device.queue.submit([encoder.finish()]);
    await target.mapAsync(bytes, 'reading the bodies back from the GPU failed');
    const started = performance.now();
    // The last state stays readable until this one is mapped, and is released before this one's
    // ranges are taken, so that V8 sees the ranges of one state at a time.
    this.releaseState();
    this.stagingNow = next;
    this.stateFresh = true;
    this.state.open(target.current, n, this.keepReadBack);
    if (joints > 0) mirror.unpackJointStates(new Float32Array(target.range(jointsAt, JOINT_STATE_BYTES * joints)));
    at = jointsAt + JOINT_STATE_BYTES * joints;
    for (const r of extras) {
      at = align8(at);
      r.data = r.size > 0 ? new Uint8Array(target.range(at, r.size)) : new Uint8Array(0);
      at += r.size;
    }
    this.readStats.bytes = bytes;
    this.readStats.unpackMs = performance.now() - started;
    return n;
  }

  /** The state read last (readState) into `body`, when that read has it (not for a body new since). */
  pullBody(body: b2Body): void {
    const slot = this.mirror.bodySlot(body);
    if (slot >= 0 && slot < this.state.slots) this.writeBody(slot, body);
  }

  /**
   * Body slot `slot` of the last read state into `body`; and its awake flag into the mirror's
   * shadow, which then holds what the GPU holds for it: sync() uploads the flag again only when
   * JavaScript changes it (GpuWorld's header), and sync() looks at the flag only of bodies that
   * fetched the last state.
   */
  private writeBody(slot: number, body: b2Body): void {
    const state = this.state;
    const xf = state.chunk(XF, slot);
    const cell = state.chunk(CELL, slot);
    const sweep = state.chunk(SWEEP, slot);
    const vel = state.chunk(VEL, slot);
    const i = slot & STATE_CHUNK_MASK;
    const flag = state.chunk(AWAKE, slot)[i];
    const S = this.mirror.cellSize;
    const ox = cell[2 * i] * S;
    const oy = cell[2 * i + 1] * S;
    body.m_xf.p.x = ox + xf[4 * i];
    body.m_xf.p.y = oy + xf[4 * i + 1];
    body.m_xf.q.c = xf[4 * i + 2];
    body.m_xf.q.s = xf[4 * i + 3];
    const s = 8 * i;
    body.m_sweep.c0.x = ox + sweep[s];
    body.m_sweep.c0.y = oy + sweep[s + 1];
    body.m_sweep.a0 = sweep[s + 2];
    body.m_sweep.alpha0 = sweep[s + 3];
    body.m_sweep.c.x = ox + sweep[s + 4];
    body.m_sweep.c.y = oy + sweep[s + 5];
    body.m_sweep.a = sweep[s + 6];
    body.m_linearVelocity.x = vel[4 * i];
    body.m_linearVelocity.y = vel[4 * i + 1];
    body.m_angularVelocity = vel[4 * i + 2];
    body.m_sleepTime = sweep[s + 7];
    body.m_flags = flag !== 0 ? body.m_flags | e_awakeFlag : body.m_flags & ~e_awakeFlag;
    this.mirror.bodyAwake.u32[slot] = flag;
  }

  /**
   * The state read last into every body it has, or (`epoch` given) into those whose m_stateEpoch
   * differs, stamping them with it. Returns the number of bodies written.
   */
  pullAll(epoch?: number): number {
    const mirror = this.mirror;
    let written = 0;
    for (let slot = 0; slot < this.state.slots; ++slot) {
      const b = mirror.bodyAt(slot);
      if (b === null || (epoch !== undefined && b.m_stateEpoch === epoch)) continue;
      this.writeBody(slot, b);
      if (epoch !== undefined) b.m_stateEpoch = epoch;
      written++;
    }
    return written;
  }

  /**
   * Reads the bodies back (readState) and writes every body's motion into the world's b2Body
   * objects (m_xf, m_sweep, velocities, awake flag, sleep time) at once. Returns the number written.
   */
  async readBodies(extras: GpuReadRange[] = []): Promise<number> {
    await this.readState(extras);
    return this.pullAll();
  }

  /** Unmaps the staging buffer holding the last read state (its views are then gone). */
  private releaseState(): void {
    this.state.close();
    if (this.stagingNow >= 0) this.bodyStaging[this.stagingNow].unmap();
    this.stagingNow = -1;
    this.stateFresh = false;
  }

  /**
   * Bulk read for renderers: copies every body slot's transform into `out` (x, y, cos, sin of the
   * body origin at 4 * slot, in world coordinates) and, when given, its awake flag into
   * `awake[slot]` (1 awake, 0 asleep), after every step submitted so far. The world's b2Body
   * objects are not touched. A Float32Array is filled on the GPU (GpuTransformRead: one map of 16
   * bytes a body, one copy); a Float64Array keeps the positions' full precision (cell and offset
   * added in float64 on the host, as the getters do), from the state readState() holds when no
   * step came since (a synchronisation just before), else with one map of 28 bytes a body.
   * Slots that hold no body (destroyed, not yet reused) are written as NaN and 0. Returns the
   * number of slots (GpuWorld.bodySlotCount).
   */
  async readTransforms(out: Float32Array | Float64Array, awake?: Uint8Array): Promise<number> {
    const ctx = this.ctx;
    ctx.assertAlive();
    const mirror = this.mirror;
    const n = mirror.bodySlotCount;
    if (out.length < 4 * n) {
      throw new RangeError(`readTransforms: out holds ${out.length} numbers; this world needs 4 per body slot, ${4 * n}`);
    }
    if (awake !== undefined && awake.length < n) {
      throw new RangeError(`readTransforms: awake holds ${awake.length} flags; this world needs one per body slot, ${n}`);
    }
    if (n === 0) return 0;
    if (out instanceof Float32Array) {
      this.readStats.bytes = await this.transformRead.read(mirror, out, awake);
      this.readStats.unpackMs = this.transformRead.copyMs;
      return n;
    }
    if (this.stateFresh && this.state.slots === n) {
      const started = performance.now();
      const state = this.state;
      const taken = state.bytes;
      for (let first = 0; first < n; first += STATE_CHUNK) {
        const xf = state.chunk(XF, first) as Float32Array;
        const cell = state.chunk(CELL, first) as Int32Array;
        const flags = state.chunk(AWAKE, first) as Uint32Array;
        this.unpackTransforms(first, Math.min(n, first + STATE_CHUNK), xf, cell, flags, out, awake);
      }
      this.readStats.bytes = state.bytes - taken;
      this.readStats.unpackMs = performance.now() - started;
      return n;
    }
    const bytes = TRANSFORM_READ_BYTES * n;
    const staging = this.transformStaging.get(bytes);
    const encoder = ctx.device.createCommandEncoder({ label: 'stepper transform read-back' });
    encoder.copyBufferToBuffer(mirror.bodyXf.buffer, 0, staging, 0, 16 * n);
    encoder.copyBufferToBuffer(mirror.bodyCell.buffer, 0, staging, 16 * n, 8 * n);
    encoder.copyBufferToBuffer(mirror.bodyAwake.buffer, 0, staging, 24 * n, 4 * n);
    ctx.device.queue.submit([encoder.finish()]);
    const mapped = await this.transformStaging.map(bytes, 'reading the transforms back from the GPU failed');
    const started = performance.now();
    this.unpackTransforms(0, n, new Float32Array(mapped, 0, 4 * n), new Int32Array(mapped, 16 * n, 2 * n), new Uint32Array(mapped, 24 * n, n), out, awake);
    this.transformStaging.unmap();
    this.readStats.bytes = bytes;
    this.readStats.unpackMs = performance.now() - started;
    return n;
  }

  /**
   * readTransforms' copy of slots [first, end) from field arrays that start at slot `first`: cells
   * and offsets to world coordinates, empty slots NaN.
   */
  private unpackTransforms(
    first: number,
    end: number,
    xf: Float32Array,
    cell: Int32Array,
    flags: Uint32Array,
    out: Float64Array,
    awake: Uint8Array | undefined,
  ): void {
    const mirror = this.mirror;
    const S = mirror.cellSize;
    for (let slot = first; slot < end; ++slot) {
      const at = 4 * slot;
      const i = slot - first;
      if (mirror.bodyAt(slot) === null) {
        out[at] = out[at + 1] = out[at + 2] = out[at + 3] = NaN;
        if (awake !== undefined) awake[slot] = 0;
        continue;
      }
      out[at] = cell[2 * i] * S + xf[4 * i];
      out[at + 1] = cell[2 * i + 1] * S + xf[4 * i + 1];
      out[at + 2] = xf[4 * i + 2];
      out[at + 3] = xf[4 * i + 3];
      if (awake !== undefined) awake[slot] = flags[i] !== 0 ? 1 : 0;
    }
  }

  destroy(): void {
    this.releaseState();
    for (const staging of this.bodyStaging) staging.destroy();
    this.transformStaging.destroy();
    this.transformRead.destroy();
    this.pipeline.destroy();
    this.solver.destroy();
    this.narrowPhase.destroy();
    this.broadPhase.destroy();
    this.mirror.destroy();
  }
}
