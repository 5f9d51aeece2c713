/*
 * Contacts and contact events of the WebGPU backend (backend.ts) on the host: the GPU's begin/end
 * lists and contacts of every step kept until the next synchronisation, then delivered to the
 * world's b2ContactListener with b2Contact objects this module keeps.
 *
 * In:  record(): after a step's submission, appended to log buffers on the GPU (one submission):
 *      a copy of its event list when asked (the narrow phase's whole list buffer, 2 x contact
 *      capacity records), and of its contact keys and manifolds (with the solver's impulses) when
 *      asked (for PostSolve: the whole buffers, contact capacity records); the counts are known
 *      only from the step's read-back. plan(): the ranges a synchronisation copies in
 *      readState()'s one map: each logged step's events and contacts, and the last step's contact
 *      keys and manifolds when someone needs them (a listener, or the switch back to the
 *      JavaScript engine): its logged ones when it logged them, else the narrow phase's.
 * Out: deliver(): for every logged step, in step order, its BeginContact / EndContact in the GPU's
 *      event order (sorted by the pair's proxy slots, then the contacts gone with their pair, in
 *      the same order), then, when it logged its contacts, PostSolve for the contacts the solver
 *      solved in it (touching, not sensors, in awake islands: MF.SOLVED), in contact order,
 *      with its normal and tangent impulses and its manifold in the b2Contact; none for a contact
 *      whose fixture was destroyed after the step (its EndContact comes with the next step).
 * Invariants: one b2Contact per GPU contact (pair of proxy slots, checked against the slots'
 *      fixtures) from its begin until its end or until it leaves the GPU's contact list: BeginContact
 *      and EndContact get the same object. These objects are not in the world's contact list.
 *      After a synchronisation their manifolds are its last step's.
 */

import type { b2Contact } from '../../src/dynamics/contacts/b2Contact';
import type { b2ContactImpulse, b2ContactListener } from '../../src/dynamics/b2WorldCallbacks';
import type { b2World } from '../../src/dynamics/b2World';
import type { b2WorldBackendEngine } from '../../src/dynamics/b2WorldBackend';
import { b2ContactFlags, b2WorldFlags } from '../../src/common/b2Constants';
import { GpuArray } from '../device/buffers';
import type { GpuContext } from '../device/device';
import { EVENT_BEGIN, MANIFOLD_WORDS, MF } from '../device/layout';
import type { GpuNarrowPhase, NarrowPhaseResult } from '../narrowphase/narrowPhase';
import type { GpuReadRange } from '../stepper';
import type { GpuWorld } from '../world/world';

const { e_touchingFlag } = b2ContactFlags;
const { e_locked } = b2WorldFlags;
/** Bytes per event record and per contact (key + manifold). */
const EVENT_BYTES = 16;
const KEY_BYTES = 16;
const MANIFOLD_BYTES = 4 * MANIFOLD_WORDS;

/** Records of one step in a log. */
interface LogRange {
  /** First record in the log. */
  offset: number;
  /** Records copied (the step's buffer capacity). */
  capacity: number;
  /** The step's count, once its read-back is in. */
  count: number | null;
}

/** One step's entries in the logs (events, contacts: null when not logged). */
interface Segment {
  events: LogRange | null;
  contacts: LogRange | null;
  counted: boolean;
  settled: Promise<unknown>;
}

/** A range readState() filled, as words (its offset and size are multiples of 4). */
function u32(range: GpuReadRange): Uint32Array {
  const d = range.data!;
  return new Uint32Array(d.buffer, d.byteOffset, d.byteLength / 4);
}

function f32(range: GpuReadRange): Float32Array {
  const d = range.data!;
  return new Float32Array(d.buffer, d.byteOffset, d.byteLength / 4);
}

/** The GPU's contacts of one step: keys and manifold records (views of the read state: valid until the next read). */
export interface GpuContactSet {
  count: number;
  /** (proxy a, proxy b, generation a, generation b) per contact, a < b. */
  keys: Uint32Array;
  manifoldU32: Uint32Array;
  manifoldF32: Float32Array;
}

/** The first `count` contacts of a step, read: keys and manifold records. */
export interface ContactRead {
  keys: GpuReadRange;
  manifolds: GpuReadRange;
  count: number;
}

/** A synchronisation's read: readState() fills the ranges, then contactSet() decodes. */
export interface EventPlan {
  /** Every logged step, in step order. */
  steps: { events: GpuReadRange | null; contacts: ContactRead | null }[];
  /** The last step's contacts (the last logged step's own when they are its), null when not read. */
  last: ContactRead | null;
}

/** Pair key of two proxy slots in either order: min << 26 | max (slots stay far below 2^26). */
function pairKey(a: number, b: number): number {
  return Math.min(a, b) * 0x4000000 + Math.max(a, b);
}

/** Whether the listener wants BeginContact / EndContact events. */
export function wantsEvents(engine: b2WorldBackendEngine, listener: b2ContactListener | null): boolean {
  return engine.listenerOverrides(listener, 'BeginContact') || engine.listenerOverrides(listener, 'EndContact');
}

export class GpuContactEvents {
  private readonly ctx: GpuContext;
  private readonly engine: b2WorldBackendEngine;
  private readonly eventLog: GpuArray;
  private readonly keyLog: GpuArray;
  private readonly manifoldLog: GpuArray;
  private eventsUsed = 0;
  private contactsUsed = 0;
  private segments: Segment[] = [];
  /** The last step recorded, when it logged anything. */
  private lastStep: Segment | null = null;
  /** The backend's b2Contact objects by pair key. */
  readonly contacts = new Map<number, b2Contact>();
  private readonly impulse: b2ContactImpulse;

  constructor(ctx: GpuContext, engine: b2WorldBackendEngine) {
    this.ctx = ctx;
    this.engine = engine;
    this.eventLog = new GpuArray(ctx, 'contact event log', EVENT_BYTES, 1024);
    this.keyLog = new GpuArray(ctx, 'contact key log', KEY_BYTES, 1024);
    this.manifoldLog = new GpuArray(ctx, 'contact manifold log', MANIFOLD_BYTES, 1024);
    this.impulse = engine.createImpulse();
  }

  /** Takes the world's contacts as the backend's (same objects), keyed by the mirror's proxy slots. */
  adopt(world: b2World, mirror: GpuWorld): void {
    for (let c: b2Contact | null = world.m_contactManager.m_contactList; c; c = c.m_next) {
      const pa = mirror.proxySlot(c.m_fixtureA, c.m_indexA);
      const pb = mirror.proxySlot(c.m_fixtureB, c.m_indexB);
      if (pa >= 0 && pb >= 0) this.contacts.set(pairKey(pa, pb), c);
    }
  }

  /**
   * Called after each step's submission: appends its event list (`events`) and its contact keys
   * and manifolds (`contacts`) to the logs, with one submission on the GPU queue; nothing when
   * neither is asked.
   */
  record(np: GpuNarrowPhase, settled: Promise<NarrowPhaseResult>, events: boolean, contacts: boolean): void {
    if (!events && !contacts) {
      this.lastStep = null;
      return;
    }
    const segment: Segment = { events: null, contacts: null, counted: false, settled };
    const encoder = this.ctx.device.createCommandEncoder({ label: 'contact event log' });
    if (events) {
      const capacity = Math.min(Math.floor(np.events.size / EVENT_BYTES), 2 * np.contactCapacity);
      this.eventLog.ensure(this.eventsUsed + capacity, this.eventsUsed);
      encoder.copyBufferToBuffer(np.events, 0, this.eventLog.buffer, EVENT_BYTES * this.eventsUsed, EVENT_BYTES * capacity);
      segment.events = { offset: this.eventsUsed, capacity, count: null };
      this.eventsUsed += capacity;
    }
    if (contacts) {
      const keys = np.contactKeys;
      const manifolds = np.manifolds;
      const capacity = Math.min(Math.floor(keys.size / KEY_BYTES), Math.floor(manifolds.size / MANIFOLD_BYTES), np.contactCapacity);
      const at = this.contactsUsed;
      this.keyLog.ensure(at + capacity, at);
      this.manifoldLog.ensure(at + capacity, at);
      encoder.copyBufferToBuffer(keys, 0, this.keyLog.buffer, KEY_BYTES * at, KEY_BYTES * capacity);
      encoder.copyBufferToBuffer(manifolds, 0, this.manifoldLog.buffer, MANIFOLD_BYTES * at, MANIFOLD_BYTES * capacity);
      segment.contacts = { offset: at, capacity, count: null };
      this.contactsUsed += capacity;
    }
    this.ctx.device.queue.submit([encoder.finish()]);
    segment.settled = settled.then((r) => {
      if (segment.events !== null) segment.events.count = Math.min(r.eventCount, segment.events.capacity);
      if (segment.contacts !== null) segment.contacts.count = Math.min(r.contactCount, segment.contacts.capacity);
      segment.counted = true;
    });
    this.segments.push(segment);
    this.lastStep = segment;
  }

  /** Resolves once the logged steps' counts are in (a step logged meanwhile is not waited for). */
  async counted(): Promise<void> {
    await Promise.all(this.segments.map((s) => s.settled));
  }

  /** Whether every logged step's counts are in. */
  get allCounted(): boolean {
    return this.segments.every((s) => s.counted);
  }

  /**
   * The ranges of one synchronisation (every logged step counted: see counted()): the logged steps'
   * events and contacts, and the last step's `contactCount` contacts (keys, manifolds) when
   * `contacts`. The logs are emptied: the next step logs from their start, after this read's
   * copy on the queue.
   */
  plan(np: GpuNarrowPhase, contacts: boolean, contactCount: number): EventPlan {
    const steps = this.segments.map((s) => ({
      events: s.events && { buffer: this.eventLog.buffer, offset: EVENT_BYTES * s.events.offset, size: EVENT_BYTES * s.events.count!, data: null },
      contacts: s.contacts && {
        keys: { buffer: this.keyLog.buffer, offset: KEY_BYTES * s.contacts.offset, size: KEY_BYTES * s.contacts.count!, data: null },
        manifolds: { buffer: this.manifoldLog.buffer, offset: MANIFOLD_BYTES * s.contacts.offset, size: MANIFOLD_BYTES * s.contacts.count!, data: null },
        count: s.contacts.count!,
      },
    }));
    const logged = this.lastStep !== null ? steps[steps.length - 1].contacts : null;
    this.segments = [];
    this.lastStep = null;
    this.eventsUsed = 0;
    this.contactsUsed = 0;
    if (!contacts) return { steps, last: null };
    return {
      steps,
      last: logged ?? {
        keys: { buffer: np.contactKeys, offset: 0, size: KEY_BYTES * contactCount, data: null },
        manifolds: { buffer: np.manifolds, offset: 0, size: MANIFOLD_BYTES * contactCount, data: null },
        count: contactCount,
      },
    };
  }

  /** The ranges of a plan, for readState() (the last step's contacts once, when it logged them). */
  static ranges(plan: EventPlan): GpuReadRange[] {
    const out: GpuReadRange[] = [];
    for (const s of plan.steps) {
      if (s.events !== null) out.push(s.events);
      if (s.contacts !== null) out.push(s.contacts.keys, s.contacts.manifolds);
    }
    if (plan.last !== null && plan.last !== plan.steps[plan.steps.length - 1]?.contacts) out.push(plan.last.keys, plan.last.manifolds);
    return out;
  }

  /** The contact set a read holds (null for none). */
  static contactSet(read: ContactRead | null): GpuContactSet | null {
    if (read === null) return null;
    return {
      count: read.count,
      keys: u32(read.keys),
      manifoldU32: u32(read.manifolds),
      manifoldF32: f32(read.manifolds),
    };
  }

  /** The index in `set` of the contact with pair key `key`, or -1 (keys are sorted by a, then b). */
  static find(set: GpuContactSet, key: number): number {
    const a = Math.floor(key / 0x4000000);
    const b = key - a * 0x4000000;
    let lo = 0;
    let hi = set.count;
    while (lo < hi) {
      const mid = (lo + hi) >>> 1;
      const ka = set.keys[4 * mid];
      if (ka < a || (ka === a && set.keys[4 * mid + 1] < b)) lo = mid + 1;
      else hi = mid;
    }
    return lo < set.count && set.keys[4 * lo] === a && set.keys[4 * lo + 1] === b ? lo : -1;
  }

  /** Writes record i of `set` into a b2Contact's manifold and touching flag. */
  static writeManifold(c: b2Contact, set: GpuContactSet, i: number): void {
    const u = set.manifoldU32;
    const f = set.manifoldF32;
    const o = MANIFOLD_WORDS * i;
    const h = u[o];
    const m = c.m_manifold;
    const count = (h >> 2) & 3;
    m.type = h & 3;
    m.pointCount = count;
    m.localNormal.x = f[o + 4];
    m.localNormal.y = f[o + 5];
    m.localPoint.x = f[o + 6];
    m.localPoint.y = f[o + 7];
    for (let k = 0; k < count; ++k) {
      const p = m.points[k];
      p.localPoint.x = f[o + 8 + 2 * k];
      p.localPoint.y = f[o + 9 + 2 * k];
      p.id.key = u[o + 1 + k];
      p.normalImpulse = f[o + 12 + 2 * k];
      p.tangentImpulse = f[o + 13 + 2 * k];
    }
    if ((h & MF.TOUCHING) !== 0) c.m_flags |= e_touchingFlag;
    else c.m_flags &= ~e_touchingFlag;
  }

  /** The proxy slots of contact i's fixture A and fixture B. */
  static oriented(set: GpuContactSet, i: number): [number, number] {
    const a = set.keys[4 * i];
    const b = set.keys[4 * i + 1];
    return (set.manifoldU32[MANIFOLD_WORDS * i] & MF.SWAPPED) !== 0 ? [b, a] : [a, b];
  }

  /**
   * The backend's b2Contact for (proxy A, proxy B), created when missing or when a slot now holds
   * another fixture; null when a fixture is gone.
   */
  private contactFor(mirror: GpuWorld, proxyA: number, proxyB: number): b2Contact | null {
    const key = pairKey(proxyA, proxyB);
    const known = this.contacts.get(key);
    const A = mirror.proxyAt(proxyA);
    const B = mirror.proxyAt(proxyB);
    if (known !== undefined) {
      const same =
        A !== null &&
        B !== null &&
        known.m_fixtureA === A.fixture &&
        known.m_indexA === A.childIndex &&
        known.m_fixtureB === B.fixture &&
        known.m_indexB === B.childIndex;
      if (same || A === null || B === null) return known;
    }
    if (A === null || B === null) return null;
    const c = this.engine.createContact(A.fixture, A.childIndex, B.fixture, B.childIndex);
    if (c !== null) this.contacts.set(key, c);
    return c;
  }

  /**
   * Delivers a synchronisation's events to the world's listener (the world locked, as during
   * b2World.Step), step by step, and leaves the b2Contact objects with the last step's contacts
   * (`set`, the plan's `last`). Contacts no longer on the GPU are forgotten.
   */
  deliver(world: b2World, mirror: GpuWorld, plan: EventPlan, set: GpuContactSet | null): void {
    const listener = world.m_contactManager.m_contactListener;
    if (set !== null) {
      for (const [key, c] of this.contacts) {
        const i = GpuContactEvents.find(set, key);
        if (i >= 0) GpuContactEvents.writeManifold(c, set, i);
      }
    }
    world.m_flags |= e_locked;
    try {
      if (listener !== null) {
        const events = wantsEvents(this.engine, listener);
        const postSolve = this.engine.listenerOverrides(listener, 'PostSolve');
        for (const step of plan.steps) {
          const stepSet = step.contacts === null ? null : step.contacts === plan.last ? set : GpuContactEvents.contactSet(step.contacts);
          if (events && step.events !== null) this.beginEnd(listener, mirror, step.events, stepSet ?? set);
          if (postSolve && stepSet !== null) this.postSolve(listener, mirror, stepSet);
        }
      }
      if (set !== null) {
        for (const [key, c] of this.contacts) {
          const i = GpuContactEvents.find(set, key);
          if (i < 0) this.contacts.delete(key);
          else GpuContactEvents.writeManifold(c, set, i);
        }
      }
    } finally {
      world.m_flags &= ~e_locked;
    }
  }

  /** One step's BeginContact / EndContact; a begun contact gets its manifold from `set` (the step's, else the last step's). */
  private beginEnd(listener: b2ContactListener, mirror: GpuWorld, events: GpuReadRange, set: GpuContactSet | null): void {
    const w = u32(events);
    for (let e = 0; 4 * e < w.length; ++e) {
      const c = this.contactFor(mirror, w[4 * e], w[4 * e + 1]);
      if (c === null) continue;
      if (w[4 * e + 2] === EVENT_BEGIN) {
        const i = set === null ? -1 : GpuContactEvents.find(set, pairKey(w[4 * e], w[4 * e + 1]));
        if (i >= 0) GpuContactEvents.writeManifold(c, set!, i);
        c.m_flags |= e_touchingFlag;
        listener.BeginContact(c);
      } else {
        c.m_flags &= ~e_touchingFlag;
        listener.EndContact(c);
      }
    }
  }

  private postSolve(listener: b2ContactListener, mirror: GpuWorld, set: GpuContactSet): void {
    const impulse = this.impulse;
    for (let i = 0; i < set.count; ++i) {
      const o = MANIFOLD_WORDS * i;
      const h = set.manifoldU32[o];
      // Solved this step: touching, not a sensor, in an awake island (b2Island::Report).
      if ((h & MF.SOLVED) === 0) continue;
      const [pa, pb] = GpuContactEvents.oriented(set, i);
      const c = this.contactFor(mirror, pa, pb);
      // A fixture destroyed after the step was taken is gone: the application hears of its
      // contacts only through their EndContact (the next synchronisation's).
      if (c === null || c.m_fixtureA.m_destroyed || c.m_fixtureB.m_destroyed) continue;
      GpuContactEvents.writeManifold(c, set, i);
      impulse.count = (h >> 2) & 3;
      for (let k = 0; k < impulse.count; ++k) {
        impulse.normalImpulses[k] = set.manifoldF32[o + 12 + 2 * k];
        impulse.tangentImpulses[k] = set.manifoldF32[o + 13 + 2 * k];
      }
      listener.PostSolve(c, impulse);
    }
  }

  destroy(): void {
    this.eventLog.destroy();
    this.keyLog.destroy();
    this.manifoldLog.destroy();
  }
}
