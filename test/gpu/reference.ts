/*
 * CPU references for the GPU broad phase: the pairs of a set of float32 AABBs that overlap (as
 * b2TestOverlap: touching counts) and pass a filter, by brute force over all pairs, or by a plain
 * CPU sweep along x for sets too large for O(n^2) (checked against the brute force in the tests).
 * Pairs are (a, b) with a < b, sorted by (a, b), two words each, as GpuBroadPhase.readPairs().
 */

export type PairFilter = (a: number, b: number) => boolean;

function overlaps(aabbs: Float32Array, a: number, b: number): boolean {
  return aabbs[4 * b] <= aabbs[4 * a + 2] && aabbs[4 * b + 1] <= aabbs[4 * a + 3] && aabbs[4 * a] <= aabbs[4 * b + 2] && aabbs[4 * a + 1] <= aabbs[4 * b + 3];
}

function isLive(aabbs: Float32Array, i: number): boolean {
  return aabbs[4 * i] <= aabbs[4 * i + 2];
}

function finish(pairs: number[]): Uint32Array {
  const n = pairs.length / 2;
  const order = Array.from({ length: n }, (_, i) => i);
  order.sort((x, y) => pairs[2 * x] - pairs[2 * y] || pairs[2 * x + 1] - pairs[2 * y + 1]);
  const out = new Uint32Array(2 * n);
  for (let i = 0; i < n; ++i) {
    out[2 * i] = pairs[2 * order[i]];
    out[2 * i + 1] = pairs[2 * order[i] + 1];
  }
  return out;
}

/** Every pair a < b of live AABBs that overlap and pass `filter`, by testing all pairs. */
export function bruteForcePairs(aabbs: Float32Array, filter: PairFilter = () => true): Uint32Array {
  const n = aabbs.length / 4;
  const pairs: number[] = [];
  for (let a = 0; a < n; ++a) {
    if (!isLive(aabbs, a)) continue;
    for (let b = a + 1; b < n; ++b) {
      if (isLive(aabbs, b) && overlaps(aabbs, a, b) && filter(a, b)) pairs.push(a, b);
    }
  }
  return finish(pairs);
}

/** The same set by a CPU sweep along x (sorted by lower.x, scan while lower.x <= upper.x). */
export function sweepPairs(aabbs: Float32Array, filter: PairFilter = () => true): Uint32Array {
  const n = aabbs.length / 4;
  const live: number[] = [];
  for (let i = 0; i < n; ++i) if (isLive(aabbs, i)) live.push(i);
  live.sort((x, y) => aabbs[4 * x] - aabbs[4 * y] || x - y);
  const pairs: number[] = [];
  for (let i = 0; i < live.length; ++i) {
    const a = live[i];
    const upper = aabbs[4 * a + 2];
    for (let j = i + 1; j < live.length; ++j) {
      const b = live[j];
      if (aabbs[4 * b] > upper) break;
      if (overlaps(aabbs, a, b) && filter(a, b)) pairs.push(Math.min(a, b), Math.max(a, b));
    }
  }
  return finish(pairs);
}

/** Throws with the first pair only one side has, or passes when both lists are equal. */
export function expectSamePairs(got: Uint32Array, expected: Uint32Array, what: string): void {
  let i = 0;
  let j = 0;
  const missing: string[] = [];
  const extra: string[] = [];
  while ((i < got.length || j < expected.length) && missing.length + extra.length < 5) {
    const g = i < got.length ? [got[i], got[i + 1]] : null;
    const e = j < expected.length ? [expected[j], expected[j + 1]] : null;
    if (g && e && g[0] === e[0] && g[1] === e[1]) {
      i += 2;
      j += 2;
    } else if (!e || (g && (g[0] < e[0] || (g[0] === e[0] && g[1] < e[1])))) {
      extra.push(`(${g![0]}, ${g![1]})`);
      i += 2;
    } else {
      missing.push(`(${e[0]}, ${e[1]})`);
      j += 2;
    }
  }
  if (missing.length + extra.length > 0) {
    throw new Error(
      `${what}: GPU pairs ${got.length / 2}, reference ${expected.length / 2}; ` +
        `missing on the GPU: ${missing.join(' ') || 'none'}; extra on the GPU: ${extra.join(' ') || 'none'}`,
    );
  }
}
