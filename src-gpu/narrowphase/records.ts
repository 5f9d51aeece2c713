/*
 * The narrow phase's records decoded for tests and tools: contacts (keys, contactRef, manifold) and
 * begin / end events, as GpuNarrowPhase.readContacts() and readEvents() return them.
 *
 * In:  words copied from the GPU buffers (layout.ts: contact keys, contactRef, manifolds, events).
 * Out: plain objects, one per contact or event, in buffer order.
 * Invariants: decoding only; nothing here runs in a step.
 */

import { CONTACT_KEPT, MANIFOLD_WORDS, MF, NO_CONTACT } from '../device/layout';

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
  /** Not collided this step: the previous step's manifold, kept (CONTACT_KEPT: bodies asleep or static). */
  kept: boolean;
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

/** `n` contacts from their keys (4 words each), contactRef records (8 words) and manifolds. */
export function decodeContacts(keys: Uint32Array, refs: Uint32Array, manifolds: ArrayBuffer, n: number): GpuContactRecord[] {
  const mu = new Uint32Array(manifolds);
  const mf = new Float32Array(manifolds);
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
      kept: (refs[8 * i + 3] & CONTACT_KEPT) !== 0,
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

/** `n` begin / end events (4 words each). */
export function decodeEvents(w: Uint32Array, n: number): GpuContactEvent[] {
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
