/*
 * The engine's contacts as the narrow phase's previous step: for handing a running world to the
 * GPU warm (GpuNarrowPhase.seedFromWorld) and for tests.
 *
 * In:  a synced GpuWorld and its b2World's contact list (b2Contact: fixtures, children, manifold,
 *      touching flag).
 * Out: contact keys (4 words each) and manifold records (MANIFOLD_WORDS each, layout.ts), sorted
 *      by (proxy a, proxy b) as the narrow phase keeps them.
 * Invariants: contacts of proxies the mirror does not have are skipped; the records hold what the
 *      narrow phase would have written for these contacts, impulses included.
 */

import type { b2Contact } from '../../src/dynamics/contacts/b2Contact';
import { b2ContactFlags } from '../../src/common/b2Constants';
import { MANIFOLD_WORDS, MF, NO_CONTACT } from '../device/layout';
import type { GpuWorld } from '../world/world';

const { e_touchingFlag } = b2ContactFlags;

/** `order` stably sorted by keys[order[i]] in [0, buckets): a counting sort (no comparisons, no per-item objects). */
function countingSort(keys: Int32Array, order: Int32Array, buckets: number): Int32Array {
  const starts = new Int32Array(buckets + 1);
  for (let i = 0; i < order.length; ++i) starts[keys[order[i]] + 1]++;
  for (let k = 0; k < buckets; ++k) starts[k + 1] += starts[k];
  const sorted = new Int32Array(order.length);
  for (let i = 0; i < order.length; ++i) sorted[starts[keys[order[i]]]++] = order[i];
  return sorted;
}

/**
 * The world's contacts as key and manifold records (at least one record's room each, for
 * writeBuffer): packed into one array as the contact list is walked, then ordered by (a, b) with
 * two counting sorts of record indices (a million-contact world makes no per-contact object).
 */
export function packWorldContacts(mirror: GpuWorld): { count: number; keys: Uint32Array<ArrayBuffer>; manifolds: Uint32Array<ArrayBuffer> } {
  const world = mirror.world;
  const capacity = Math.max(1, world.m_contactManager.m_contactCount);
  const keyOf = new Uint32Array(4 * capacity);
  const recordOf = new Uint32Array(MANIFOLD_WORDS * capacity);
  // The same words as floats: what a manifold holds as float32.
  const recordF32 = new Float32Array(recordOf.buffer);
  const first = new Int32Array(capacity);
  const second = new Int32Array(capacity);
  let n = 0;
  let slots = 1;
  for (let c: b2Contact | null = world.m_contactManager.m_contactList; c; c = c.m_next) {
    const pa = mirror.proxySlot(c.m_fixtureA, c.m_indexA);
    const pb = mirror.proxySlot(c.m_fixtureB, c.m_indexB);
    if (pa < 0 || pb < 0) continue;
    const a = Math.min(pa, pb);
    const b = Math.max(pa, pb);
    slots = Math.max(slots, b + 1);
    first[n] = a;
    second[n] = b;
    const m = c.m_manifold;
    const touching = (c.m_flags & e_touchingFlag) !== 0;
    const sensor = c.m_fixtureA.m_isSensor || c.m_fixtureB.m_isSensor;
    const k = 4 * n;
    keyOf[k] = a;
    keyOf[k + 1] = b;
    keyOf[k + 2] = mirror.proxyGenerationOf(a);
    keyOf[k + 3] = mirror.proxyGenerationOf(b);
    const count = m.pointCount;
    let header = count > 0 ? (m.type | (count << 2)) >>> 0 : 0;
    if (touching) header |= MF.TOUCHING;
    if (sensor) header |= MF.SENSOR;
    if (pa > pb) header |= MF.SWAPPED;
    const h = MANIFOLD_WORDS * n;
    recordOf[h] = header;
    recordOf[h + 1] = count > 0 ? m.points[0].id.key : 0;
    recordOf[h + 2] = count > 1 ? m.points[1].id.key : 0;
    recordOf[h + 3] = NO_CONTACT;
    if (count > 0) {
      recordF32[h + 4] = m.localNormal.x;
      recordF32[h + 5] = m.localNormal.y;
      recordF32[h + 6] = m.localPoint.x;
      recordF32[h + 7] = m.localPoint.y;
    }
    for (let p = 0; p < count; ++p) {
      const point = m.points[p];
      recordF32[h + 8 + 2 * p] = point.localPoint.x;
      recordF32[h + 9 + 2 * p] = point.localPoint.y;
      recordF32[h + 12 + 2 * p] = point.normalImpulse;
      recordF32[h + 13 + 2 * p] = point.tangentImpulse;
    }
    ++n;
  }
  // By b, then (stably) by a: ordered by (a, b).
  let order: Int32Array = new Int32Array(n);
  for (let i = 0; i < n; ++i) order[i] = i;
  order = countingSort(first, countingSort(second, order, slots), slots);
  const keys = new Uint32Array(4 * Math.max(1, n));
  const manifolds = new Uint32Array(MANIFOLD_WORDS * Math.max(1, n));
  for (let i = 0; i < n; ++i) {
    const r = order[i];
    for (let w = 0; w < 4; ++w) keys[4 * i + w] = keyOf[4 * r + w];
    for (let w = 0; w < MANIFOLD_WORDS; ++w) manifolds[MANIFOLD_WORDS * i + w] = recordOf[MANIFOLD_WORDS * r + w];
  }
  return { count: n, keys, manifolds };
}
