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

/** The world's contacts as key and manifold records (at least one record's room each, for writeBuffer). */
export function packWorldContacts(mirror: GpuWorld): { count: number; keys: Uint32Array<ArrayBuffer>; manifolds: Uint32Array<ArrayBuffer> } {
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
  const keys = new Uint32Array(4 * Math.max(1, n));
  const manifolds = new Uint32Array(MANIFOLD_WORDS * Math.max(1, n));
  records.forEach((r, i) => {
    keys.set(r.words.subarray(0, 4), 4 * i);
    manifolds.set(r.words.subarray(4), MANIFOLD_WORDS * i);
  });
  return { count: n, keys, manifolds };
}
