import { describe, expect, it } from 'vitest';
import { b2BroadPhase, b2Pair, b2PairLessThan } from '../../src/collision/b2BroadPhase';
import type { b2BroadPhasePairCallback } from '../../src/collision/b2BroadPhase';
import { b2AABB, b2TestOverlap } from '../../src/collision/b2Collision';
import { b2Vec2 } from '../../src/common/b2Math';
import { Fnv1a, hashTree, mulberry32, probe, randomAABB } from './b2DynamicTree.support';

function box(lx: number, ly: number, ux: number, uy: number): b2AABB {
  const aabb = new b2AABB();
  aabb.lowerBound.Set(lx, ly);
  aabb.upperBound.Set(ux, uy);
  return aabb;
}

class PairLog implements b2BroadPhasePairCallback {
  readonly pairs: [any, any][] = [];
  AddPair(userDataA: any, userDataB: any): void {
    this.pairs.push([userDataA, userDataB]);
  }
}

function update(bp: b2BroadPhase): [any, any][] {
  const log = new PairLog();
  bp.UpdatePairs(log);
  return log.pairs;
}

function pair(a: number, b: number): b2Pair {
  const p = new b2Pair();
  p.proxyIdA = a;
  p.proxyIdB = b;
  return p;
}

// a [0,1]^2 and b [0.5,1.5]^2 overlap; d [1.5,2]x[0,1] overlaps b (fat AABBs touch at x 1.4..1.6)
// but not a; c is alone. Ids follow the tree pool: leaves 0, 1, 3, 5 with inner nodes 2, 4, 6.
function handBroadPhase(): b2BroadPhase {
  const bp = new b2BroadPhase();
  expect(bp.CreateProxy(box(0, 0, 1, 1), 'a')).toBe(0);
  expect(bp.CreateProxy(box(0.5, 0.5, 1.5, 1.5), 'b')).toBe(1);
  expect(bp.CreateProxy(box(5, 5, 6, 6), 'c')).toBe(3);
  expect(bp.CreateProxy(box(1.5, 0, 2, 1), 'd')).toBe(5);
  return bp;
}

describe('b2PairLessThan', () => {
  it('orders pairs lexicographically by (proxyIdA, proxyIdB)', () => {
    expect(b2PairLessThan(pair(1, 9), pair(2, 0))).toBe(true);
    expect(b2PairLessThan(pair(2, 0), pair(1, 9))).toBe(false);
    expect(b2PairLessThan(pair(2, 3), pair(2, 4))).toBe(true);
    expect(b2PairLessThan(pair(2, 4), pair(2, 3))).toBe(false);
    expect(b2PairLessThan(pair(2, 3), pair(2, 3))).toBe(false);
  });
});

describe('b2BroadPhase', () => {
  it('counts proxies and buffers a move for each new proxy', () => {
    const bp = handBroadPhase();
    expect(bp.GetProxyCount()).toBe(4);
    expect(bp.m_moveCount).toBe(4);
    expect(Array.from(bp.m_moveBuffer.subarray(0, 4))).toEqual([0, 1, 3, 5]);
    expect(bp.GetUserData(3)).toBe('c');
    expect(bp.TestOverlap(0, 1)).toBe(true);
    expect(bp.TestOverlap(0, 5)).toBe(false);
    expect(bp.TestOverlap(1, 5)).toBe(true);
  });

  it('reports each overlapping pair once, in (min id, max id) order, with the user data of each side', () => {
    const bp = handBroadPhase();
    // Queries for 0, 1, 3, 5 buffer (0,1), (0,1), (1,5), (1,5); sorting exposes the duplicates.
    expect(update(bp)).toEqual([
      ['a', 'b'],
      ['b', 'd'],
    ]);
    expect(bp.m_pairCount).toBe(4);
    expect(bp.m_moveCount).toBe(0);
  });

  it('reports nothing for proxies that did not move', () => {
    const bp = handBroadPhase();
    update(bp);
    expect(update(bp)).toEqual([]);
    // A move that stays inside the fat AABB is not buffered either.
    bp.MoveProxy(0, box(0.05, 0.05, 1.05, 1.05), new b2Vec2(0.05, 0.05));
    expect(bp.m_moveCount).toBe(0);
    expect(update(bp)).toEqual([]);
  });

  it('puts the smaller proxy id first when the moved proxy has the larger id', () => {
    const bp = handBroadPhase();
    update(bp);
    // c (id 3) moves onto a and b: the query from 3 yields (0,3) and (1,3).
    bp.MoveProxy(3, box(0.2, 0.2, 1.2, 1.2), new b2Vec2(-4.8, -4.8));
    expect(bp.m_moveCount).toBe(1);
    expect(update(bp)).toEqual([
      ['a', 'c'],
      ['b', 'c'],
    ]);
  });

  it('re-reports the pairs of a touched proxy', () => {
    const bp = handBroadPhase();
    update(bp);
    bp.TouchProxy(5);
    expect(update(bp)).toEqual([['b', 'd']]);
  });

  it('drops the buffered move of a destroyed proxy', () => {
    const bp = handBroadPhase();
    update(bp);
    bp.MoveProxy(5, box(0.6, 0.6, 1.1, 1.1), new b2Vec2(-0.9, 0.6));
    expect(Array.from(bp.m_moveBuffer.subarray(0, bp.m_moveCount))).toEqual([5]);
    bp.DestroyProxy(5);
    expect(Array.from(bp.m_moveBuffer.subarray(0, bp.m_moveCount))).toEqual([b2BroadPhase.e_nullProxy]);
    expect(bp.GetProxyCount()).toBe(3);
    expect(update(bp)).toEqual([]);
  });

  it('forwards queries, ray casts and tree statistics to its tree', () => {
    const bp = handBroadPhase();
    const seen: number[] = [];
    bp.Query({ QueryCallback: (id: number) => (seen.push(id), true) }, box(-1, -1, 3, 3));
    expect(seen.sort()).toEqual([0, 1, 5]);
    expect(bp.GetTreeHeight()).toBe(bp.m_tree.GetHeight());
    expect(bp.GetTreeBalance()).toBe(bp.m_tree.GetMaxBalance());
    expect(Object.is(bp.GetTreeQuality(), bp.m_tree.GetAreaRatio())).toBe(true);
    expect(bp.GetFatAABB(3)).toEqual(bp.m_tree.GetFatAABB(3));
    const out = new b2AABB();
    expect(bp.GetFatAABB(3, out)).toBe(out);
    expect(out).toEqual(bp.m_tree.GetFatAABB(3));
  });

  it('grows the move and pair buffers by doubling and still reports every pair once in order', () => {
    const bp = new b2BroadPhase();
    // 20 coincident proxies: 40 - 1 tree nodes, 20 moves, 380 buffered pairs for 190 unique ones.
    for (let i = 0; i < 20; i++) bp.CreateProxy(box(0, 0, 1, 1), i);
    expect(bp.m_moveCapacity).toBe(32);
    const pairs = update(bp);
    expect(bp.m_pairCount).toBe(380);
    expect(bp.m_pairCapacity).toBe(512);
    expect(bp.m_pairBuffer.length).toBe(512);
    const ids = Array.from({ length: 20 }, (_, i) => i);
    const idOf = new Map(ids.map((tag) => [tag, -1]));
    for (let id = 0; id < bp.m_tree.m_nodeCapacity; id++) {
      const node = bp.m_tree.GetNode(id);
      if (node.height === 0) idOf.set(node.userData as number, id);
    }
    const want: [number, number][] = [];
    for (const a of ids) for (const b of ids) if (idOf.get(a)! < idOf.get(b)!) want.push([a, b]);
    want.sort((p, q) => idOf.get(p[0])! - idOf.get(q[0])! || idOf.get(p[1])! - idOf.get(q[1])!);
    expect(pairs).toEqual(want);
  });

  it('matches a brute-force pair search through random moves, creations and destructions', () => {
    const rnd = mulberry32(31337);
    const bp = new b2BroadPhase();
    const live: { id: number; aabb: b2AABB }[] = [];
    const d = new b2Vec2();
    for (let i = 0; i < 80; i++) {
      const aabb = randomAABB(rnd, new b2AABB(), 12, 1);
      live.push({ id: bp.CreateProxy(aabb, null), aabb });
    }
    for (let step = 0; step < 1500; step++) {
      const r = rnd();
      if (r < 0.6) {
        const p = live[Math.floor(rnd() * live.length)];
        d.Set((rnd() * 2 - 1) * 0.4, (rnd() * 2 - 1) * 0.4);
        p.aabb.lowerBound.Add(d);
        p.aabb.upperBound.Add(d);
        bp.MoveProxy(p.id, p.aabb, d);
      } else if (r < 0.8 && live.length < 150) {
        const aabb = randomAABB(rnd, new b2AABB(), 12, 1);
        live.push({ id: bp.CreateProxy(aabb, null), aabb });
      } else if (live.length > 20) {
        const k = Math.floor(rnd() * live.length);
        bp.DestroyProxy(live[k].id);
        live[k] = live[live.length - 1];
        live.pop();
      }
      if (step % 10 === 9) {
        const moved = new Set(Array.from(bp.m_moveBuffer.subarray(0, bp.m_moveCount)));
        const want: string[] = [];
        for (const p of live) {
          for (const q of live) {
            const candidate = p.id < q.id && (moved.has(p.id) || moved.has(q.id));
            if (candidate && b2TestOverlap(bp.GetFatAABB(p.id), bp.GetFatAABB(q.id))) {
              want.push(`${p.id},${q.id}`);
            }
          }
        }
        want.sort((x, y) => {
          const [xa, xb] = x.split(',').map(Number);
          const [ya, yb] = y.split(',').map(Number);
          return xa - ya || xb - yb;
        });
        // The user data here is null; read the ids back from the sorted pair buffer's keys
        // (proxyIdA * 2^26 + proxyIdB) instead.
        const got: string[] = [];
        bp.UpdatePairs({ AddPair: () => undefined });
        for (let i = 0; i < bp.m_pairCount; i++) {
          const key = `${Math.floor(bp.m_pairBuffer[i] / 2 ** 26)},${bp.m_pairBuffer[i] % 2 ** 26}`;
          if (got[got.length - 1] !== key) got.push(key);
        }
        expect(got).toEqual(want);
        // TestOverlap (on the tree's copy of the fat AABBs) agrees with b2TestOverlap on the AABBs.
        const disagree = live.flatMap((p) => live.filter((q) => bp.TestOverlap(p.id, q.id) !== b2TestOverlap(bp.GetFatAABB(p.id), bp.GetFatAABB(q.id))));
        expect(disagree).toEqual([]);
      }
    }
    expect(bp.GetProxyCount()).toBe(live.length);
    bp.m_tree.Validate();
  });
});

describe('b2BroadPhase against the C++ reference', () => {
  it('produces the pairs, ids and tree of Box2D 2.2.1 through a random proxy workload', () => {
    // broadPhaseScenario of b2DynamicTree.reference.cpp: every UpdatePairs contributes its
    // AddPair sequence (user tags) and count to the digest, then the final tree and a probe.
    const rnd = mulberry32(777);
    const hash = new Fnv1a();
    const bp = new b2BroadPhase();
    const ids: number[] = [];
    const boxes: b2AABB[] = [];
    const live: number[] = [];
    let liveCount = 0;
    let totalPairs = 0;
    const recorder = {
      count: 0,
      AddPair(a: number, b: number): void {
        hash.int(a);
        hash.int(b);
        ++this.count;
      },
    };
    const create = (): void => {
      const tag = boxes.length;
      boxes.push(randomAABB(rnd, new b2AABB(), 10.0, 1.0));
      ids.push(bp.CreateProxy(boxes[tag], tag + 1));
      live[liveCount++] = tag;
    };
    for (let i = 0; i < 60; i++) create();
    bp.UpdatePairs(recorder);
    hash.int(recorder.count);
    totalPairs += recorder.count;
    expect([recorder.count, hash.hex()]).toEqual([26, 'de54d663']);

    const d = new b2Vec2();
    for (let step = 0; step < 2000; step++) {
      const r = rnd();
      if (r < 0.55 && liveCount > 0) {
        const tag = live[Math.floor(rnd() * liveCount)];
        d.x = (rnd() * 2.0 - 1.0) * 0.3;
        d.y = (rnd() * 2.0 - 1.0) * 0.3;
        boxes[tag].lowerBound.Add(d);
        boxes[tag].upperBound.Add(d);
        bp.MoveProxy(ids[tag], boxes[tag], d);
      } else if (r < 0.65 && liveCount > 0) {
        bp.TouchProxy(ids[live[Math.floor(rnd() * liveCount)]]);
      } else if (r < 0.82 && liveCount < 200) {
        create();
        hash.int(ids[ids.length - 1]);
      } else if (liveCount > 0) {
        const k = Math.floor(rnd() * liveCount);
        const tag = live[k];
        bp.DestroyProxy(ids[tag]);
        hash.int(ids[tag]);
        live[k] = live[--liveCount];
      }
      if (step % 20 === 19) {
        recorder.count = 0;
        bp.UpdatePairs(recorder);
        hash.int(recorder.count);
        totalPairs += recorder.count;
      }
    }
    hashTree(hash, bp.m_tree);
    probe(hash, rnd, bp, 10.0);
    expect([bp.GetProxyCount(), totalPairs, bp.GetTreeHeight(), bp.GetTreeBalance()]).toEqual([40, 798, 7, 1]);
    expect([bp.m_pairCapacity, bp.m_moveCapacity]).toEqual([64, 64]);
    expect(Object.is(bp.GetTreeQuality(), 14.526524477037857)).toBe(true);
    expect(hash.hex()).toBe('eed70ed5');
  });
});
