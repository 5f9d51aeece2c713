/*
 * The GPU narrow phase against the JavaScript engine on the golden scenes
 * (../shared/golden/scenes), at several steps.
 *
 * At step k (the world as the engine left it after k steps):
 *   1. the mirror is synced and the GPU's previous contacts are seeded with the engine's contacts
 *      as they are now (GpuNarrowPhase.seedFromWorld: keys, ids, impulses after the solve of step
 *      k, touching flags);
 *   2. the GPU runs the broad and narrow phase on this state;
 *   3. the engine takes step k + 1, and its contacts are captured right after b2ContactManager::
 *      Collide, i.e. after b2Contact::Update at the same state: manifolds, touching flags, and the
 *      impulses Update carried over by contact-feature id.
 * Then, contact by contact (pairs of proxy slots):
 *   - the touching sets are equal (sensors included: b2TestOverlap);
 *   - fixture A and B are the engine's (b2Contact::Create's order);
 *   - for touching contacts: the same manifold type, point count and ids; local normal within
 *     1e-5 and local points within 1e-5 * S (S = max(1, the largest coordinate of the two shapes
 *     in their body frames, the distance between the bodies)); the carried impulses equal the
 *     engine's carried impulses rounded to float32 (they are copies, so exactly);
 *   - GPU contacts the engine does not have (the GPU's AABBs are recomputed each step, the
 *     engine's fat AABBs persist) are checked against the engine's collide function, run on the
 *     same fixtures and transforms.
 * Disagreements in a discrete outcome must be float32 threshold cases (thresholds.ts); the test
 * reports their number.
 */

import { expect, it } from 'vitest';
import { b2Manifold } from '../../src/collision/b2Collision';
import type { b2ChainShape } from '../../src/collision/shapes/b2ChainShape';
import { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import type { b2Shape } from '../../src/collision/shapes/b2Shape';
import { b2Transform } from '../../src/common/b2Math';
import type { b2Fixture } from '../../src/dynamics/b2Fixture';
import { GpuBroadPhase } from '../../src-gpu/broadphase/broadPhase';
import { BIN } from '../../src-gpu/device/layout';
import { GpuNarrowPhase } from '../../src-gpu/narrowphase/narrowPhase';
import { GpuPipeline } from '../../src-gpu/pipeline';
import type { GpuContactRecord } from '../../src-gpu/narrowphase/records';
import { GpuWorld } from '../../src-gpu/world/world';
import { goldenSceneNames, loadGoldenScene } from '../support/scene';
import { describeGpu } from './support';
import { caseScale, classifyThreshold, discrete, engineManifold } from './thresholds';
import type { CaseObjects, Family } from './thresholds';

const STEPS = [1, 45, 70, 180];

const FAMILY_OF_BIN: Record<number, Family> = {
  [BIN.CIRCLES]: 'collideCircles',
  [BIN.POLYGON_CIRCLE]: 'collidePolygonAndCircle',
  [BIN.POLYGONS]: 'collidePolygons',
  [BIN.EDGE_CIRCLE]: 'collideEdgeAndCircle',
  [BIN.EDGE_POLYGON]: 'collideEdgeAndPolygon',
  [BIN.CHAIN_CIRCLE]: 'collideEdgeAndCircle',
  [BIN.CHAIN_POLYGON]: 'collideEdgeAndPolygon',
  [BIN.SENSOR]: 'overlap',
};

/** A fixture child as the collide functions see it (a chain child as its b2EdgeShape). */
function childShape(f: b2Fixture, child: number): b2Shape {
  if (f.m_shape.m_type !== 3) return f.m_shape;
  const edge = new b2EdgeShape();
  (f.m_shape as b2ChainShape).GetChildEdge(edge, child);
  return edge;
}

interface Snapshot {
  proxyA: number;
  touching: boolean;
  sensor: boolean;
  type: number;
  pointCount: number;
  ids: number[];
  normal: { x: number; y: number };
  point: { x: number; y: number };
  points: { x: number; y: number }[];
  impulses: number[];
}

function gpuDiscrete(c: GpuContactRecord): string {
  if (c.sensor) return c.touching ? '0/1/0' : '0';
  if (c.pointCount === 0) return '0';
  return `${c.type}/${c.pointCount}/${c.points.map((p) => p.id).join(',')}`;
}

interface Totals {
  contacts: number;
  touching: number;
  comparedManifolds: number;
  comparedImpulses: number;
  nonZeroImpulses: number;
  extraGpu: number;
  threshold: string[];
  chainContacts: number;
  sensorContacts: number;
}

describeGpu('GPU narrow phase against the engine on the golden scenes', (ctx) => {
  const broadPhase = new GpuBroadPhase(ctx);
  const narrow = new GpuNarrowPhase(ctx);
  const pipeline = new GpuPipeline(ctx, broadPhase, narrow);
  const totals: Totals = {
    contacts: 0,
    touching: 0,
    comparedManifolds: 0,
    comparedImpulses: 0,
    nonZeroImpulses: 0,
    extraGpu: 0,
    threshold: [],
    chainContacts: 0,
    sensorContacts: 0,
  };

  for (const name of goldenSceneNames()) {
    it(`${name}: touching contacts, manifolds and carried impulses equal the engine's at steps ${STEPS.join(', ')}`, async () => {
      const scene = loadGoldenScene(name);
      const world = scene.world;
      const mirror = new GpuWorld(ctx, world);
      const failures: string[] = [];
      let step = 0;
      for (const target of STEPS) {
        while (step < target) {
          scene.step();
          step++;
        }
        mirror.sync();
        narrow.seedFromWorld(mirror);
        const result = await pipeline.step(mirror);
        const contacts = await narrow.readContacts();
        expect(contacts.length).toBe(result.contactCount);

        // The engine's step k + 1, captured after its Collide.
        const snap = new Map<number, Snapshot>();
        const cm = world.m_contactManager;
        const collide = cm.Collide;
        cm.Collide = function (this: typeof cm) {
          collide.call(this);
          for (let c = this.m_contactList; c; c = c.m_next) {
            const a = mirror.proxySlot(c.m_fixtureA, c.m_indexA);
            const b = mirror.proxySlot(c.m_fixtureB, c.m_indexB);
            const m = c.m_manifold;
            const ids: number[] = [];
            const points: { x: number; y: number }[] = [];
            const impulses: number[] = [];
            for (let i = 0; i < m.pointCount; ++i) {
              ids.push(m.points[i].id.key);
              points.push({ x: m.points[i].localPoint.x, y: m.points[i].localPoint.y });
              impulses.push(m.points[i].normalImpulse, m.points[i].tangentImpulse);
            }
            snap.set(Math.min(a, b) * 2 ** 26 + Math.max(a, b), {
              proxyA: a,
              touching: c.IsTouching(),
              sensor: c.m_fixtureA.m_isSensor || c.m_fixtureB.m_isSensor,
              type: m.type,
              pointCount: m.pointCount,
              ids,
              normal: { x: m.localNormal.x, y: m.localNormal.y },
              point: { x: m.localPoint.x, y: m.localPoint.y },
              points,
              impulses,
            });
          }
        };
        scene.step();
        step++;
        delete (cm as { Collide?: unknown }).Collide;
        expect(cm.Collide).toBe(collide);

        const seen = new Set<number>();
        for (const c of contacts) {
          const key = c.a * 2 ** 26 + c.b;
          seen.add(key);
          totals.contacts++;
          if (c.bin === BIN.CHAIN_CIRCLE || c.bin === BIN.CHAIN_POLYGON) totals.chainContacts++;
          if (c.sensor) totals.sensorContacts++;
          const pa = mirror.proxyAt(c.proxyA)!;
          const pb = mirror.proxyAt(c.proxyB)!;
          const objects: CaseObjects = {
            a: childShape(pa.fixture, pa.childIndex),
            xfA: pa.fixture.m_body.m_xf.Clone(),
            b: childShape(pb.fixture, pb.childIndex),
            xfB: pb.fixture.m_body.m_xf.Clone(),
          };
          const family = FAMILY_OF_BIN[c.bin];
          const js = snap.get(key);
          let reference: Snapshot;
          if (js) {
            if (js.proxyA !== c.proxyA)
              failures.push(`step ${target}: contact (${c.a}, ${c.b}): fixture A is proxy ${c.proxyA} on the GPU, ${js.proxyA} in the engine`);
            reference = js;
          } else {
            // A pair the engine has no contact for: its collide function on the same inputs.
            totals.extraGpu++;
            const m: b2Manifold = engineManifold(family, objects);
            const ids: number[] = [];
            const points: { x: number; y: number }[] = [];
            for (let i = 0; i < m.pointCount; ++i) {
              ids.push(m.points[i].id.key);
              points.push({ x: m.points[i].localPoint.x, y: m.points[i].localPoint.y });
            }
            reference = {
              proxyA: c.proxyA,
              touching: m.pointCount > 0,
              sensor: c.sensor,
              type: m.type,
              pointCount: family === 'overlap' ? 0 : m.pointCount,
              ids: family === 'overlap' ? [] : ids,
              normal: { x: m.localNormal.x, y: m.localNormal.y },
              point: { x: m.localPoint.x, y: m.localPoint.y },
              points: family === 'overlap' ? [] : points,
              impulses: [],
            };
          }
          const refDiscrete = reference.sensor
            ? reference.touching
              ? '0/1/0'
              : '0'
            : reference.pointCount === 0
              ? '0'
              : `${reference.type}/${reference.pointCount}/${reference.ids.join(',')}`;
          if (gpuDiscrete(c) !== refDiscrete || c.touching !== reference.touching) {
            const verdict = classifyThreshold(family, objects, family === 'overlap' ? (c.touching ? '0/1/0' : '0') : gpuDiscrete(c));
            // The engine on the same objects must give the reference's answer (else the capture is off).
            const engine = discrete(engineManifold(family, objects));
            if (verdict.explained && engine === (family === 'overlap' ? (reference.touching ? '0/1/0' : '0') : refDiscrete)) {
              totals.threshold.push(`${name} step ${target} (${c.a}, ${c.b}) ${family}: GPU ${gpuDiscrete(c)}, engine ${refDiscrete}`);
            } else {
              failures.push(`step ${target}: contact (${c.a}, ${c.b}) ${family}: GPU ${gpuDiscrete(c)}, engine ${refDiscrete}; ${verdict.why}`);
            }
            continue;
          }
          if (!c.touching) continue;
          totals.touching++;
          if (c.sensor) continue;
          totals.comparedManifolds++;
          const local = caseScale({ a: objects.a, b: objects.b, xfA: new b2Transform(), xfB: new b2Transform() });
          const S = Math.max(local, Math.hypot(objects.xfB.p.x - objects.xfA.p.x, objects.xfB.p.y - objects.xfA.p.y));
          const ne = Math.max(Math.abs(c.localNormal.x - reference.normal.x), Math.abs(c.localNormal.y - reference.normal.y));
          let pe = Math.max(Math.abs(c.localPoint.x - reference.point.x), Math.abs(c.localPoint.y - reference.point.y));
          c.points.forEach((p, i) => {
            pe = Math.max(pe, Math.abs(p.localPoint.x - reference.points[i].x), Math.abs(p.localPoint.y - reference.points[i].y));
          });
          if (ne > 1e-5 || pe > 1e-5 * S) {
            failures.push(
              `step ${target}: contact (${c.a}, ${c.b}) ${family}: normal error ${ne.toExponential(2)}, point error ${pe.toExponential(2)} (S ${S.toPrecision(3)})`,
            );
          }
          if (js) {
            c.points.forEach((p, i) => {
              totals.comparedImpulses++;
              const want = [Math.fround(js.impulses[2 * i]), Math.fround(js.impulses[2 * i + 1])];
              if (want[0] !== 0 || want[1] !== 0) totals.nonZeroImpulses++;
              if (p.normalImpulse !== want[0] || p.tangentImpulse !== want[1]) {
                failures.push(
                  `step ${target}: contact (${c.a}, ${c.b}) point ${i}: carried impulses (${p.normalImpulse}, ${p.tangentImpulse}), engine (${want[0]}, ${want[1]})`,
                );
              }
            });
          }
        }
        // Every contact the engine has touching is a GPU contact.
        for (const [key, js] of snap) {
          if (js.touching && !seen.has(key)) failures.push(`step ${target}: the engine's touching contact ${key} is not a GPU contact`);
        }
      }
      mirror.destroy();
      expect(failures, failures.slice(0, 6).join('\n')).toEqual([]);
    });
  }

  it('compared enough contacts, chain and sensor contacts among them; threshold cases are rare', () => {
    console.log(
      `golden scenes: ${totals.contacts} GPU contacts, ${totals.touching} touching, ${totals.comparedManifolds} manifolds compared, ` +
        `${totals.comparedImpulses} points' carried impulses compared (${totals.nonZeroImpulses} non-zero), ${totals.extraGpu} contacts the engine lacks, ` +
        `${totals.chainContacts} chain contacts, ${totals.sensorContacts} sensor contacts, ${totals.threshold.length} threshold cases` +
        (totals.threshold.length ? `:\n  ${totals.threshold.join('\n  ')}` : ''),
    );
    expect(totals.comparedManifolds).toBeGreaterThan(1000);
    expect(totals.nonZeroImpulses).toBeGreaterThan(1000);
    expect(totals.chainContacts).toBeGreaterThan(0);
    expect(totals.sensorContacts).toBeGreaterThan(0);
    expect(totals.threshold.length).toBeLessThanOrEqual(Math.max(3, totals.touching / 1000));
  });
});
