import { describe, expect, it } from 'vitest';
import { b2ProxyPairSet } from '../../src/dynamics/b2ProxyPairSet';

/** A small deterministic generator (xorshift32), so a failure replays. */
function random(seed: number): () => number {
  let x = seed >>> 0 || 1;
  return () => {
    x ^= x << 13;
    x >>>= 0;
    x ^= x >>> 17;
    x ^= x << 5;
    x >>>= 0;
    return x / 0x100000000;
  };
}

describe('b2ProxyPairSet', () => {
  it('holds a pair in either order until it is removed', () => {
    const set = new b2ProxyPairSet();
    expect(set.Has(3, 7)).toBe(false);
    set.Add(7, 3);
    expect(set.Has(3, 7)).toBe(true);
    expect(set.Has(7, 3)).toBe(true);
    expect(set.Has(3, 8)).toBe(false);
    expect(set.GetCount()).toBe(1);
    expect(set.Remove(3, 7)).toBe(true);
    expect(set.Remove(3, 7)).toBe(false);
    expect(set.Has(7, 3)).toBe(false);
    expect(set.GetCount()).toBe(0);
  });

  it('answers like a plain set through random adds and removes, growing from a small table', () => {
    // Ids from a small range collide in the table, so removals shift long runs back.
    for (const [seed, range] of [
      [1, 40],
      [2, 400],
      [3, 5000],
    ]) {
      const next = random(seed);
      const set = new b2ProxyPairSet(1);
      const reference = new Set<string>();
      const key = (a: number, b: number): string => (a < b ? `${a},${b}` : `${b},${a}`);
      for (let op = 0; op < 20000; ++op) {
        const a = Math.floor(next() * range);
        let b = Math.floor(next() * range);
        if (b === a) b = (a + 1) % range;
        const held = reference.has(key(a, b));
        expect(set.Has(a, b)).toBe(held);
        if (next() < 0.55) {
          if (!held) {
            set.Add(a, b);
            reference.add(key(a, b));
          }
        } else {
          expect(set.Remove(b, a)).toBe(held);
          reference.delete(key(a, b));
        }
        expect(set.GetCount()).toBe(reference.size);
      }
      for (const k of reference) {
        const [a, b] = k.split(',').map(Number);
        expect(set.Has(b, a)).toBe(true);
      }
    }
  });

  it('Clear empties the set', () => {
    const set = new b2ProxyPairSet(4);
    for (let i = 0; i < 100; ++i) set.Add(i, i + 1000);
    set.Clear();
    expect(set.GetCount()).toBe(0);
    for (let i = 0; i < 100; ++i) expect(set.Has(i, i + 1000)).toBe(false);
    set.Add(5, 1005);
    expect(set.Has(1005, 5)).toBe(true);
  });
});
