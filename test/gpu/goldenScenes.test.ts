/*
 * The GPU broad phase on the golden scenes (../shared/golden/scenes): each scene is loaded with
 * b2dJsonRead, stepped by the JavaScript engine, mirrored with GpuWorld, and at several steps the
 * GPU pair set must equal the brute-force set of proxy pairs whose (GPU) AABBs overlap and that
 * pass Box2D's own pair rules (asked of the engine: b2Body::ShouldCollide, the contact registry,
 * the world's contact filter). The GPU AABBs must match the engine's b2Shape::ComputeAABB at the
 * start of the body's sweep and at its transform (united, as b2Fixture::Synchronize sweeps them),
 * extended by b2_aabbExtension and by b2_aabbMultiplier x the sweep's displacement and x dt x v
 * (bounds.wgsl's prediction), and every contact of the JavaScript world whose shapes overlap at the
 * current transforms (b2TestOverlap on the shapes) must be among the GPU pairs.
 */

import { expect, it } from 'vitest';
import { b2AABB, b2TestOverlapShapes } from '../../src/collision/b2Collision';
import { b2Transform } from '../../src/common/b2Math';
import { b2_aabbExtension, b2_aabbMultiplier } from '../../src/common/b2Settings';
import { b2Contact } from '../../src/dynamics/contacts/b2Contact';
import { GpuBroadPhase } from '../../src-gpu/broadphase/broadPhase';
import { GpuWorld } from '../../src-gpu/world/world';
import { goldenSceneNames, loadGoldenScene } from '../support/scene';
import { bruteForcePairs, expectSamePairs } from './reference';
import { describeGpu } from './support';

const STEPS = [0, 1, 45, 180];

describeGpu('GPU broad phase on the golden scenes', (ctx) => {
  const broadPhase = new GpuBroadPhase(ctx);
  let checkedContacts = 0;

  for (const name of goldenSceneNames()) {
    it(`${name}: GPU pairs equal the brute-force pairs at steps ${STEPS.join(', ')}`, async () => {
      const scene = loadGoldenScene(name);
      const world = scene.world;
      const mirror = new GpuWorld(ctx, world);
      const aabb = new b2AABB();
      const start = new b2AABB();
      const xf0 = new b2Transform();
      let step = 0;
      for (const target of STEPS) {
        while (step < target) {
          scene.step();
          step++;
        }
        mirror.sync();
        const result = await broadPhase.update(mirror);
        const aabbs = await broadPhase.readAABBs();
        const pairs = await broadPhase.readPairs();
        expect(pairs.length / 2).toBe(result.pairCount);

        // The AABBs: the engine's, swept, fattened and predicted, to float32 accuracy.
        const dt = world.m_inv_dt0 > 0 ? 1 / world.m_inv_dt0 : 0;
        for (let slot = 0; slot < mirror.proxySlotCount; ++slot) {
          const proxy = mirror.proxyAt(slot);
          if (!proxy) {
            expect(aabbs[4 * slot]).toBeGreaterThan(aabbs[4 * slot + 2]);
            continue;
          }
          const f = proxy.fixture;
          const body = f.m_body;
          const sweep = body.m_sweep;
          f.m_shape.ComputeAABB(aabb, body.m_xf, proxy.childIndex);
          // b2Body::SynchronizeFixtures' xf1, the transform at the sweep's start, with the turn
          // a0 - a the mirror's float32 angles give (a lever of metres turns the rounding of a
          // large angle into micrometres).
          xf0.q.Set(sweep.a + (Math.fround(sweep.a0) - Math.fround(sweep.a)));
          xf0.p.Set(
            sweep.c0.x - (xf0.q.c * sweep.localCenter.x - xf0.q.s * sweep.localCenter.y),
            sweep.c0.y - (xf0.q.s * sweep.localCenter.x + xf0.q.c * sweep.localCenter.y),
          );
          f.m_shape.ComputeAABB(start, xf0, proxy.childIndex);
          const d = [b2_aabbMultiplier * (body.m_xf.p.x - xf0.p.x), b2_aabbMultiplier * (body.m_xf.p.y - xf0.p.y)];
          const e = [b2_aabbMultiplier * dt * body.m_linearVelocity.x, b2_aabbMultiplier * dt * body.m_linearVelocity.y];
          const expected = [
            Math.min(aabb.lowerBound.x, start.lowerBound.x) - b2_aabbExtension + Math.min(d[0], e[0], 0),
            Math.min(aabb.lowerBound.y, start.lowerBound.y) - b2_aabbExtension + Math.min(d[1], e[1], 0),
            Math.max(aabb.upperBound.x, start.upperBound.x) + b2_aabbExtension + Math.max(d[0], e[0], 0),
            Math.max(aabb.upperBound.y, start.upperBound.y) + b2_aabbExtension + Math.max(d[1], e[1], 0),
          ];
          for (let k = 0; k < 4; ++k) {
            const tolerance = 2e-6 * (1 + Math.abs(expected[k]));
            if (Math.abs(aabbs[4 * slot + k] - expected[k]) > tolerance) {
              throw new Error(`${name} step ${step}: proxy ${slot} AABB[${k}] is ${aabbs[4 * slot + k]}, the engine's ${expected[k]}`);
            }
          }
        }

        // The pairs: brute force over the GPU's AABBs with the engine's own pair rules.
        const filter = (a: number, b: number) => {
          const fa = mirror.proxyAt(a)!.fixture;
          const fb = mirror.proxyAt(b)!.fixture;
          const ba = fa.m_body;
          const bb = fb.m_body;
          if (ba === bb || !bb.ShouldCollide(ba)) return false;
          if (b2Contact.s_registers[fa.m_shape.m_type][fb.m_shape.m_type].createFcn === null) return false;
          return world.m_contactManager.m_contactFilter!.ShouldCollide(fa, fb);
        };
        const expected = bruteForcePairs(aabbs, filter);
        expectSamePairs(pairs, expected, `${name} step ${step}`);

        // Every contact of the JavaScript world whose shapes overlap now is a GPU pair. (Touching
        // is not enough: the engine set it before the step's solve moved the bodies.)
        const set = new Set<number>();
        for (let i = 0; i < pairs.length; i += 2) set.add(pairs[i] * 2 ** 26 + pairs[i + 1]);
        let overlapping = 0;
        for (let c = world.GetContactList(); c; c = c.GetNext()) {
          const fa = c.m_fixtureA;
          const fb = c.m_fixtureB;
          if (!b2TestOverlapShapes(fa.m_shape, c.m_indexA, fb.m_shape, c.m_indexB, fa.m_body.m_xf, fb.m_body.m_xf)) continue;
          overlapping++;
          const a = mirror.proxySlot(c.m_fixtureA, c.m_indexA);
          const b = mirror.proxySlot(c.m_fixtureB, c.m_indexB);
          if (!set.has(Math.min(a, b) * 2 ** 26 + Math.max(a, b))) {
            throw new Error(`${name} step ${step}: the shapes of contact (proxies ${a}, ${b}) overlap, but it is not a GPU pair`);
          }
        }
        checkedContacts += overlapping;
      }
      expect(mirror.usesCustomContactFilter).toBe(false);
      mirror.destroy();
    });
  }

  it('checked engine contacts whose shapes overlap in the scenes above', () => {
    expect(checkedContacts).toBeGreaterThan(500);
  });
});
