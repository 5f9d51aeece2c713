/*
 * The broad-phase (b2BroadPhase.h, b2BroadPhase.cpp).
 *
 * The move buffer and the pair buffer grow as the C++ ones do (capacity 16, doubling) and are
 * reused across steps, so UpdatePairs does not allocate in steady state. The pair buffer holds
 * each b2Pair as its sort key (proxyIdA * 2^26 + proxyIdB), which orders as b2PairLessThan orders
 * the pairs: sorting and finding duplicates then read one double a pair, not two object fields.
 */

import type { b2Vec2 } from '../common/b2Math';
import { b2Max, b2Min } from '../common/b2Math';
import { b2Assert } from '../common/b2Settings';
import { b2DynamicTree } from './b2DynamicTree';
import type { b2TreeQueryCallback, b2TreeRayCastCallback } from './b2DynamicTree';
import { b2AABB } from './b2Collision';
import type { b2RayCastInput } from './b2Collision';

/** Not used by the engine, whose pair buffer holds keys (see above); the C++ struct, for its users. */
export class b2Pair {
  proxyIdA = -1;
  proxyIdB = -1;
  /** Declared by the C++ struct; 2.2.1 never reads or writes it. */
  next = -1;
}

/** The C++ template parameter T of b2BroadPhase::UpdatePairs (b2ContactManager in the engine). */
export interface b2BroadPhasePairCallback {
  AddPair(proxyUserDataA: any, proxyUserDataB: any): void;
}

/** This is used to sort pairs. */
export function b2PairLessThan(pair1: Readonly<b2Pair>, pair2: Readonly<b2Pair>): boolean {
  if (pair1.proxyIdA < pair2.proxyIdA) {
    return true;
  }

  if (pair1.proxyIdA === pair2.proxyIdA) {
    return pair1.proxyIdB < pair2.proxyIdB;
  }

  return false;
}

/**
 * The broad-phase is used for computing pairs and performing volume queries and ray casts.
 * This broad-phase does not persist pairs. Instead, this reports potentially new pairs.
 * It is up to the client to consume the new pairs and to track subsequent overlap.
 */
export class b2BroadPhase implements b2TreeQueryCallback {
  static readonly e_nullProxy = -1;

  m_tree = new b2DynamicTree();

  m_proxyCount: number;

  m_moveBuffer: Int32Array;
  m_moveCapacity: number;
  m_moveCount: number;

  /** Each pair's key, proxyIdA * b2_pairKeyScale + proxyIdB (b2PairKey). */
  m_pairBuffer: Float64Array;
  m_pairCapacity: number;
  m_pairCount: number;

  m_queryProxyId: number;

  /** Not in the C++: where UpdatePairs copies each moved proxy's fat AABB to query the tree with. */
  readonly m_queryAABB = new b2AABB();

  constructor() {
    this.m_proxyCount = 0;

    this.m_pairCapacity = 16;
    this.m_pairCount = 0;
    this.m_pairBuffer = new Float64Array(this.m_pairCapacity);

    this.m_moveCapacity = 16;
    this.m_moveCount = 0;
    this.m_moveBuffer = new Int32Array(this.m_moveCapacity);

    this.m_queryProxyId = b2BroadPhase.e_nullProxy;
  }

  /**
   * Create a proxy with an initial AABB. Pairs are not reported until
   * UpdatePairs is called.
   */
  CreateProxy(aabb: Readonly<b2AABB>, userData: any): number {
    const proxyId = this.m_tree.CreateProxy(aabb, userData);
    ++this.m_proxyCount;
    this.BufferMove(proxyId);
    return proxyId;
  }

  /** Destroy a proxy. It is up to the client to remove any pairs. */
  DestroyProxy(proxyId: number): void {
    this.UnBufferMove(proxyId);
    --this.m_proxyCount;
    this.m_tree.DestroyProxy(proxyId);
  }

  /**
   * Call MoveProxy as many times as you like, then when you are done
   * call UpdatePairs to finalized the proxy pairs (for your time step).
   */
  MoveProxy(proxyId: number, aabb: Readonly<b2AABB>, displacement: Readonly<b2Vec2>): void {
    const buffer = this.m_tree.MoveProxy(proxyId, aabb, displacement);
    if (buffer) {
      this.BufferMove(proxyId);
    }
  }

  /** Call to trigger a re-processing of it's pairs on the next call to UpdatePairs. */
  TouchProxy(proxyId: number): void {
    this.BufferMove(proxyId);
  }

  /**
   * Get the fat AABB for a proxy: a copy, into `aabb` (a new one when omitted), as
   * b2DynamicTree.GetFatAABB says.
   */
  GetFatAABB(proxyId: number, aabb?: b2AABB): b2AABB {
    return this.m_tree.GetFatAABB(proxyId, aabb);
  }

  /** Get user data from a proxy. Returns NULL if the id is invalid. */
  GetUserData(proxyId: number): any {
    return this.m_tree.GetUserData(proxyId);
  }

  /** Test overlap of fat AABBs. */
  TestOverlap(proxyIdA: number, proxyIdB: number): boolean {
    // b2TestOverlap(GetFatAABB(proxyIdA), GetFatAABB(proxyIdB)), read in place from the tree's
    // array of AABBs: the contact manager asks this for every contact each step.
    const fat = this.m_tree.m_fatAABBs;
    const a = 4 * proxyIdA;
    const b = 4 * proxyIdB;
    const d1x = fat[b] - fat[a + 2];
    const d1y = fat[b + 1] - fat[a + 3];
    const d2x = fat[a] - fat[b + 2];
    const d2y = fat[a + 1] - fat[b + 3];

    if (d1x > 0.0 || d1y > 0.0) return false;

    if (d2x > 0.0 || d2y > 0.0) return false;

    return true;
  }

  /** Get the number of proxies. */
  GetProxyCount(): number {
    return this.m_proxyCount;
  }

  /** Update the pairs. This results in pair callbacks. This can only add pairs. */
  UpdatePairs(callback: b2BroadPhasePairCallback): void {
    // Reset pair buffer
    this.m_pairCount = 0;

    // Perform tree queries for all moving proxies.
    for (let i = 0; i < this.m_moveCount; ++i) {
      this.m_queryProxyId = this.m_moveBuffer[i];
      if (this.m_queryProxyId === b2BroadPhase.e_nullProxy) {
        continue;
      }

      // We have to query the tree with the fat AABB so that
      // we don't fail to create a pair that may touch later.
      const fatAABB = this.m_tree.GetFatAABB(this.m_queryProxyId, this.m_queryAABB);

      // Query tree, create pairs and add them pair buffer.
      this.m_tree.Query(this, fatAABB);
    }

    // Reset move buffer
    this.m_moveCount = 0;

    // Sort the pair buffer to expose duplicates.
    b2SortPairs(this.m_pairBuffer, this.m_pairCount);

    // Send the pairs back to the client.
    let i = 0;
    while (i < this.m_pairCount) {
      const primaryPair = this.m_pairBuffer[i];
      const proxyIdA = b2PairProxyIdA(primaryPair);
      const userDataA = this.m_tree.GetUserData(proxyIdA);
      const userDataB = this.m_tree.GetUserData(b2PairProxyIdB(primaryPair, proxyIdA));

      callback.AddPair(userDataA, userDataB);
      ++i;

      // Skip any duplicate pairs: equal keys are equal pairs.
      while (i < this.m_pairCount) {
        if (this.m_pairBuffer[i] !== primaryPair) {
          break;
        }
        ++i;
      }
    }
  }

  /**
   * Query an AABB for overlapping proxies. The callback class
   * is called for each proxy that overlaps the supplied AABB.
   */
  Query(callback: b2TreeQueryCallback, aabb: Readonly<b2AABB>): void {
    this.m_tree.Query(callback, aabb);
  }

  /**
   * Ray-cast against the proxies in the tree. This relies on the callback
   * to perform a exact ray-cast in the case were the proxy contains a shape.
   * The callback also performs the any collision filtering. This has performance
   * roughly equal to k * log(n), where k is the number of collisions and n is the
   * number of proxies in the tree.
   * @param input the ray-cast input data. The ray extends from p1 to p1 + maxFraction * (p2 - p1).
   * @param callback a callback class that is called for each proxy that is hit by the ray.
   */
  RayCast(callback: b2TreeRayCastCallback, input: Readonly<b2RayCastInput>): void {
    this.m_tree.RayCast(callback, input);
  }

  /** Get the height of the embedded tree. */
  GetTreeHeight(): number {
    return this.m_tree.GetHeight();
  }

  /** Get the balance of the embedded tree. */
  GetTreeBalance(): number {
    return this.m_tree.GetMaxBalance();
  }

  /** Get the quality metric of the embedded tree. */
  GetTreeQuality(): number {
    return this.m_tree.GetAreaRatio();
  }

  BufferMove(proxyId: number): void {
    if (this.m_moveCount === this.m_moveCapacity) {
      const oldBuffer = this.m_moveBuffer;
      this.m_moveCapacity *= 2;
      this.m_moveBuffer = new Int32Array(this.m_moveCapacity);
      this.m_moveBuffer.set(oldBuffer.subarray(0, this.m_moveCount));
    }

    this.m_moveBuffer[this.m_moveCount] = proxyId;
    ++this.m_moveCount;
  }

  /**
   * Clear every move-buffer entry of a proxy being destroyed. 2.2.1 returns after the first entry,
   * but a proxy can be buffered twice (CreateProxy or MoveProxy, then TouchProxy from Refilter or
   * SetType): the stale entry then names a freed node, or a node reused by another proxy or by an
   * inner node, and UpdatePairs reports pairs for a destroyed fixture (a dangling pointer in the
   * C++). Box2D 2.3 clears them all, as here; for any world 2.2.1 handles, the pairs are the same.
   */
  UnBufferMove(proxyId: number): void {
    for (let i = 0; i < this.m_moveCount; ++i) {
      if (this.m_moveBuffer[i] === proxyId) {
        this.m_moveBuffer[i] = b2BroadPhase.e_nullProxy;
      }
    }
  }

  /** This is called from b2DynamicTree::Query when we are gathering pairs. */
  QueryCallback(proxyId: number): boolean {
    // A proxy cannot form a pair with itself.
    if (proxyId === this.m_queryProxyId) {
      return true;
    }

    // Grow the pair buffer as needed.
    if (this.m_pairCount === this.m_pairCapacity) {
      const oldBuffer = this.m_pairBuffer;
      this.m_pairCapacity *= 2;
      this.m_pairBuffer = new Float64Array(this.m_pairCapacity);
      this.m_pairBuffer.set(oldBuffer);
    }

    const proxyIdA = b2Min(proxyId, this.m_queryProxyId);
    const proxyIdB = b2Max(proxyId, this.m_queryProxyId);
    this.m_pairBuffer[this.m_pairCount] = b2PairKey(proxyIdA, proxyIdB);
    ++this.m_pairCount;

    return true;
  }
}

/** A pair's key is proxyIdA * 2^26 + proxyIdB: exact, and ordered as the pairs, for ids below 2^26. */
const b2_pairKeyScale = 67108864;

function b2PairKey(proxyIdA: number, proxyIdB: number): number {
  b2Assert(proxyIdB < b2_pairKeyScale, 'proxy id too large to pack');
  return proxyIdA * b2_pairKeyScale + proxyIdB;
}

function b2PairProxyIdA(key: number): number {
  return (key / b2_pairKeyScale) | 0;
}

function b2PairProxyIdB(key: number, proxyIdA: number): number {
  return (key - proxyIdA * b2_pairKeyScale) | 0;
}

/*
 * std::sort of the pairs' keys in [0, count) (b2PairLessThan on the pairs), in place and without
 * allocating: an introsort (median-of-three quicksort, heapsort past a depth limit, insertion sort
 * for short runs). Keys that compare equal are duplicates of one pair, so the sequence of pairs it
 * leaves is the one std::sort leaves.
 */
function b2SortPairs(keys: Float64Array, count: number): void {
  if (count < 2) {
    return;
  }
  let depthLimit = 0;
  for (let n = count; n > 1; n >>= 1) {
    depthLimit += 2;
  }
  b2IntroSort(keys, 0, count, depthLimit);
  b2InsertionSort(keys, 0, count);
}

/**
 * Ranges this short are left for the final insertion sort (std::sort's 16; the unguarded partition
 * needs at least 3 elements).
 */
const b2_sortThreshold = 16;

function b2IntroSort(keys: Float64Array, first: number, last: number, depthLimit: number): void {
  while (last - first > b2_sortThreshold) {
    if (depthLimit === 0) {
      b2HeapSort(keys, first, last);
      return;
    }
    --depthLimit;

    // Median of three moved to keys[first] as the pivot.
    const mid = first + ((last - first) >> 1);
    b2MoveMedianToFirst(keys, first, first + 1, mid, last - 1);
    const pivot = keys[first];

    // Unguarded Hoare partition of [first + 1, last): the median guards both ends.
    let lo = first + 1;
    let hi = last;
    for (;;) {
      while (keys[lo] < pivot) {
        ++lo;
      }
      --hi;
      while (pivot < keys[hi]) {
        --hi;
      }
      if (!(lo < hi)) {
        break;
      }
      const t = keys[lo];
      keys[lo] = keys[hi];
      keys[hi] = t;
      ++lo;
    }

    // Recurse into the shorter side, loop on the longer one, so the stack stays logarithmic.
    if (lo - first < last - lo) {
      b2IntroSort(keys, first, lo, depthLimit);
      first = lo;
    } else {
      b2IntroSort(keys, lo, last, depthLimit);
      last = lo;
    }
  }
}

function b2MoveMedianToFirst(keys: Float64Array, result: number, a: number, b: number, c: number): void {
  const pa = keys[a];
  const pb = keys[b];
  const pc = keys[c];
  let median: number;
  if (pa < pb) {
    if (pb < pc) {
      median = b;
    } else if (pa < pc) {
      median = c;
    } else {
      median = a;
    }
  } else if (pa < pc) {
    median = a;
  } else if (pb < pc) {
    median = c;
  } else {
    median = b;
  }
  const t = keys[result];
  keys[result] = keys[median];
  keys[median] = t;
}

function b2HeapSort(keys: Float64Array, first: number, last: number): void {
  const n = last - first;
  for (let start = (n >> 1) - 1; start >= 0; --start) {
    b2SiftDown(keys, first, start, n);
  }
  for (let end = n - 1; end > 0; --end) {
    const t = keys[first];
    keys[first] = keys[first + end];
    keys[first + end] = t;
    b2SiftDown(keys, first, 0, end);
  }
}

function b2SiftDown(keys: Float64Array, first: number, root: number, n: number): void {
  for (;;) {
    let child = 2 * root + 1;
    if (child >= n) {
      return;
    }
    if (child + 1 < n && keys[first + child] < keys[first + child + 1]) {
      ++child;
    }
    if (!(keys[first + root] < keys[first + child])) {
      return;
    }
    const t = keys[first + root];
    keys[first + root] = keys[first + child];
    keys[first + child] = t;
    root = child;
  }
}

function b2InsertionSort(keys: Float64Array, first: number, last: number): void {
  for (let i = first + 1; i < last; ++i) {
    const value = keys[i];
    let j = i;
    while (j > first && value < keys[j - 1]) {
      keys[j] = keys[j - 1];
      --j;
    }
    keys[j] = value;
  }
}
