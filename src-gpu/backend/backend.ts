/*
 * The WebGPU backend behind the world API: `await world.SetBackend(await WebGPUBackend.create())`,
 * then world.Step as on the JavaScript engine (docs/GPU.md, "The world API on the GPU", is the
 * contract).
 *
 * In:  the world (Attach: a GpuStepper is built from it, its contacts and impulses seed the GPU's);
 *      Step(dt, vi, pi) from b2World.Step.
 * Out: Step submits a GpuStepper step without waiting. Synchronize() / StepAsync() wait for the
 *      steps in flight and read back, in one map (GpuStepper.readState with extra ranges), the
 *      body motion, the logged steps' contact events (logged while the listener has BeginContact or
 *      EndContact) and contacts (logged while it has PostSolve: each step's impulses and
 *      manifolds), and the last step's contacts when the listener has any event method (their
 *      b2Contact objects' manifolds) or the world is handed back; then advance the world's
 *      m_stateEpoch and deliver the events (events.ts). The body motion stays on the host, mapped:
 *      PullBody writes a body's into its object when the body is first read, PullAll every body's
 *      and moves the engine's broad-phase proxies (queries, ray casts, the debug draw).
 *      readTransforms() reads every transform in bulk without touching the objects.
 *      GetPenetration() gives the accuracy target the deepest penetration of the synchronised step,
 *      measured on the GPU (from its first call on) and read back with the step's counts (no map
 *      of its own). KeepsContacts() tells the engine the GPU finds the pairs (SetTransform adds
 *      none to the world's list). Detach() reads everything, pulls every body, rebuilds the
 *      JavaScript engine's contacts with the GPU's manifolds and impulses, and touches its
 *      broad-phase proxies.
 * Invariants: steps run in call order, each recorded after the previous one's submission; at most
 *      `maxQueuedSteps` wait to be recorded (Step throws beyond); the GPU holds at most four more
 *      (the narrow phase's read-back ring). A listener overriding PreSolve, or a custom contact
 *      filter, is refused at Attach and at every Step. What the GPU steps (joints, sleeping,
 *      continuous collision) is GpuStepper's.
 */

import type { b2Contact } from '../../src/dynamics/contacts/b2Contact';
import type { b2Body } from '../../src/dynamics/b2Body';
import type { b2Fixture } from '../../src/dynamics/b2Fixture';
import type { b2World } from '../../src/dynamics/b2World';
import type { b2WorldBackend, b2WorldBackendEngine } from '../../src/dynamics/b2WorldBackend';
import { b2ContactFlags, b2WorldFlags } from '../../src/common/b2Constants';
import { requestGpu } from '../device/device';
import type { GpuContext, GpuContextOptions } from '../device/device';
import { GpuContactEvents, wantsEvents } from './events';
import { gpuRefusal } from './refusal';
import type { GpuContactSet } from './events';
import type { NarrowPhaseResult } from '../narrowphase/narrowPhase';
import { GpuStepper } from '../stepper';
import type { GpuWorld } from '../world/world';
import type { GpuReadStats, GpuStepperOptions } from '../stepper';

export interface WebGPUBackendOptions extends GpuContextOptions {
  /** A device already requested (requestGpu); otherwise create() requests one with these options. */
  context?: GpuContext;
  stepper?: GpuStepperOptions;
  /** Steps Step() may queue before the previous ones are submitted (default 4); Step throws beyond. */
  maxQueuedSteps?: number;
}

const { e_newFixture, e_clearForces } = b2WorldFlags;
const { e_touchingFlag } = b2ContactFlags;

/**
 * The forces of a step queued behind another: taken when Step is called (and cleared, as
 * b2World::Step clears them), put back into the bodies while the step is recorded, so forces
 * applied between two Steps go into the second even when both wait to be recorded. Reused.
 */
class ForceSnapshot {
  readonly bodies: b2Body[] = [];
  readonly values: number[] = [];

  /**
   * Takes the world's non-zero forces; clears them when the world auto-clears forces. Then only
   * the bodies the API changed since the last step was recorded can hold one (GpuWorld's change
   * log), so a step costs what changed; forces kept across steps are found by walking the bodies.
   */
  take(world: b2World, mirror: GpuWorld): void {
    this.bodies.length = 0;
    this.values.length = 0;
    if ((world.m_flags & e_clearForces) !== 0) {
      mirror.forEachChangedBody(this.takeAndClear);
    } else {
      for (let b = world.m_bodyList; b; b = b.m_next) this.takeBody(b, false);
    }
  }

  private readonly takeAndClear = (b: b2Body): void => this.takeBody(b, true);

  private takeBody(b: b2Body, clear: boolean): void {
    if (b.m_force.x === 0 && b.m_force.y === 0 && b.m_torque === 0) return;
    this.bodies.push(b);
    this.values.push(b.m_force.x, b.m_force.y, b.m_torque);
    if (clear) {
      b.m_force.SetZero();
      b.m_torque = 0;
    }
  }

  /**
   * Swaps these forces with the world's (a second swap restores both), telling the world's change
   * listener (GpuWorld's change log) about every body whose force it sets.
   */
  swap(world: b2World, mirror: GpuWorld, other: ForceSnapshot): void {
    other.take(world, mirror);
    const changes = world.m_changeListener;
    for (const b of other.bodies) {
      b.m_force.SetZero();
      b.m_torque = 0;
      changes?.BodyChanged(b, false);
    }
    for (let i = 0; i < this.bodies.length; ++i) {
      const b = this.bodies[i];
      b.m_force.x = this.values[3 * i];
      b.m_force.y = this.values[3 * i + 1];
      b.m_torque = this.values[3 * i + 2];
      changes?.BodyChanged(b, false);
    }
  }
}

/**
 * The engine's contact for two fixture children, created as its pair search would
 * (b2ContactManager.AddPair, the lower proxy id first as b2BroadPhase::UpdatePairs reports them),
 * with fixture A the given one; null when the engine would create none.
 */
function addContact(world: b2World, fixtureA: b2Fixture, indexA: number, fixtureB: b2Fixture, indexB: number): b2Contact | null {
  const cm = world.m_contactManager;
  const proxyA = fixtureA.m_proxies[indexA];
  const proxyB = fixtureB.m_proxies[indexB];
  const head = cm.m_contactList;
  if (proxyA.proxyId < proxyB.proxyId) cm.AddPair(proxyA, proxyB);
  else cm.AddPair(proxyB, proxyA);
  const c = cm.m_contactList;
  if (c === null || c === head) return null;
  if (c.m_fixtureA !== fixtureA || c.m_indexA !== indexA) {
    throw new Error('WebGPUBackend.Detach: the engine created a contact with its fixtures in the other order than the GPU');
  }
  return c;
}

export class WebGPUBackend implements b2WorldBackend {
  readonly ctx: GpuContext;
  readonly maxQueuedSteps: number;
  private readonly stepperOptions: GpuStepperOptions;
  private world: b2World | null = null;
  private engine: b2WorldBackendEngine | null = null;
  private stepperNow: GpuStepper | null = null;
  private events: GpuContactEvents | null = null;
  /** Steps called and not yet submitted. */
  private queued = 0;
  /** The chain of steps waiting to be recorded. */
  private tail: Promise<void> = Promise.resolve();
  /** Forces of the queued steps (a ring of maxQueuedSteps), and the world's while one records. */
  private readonly forces: ForceSnapshot[];
  private forceCursor = 0;
  private readonly pending = new ForceSnapshot();
  /** The last submitted step's read-back, and its contact count once that is in. */
  private lastStep: Promise<NarrowPhaseResult> | null = null;
  private lastContactCount: number | null = null;
  private readonly counts = { contacts: 0, touching: 0 };
  private countsKnown = false;
  /** The penetration of the latest step whose read-back is in, and of the step the last synchronisation shows (-1: none measured). */
  private latestPenetration = -1;
  private syncedPenetration = -1;
  /** Steps the GPU recorded since the last read-back (one skipped at rest records nothing: GpuPipeline.skipResting). */
  private recordedSinceRead = 0;
  private failure: unknown = null;
  private detaching = false;
  private destroyed = false;
  /** The world's m_stateEpoch when every body and proxy was last brought to the synchronised state (PullAll). */
  private pulledEpoch = 0;
  private reading: Promise<unknown> = Promise.resolve();
  /** Maps made by synchronisations (for tests: one per synchronisation that had recorded steps to read). */
  readbacks = 0;

  private constructor(ctx: GpuContext, options: WebGPUBackendOptions) {
    this.ctx = ctx;
    this.maxQueuedSteps = Math.max(1, options.maxQueuedSteps ?? 4);
    this.stepperOptions = options.stepper ?? {};
    this.forces = Array.from({ length: this.maxQueuedSteps }, () => new ForceSnapshot());
  }

  static async create(options: WebGPUBackendOptions = {}): Promise<WebGPUBackend> {
    return new WebGPUBackend(options.context ?? (await requestGpu(options)), options);
  }

  /** The stepper of the attached world (null when detached). */
  get stepper(): GpuStepper | null {
    return this.stepperNow;
  }

  /**
   * The GPU's contacts after the latest step whose counts are back (every step reads its own):
   * pairs in its contact list, touching or not (b2World.GetContactCount's count on the JavaScript
   * engine, which pairs fattened AABBs where the GPU pairs current ones, so it holds more), and
   * touching non-sensor ones. Null before the first step.
   */
  get contactCounts(): { readonly contacts: number; readonly touching: number } | null {
    return this.countsKnown ? this.counts : null;
  }

  /** Bytes and host time of the last read-back (Synchronize, StepAsync, readTransforms), and of the last PullAll. */
  get readStats(): GpuReadStats | null {
    return this.stepperNow?.readStats ?? null;
  }

  /**
   * The error that stopped the attached world's steps (a lost device, a GPU failure), which
   * Synchronize rejects with and Step throws; null while the steps run.
   */
  get failed(): unknown {
    return this.failure;
  }

  /** The slot of `body` in readTransforms' output; -1 for a body the GPU has not seen yet. */
  bodySlot(body: b2Body): number {
    return this.attached('bodySlot').stepper.mirror.bodySlot(body);
  }

  /**
   * A bulk read for renderers and games that want every body: waits for every step called so far
   * and copies, with one map, each body slot's transform into `out` (x, y, cos, sin at 4 * slot;
   * bodySlot(body) gives the slot) and its awake flag into `awake[slot]`. A Float32Array is the
   * fast path (packed on the GPU, 16 bytes a body, one copy); a Float64Array keeps the positions'
   * full precision (28 bytes a body, converted on the host: several times slower at 10^6). No
   * per-body objects, and the world's b2Body objects are not touched: call Synchronize where the
   * application reads bodies through the API or needs contact events.
   * Slots without a body are written as NaN. Resolves with the slot count.
   */
  async readTransforms(out: Float32Array | Float64Array, awake?: Uint8Array): Promise<number> {
    const { stepper } = this.attached('readTransforms');
    if (this.detaching) throw new Error('WebGPUBackend.readTransforms: the world is being handed back to the JavaScript engine');
    return this.serialised(async () => {
      await this.submitted();
      if (this.failure !== null) throw this.failure;
      return stepper.readTransforms(out, awake);
    });
  }

  /**
   * Releases the GPU resources of the attached world without handing it back, for a world the
   * application throws away (SetBackend(null) would read everything back and rebuild the engine's
   * contacts first). Waits for the steps in flight. The backend is finished: its methods throw
   * from now on, the world's Step and Synchronize with them; world.SetBackend(null) rejects, and
   * leaves the world on the JavaScript engine with the state its bodies last fetched and no contacts.
   */
  async destroy(): Promise<void> {
    const { stepper, events } = this.attached('destroy');
    await this.serialised(async () => {
      await this.submitted();
      await this.lastStep?.catch(() => undefined);
    });
    this.destroyed = true;
    events.destroy();
    stepper.destroy();
    this.stepperNow = null;
    this.events = null;
  }

  PullBody(body: b2Body): void {
    this.stepperNow?.pullBody(body);
  }

  /** While attached the GPU keeps the world's contacts (b2WorldBackend.KeepsContacts). */
  KeepsContacts(): boolean {
    return this.world !== null;
  }

  /**
   * The deepest penetration (m) of the touching contacts after the step the last synchronisation
   * shows, measured on the GPU at the end of that step and read back with its counts (the
   * accuracy target's measure: b2WorldBackend.GetPenetration); null before a synchronised step
   * that solved (dt > 0, no overflow) and measured it. The GPU measures it from the first step
   * recorded after the first call (GpuPipeline.measurePenetration): a world that never asks
   * does not pay for it.
   */
  GetPenetration(): number | null {
    if (this.stepperNow !== null) this.stepperNow.pipeline.measurePenetration = true;
    return this.world !== null && this.syncedPenetration >= 0 ? this.syncedPenetration : null;
  }

  PullAll(): void {
    const world = this.world;
    const stepper = this.stepperNow;
    if (world === null || stepper === null || this.pulledEpoch === world.m_stateEpoch) return;
    const started = performance.now();
    stepper.pullAll(world.m_stateEpoch);
    // Queries (QueryAABB, RayCast) see the synchronised positions. The GPU finds its own pairs, so
    // the moves are not kept for the engine's pair search (Detach touches every proxy instead).
    for (let b = world.m_bodyList; b; b = b.m_next) b.SynchronizeFixtures();
    world.m_contactManager.m_broadPhase.m_moveCount = 0;
    this.pulledEpoch = world.m_stateEpoch;
    stepper.readStats.pullMs = performance.now() - started;
  }

  Attach(world: b2World, engine: b2WorldBackendEngine): void {
    if (this.destroyed) throw new Error('WebGPUBackend.Attach: this backend was destroyed (backend.destroy()); create another');
    if (this.world !== null) throw new Error('WebGPUBackend: already attached to a world; one backend steps one world');
    this.refuseUnsupported(world, engine);
    const stepper = new GpuStepper(this.ctx, world, this.stepperOptions);
    const events = new GpuContactEvents(this.ctx, engine);
    // The GPU took the world's contacts as its previous step's; their objects become the
    // backend's, and the world's contact list stays empty while the GPU owns the contacts.
    events.adopt(world, stepper.mirror);
    world.m_contactManager.UnlinkAllContacts();
    this.world = world;
    this.engine = engine;
    this.stepperNow = stepper;
    this.events = events;
    this.failure = null;
    this.lastStep = null;
    this.lastContactCount = null;
    this.countsKnown = false;
    this.latestPenetration = -1;
    this.syncedPenetration = -1;
    this.recordedSinceRead = 0;
    this.pulledEpoch = world.m_stateEpoch;
  }

  /** Throws when the world asks for what must run inside the solver or per pair on the host. */
  private refuseUnsupported(world: b2World, engine: b2WorldBackendEngine): void {
    const refusal = gpuRefusal(world, engine);
    if (refusal !== null) throw new Error(refusal.message);
  }

  private attached(method: string): { world: b2World; engine: b2WorldBackendEngine; stepper: GpuStepper; events: GpuContactEvents } {
    if (this.destroyed) throw new Error(`WebGPUBackend.${method}: this backend was destroyed (backend.destroy()); its world can no longer be stepped on it`);
    if (this.world === null || this.engine === null || this.stepperNow === null || this.events === null) {
      throw new Error(`WebGPUBackend.${method}: not attached to a world (world.SetBackend(backend) attaches it)`);
    }
    return { world: this.world, engine: this.engine, stepper: this.stepperNow, events: this.events };
  }

  Step(dt: number, velocityIterations: number, positionIterations: number): void {
    const { world, engine, stepper } = this.attached('Step');
    if (this.detaching) throw new Error('b2World.Step: the world is being handed back to the JavaScript engine; await world.SetBackend(null) first');
    if (this.failure !== null) throw this.failure;
    this.refuseUnsupported(world, engine);
    if (this.queued >= this.maxQueuedSteps) {
      throw new Error(
        `b2World.Step: ${this.queued} steps are already waiting to be submitted to the GPU (at most ${this.maxQueuedSteps}); ` +
          'await world.Synchronize() or world.StepAsync() before stepping again',
      );
    }
    this.queued++;
    // With nothing queued the step is recorded now (the world's changes go into it); otherwise
    // after the previous step's submission, with the forces it had when Step was called.
    if (this.queued === 1) {
      this.tail = this.runStep(dt, velocityIterations, positionIterations, null);
    } else {
      const forces = this.forces[this.forceCursor];
      this.forceCursor = (this.forceCursor + 1) % this.forces.length;
      forces.take(world, stepper.mirror);
      this.tail = this.tail.then(() => this.runStep(dt, velocityIterations, positionIterations, forces));
    }
  }

  private async runStep(dt: number, velocityIterations: number, positionIterations: number, forces: ForceSnapshot | null): Promise<void> {
    try {
      if (this.failure !== null) return;
      const { world, engine, stepper, events } = this.attached('Step');
      // GpuStepper.step takes the forces (and clears them) before its first await.
      forces?.swap(world, stepper.mirror, this.pending);
      const stepping = stepper.step(dt, velocityIterations, positionIterations, { wait: false });
      if (forces !== null) this.pending.swap(world, stepper.mirror, forces);
      const result = await stepping;
      const settled = result.settled!;
      this.lastStep = settled;
      this.lastContactCount = null;
      settled.then(
        (r) => {
          if (this.lastStep === settled) this.lastContactCount = r.contactCount;
          this.counts.contacts = r.contactCount;
          this.counts.touching = r.solverCount;
          this.countsKnown = true;
          this.latestPenetration = r.penetration;
        },
        () => undefined,
      );
      // A step skipped at rest changed nothing on the GPU: no events, nothing new to read.
      if (result.skipped) return;
      this.recordedSinceRead++;
      // PostSolve follows a step's solve only (b2World::Step solves when dt > 0).
      const listener = world.m_contactManager.m_contactListener;
      events.record(stepper.narrowPhase, settled, wantsEvents(engine, listener), dt > 0 && engine.listenerOverrides(listener, 'PostSolve'));
    } catch (err) {
      this.failure = err;
    } finally {
      this.queued--;
    }
  }

  /** Resolves once every step called so far is submitted to the GPU (nothing is read back). */
  async submitted(): Promise<void> {
    while (this.queued > 0) await this.tail;
  }

  async StepAsync(dt: number, velocityIterations: number, positionIterations: number): Promise<void> {
    this.Step(dt, velocityIterations, positionIterations);
    await this.Synchronize();
  }

  async Synchronize(): Promise<void> {
    const { world } = this.attached('Synchronize');
    await this.serialised(() => this.read(world, false));
  }

  /** One synchronisation at a time (a second waits for the first). */
  private serialised<T>(body: () => Promise<T>): Promise<T> {
    const run = this.reading.then(body, body);
    this.reading = run.catch(() => undefined);
    return run;
  }

  /**
   * Waits for every step called so far and reads back (one map) the bodies, the logged events and
   * contacts and, when someone needs them (`carry`, or a listener), the last step's contacts;
   * delivers the events. Returns the last step's contact set read, if any.
   */
  private async read(world: b2World, carry: boolean): Promise<GpuContactSet | null> {
    const { engine, stepper, events } = this.attached('Synchronize');
    // Steps called while this waits are waited for too; from the plan to the copy's submission
    // nothing is awaited, so no step can come in between.
    while (this.queued > 0 || !events.allCounted || (this.lastStep !== null && this.lastContactCount === null)) {
      await this.submitted();
      await events.counted();
      await this.lastStep;
    }
    if (this.failure !== null) throw this.failure;
    // No step since the last read-back, or only steps skipped at rest: the GPU holds the state
    // read then, which the bodies have.
    if (this.recordedSinceRead === 0 && !carry) return null;
    const listener = world.m_contactManager.m_contactListener;
    // Before the first step the GPU's contacts are the world's own (Detach keeps those).
    const needContacts = this.lastStep !== null && (carry || wantsEvents(engine, listener) || engine.listenerOverrides(listener, 'PostSolve'));
    const plan = events.plan(stepper.narrowPhase, needContacts, needContacts ? this.lastContactCount! : 0);
    this.recordedSinceRead = 0;
    this.readbacks++;
    await stepper.readState(GpuContactEvents.ranges(plan));
    this.syncedPenetration = this.latestPenetration;
    // Each body fetches this state when it is first read (b2Body.PullState), queries and the debug
    // draw all of it first (PullAll): a synchronisation costs what the application reads.
    world.m_stateEpoch++;
    // The GPU finds its own pairs: the engine's move buffer is not kept (PullAll and Detach
    // bring the proxies up to date).
    world.m_contactManager.m_broadPhase.m_moveCount = 0;
    const set = GpuContactEvents.contactSet(plan.last);
    events.deliver(world, stepper.mirror, plan, set);
    return set;
  }

  async Detach(): Promise<void> {
    const { world, stepper, events } = this.attached('Detach');
    this.detaching = true;
    try {
      const stepped = this.lastStep !== null;
      const set = await this.serialised(() => this.read(world, true));
      this.PullAll();
      const mirror = stepper.mirror;
      if (stepped && set !== null) {
        for (let i = 0; i < set.count; ++i) {
          const [pa, pb] = GpuContactEvents.oriented(set, i);
          const A = mirror.proxyAt(pa);
          const B = mirror.proxyAt(pb);
          if (A === null || B === null) continue;
          const c = addContact(world, A.fixture, A.childIndex, B.fixture, B.childIndex);
          if (c !== null) GpuContactEvents.writeManifold(c, set, i);
        }
      } else {
        // Never stepped: the world's own contacts, as they were handed over.
        for (const old of events.contacts.values()) {
          const c = addContact(world, old.m_fixtureA, old.m_indexA, old.m_fixtureB, old.m_indexB);
          if (c === null) continue;
          c.m_manifold.Assign(old.m_manifold);
          c.m_flags = (c.m_flags & ~e_touchingFlag) | (old.m_flags & e_touchingFlag);
        }
      }
    } finally {
      // The engine's pair search looks at every proxy at the next Step, so that it has every
      // contact its fat AABBs give (the GPU's are those of the current AABBs; after a failure, none).
      const broadPhase = world.m_contactManager.m_broadPhase;
      for (let b = world.m_bodyList; b; b = b.m_next) {
        for (let f = b.m_fixtureList; f; f = f.m_next) {
          for (let k = 0; k < f.m_proxyCount; ++k) broadPhase.TouchProxy(f.m_proxies[k].proxyId);
        }
      }
      world.m_flags |= e_newFixture;
      events.destroy();
      stepper.destroy();
      this.world = null;
      this.engine = null;
      this.stepperNow = null;
      this.events = null;
      this.detaching = false;
    }
  }
}
