/*
 * The GPU narrow-phase kernels on every case of the C++ reference vectors for the five collide
 * families (../shared/golden/collision-vectors.json): circles, polygon-circle, polygons,
 * edge-circle, edge-polygon (edges with ghost vertices: one-sided and smooth cases included).
 *
 * Each case becomes two bodies of a b2World (shape A created first, so it gets the lower engine
 * proxy id and is fixture A, as for the reference), mirrored with GpuWorld, and the pair goes
 * through GpuPipeline.collideGivenPairs: classify, bin, collide kernel, persist.
 *
 * Agreement: the same manifold type, point count and contact-feature ids (b2ContactID::key), and
 * normals and points within tolerance: |GPU - reference| <= 1e-5 for the local normal (a unit
 * vector), <= 1e-5 * S for local points, S = max(1, the largest coordinate magnitude of the
 * case's inputs: shape vertices and radii, transform positions). The GPU works in float32 from
 * float32 copies of the inputs (relative rounding 6e-8), so its results differ from the float64
 * reference by a few float32 ulps of S.
 *
 * Threshold cases: a discrete decision of the algorithm (a separation against the radius, a
 * clip, a region test, the 0.98 / 0.001 hysteresis) can fall on either side when the quantity
 * lies within float32 rounding of its threshold. A case whose type, count or ids differ is
 * accepted only when float64 evaluation on the CPU (thresholds.ts, with the engine's own collide
 * functions) shows exactly that: its decision margin (the smallest change of its inputs, relative
 * to S, that changes the engine's answer) is below 1e-5, and the engine gives the GPU's answer for
 * inputs moved by at most THRESHOLD_ULPS float32 ulps. The test counts those cases per family (at
 * most a handful each) and fails on any other disagreement; two further tests show the classifier
 * accepting a real float32 flip (circles 2^-30 m apart, touching on the GPU) and refusing a
 * disagreement far from every threshold.
 */

import { expect, it } from 'vitest';
import { b2Manifold } from '../../src/collision/b2Collision';
import { b2CollideCircles } from '../../src/collision/b2CollideCircle';
import type { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody } from '../../src/dynamics/b2Body';
import { b2World } from '../../src/dynamics/b2World';
import { GpuBroadPhase } from '../../src-gpu/broadphase/broadPhase';
import { GpuNarrowPhase } from '../../src-gpu/narrowphase/narrowPhase';
import { GpuPipeline } from '../../src-gpu/pipeline';
import type { GpuContactRecord } from '../../src-gpu/narrowphase/records';
import type { GpuContext } from '../../src-gpu/device/device';
import { GpuWorld } from '../../src-gpu/world/world';
import { collisionVectors, makeShape, makeTransform } from '../support/collisionVectors';
import type { CollideCase, ManifoldJson, ShapeJson } from '../support/collisionVectors';
import { describeGpu } from './support';
import { caseScale, classifyThreshold, margins, THRESHOLD_ULPS } from './thresholds';
import type { Family } from './thresholds';

const FAMILIES: Exclude<Family, 'overlap'>[] = [
  'collideCircles',
  'collidePolygonAndCircle',
  'collidePolygons',
  'collideEdgeAndCircle',
  'collideEdgeAndPolygon',
];

/** Most threshold cases a family may have (each one shown to be a float32 rounding flip). */
const MAX_THRESHOLD_CASES = 6;

/** "type/count/ids" of a manifold (points only when there are any). */
function discreteJson(m: ManifoldJson): string {
  if (m.pointCount === 0) return '0';
  return `${m.type}/${m.pointCount}/${m.points.map((p) => p.id.key).join(',')}`;
}
function discreteGpu(c: GpuContactRecord): string {
  if (c.pointCount === 0) return '0';
  return `${c.type}/${c.pointCount}/${c.points.map((p) => p.id).join(',')}`;
}

/**
 * The cases as pairs of bodies of one b2World (shape A's fixture created first, so it has the
 * lower engine proxy id and is fixture A), through GpuPipeline.collideGivenPairs; the contacts
 * come back in case order.
 */
async function collideOnGpu(
  ctx: GpuContext,
  pipeline: GpuPipeline,
  cases: CollideCase<ShapeJson, ShapeJson>[],
): Promise<{ contacts: GpuContactRecord[]; order: number[]; close: () => void }> {
  const world = new b2World(new b2Vec2(0, 0));
  const fixtures = cases.map((c) => {
    const defA = new b2BodyDef();
    defA.position.Set(c.xfA.p.x, c.xfA.p.y);
    defA.angle = c.xfA.angle;
    const bodyA = world.CreateBody(defA);
    const fa = bodyA.CreateFixture(makeShape(c.shapeA), 0);
    const defB = new b2BodyDef();
    defB.type = b2_dynamicBody;
    defB.position.Set(c.xfB.p.x, c.xfB.p.y);
    defB.angle = c.xfB.angle;
    const bodyB = world.CreateBody(defB);
    const fb = bodyB.CreateFixture(makeShape(c.shapeB), 1);
    // The bodies' rotations are b2Rot(angle), as the reference's transforms.
    expect(bodyA.m_xf.q.s).toBe(makeTransform(c.xfA).q.s);
    expect(bodyB.m_xf.q.c).toBe(makeTransform(c.xfB).q.c);
    return [fa, fb] as const;
  });
  const mirror = new GpuWorld(ctx, world);
  mirror.sync();
  const pairs = new Uint32Array(2 * cases.length);
  fixtures.forEach(([fa, fb], i) => {
    const a = mirror.proxySlot(fa, 0);
    const b = mirror.proxySlot(fb, 0);
    pairs[2 * i] = Math.min(a, b);
    pairs[2 * i + 1] = Math.max(a, b);
  });
  // The narrow phase takes the pairs sorted, as the broad phase gives them.
  const order = cases.map((_, i) => i).sort((x, y) => pairs[2 * x] - pairs[2 * y] || pairs[2 * x + 1] - pairs[2 * y + 1]);
  const sorted = new Uint32Array(pairs.length);
  order.forEach((caseIndex, k) => {
    sorted[2 * k] = pairs[2 * caseIndex];
    sorted[2 * k + 1] = pairs[2 * caseIndex + 1];
  });
  const narrow = pipeline.narrowPhase;
  narrow.reset();
  const result = await pipeline.collideGivenPairs(mirror, sorted);
  expect(result.contactCount).toBe(cases.length);
  const sortedContacts = await narrow.readContacts();
  const contacts: GpuContactRecord[] = new Array(cases.length);
  sortedContacts.forEach((c, k) => {
    const [fa, fb] = fixtures[order[k]];
    // Fixture A of the contact is the reference's shape A.
    expect(c.proxyA).toBe(mirror.proxySlot(fa, 0));
    expect(c.proxyB).toBe(mirror.proxySlot(fb, 0));
    contacts[order[k]] = c;
  });
  return { contacts, order: cases.map((_, i) => i), close: () => mirror.destroy() };
}

interface FamilyReport {
  cases: number;
  exact: number;
  threshold: number[];
  failures: string[];
  maxNormalError: number;
  maxPointError: number;
}

describeGpu('GPU narrow-phase kernels on the C++ collision vectors', (ctx) => {
  const pipeline = new GpuPipeline(ctx, new GpuBroadPhase(ctx), new GpuNarrowPhase(ctx, { initialContactCapacity: 512 }));
  const reports: Record<string, FamilyReport> = {};

  for (const family of FAMILIES) {
    it(`${family}: every case, same type, points and ids as the reference (threshold cases explained)`, async () => {
      const cases = collisionVectors[family] as CollideCase<ShapeJson, ShapeJson>[];
      const { contacts, order, close } = await collideOnGpu(ctx, pipeline, cases);
      const report: FamilyReport = { cases: cases.length, exact: 0, threshold: [], failures: [], maxNormalError: 0, maxPointError: 0 };
      contacts.forEach((c, k) => {
        const i = order[k];
        const tc = cases[i];
        const ref = tc.manifold;
        if (discreteGpu(c) !== discreteJson(ref)) {
          const verdict = classifyThreshold(family, tc, discreteGpu(c));
          if (verdict.explained) report.threshold.push(i);
          else report.failures.push(`case ${i}: GPU ${discreteGpu(c)}, reference ${discreteJson(ref)}; ${verdict.why}`);
          return;
        }
        report.exact++;
        if (ref.pointCount === 0) return;
        const S = caseScale(tc);
        const ne = Math.max(Math.abs(c.localNormal.x - ref.localNormal!.x), Math.abs(c.localNormal.y - ref.localNormal!.y));
        let pe = Math.max(Math.abs(c.localPoint.x - ref.localPoint!.x), Math.abs(c.localPoint.y - ref.localPoint!.y));
        c.points.forEach((p, j) => {
          const e = ref.points[j].localPoint;
          pe = Math.max(pe, Math.abs(p.localPoint.x - e.x), Math.abs(p.localPoint.y - e.y));
        });
        report.maxNormalError = Math.max(report.maxNormalError, ne);
        report.maxPointError = Math.max(report.maxPointError, pe / S);
        if (ne > 1e-5 || pe > 1e-5 * S) {
          report.failures.push(`case ${i}: normal error ${ne.toExponential(2)}, point error ${pe.toExponential(2)} (S = ${S.toPrecision(3)})`);
        }
      });
      reports[family] = report;
      console.log(
        `${family}: ${report.cases} cases, ${report.exact} exact in type/count/ids, threshold cases [${report.threshold.join(', ')}], ` +
          `max normal error ${report.maxNormalError.toExponential(2)}, max point error / S ${report.maxPointError.toExponential(2)}`,
      );
      expect(report.failures, report.failures.slice(0, 5).join('\n')).toEqual([]);
      expect(report.threshold.length).toBeLessThanOrEqual(MAX_THRESHOLD_CASES);
      expect(report.exact + report.threshold.length).toBe(cases.length);
      close();
    });
  }

  it('identifies a real float32 threshold case: circles apart by 2^-30 m in float64, touching in float32', async () => {
    const tc: CollideCase<ShapeJson, ShapeJson> = {
      shapeA: { radius: 0.5, center: { x: 0, y: 0 } },
      xfA: { p: { x: 0, y: 0 }, angle: 0 },
      shapeB: { radius: 0.5, center: { x: 0, y: 0 } },
      xfB: { p: { x: 1 + 2 ** -30, y: 0 }, angle: 0 },
      manifold: { type: 0, pointCount: 0, points: [] },
    };
    const reference = new b2Manifold();
    b2CollideCircles(reference, makeShape(tc.shapeA) as b2CircleShape, makeTransform(tc.xfA), makeShape(tc.shapeB) as b2CircleShape, makeTransform(tc.xfB));
    expect(reference.pointCount).toBe(0);
    const { contacts, close } = await collideOnGpu(ctx, pipeline, [tc]);
    close();
    expect(discreteGpu(contacts[0])).toBe('0/1/0');
    const verdict = classifyThreshold('collideCircles', tc, '0/1/0');
    expect(verdict.explained, verdict.why).toBe(true);
    expect(verdict.flipUlps).toBe(0);
    expect(verdict.margin).toBeLessThan(1e-8);
  });

  it('does not excuse a disagreement far from every threshold', () => {
    const cases = collisionVectors.collidePolygons as CollideCase<ShapeJson, ShapeJson>[];
    const i = cases.findIndex((c) => c.manifold.pointCount === 2 && margins('collidePolygons', c) > 1e-3);
    expect(i).toBeGreaterThanOrEqual(0);
    const verdict = classifyThreshold('collidePolygons', cases[i], '0');
    expect(verdict.explained).toBe(false);
    expect(verdict.flipUlps).toBeGreaterThan(THRESHOLD_ULPS);
  });

  it('covers every case of the five families', () => {
    for (const family of FAMILIES) expect(reports[family]?.cases, family).toBe(300);
  });
});
