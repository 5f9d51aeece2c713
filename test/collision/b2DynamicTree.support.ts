/*
 * Shared by the dynamic tree and broad-phase tests: the seeded generator, the FNV-1a digest and the
 * probes of b2DynamicTree.reference.cpp, written operation for operation as that C++ harness does
 * them, so the digests it printed can be compared here.
 */

import { b2AABB, b2RayCastInput } from '../../src/collision/b2Collision';
import type { b2DynamicTree } from '../../src/collision/b2DynamicTree';
import type { b2TreeQueryCallback, b2TreeRayCastCallback } from '../../src/collision/b2DynamicTree';

/** mulberry32, the same uint32 arithmetic as rnd() in the C++ harness. */
export function mulberry32(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** 32-bit FNV-1a over int32s (4 bytes) and doubles (8 bytes), little-endian. */
export class Fnv1a {
  h = 2166136261;
  private readonly view = new DataView(new ArrayBuffer(8));

  private bytes(n: number): void {
    for (let i = 0; i < n; i++) {
      this.h = Math.imul((this.h ^ this.view.getUint8(i)) >>> 0, 16777619) >>> 0;
    }
  }

  int(v: number): void {
    this.view.setInt32(0, v, true);
    this.bytes(4);
  }

  double(v: number): void {
    this.view.setFloat64(0, v, true);
    this.bytes(8);
  }

  hex(): string {
    return this.h.toString(16).padStart(8, '0');
  }
}

/** randomAABB() of the harness: centre in [-range, range]^2, half-extents in [0.05, size + 0.05). */
export function randomAABB(rnd: () => number, aabb: b2AABB, range: number, size: number): b2AABB {
  const cx = rnd() * (2.0 * range) - range;
  const cy = rnd() * (2.0 * range) - range;
  const hw = rnd() * size + 0.05;
  const hh = rnd() * size + 0.05;
  aabb.lowerBound.Set(cx - hw, cy - hh);
  aabb.upperBound.Set(cx + hw, cy + hh);
  return aabb;
}

/** hashTree() of the harness: pool bookkeeping, then every node (free nodes by their next link). */
export function hashTree(hash: Fnv1a, tree: b2DynamicTree): void {
  hash.int(tree.m_root);
  hash.int(tree.m_nodeCount);
  hash.int(tree.m_nodeCapacity);
  hash.int(tree.m_freeList);
  hash.int(tree.m_insertionCount);
  for (let i = 0; i < tree.m_nodeCapacity; i++) {
    const n = tree.GetNode(i);
    hash.int(n.height);
    if (n.height < 0) {
      hash.int(n.next);
      continue;
    }
    hash.int(n.parent);
    hash.int(n.child1);
    hash.int(n.child2);
    hash.int(n.userData === null ? 0 : (n.userData as number));
    hash.double(n.aabb.lowerBound.x);
    hash.double(n.aabb.lowerBound.y);
    hash.double(n.aabb.upperBound.x);
    hash.double(n.aabb.upperBound.y);
  }
}

class QueryRecorder implements b2TreeQueryCallback {
  count = 0;
  constructor(
    private readonly hash: Fnv1a,
    private readonly limit: number,
  ) {}

  QueryCallback(proxyId: number): boolean {
    this.hash.int(proxyId);
    ++this.count;
    return this.count !== this.limit;
  }
}

/** Ignores ids = 0 mod 3, clips to 0.75 x maxFraction for 1 mod 3, keeps 2 mod 3, stops at the 10th. */
class RayRecorder implements b2TreeRayCastCallback {
  count = 0;
  constructor(private readonly hash: Fnv1a) {}

  RayCastCallback(input: b2RayCastInput, proxyId: number): number {
    this.hash.int(proxyId);
    this.hash.double(input.maxFraction);
    ++this.count;
    if (this.count === 10) return 0.0;
    if (proxyId % 3 === 0) return -1.0;
    if (proxyId % 3 === 1) return input.maxFraction * 0.75;
    return input.maxFraction;
  }
}

/** A tree or a broad-phase: both offer Query and RayCast with the tree's callbacks. */
export interface Probeable {
  Query(callback: b2TreeQueryCallback, aabb: b2AABB): void;
  RayCast(callback: b2TreeRayCastCallback, input: b2RayCastInput): void;
}

/** probe() of the harness: a full query, a query stopped at the third hit, a ray cast. */
export function probe(hash: Fnv1a, rnd: () => number, target: Probeable, range: number): void {
  const box = randomAABB(rnd, new b2AABB(), range, 8.0);
  const q = new QueryRecorder(hash, -1);
  target.Query(q, box);
  hash.int(q.count);
  const q3 = new QueryRecorder(hash, 3);
  target.Query(q3, box);
  hash.int(q3.count);
  const input = new b2RayCastInput();
  input.p1.x = rnd() * (2.0 * range) - range;
  input.p1.y = rnd() * (2.0 * range) - range;
  input.p2.x = rnd() * (2.0 * range) - range;
  input.p2.y = rnd() * (2.0 * range) - range;
  input.maxFraction = 1.0;
  const r = new RayRecorder(hash);
  target.RayCast(r, input);
  hash.int(r.count);
}
