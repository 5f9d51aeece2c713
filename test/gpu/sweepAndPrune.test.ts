/*
 * The sweep-and-prune broad phase on sets of AABBs given directly (GpuProxySet): the GPU pair list
 * against a CPU reference, for distributions that stress it (mixed sizes, huge AABBs, all equal,
 * one dense cluster), with Box2D's pair filters, capacity overflow, and determinism.
 */

import { expect, it } from 'vitest';
import { GpuBroadPhase } from '../../src-gpu/broadphase/broadPhase';
import { requestGpu } from '../../src-gpu/device/device';
import { MAX_STRIPS } from '../../src-gpu/device/layout';
import { GpuProxySet } from '../../src-gpu/broadphase/proxies';
import type { RawProxies } from '../../src-gpu/broadphase/proxies';
import { bruteForcePairs, expectSamePairs, sweepPairs } from './reference';
import { describeGpu, rng } from './support';

/** n AABBs with centres uniform in a square of side `side`, half-sizes from `halfSize`. */
function randomAABBs(n: number, side: number, halfSize: (r: () => number) => number, seed: number): Float32Array {
  const r = rng(seed);
  const out = new Float32Array(4 * n);
  for (let i = 0; i < n; ++i) {
    const cx = (r() - 0.5) * side;
    const cy = (r() - 0.5) * side;
    const hx = halfSize(r);
    const hy = halfSize(r);
    out[4 * i] = cx - hx;
    out[4 * i + 1] = cy - hy;
    out[4 * i + 2] = cx + hx;
    out[4 * i + 3] = cy + hy;
  }
  return out;
}

/** Mixed sizes: mostly 0.05-1 m, some tiny (1 mm), a few 20-200 m. */
const mixed = (r: () => number) => {
  const u = r();
  if (u < 0.1) return 0.001;
  if (u < 0.1005) return 20 + 180 * r();
  return 0.05 + r() * 0.95;
};

function isSortedUnique(pairs: Uint32Array): boolean {
  for (let i = 0; i < pairs.length; i += 2) {
    if (pairs[i] >= pairs[i + 1]) return false;
    if (i > 0 && (pairs[i - 2] > pairs[i] || (pairs[i - 2] === pairs[i] && pairs[i - 1] >= pairs[i + 1]))) return false;
  }
  return true;
}

describeGpu('sweep-and-prune on AABB sets', (ctx) => {
  const broadPhase = new GpuBroadPhase(ctx);
  const proxies = new GpuProxySet(ctx);

  async function gpuPairs(raw: RawProxies): Promise<Uint32Array> {
    proxies.set(raw);
    const result = await broadPhase.update(proxies);
    const pairs = await broadPhase.readPairs();
    expect(pairs.length / 2).toBe(result.pairCount);
    expect(isSortedUnique(pairs)).toBe(true);
    return pairs;
  }

  it('the CPU sweep reference equals brute force (mixed sizes, 4000 AABBs)', () => {
    const aabbs = randomAABBs(4000, 60, mixed, 1);
    expectSamePairs(sweepPairs(aabbs), bruteForcePairs(aabbs), 'sweep vs brute force');
  });

  it('finds exactly the overlapping pairs of 20 000 AABBs of mixed sizes (brute force)', async () => {
    const aabbs = randomAABBs(20_000, 250, mixed, 2);
    const expected = bruteForcePairs(aabbs);
    expect(expected.length / 2).toBeGreaterThan(10_000);
    expectSamePairs(await gpuPairs({ aabbs }), expected, 'mixed 2e4');
  });

  it('finds exactly the overlapping pairs of 100 000 AABBs of mixed sizes', async () => {
    const aabbs = randomAABBs(100_000, 600, mixed, 3);
    expectSamePairs(await gpuPairs({ aabbs }), sweepPairs(aabbs), 'mixed 1e5');
  });

  it('finds exactly the overlapping pairs with the coarsest keys (4096 strips: 12 quantisation bits) and many tied lower bounds', async () => {
    // Keys are KEY_BITS = 24 bits: with 4096 strips (12 bits) the sweep axis keeps 12 bits, cells
    // of 8000 m / 4096 = 1.95 m. Rows of 10 boxes 3 cm apart, each 4 cm wide, fall in one cell
    // (equal keys) and overlap their neighbours; the exact test must keep those pairs and only those.
    const n = 140_000;
    const aabbs = randomAABBs(n, 8000, () => 0.005, 14);
    const r = rng(15);
    for (let row = 0; row < 2000; ++row) {
      const x0 = (r() - 0.5) * 7900;
      const y0 = (r() - 0.5) * 7900;
      for (let j = 0; j < 10; ++j) aabbs.set([x0 + 0.03 * j - 0.02, y0 - 0.02, x0 + 0.03 * j + 0.02, y0 + 0.02], 4 * (10 * row + j));
    }
    proxies.set({ aabbs });
    const result = await broadPhase.update(proxies);
    expect(result.strips).toBe(MAX_STRIPS);
    const pairs = await broadPhase.readPairs();
    expect(isSortedUnique(pairs)).toBe(true);
    const expected = sweepPairs(aabbs);
    expect(expected.length / 2).toBeGreaterThanOrEqual(2000 * 9);
    expectSamePairs(pairs, expected, 'coarse keys');
  });

  it('handles tiny AABBs among a few that span the whole set', async () => {
    const aabbs = randomAABBs(20_000, 1000, () => 0.0005, 4);
    // three huge boxes (one of them with the lowest index, so its pairs lead the list)
    for (const [i, h] of [
      [0, 2000],
      [777, 600],
      [19_999, 1500],
    ]) {
      aabbs.set([-h, -h, h, h], 4 * i);
    }
    const expected = bruteForcePairs(aabbs);
    expect(expected.length / 2).toBeGreaterThan(45_000);
    expectSamePairs(await gpuPairs({ aabbs }), expected, 'tiny and huge');
  });

  it('handles AABBs that are all equal (every pair overlaps)', async () => {
    const n = 900;
    const aabbs = new Float32Array(4 * n);
    for (let i = 0; i < n; ++i) aabbs.set([1.25, -3, 2.5, 4], 4 * i);
    const pairs = await gpuPairs({ aabbs });
    expect(pairs.length / 2).toBe((n * (n - 1)) / 2);
    expectSamePairs(pairs, bruteForcePairs(aabbs), 'all equal');
  });

  it('handles a sparse field with one dense cluster where everything overlaps', async () => {
    const aabbs = randomAABBs(10_000, 400, mixed, 5);
    const r = rng(6);
    for (let i = 0; i < 800; ++i) {
      const k = Math.floor(r() * 10_000);
      const cx = 3 + r() * 0.1;
      const cy = -7 + r() * 0.1;
      aabbs.set([cx - 0.2, cy - 0.2, cx + 0.2, cy + 0.2], 4 * k);
    }
    expectSamePairs(await gpuPairs({ aabbs }), bruteForcePairs(aabbs), 'cluster');
  });

  it('keeps only the pairs Box2D would (bodies, body types, shapes, groups, masks, joints)', async () => {
    const n = 6000;
    const r = rng(7);
    const aabbs = randomAABBs(n, 90, mixed, 8);
    const bodyCount = 2500;
    const bodies = new Uint32Array(n);
    for (let i = 0; i < n; ++i) bodies[i] = Math.floor(r() * bodyCount);
    const bodyTypes = new Uint8Array(bodyCount);
    for (let b = 0; b < bodyCount; ++b) bodyTypes[b] = r() < 0.2 ? 0 : r() < 0.1 ? 1 : 2;
    const shapeTypes = new Uint8Array(n);
    const categoryBits = new Uint16Array(n);
    const maskBits = new Uint16Array(n);
    const groupIndex = new Int16Array(n);
    for (let i = 0; i < n; ++i) {
      shapeTypes[i] = Math.floor(r() * 4);
      categoryBits[i] = 1 << Math.floor(r() * 4);
      maskBits[i] = r() < 0.7 ? 0xffff : Math.floor(r() * 0x10000);
      groupIndex[i] = r() < 0.6 ? 0 : Math.floor(r() * 7) - 3;
    }
    const noCollide: [number, number][] = [];
    for (let k = 0; k < 800; ++k) noCollide.push([Math.floor(r() * bodyCount), Math.floor(r() * bodyCount)]);
    const joined = new Set(noCollide.flatMap(([a, b]) => [`${a}:${b}`, `${b}:${a}`]));
    const filter = (a: number, b: number) => {
      const ba = bodies[a];
      const bb = bodies[b];
      if (ba === bb) return false;
      if (bodyTypes[ba] !== 2 && bodyTypes[bb] !== 2) return false;
      const edgeLike = (t: number) => t === 1 || t === 3;
      if (edgeLike(shapeTypes[a]) && edgeLike(shapeTypes[b])) return false;
      if (joined.has(`${ba}:${bb}`)) return false;
      if (groupIndex[a] === groupIndex[b] && groupIndex[a] !== 0) return groupIndex[a] > 0;
      return (maskBits[a] & categoryBits[b]) !== 0 && (categoryBits[a] & maskBits[b]) !== 0;
    };
    const expected = bruteForcePairs(aabbs, filter);
    const all = bruteForcePairs(aabbs);
    expect(expected.length).toBeLessThan(all.length / 2);
    expect(expected.length).toBeGreaterThan(0);
    const got = await gpuPairs({ aabbs, bodies, bodyTypes, shapeTypes, categoryBits, maskBits, groupIndex, noCollide });
    expectSamePairs(got, expected, 'filters');
  });

  it('skips dead proxies (lower bound above upper bound)', async () => {
    const aabbs = randomAABBs(3000, 40, mixed, 9);
    for (let i = 0; i < 3000; i += 3) aabbs.set([3e38, 3e38, -3e38, -3e38], 4 * i);
    expectSamePairs(await gpuPairs({ aabbs }), bruteForcePairs(aabbs), 'dead slots');
  });

  it('detects a pair capacity that is too small, grows it and gives the exact pair set', async () => {
    const small = new GpuBroadPhase(ctx, { initialPairCapacity: 1024 });
    const aabbs = randomAABBs(8000, 60, mixed, 10);
    const expected = bruteForcePairs(aabbs);
    expect(expected.length / 2).toBeGreaterThan(4 * 1024);
    const set = new GpuProxySet(ctx);
    set.set({ aabbs });
    const first = await small.update(set);
    expect(first.regrows).toBeGreaterThan(0);
    expect(first.pairCapacity).toBeGreaterThanOrEqual(expected.length / 2);
    expectSamePairs(await small.readPairs(), expected, 'after regrow');
    // The grown buffer now fits: no regrow the second time.
    const second = await small.update(set);
    expect(second.regrows).toBe(0);
    expectSamePairs(await small.readPairs(), expected, 'second update');
    small.destroy();
    set.destroy();
  });

  it('detects sweep entries that do not fit, grows the entry buffers and gives the exact pair set', async () => {
    const small = new GpuBroadPhase(ctx, { initialEntryCapacity: 100 });
    const aabbs = randomAABBs(5000, 50, mixed, 13);
    const set = new GpuProxySet(ctx);
    set.set({ aabbs });
    const result = await small.update(set);
    expect(small.entryRegrows).toBeGreaterThan(0);
    expect(result.entries).toBeGreaterThanOrEqual(5000);
    expectSamePairs(await small.readPairs(), bruteForcePairs(aabbs), 'after entry regrow');
    small.destroy();
    set.destroy();
  });

  it('gives byte-identical pair lists for the same input', async () => {
    const aabbs = randomAABBs(30_000, 300, mixed, 11);
    const a = await gpuPairs({ aabbs });
    const b = await gpuPairs({ aabbs });
    const other = new GpuBroadPhase(ctx, { initialPairCapacity: 1024 });
    const set = new GpuProxySet(ctx);
    set.set({ aabbs });
    await other.update(set);
    const c = await other.readPairs();
    expect(Buffer.from(b.buffer).equals(Buffer.from(a.buffer))).toBe(true);
    expect(Buffer.from(c.buffer).equals(Buffer.from(a.buffer))).toBe(true);
    other.destroy();
    set.destroy();
  });

  it('dispatches in 2D when a grid passes the per-dimension limit (forced down to 3)', async () => {
    const narrow = await requestGpu();
    narrow.maxWorkgroupsPerDimension = 3;
    const bp = new GpuBroadPhase(narrow, { initialPairCapacity: 1024 });
    const set = new GpuProxySet(narrow);
    const aabbs = randomAABBs(30_000, 250, mixed, 12);
    set.set({ aabbs });
    const result = await bp.update(set);
    expect(result.regrows).toBeGreaterThan(0);
    expectSamePairs(await bp.readPairs(), sweepPairs(aabbs), '2D dispatch');
    narrow.destroy();
  });

  it('handles empty and single-proxy sets', async () => {
    expect((await gpuPairs({ aabbs: new Float32Array(0) })).length).toBe(0);
    expect((await gpuPairs({ aabbs: new Float32Array([0, 0, 1, 1]) })).length).toBe(0);
  });
});
