/*
 * Contacts and contact events of the WebGPU backend (backend.ts) on the host: the GPU's begin/end
 * lists of every step kept until the next synchronisation, then delivered to the world's
 * b2ContactListener with b2Contact objects this module keeps.
 *
 * In:  record(): after a step's submission, a copy of its event list (the narrow phase's whole
 *      list buffer, 2 x contact capacity records: the count is known only from the step's
 *      read-back) appended to a log buffer on the GPU. plan(): the ranges a synchronisation copies
 *      in readBodies()'s one map: each logged step's events, and the last step's contact keys and
 *      manifolds when someone needs them (a listener, or the switch back to the JavaScript engine).
 * Out: deliver(): BeginContact / EndContact of every logged step, in step order, each step's in the
 *      GPU's event order (sorted by the pair's proxy slots, then the contacts gone with their pair,
 *      in the same order), then PostSolve for the last step's touching non-sensor contacts, in
 *      contact order, with the GPU's normal and tangent impulses.
 * Invariants: one b2Contact per GPU contact (pair of proxy slots, checked against the slots'
 *      fixtures) from its begin until its end or until it leaves the GPU's contact list: BeginContact
 *      and EndContact get the same object. These objects are not in the world's contact list.
 *      Their manifolds are the last synchronised step's.
 */

import type { b2Contact } from '../src/dynamics/contacts/b2Contact';
import type { b2ContactImpulse, b2ContactListener } from '../src/dynamics/b2WorldCallbacks';
import type { b2World } from '../src/dynamics/b2World';
import type { b2WorldBackendEngine } from '../src/dynamics/b2WorldBackend';
import { GpuArray } from './buffers';
import type { GpuContext } from './device';
import { EVENT_BEGIN, MANIFOLD_WORDS, MF } from './layout';
import type { GpuNarrowPhase, NarrowPhaseResult } from './narrowPhase';
import type { GpuReadRange } from './stepper';
import type { GpuWorld } from './world';

/** b2Contact::e_touchingFlag and b2World::e_locked (src/ is imported for types only). */
const e_touchingFlag = 0x0002;
const e_locked = 0x0002;
/** Bytes per event record and per contact (key + manifold). */
const EVENT_BYTES = 16;
const KEY_BYTES = 16;
const MANIFOLD_BYTES = 4 * MANIFOLD_WORDS;

/** One step's events in the log. */
interface Segment {
  /** First record in the log. */
  offset: number;
  /** Records copied (the step's list capacity). */
  capacity: number;
  /** The step's event count, once its read-back is in. */
  count: number | null;
  settled: Promise<unknown>;
}

/** The GPU's contacts of the last synchronised step: keys and manifold records. */
export interface GpuContactSet {
  count: number;
  /** (proxy a, proxy b, generation a, generation b) per contact, a < b. */
  keys: Uint32Array;
  manifoldU32: Uint32Array;
  manifoldF32: Float32Array;
}

/** A synchronisation's read: readBodies() fills the ranges, then contactSet() decodes. */
export interface EventPlan {
  eventRanges: GpuReadRange[];
  keys: GpuReadRange | null;
  manifolds: GpuReadRange | null;
  contactCount: number;
}

/** Pair key of two proxy slots, a < b (slots stay far below 2^26). */
function pairKey(a: number, b: number): number {
  return a * 0x4000000 + b;
}

/** Whether the listener wants BeginContact / EndContact events. */
export function wantsEvents(engine: b2WorldBackendEngine, listener: b2ContactListener | null): boolean {
  return engine.listenerOverrides(listener, 'BeginContact') || engine.listenerOverrides(listener, 'EndContact');
}

export class GpuContactEvents {
  private readonly ctx: GpuContext;
  private readonly engine: b2WorldBackendEngine;
  private readonly log: GpuArray;
  private used = 0;
  private segments: Segment[] = [];
  /** The backend's b2Contact objects by pair key. */
  readonly contacts = new Map<number, b2Contact>();
  private readonly impulse: b2ContactImpulse;

  constructor(ctx: GpuContext, engine: b2WorldBackendEngine) {
    this.ctx = ctx;
    this.engine = engine;
    this.log = new GpuArray(ctx, 'contact event log', EVENT_BYTES, 1024);
    this.impulse = engine.createImpulse();
  }

  /** Takes the world's contacts as the backend's (same objects), keyed by the mirror's proxy slots. */
  adopt(world: b2World, mirror: GpuWorld): void {
    for (let c: b2Contact | null = world.m_contactManager.m_contactList; c; c = c.m_next) {
      const pa = mirror.proxySlot(c.m_fixtureA, c.m_indexA);
      const pb = mirror.proxySlot(c.m_fixtureB, c.m_indexB);
      if (pa >= 0 && pb >= 0) this.contacts.set(pairKey(Math.min(pa, pb), Math.max(pa, pb)), c);
    }
  }

  /** Appends the step just submitted's event list to the log (one copy on the GPU queue). */
  record(np: GpuNarrowPhase, settled: Promise<NarrowPhaseResult>): void {
    const events = np.events;
    const capacity = Math.min(Math.floor(events.size / EVENT_BYTES), 2 * np.contactCapacity);
    this.log.ensure(this.used + capacity, this.used);
    const encoder = this.ctx.device.createCommandEncoder({ label: 'contact event log' });
    encoder.copyBufferToBuffer(events, 0, this.log.buffer, EVENT_BYTES * this.used, EVENT_BYTES * capacity);
    this.ctx.device.queue.submit([encoder.finish()]);
    const segment: Segment = { offset: this.used, capacity, count: null, settled };
    segment.settled = settled.then((r) => {
      segment.count = Math.min(r.eventCount, capacity);
    });
    this.segments.push(segment);
    this.used += capacity;
  }

  /** Resolves once the logged steps' event counts are in (a step logged meanwhile is not waited for). */
  async counted(): Promise<void> {
    await Promise.all(this.segments.map((s) => s.settled));
  }

  /** Whether every logged step's event count is in. */
  get allCounted(): boolean {
    return this.segments.every((s) => s.count !== null);
  }

  /**
   * The ranges of one synchronisation (every logged step counted: see counted()): the logged steps'
   * events, and the last step's `contactCount` contacts (keys, manifolds) when `contacts`. The log
   * is emptied: the next step logs from its start, after this read's copy on the queue.
   */
  plan(np: GpuNarrowPhase, contacts: boolean, contactCount: number): EventPlan {
    const eventRanges: GpuReadRange[] = this.segments.map((s) => ({ buffer: this.log.buffer, offset: EVENT_BYTES * s.offset, size: EVENT_BYTES * s.count!, data: null }));
    this.segments = [];
    this.used = 0;
    if (!contacts) return { eventRanges, keys: null, manifolds: null, contactCount: 0 };
    return {
      eventRanges,
      keys: { buffer: np.contactKeys, offset: 0, size: KEY_BYTES * contactCount, data: null },
      manifolds: { buffer: np.manifolds, offset: 0, size: MANIFOLD_BYTES * contactCount, data: null },
      contactCount,
    };
  }

  /** The ranges of a plan, for readBodies(). */
  static ranges(plan: EventPlan): GpuReadRange[] {
    return plan.keys && plan.manifolds ? [...plan.eventRanges, plan.keys, plan.manifolds] : plan.eventRanges;
  }

  /** The contact set a plan read (null when it read none). */
  static contactSet(plan: EventPlan): GpuContactSet | null {
    if (plan.keys === null || plan.manifolds === null) return null;
    return {
      count: plan.contactCount,
      keys: new Uint32Array(plan.keys.data!),
      manifoldU32: new Uint32Array(plan.manifolds.data!),
      manifoldF32: new Float32Array(plan.manifolds.data!),
    };
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
    const key = pairKey(Math.min(proxyA, proxyB), Math.max(proxyA, proxyB));
    const known = this.contacts.get(key);
    const A = mirror.proxyAt(proxyA);
    const B = mirror.proxyAt(proxyB);
    if (known !== undefined) {
      const same = A !== null && B !== null && known.m_fixtureA === A.fixture && known.m_indexA === A.childIndex && known.m_fixtureB === B.fixture && known.m_indexB === B.childIndex;
      if (same || A === null || B === null) return known;
    }
    if (A === null || B === null) return null;
    const c = this.engine.createContact(A.fixture, A.childIndex, B.fixture, B.childIndex);
    if (c !== null) this.contacts.set(key, c);
    return c;
  }

  /**
   * Delivers a synchronisation's events to the world's listener (the world locked, as during
   * b2World.Step) and updates the b2Contact objects from the last step's contacts. Contacts no
   * longer on the GPU are forgotten.
   */
  deliver(world: b2World, mirror: GpuWorld, plan: EventPlan, set: GpuContactSet | null): void {
    const listener = world.m_contactManager.m_contactListener;
    const index = new Map<number, number>();
    if (set !== null) {
      for (let i = 0; i < set.count; ++i) index.set(pairKey(set.keys[4 * i], set.keys[4 * i + 1]), i);
      for (const [key, c] of this.contacts) {
        const i = index.get(key);
        if (i !== undefined) GpuContactEvents.writeManifold(c, set, i);
      }
    }
    world.m_flags |= e_locked;
    try {
      if (listener !== null && wantsEvents(this.engine, listener)) {
        for (const r of plan.eventRanges) {
          const w = new Uint32Array(r.data!);
          for (let e = 0; 4 * e < w.length; ++e) {
            const c = this.contactFor(mirror, w[4 * e], w[4 * e + 1]);
            if (c === null) continue;
            const key = pairKey(Math.min(w[4 * e], w[4 * e + 1]), Math.max(w[4 * e], w[4 * e + 1]));
            if (w[4 * e + 2] === EVENT_BEGIN) {
              const i = index.get(key);
              if (set !== null && i !== undefined) GpuContactEvents.writeManifold(c, set, i);
              c.m_flags |= e_touchingFlag;
              listener.BeginContact(c);
            } else {
              c.m_flags &= ~e_touchingFlag;
              listener.EndContact(c);
            }
          }
        }
      }
      if (set !== null) {
        for (const key of this.contacts.keys()) if (!index.has(key)) this.contacts.delete(key);
        for (const [key, c] of this.contacts) GpuContactEvents.writeManifold(c, set, index.get(key)!);
        if (listener !== null && this.engine.listenerOverrides(listener, 'PostSolve')) this.postSolve(listener, mirror, set);
      }
    } finally {
      world.m_flags &= ~e_locked;
    }
  }

  private postSolve(listener: b2ContactListener, mirror: GpuWorld, set: GpuContactSet): void {
    const impulse = this.impulse;
    for (let i = 0; i < set.count; ++i) {
      const o = MANIFOLD_WORDS * i;
      const h = set.manifoldU32[o];
      if ((h & (MF.TOUCHING | MF.SENSOR)) !== MF.TOUCHING) continue;
      const [pa, pb] = GpuContactEvents.oriented(set, i);
      const c = this.contactFor(mirror, pa, pb);
      if (c === null) continue;
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
    this.log.destroy();
  }
}
